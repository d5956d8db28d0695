// The tissue on the simulation mesh with its materials and supports, the cavity's volume, the fluid's load on it and
// the load's calibration against the hydrometra curve (docs/simulator.md, "Tissue", "Boundary", "Distension").
#include "WorldImpl.h"

#include "hs/scene/Scene.h"

#include <algorithm>
#include <cmath>

namespace hs::sim {

using namespace detail;

void World::Impl::setupTissue() {
    const std::size_t n = simRest.points.size();
    std::vector<detail::TetMaterial> materials(simRest.tetCount());
    const auto& ids = simRest.tetLabels.at(scene::kMaterialLabel);
    for (std::size_t t = 0; t < simRest.tetCount(); ++t) {
        const auto& m = scene.materials[static_cast<std::size_t>(ids[t])].material;
        materials[t] = {m.youngsModulusKpa * 1e3, m.poissonRatio, m.densityKgPerM3};
    }
    // The held cervix: its vaginal part (the portio, gripped by the vagina and the tenaculum) is fixed; the rest of it
    // up to the internal os hangs in the cardinal and uterosacral ligaments, stiff springs that let the scope
    // straighten the canal a little (docs/simulator.md, "Boundary").
    std::vector<bool> fixed(n, false);
    std::vector<bool> ligament(n, false);
    const auto& support = simRest.tetLabels.at(scene::kSupportTetLabel);
    for (std::size_t t = 0; t < simRest.tetCount(); ++t)
        if (support[t] == 1)
            for (const std::int32_t p : simRest.tets[t]) {
                const auto pi = static_cast<std::size_t>(p);
                if (dot(simRest.points[pi] - frame.pivotMm, frame.axis) < kHeldPortioMm)
                    fixed[pi] = true;
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
            if (!fixed[static_cast<std::size_t>(v)]) {
                pointArea[static_cast<std::size_t>(v)] += faceArea[f] / 3.0;
                total += faceArea[f] / 3.0;
            }
    }
    std::vector<std::pair<std::int32_t, double>> tethers;
    std::size_t ligamentPoints = 0;
    for (std::size_t i = 0; i < n; ++i)
        ligamentPoints += ligament[i] && !fixed[i] ? 1 : 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (fixed[i])
            continue;
        double k = pointArea[i] > 0.0 ? kSurroundStiffnessNPerM * pointArea[i] / total : 0.0;
        if (ligament[i])
            k += kLigamentStiffnessNPerM / static_cast<double>(ligamentPoints);
        if (k > 0.0)
            tethers.emplace_back(static_cast<std::int32_t>(i), k);
    }
    tissue.build(simRest, materials, fixed, tethers);
    // The wall against the tip: a flat punch of the scope's radius on a half-space of the wall's modulus,
    // k = 2 E a / (1 - nu^2) (Johnson, Contact Mechanics, 1985, eq. 3.36 for a rigid flat punch).
    double e = 30e3, nu = 0.47;
    for (const auto& m : scene.materials)
        if (m.tissue == clinical::Tissue::Endometrium || m.tissue == clinical::Tissue::Myometrium) {
            e = m.material.youngsModulusKpa * 1e3;
            nu = m.material.poissonRatio;
        }
    contactStiffnessNPerMm = 2.0 * e * (options.scope.diameterMm * 0.5 * kMm) / (1.0 - nu * nu) * kMm;
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

void World::Impl::pressureForces(double pressureKpa, std::vector<Vec3>& forces) const {
    forces.assign(pointsMm.size(), Vec3{0.0, 0.0, 0.0});
    if (pressureKpa <= 0.0)
        return;
    const double pa = pressureKpa * 1e3 * pressureGain;
    for (std::size_t f = 0; f < triangles->size(); ++f) {
        if (!faceCavity[f])
            continue;
        const Triangle& t = (*triangles)[f];
        // Area vector in m^2 (half the cross product), pointing into the cavity; the fluid pushes the wall back.
        const Vec3 areaVector = triangleNormal(pointsMm, t) * (0.5 * kMm * kMm);
        const Vec3 force = areaVector * (-pa / 3.0);
        for (const std::int32_t v : t)
            forces[static_cast<std::size_t>(v)] = forces[static_cast<std::size_t>(v)] + force;
    }
}

void World::Impl::calibrateLoad() {
    // The wall's opening under pressure depends on the solver and the boundary, and is not linear in the load (a slit
    // cavity opens more easily once it has opened). Scale the load so that the cavity takes the hydrometra curve's
    // volume at the calibration pressure: a few fixed-point rounds of gain *= target / opened, each settling the
    // tissue under the load (docs/simulator.md, "Distension").
    restCavityMl = cavityVolumeMl(pointsMm);
    const double target = fluid.complianceMlPerKpa() * kCalibrationPressureKpa;
    pressureGain = 1.0;
    const auto steps = static_cast<int>(std::round(kCalibrationSeconds / options.stepS));
    std::vector<Vec3> forces;
    std::vector<detail::ContactPair> none;
    for (int round = 0; round < kCalibrationRounds; ++round) {
        for (int i = 0; i < steps; ++i) {
            pressureForces(kCalibrationPressureKpa, forces);
            tissue.step(options.stepS, options.solverIterations, forces, none, *triangles);
            tissue.pointsMm(pointsMm);
        }
        const double opened = cavityVolumeMl(pointsMm) - restCavityMl;
        if (!(opened > 1e-6))
            break;
        pressureGain = std::clamp(pressureGain * target / opened, 0.01, 50.0);
    }
    openPointsMm = pointsMm;
    // Back to rest for the trial.
    setupTissue();
    tissue.pointsMm(pointsMm);
}

} // namespace hs::sim
