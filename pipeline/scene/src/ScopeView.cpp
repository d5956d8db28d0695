#include "hs/scene/ScopeView.h"

#include "hs/scene/Scene.h"

#include <cmath>
#include <string>

namespace hs::scene {

namespace {

constexpr double kPi = 3.14159265358979323846;

} // namespace

Result<ScopeView> scopeView(const ScopeLandmarks& landmarks, double insertionMm, double opticDeg, double rollDeg) {
    const Vec3 canal = landmarks.internalOsMm - landmarks.externalOsMm;
    if (!(norm(canal) > 1e-6))
        return fail(ErrorCode::InvalidInput, "scope view: the external and internal os coincide");
    if (!(opticDeg >= 0.0 && opticDeg <= 90.0))
        return fail(ErrorCode::InvalidInput,
                    "scope view: optic " + std::to_string(opticDeg) + " degrees is outside 0-90 degrees");
    if (!std::isfinite(insertionMm) || !std::isfinite(rollDeg))
        return fail(ErrorCode::InvalidInput, "scope view: insertion and roll must be finite");
    ScopeView view;
    view.shaft = normalized(canal);
    view.eyeMm = landmarks.externalOsMm + view.shaft * insertionMm;
    // Roll 0: the optic looks towards anterior (+y); the roll turns the tilt about the shaft.
    const Vec3 anterior = perpendicularTo(view.shaft, {0.0, 1.0, 0.0});
    const Vec3 tiltTowards = rotatedAbout(anterior, view.shaft, rollDeg * kPi / 180.0);
    const double tilt = opticDeg * kPi / 180.0;
    view.direction = normalized(view.shaft * std::cos(tilt) + tiltTowards * std::sin(tilt));
    // The image's up: the side the optic is tilted to (for a 0 degree optic, the rolled anterior).
    view.up = perpendicularTo(view.direction, tiltTowards);
    return view;
}

Result<ScopeView> viewOfRegion(const Scene& scene, const ScopeLandmarks& landmarks, std::int32_t regionId,
                               double distanceMm) {
    Vec3 centre{0.0, 0.0, 0.0};
    std::size_t count = 0;
    for (std::size_t t = 0; t < scene.tets.tets.size() && t < scene.tets.regions.size(); ++t) {
        if (scene.tets.regions[t] != regionId)
            continue;
        const Tet& tet = scene.tets.tets[t];
        for (int k = 0; k < 4; ++k)
            centre = centre + scene.tets.points[static_cast<std::size_t>(tet[static_cast<std::size_t>(k)])] * 0.25;
        ++count;
    }
    if (count == 0)
        return fail(ErrorCode::InvalidInput, "scope view: region " + std::to_string(regionId) + " has no tets");
    centre = centre / static_cast<double>(count);
    const Vec3 middle = (landmarks.internalOsMm + landmarks.fundusMm) * 0.5;
    Vec3 towards = middle - centre;
    if (norm(towards) < 1e-6)
        towards = landmarks.internalOsMm - centre;
    ScopeView view;
    view.eyeMm = centre + normalized(towards) * distanceMm;
    view.direction = normalized(centre - view.eyeMm);
    view.shaft = normalized(landmarks.internalOsMm - landmarks.externalOsMm);
    view.up = perpendicularTo(view.direction, {0.0, 1.0, 0.0});
    return view;
}

} // namespace hs::scene
