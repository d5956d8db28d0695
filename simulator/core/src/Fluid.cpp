#include "Fluid.h"

#include <algorithm>
#include <cmath>

namespace hs::sim::detail {

void FluidModel::reset(const FluidSettings& settings) {
    m_settings = settings;
    m_state = FluidState{};
    m_state.redOut = 1.0;
    m_fluidMl = 0.0;
}

double FluidModel::step(double dt, double inflowValve, double outflowValve, double cavityMl, double complianceMlPerKpa,
                        double contactForceN) {
    const double p0 = m_state.pressureKpa;
    const double pump = m_settings.pumpPressureKpa;
    const double map = m_settings.meanArterialPressureKpa;
    const double gin = kInflowConductance * std::clamp(std::isfinite(inflowValve) ? inflowValve : 0.0, 0.0, 1.0);
    const double gout = kOutflowConductance * std::clamp(std::isfinite(outflowValve) ? outflowValve : 0.0, 0.0, 1.0);
    const double c = std::isfinite(complianceMlPerKpa) ? std::max(complianceMlPerKpa, 1e-6) : 1e-6;
    const double cavity = std::isfinite(cavityMl) ? cavityMl : m_fluidMl;
    // The cavity after the step holds cavity + c (p - p0); the fluid after it, V + dt (gin (pump - p) - gout p - q(p)).
    // Equal, for p (backward Euler in the flows), on each branch of the intravasation.
    const double base = m_fluidMl - cavity + c * p0 + dt * gin * pump;
    double p = base / (c + dt * (gin + gout + kIntravasationBelowMap));
    if (p > map)
        p = (base + dt * kIntravasationAboveMap * map) /
            (c + dt * (gin + gout + kIntravasationBelowMap + kIntravasationAboveMap));
    p = std::max(p, 0.0); // the fluid cannot pull the walls in: an emptied cavity is a slit at rest
    FluidState& s = m_state;
    s.pressureKpa = p;
    s.inflowMlPerS = gin * std::max(pump - p, 0.0);
    s.outflowMlPerS = gout * p;
    s.intravasationMlPerS = kIntravasationBelowMap * p + kIntravasationAboveMap * std::max(p - map, 0.0);
    m_fluidMl += dt * (s.inflowMlPerS - s.outflowMlPerS - s.intravasationMlPerS);
    if (p == 0.0)
        m_fluidMl = std::min(m_fluidMl, cavity); // no pressure: the fluid is what the open cavity holds, at most
    m_fluidMl = std::max(m_fluidMl, 0.0);
    s.inflowTotalMl += s.inflowMlPerS * dt;
    s.outflowTotalMl += s.outflowMlPerS * dt;
    s.deficitMl = s.inflowTotalMl - s.outflowTotalMl;
    s.distensionMl = m_fluidMl;
    s.deficitWarning = s.deficitMl >= m_settings.deficitWarningMl;
    s.deficitLimit = s.deficitMl >= m_settings.deficitLimitMl;
    // Turbidity: contact stirs debris and blood into the fluid; the flow through the cavity washes it out.
    const double volume = std::max(s.distensionMl, 0.5);
    const double washout = (s.outflowMlPerS + s.intravasationMlPerS) / volume;
    const double stir = std::isfinite(contactForceN) ? std::clamp(contactForceN, 0.0, 100.0) : 0.0;
    s.turbidity = std::clamp(s.turbidity + dt * (0.05 * stir - washout * s.turbidity), 0.0, 1.0);
    s.redOut = std::clamp((kWallsClosePressureKpa - p) / kWallsClosePressureKpa, 0.0, 1.0);
    return p;
}

} // namespace hs::sim::detail
