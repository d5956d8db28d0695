// The tissue: the scene's uterus model (hs::mechanics::UterusModel, shared with generate's hydrometra curve) with the
// simulation's solver settings, the surface the scope touches, the cavity's one-step compliance and the cavity opened
// for the script (docs/simulator.md, "Tissue", "Boundary", "Distension").
#include "WorldImpl.h"

#include "hs/scene/Scene.h"
#include "hs/sim/TissueSetup.h"

#include <algorithm>
#include <cmath>

namespace hs::sim {

using namespace detail;

namespace {

/// A contact carries at most this force, N: four times what perforates the wall (the wall has given way before).
constexpr double kMaxContactForceN = 4.0 * kPerforationForceN;

/// No tet of the simulation mesh keeps less than this share of its volume (FemSettings::minVolumeRatio): the tissues'
/// Poisson ratios of 0.45-0.49 allow a volume change of a few per cent under the pressures met here, and the
/// scripted exploration's tets keep more than 60 % of their volume (docs/simulator.md, "The volume bound"); a fifth is
/// far outside the material and inside what a step's linearization holds.
constexpr double kMinTetVolumeRatio = 0.2;
/// A tet gets its volume row when its ratio is within this of the bound after a step's free motion. Each row on an
/// interior point costs its points' columns of L^-1 (once per factor); 0.1 ran the 60 s rough trial at 176 Hz mean
/// instead of 141 (when each such row cost a solve) but let 3 tets invert
/// (ratio -0.497) over its 10 minutes, where 0.25 kept every tet above 0.19 (docs/simulator.md, "The volume bound").
constexpr double kVolumeGuardBand = 0.25;

} // namespace

/// No end residual: the world reads the contacts' forces, not the supports'.
mechanics::FemSettings tissueSolverSettings(const WorldOptions& options) {
    mechanics::FemSettings s;
    s.stepS = options.stepS;
    s.iterations = options.solverIterations;
    s.endResidual = false;
    s.maxConstraintForce = kMaxContactForceN;
    // No line search at the simulation's step: with the stiffening capped below twice the rest stiffness a chord step
    // cannot overshoot (docs/simulator.md, "Tissue"), and a force evaluation is a third of the step's time. (Capped
    // stiffening, FemSettings::maxStiffening: uncapped, with the matrix refactored every second, the 60 s exploration
    // diverged.)
    s.lineSearch = false;
    s.minVolumeRatio = kMinTetVolumeRatio;
    s.volumeGuardBand = kVolumeGuardBand;
    return s;
}

std::vector<std::int32_t> touchablePoints(const mechanics::UterusModel& model) {
    std::vector<std::int32_t> touchable;
    std::vector<char> seen(model.restMm.size(), 0);
    for (std::size_t f = 0; f < model.boundary.size(); ++f)
        if (model.faceCavity[f])
            for (const std::int32_t v : model.boundary[f])
                if (!seen[static_cast<std::size_t>(v)]) {
                    seen[static_cast<std::size_t>(v)] = 1;
                    touchable.push_back(v);
                }
    std::sort(touchable.begin(), touchable.end());
    return touchable;
}

Status World::Impl::setupTissue() {
    HS_TRY(mechanics::buildUterusModel(scene, tissueSolverSettings(options), uterus, !(options.introitusMm > 0.0),
                                       !options.linearTissue));
    // The held portio is where the device pivots: a face with a held point gives no contact.
    faceHeld.assign(uterus.boundary.size(), 0);
    for (std::size_t f = 0; f < uterus.boundary.size(); ++f)
        for (const std::int32_t v : uterus.boundary[f])
            if (uterus.pointHeld[static_cast<std::size_t>(v)])
                faceHeld[f] = 1;
    // The surface the scope touches (the cavity and the canal): its compliance precomputed, so a step's contacts cost
    // no solve.
    tissue.precomputeCompliance(touchablePoints(uterus));
    return {};
}

Status World::Impl::measureCavity() {
    // The cavity's give over one step: g^T H^-1 g for the pressure pattern g (m^2 per point), m^3/Pa -> mL/kPa.
    std::vector<Vec3> pattern;
    uterus.pressureForces(simRest.points, 1e-3, pattern); // 1 Pa
    cavityComplianceMlPerKpa = tissue.loadCompliance(pattern) * 1e9;
    // The cavity opened at the planning pressure by a static solve of the same model.
    return mechanics::staticOpen(uterus, kPlanningPressureKpa, openPointsMm);
}

Result<double> World::staticCavityOpeningMl(double pressureKpa) const {
    std::vector<Vec3> pts;
    HS_TRY(mechanics::staticOpen(impl_->uterus, pressureKpa, pts));
    return impl_->uterus.cavityVolumeMl(pts) - impl_->uterus.restCavityMl;
}

} // namespace hs::sim
