#include "hs/scene/ScopeView.h"

#include "hs/scene/Scene.h"

#include "hs/core/TetEmbedding.h"
#include "hs/core/TriangleGeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

Vec3 cavityViewpoint(const Scene& scene, const ScopePassage& passage) {
    const Vec3 middle = (passage.landmarks.internalOsMm + passage.landmarks.fundusMm) * 0.5;
    // The middle itself when it lies in the cavity (in no tet) with room for the scope (half its diameter from every
    // face of the visual surface).
    const auto embedded = embedPoints(scene.tets, {middle});
    bool inTissue = false;
    if (!embedded.empty() && embedded[0].tet >= 0) { // a tet holds it when no weight is negative
        const auto& w = embedded[0].weights;
        inTissue = *std::min_element(w.begin(), w.end()) >= -1e-9;
    }
    if (!inTissue) {
        const SurfaceMesh& surface = scene.surface.mesh;
        double nearest = std::numeric_limits<double>::infinity();
        for (const Triangle& t : surface.triangles) {
            const ClosestPoint c = closestPointOnTriangle(middle, surface.points[static_cast<std::size_t>(t[0])],
                                                          surface.points[static_cast<std::size_t>(t[1])],
                                                          surface.points[static_cast<std::size_t>(t[2])]);
            nearest = std::min(nearest, distance(c.point, middle));
        }
        if (nearest >= 0.5 * passage.scopeDiameterMm)
            return middle;
    }
    Vec3 best = middle;
    double closest = std::numeric_limits<double>::infinity();
    for (const PassagePoint& p : passage.route)
        if (p.part == PassagePart::Cavity && p.freeWidthMm >= passage.scopeDiameterMm &&
            distance(p.positionMm, middle) < closest) {
            closest = distance(p.positionMm, middle);
            best = p.positionMm;
        }
    return best;
}

Result<std::vector<OstiumSight>> ostiaInSight(const Scene& scene, const Vec3& eyeMm) {
    const SurfaceMesh& surface = scene.surface.mesh;
    std::vector<std::int32_t> faces;
    // Each face's pathology (the index of its "contact" label's pathology id in `pathologies`), -1 for the wall.
    std::vector<std::string> pathologies;
    std::vector<int> pathologyOf(surface.faceCount(), -1);
    for (const auto& label : scene.labels) {
        if (label.element != LabelElement::SurfaceFace)
            continue;
        if (label.kind == LabelKind::Ostium)
            faces.insert(faces.end(), label.indices.begin(), label.indices.end());
        if (label.kind == LabelKind::Contact && !label.pathologyId.empty()) {
            pathologies.push_back(label.pathologyId);
            for (std::int32_t f : label.indices)
                if (f >= 0 && static_cast<std::size_t>(f) < surface.faceCount())
                    pathologyOf[static_cast<std::size_t>(f)] = static_cast<int>(pathologies.size() - 1);
        }
    }
    if (faces.empty())
        return fail(ErrorCode::InvalidInput,
                    "ostia: the scene has no ostium label on its visual surface (labels.json)");
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    for (std::int32_t index : faces)
        if (index < 0 || static_cast<std::size_t>(index) >= surface.faceCount())
            return fail(ErrorCode::InvalidInput, "ostia: face " + std::to_string(index) + " is outside 0.." +
                                                     std::to_string(surface.faceCount()));
    std::vector<char> isOstium(surface.faceCount(), 0);
    for (std::int32_t index : faces)
        isOstium[static_cast<std::size_t>(index)] = 1;
    const auto corner = [&](std::size_t f, int k) -> const Vec3& {
        return surface.points[static_cast<std::size_t>(surface.triangles[f][static_cast<std::size_t>(k)])];
    };
    constexpr double kBeforeMm = 0.2; ///< a face this close before the target is the face the target lies on
    std::vector<OstiumSight> sides(2);
    sides[0].side = "left";
    sides[1].side = "right";
    std::vector<double> area(2, 0.0), seen(2, 0.0);
    std::vector<std::vector<double>> hiddenArea(2, std::vector<double>(pathologies.size() + 1, 0.0));
    for (std::int32_t index : faces) {
        const auto f = static_cast<std::size_t>(index);
        const Vec3 &a = corner(f, 0), &b = corner(f, 1), &c = corner(f, 2);
        const Vec3 centre = (a + b + c) / 3.0;
        const double w = 0.5 * norm(cross(b - a, c - a));
        const std::size_t k = centre.x < eyeMm.x ? 0 : 1;
        OstiumSight& o = sides[k];
        o.centreMm += centre * w;
        area[k] += w;
        ++o.faces;
        const Vec3 toward = centre - eyeMm;
        const double length = norm(toward);
        // The first face the sight line crosses before the target, if any.
        double first = length - kBeforeMm;
        std::size_t blocker = surface.faceCount();
        if (length > kBeforeMm) {
            const Vec3 dir = toward / length;
            for (std::size_t g = 0; g < surface.faceCount(); ++g) {
                double t = 0.0, u = 0.0, v = 0.0;
                if (!isOstium[g] && rayTriangle(eyeMm, dir, corner(g, 0), corner(g, 1), corner(g, 2), 0.0, t, u, v) &&
                    t < first) {
                    first = t;
                    blocker = g;
                }
            }
        }
        if (blocker == surface.faceCount())
            seen[k] += w;
        else
            hiddenArea[k][static_cast<std::size_t>(pathologyOf[blocker] + 1)] += w;
    }
    std::vector<OstiumSight> out;
    for (std::size_t k = 0; k < 2; ++k) {
        if (sides[k].faces == 0)
            continue;
        sides[k].centreMm = area[k] > 0.0 ? sides[k].centreMm / area[k] : sides[k].centreMm;
        sides[k].visibleFraction = area[k] > 0.0 ? seen[k] / area[k] : 0.0;
        // What hides the rest, most first (ties in label order).
        std::vector<std::size_t> order;
        for (std::size_t i = 0; i < hiddenArea[k].size(); ++i)
            if (hiddenArea[k][i] > 0.0)
                order.push_back(i);
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t x, std::size_t y) { return hiddenArea[k][x] > hiddenArea[k][y]; });
        for (std::size_t i : order)
            sides[k].hiddenBy.push_back(i == 0 ? std::string("wall") : pathologies[i - 1]);
        out.push_back(sides[k]);
    }
    return out;
}

} // namespace hs::scene
