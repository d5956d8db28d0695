#include "Fluid.h"

#include <algorithm>
#include <cmath>

namespace hs::sim::detail {

void FluidModel::reset(const FluidSettings& settings, double complianceMlPerKpa) {
    settings_ = settings;
    compliance_ = std::max(complianceMlPerKpa, 1e-3);
    state_ = FluidState{};
    state_.redOut = 1.0;
}

void FluidModel::step(double dt, double inflowValve, double outflowValve, double contactForceN) {
    const double p0 = state_.pressureKpa;
    const double pump = settings_.pumpPressureKpa;
    const double map = settings_.meanArterialPressureKpa;
    const double gin = kInflowConductance * std::clamp(inflowValve, 0.0, 1.0);
    const double gout = kOutflowConductance * std::clamp(outflowValve, 0.0, 1.0);
    // Backward Euler of C dp/dt = gin (pump - p) - gout p - q_iv(p), solved on each branch of q_iv.
    const double c = compliance_ / dt;
    double p = (c * p0 + gin * pump) / (c + gin + gout + kIntravasationBelowMap);
    if (p > map)
        p = (c * p0 + gin * pump + kIntravasationAboveMap * map) /
            (c + gin + gout + kIntravasationBelowMap + kIntravasationAboveMap);
    p = std::max(p, 0.0);
    FluidState& s = state_;
    s.pressureKpa = p;
    s.inflowMlPerS = gin * std::max(pump - p, 0.0);
    s.outflowMlPerS = gout * p;
    s.intravasationMlPerS = kIntravasationBelowMap * p + kIntravasationAboveMap * std::max(p - map, 0.0);
    s.inflowTotalMl += s.inflowMlPerS * dt;
    s.outflowTotalMl += s.outflowMlPerS * dt;
    s.deficitMl = s.inflowTotalMl - s.outflowTotalMl;
    s.distensionMl = compliance_ * p;
    s.deficitWarning = s.deficitMl >= settings_.deficitWarningMl;
    s.deficitLimit = s.deficitMl >= settings_.deficitLimitMl;
    // Turbidity: contact stirs debris and blood into the fluid; the flow through the cavity washes it out.
    const double volume = std::max(s.distensionMl, 0.5);
    const double washout = (s.outflowMlPerS + s.intravasationMlPerS) / volume;
    s.turbidity = std::clamp(s.turbidity + dt * (0.05 * contactForceN - washout * s.turbidity), 0.0, 1.0);
    s.redOut = std::clamp((kWallsClosePressureKpa - p) / kWallsClosePressureKpa, 0.0, 1.0);
}

} // namespace hs::sim::detail
