// The tissue: the solver on the simulation mesh with its materials and supports, the cavity's volume, the fluid's
// load on it and how the cavity gives under it (docs/simulator.md, "Tissue", "Boundary", "Distension").
#include "WorldImpl.h"

#include "hs/scene/Scene.h"

#include <algorithm>
#include <cmath>

namespace hs::sim {

using namespace detail;

namespace {

/// The tissue's exponential stiffening (mechanics::FemMaterial::stiffeningStrain): myometrium's C = 0.05-0.14
/// (Pearsall & Roberts 1978), its geometric middle 0.085, for |dev e| times sqrt(3/2). No such data for the
/// endometrium, the myoma or the polyp: they get the myometrium's.
constexpr double kStiffeningStrain = 0.085 * 1.2247;

/// A contact carries at most this force, N: four times what perforates the wall (the wall has given way before).
constexpr double kMaxContactForceN = 4.0 * kPerforationForceN;

/// The solver's settings for a world: its step, its iterations, no end residual (the world reads the contacts'
/// forces, not the supports').
mechanics::FemSettings solverSettings(const WorldOptions& options) {
    mechanics::FemSettings s;
    s.stepS = options.stepS;
    s.iterations = options.solverIterations;
    s.endResidual = false;
    s.maxConstraintForce = kMaxContactForceN;
    // No line search at the simulation's step: with the stiffening capped below twice the rest stiffness a chord step
    // cannot overshoot (docs/simulator.md, "Tissue"), and a force evaluation is a third of the step's time.
    s.lineSearch = false;
    // The stiffening stays below twice the rest stiffness (FemSettings::maxStiffening): the chord iteration on the
    // rest matrix converges there (uncapped, with the matrix refactored every second, the 60 s exploration diverged).
    return s;
}

/// A static solve's settle: steps this long (the inertia and the damping vanish against the stiffness), until the
/// cavity's volume changes by less than kStaticToleranceMl in a step, at most kStaticSteps.
constexpr double kStaticStepS = 1.0;
constexpr int kStaticSteps = 60;
/// The pressure is raised over this many steps (the stiffening tissue is followed, not jumped to).
constexpr int kStaticRampSteps = 20;
constexpr int kStaticIterations = 4;
constexpr double kStaticToleranceMl = 1e-4;

} // namespace

Status World::Impl::setupTissue() {
    const std::size_t n = simRest.points.size();
    std::vector<mechanics::FemMaterial> materials(simRest.tetCount());
    const auto& ids = simRest.tetLabels.at(scene::kMaterialLabel);
    for (std::size_t t = 0; t < simRest.tetCount(); ++t) {
        const auto& m = scene.materials[static_cast<std::size_t>(ids[t])].material;
        materials[t] = {m.youngsModulusKpa * 1e3, m.poissonRatio, m.densityKgPerM3, kStiffeningStrain};
    }
    // The held cervix: its vaginal part (the portio, gripped by the vagina and the tenaculum) is fixed; the rest of it
    // up to the internal os hangs in the cardinal and uterosacral ligaments, stiff springs that let the corpus tilt
    // when the scope pushes it (docs/simulator.md, "Boundary").
    std::vector<std::array<bool, 3>> fixed(n, {false, false, false});
    std::vector<bool> ligament(n, false);
    const auto& support = simRest.tetLabels.at(scene::kSupportTetLabel);
    for (std::size_t t = 0; t < simRest.tetCount(); ++t)
        if (support[t] == 1)
            for (const std::int32_t p : simRest.tets[t]) {
                const auto pi = static_cast<std::size_t>(p);
                if (dot(simRest.points[pi] - frame.pivotMm, frame.axis) < kHeldPortioMm)
                    fixed[pi] = {true, true, true};
                else
                    ligament[pi] = true;
            }
    // Tethers on the serosa's free points, by area.
    std::vector<double> pointArea(n, 0.0);
    double total = 0.0;
    for (std::size_t f = 0; f < triangles->size(); ++f) {
        if (faceCavity[f])
            continue;
        for (const std::int32_t v : (*triangles)[f])
            if (!fixed[static_cast<std::size_t>(v)][0]) {
                pointArea[static_cast<std::size_t>(v)] += faceArea[f] / 3.0;
                total += faceArea[f] / 3.0;
            }
    }
    std::vector<std::pair<std::int32_t, double>> tethers;
    std::size_t ligamentPoints = 0;
    for (std::size_t i = 0; i < n; ++i)
        ligamentPoints += ligament[i] && !fixed[i][0] ? 1 : 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (fixed[i][0])
            continue;
        double k = pointArea[i] > 0.0 ? kSurroundStiffnessNPerM * pointArea[i] / total : 0.0;
        if (ligament[i])
            k += kLigamentStiffnessNPerM / static_cast<double>(ligamentPoints);
        if (k > 0.0)
            tethers.emplace_back(static_cast<std::int32_t>(i), k);
    }
    std::vector<Vec3> pointsM(n);
    for (std::size_t i = 0; i < n; ++i)
        pointsM[i] = simRest.points[i] * kMm;
    HS_TRY(tissue.build(pointsM, simRest.tets, materials, fixed, tethers, solverSettings(options)));
    faceHeld.assign(triangles->size(), 0);
    for (std::size_t f = 0; f < triangles->size(); ++f) {
        const Triangle& t = (*triangles)[f];
        faceHeld[f] = fixed[static_cast<std::size_t>(t[0])][0] || fixed[static_cast<std::size_t>(t[1])][0] ||
                              fixed[static_cast<std::size_t>(t[2])][0]
                          ? 1
                          : 0;
    }
    // The surface the scope touches (the cavity and the canal): its compliance precomputed, so a step's contacts cost
    // no solve.
    std::vector<std::int32_t> touchable;
    std::vector<char> seen(n, 0);
    for (std::size_t f = 0; f < triangles->size(); ++f)
        if (faceCavity[f])
            for (const std::int32_t v : (*triangles)[f])
                if (!seen[static_cast<std::size_t>(v)]) {
                    seen[static_cast<std::size_t>(v)] = 1;
                    touchable.push_back(v);
                }
    std::sort(touchable.begin(), touchable.end());
    tissue.precomputeCompliance(touchable);
    return {};
}

double World::Impl::cavityVolumeMl(const std::vector<Vec3>& pts) const {
    // Volume between the cavity's faces and the external os (the canal's open end): the faces face into the cavity.
    const Vec3 o = landmarks.externalOsMm;
    double v = 0.0;
    for (std::size_t f = 0; f < triangles->size(); ++f) {
        if (!faceCavity[f])
            continue;
        const Triangle& t = (*triangles)[f];
        const Vec3 a = pts[static_cast<std::size_t>(t[0])] - o, b = pts[static_cast<std::size_t>(t[1])] - o,
                   c = pts[static_cast<std::size_t>(t[2])] - o;
        v -= dot(a, cross(b, c)) / 6.0;
    }
    return v / 1000.0;
}

void World::Impl::pressureForces(const std::vector<Vec3>& pts, double pressureKpa, std::vector<Vec3>& forces) const {
    forces.assign(pts.size(), Vec3{0.0, 0.0, 0.0});
    if (!(pressureKpa > 0.0))
        return;
    const double pa = pressureKpa * 1e3;
    for (std::size_t f = 0; f < triangles->size(); ++f) {
        if (!faceCavity[f])
            continue;
        const Triangle& t = (*triangles)[f];
        // Area vector in m^2 (half the cross product), pointing into the cavity; the fluid pushes the wall back. Per
        // pascal this is also the gradient of the cavity's volume (m^3 per m) at the face's points.
        const Vec3 areaVector = triangleNormal(pts, t) * (0.5 * kMm * kMm);
        const Vec3 force = areaVector * (-pa / 3.0);
        for (const std::int32_t v : t)
            forces[static_cast<std::size_t>(v)] += force;
    }
}

Status World::Impl::staticOpen(double pressureKpa, std::vector<Vec3>& pts) const {
    // The same model solved statically (long steps), the pressure raised over kStaticRampSteps and following the
    // faces as they open, until the cavity's volume settles.
    mechanics::CorotationalFem still;
    mechanics::FemSettings settings = tissue.settings();
    settings.stepS = kStaticStepS;
    settings.iterations = kStaticIterations;
    settings.lineSearch = true; // long steps stiffen the tissue beyond what one chord step follows
    HS_TRY(still.buildLike(tissue, settings));
    std::vector<Vec3> forces;
    pts = simRest.points;
    std::vector<mechanics::FemConstraint> none;
    double last = cavityVolumeMl(pts);
    for (int s = 0; s < kStaticSteps; ++s) {
        pressureForces(pts, pressureKpa * std::min(1.0, static_cast<double>(s + 1) / kStaticRampSteps), forces);
        still.step(forces, none);
        for (std::size_t i = 0; i < pts.size(); ++i)
            pts[i] = still.positionsM()[i] / kMm;
        const double volume = cavityVolumeMl(pts);
        if (s >= kStaticRampSteps && std::abs(volume - last) < kStaticToleranceMl)
            break;
        last = volume;
    }
    if (still.recoveries() > 0)
        return fail(ErrorCode::InvalidInput,
                    "the tissue found no equilibrium at " + std::to_string(pressureKpa) + " kPa in the cavity");
    return {};
}

Status World::Impl::measureCavity() {
    restCavityMl = cavityVolumeMl(simRest.points);
    // The cavity's give over one step: g^T H^-1 g for the pressure pattern g (m^2 per point), m^3/Pa -> mL/kPa.
    std::vector<Vec3> pattern;
    pressureForces(simRest.points, 1e-3, pattern); // 1 Pa
    cavityComplianceMlPerKpa = tissue.loadCompliance(pattern) * 1e9;
    // The cavity opened at the planning pressure.
    return staticOpen(kPlanningPressureKpa, openPointsMm);
}

Result<double> World::staticCavityOpeningMl(double pressureKpa) const {
    if (!std::isfinite(pressureKpa) || pressureKpa < 0.0 || pressureKpa > 40.0)
        return fail(ErrorCode::InvalidInput,
                    "static cavity: pressure " + std::to_string(pressureKpa) + " kPa is outside 0-40 kPa");
    std::vector<Vec3> pts;
    HS_TRY(impl_->staticOpen(pressureKpa, pts));
    return impl_->cavityVolumeMl(pts) - impl_->restCavityMl;
}

} // namespace hs::sim
