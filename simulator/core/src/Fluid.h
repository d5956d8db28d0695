#pragma once
// The distension fluid as a lumped model (docs/simulator.md, "Distension"): the cavity a compliance taken from the
// scene's hydrometra curve, an inflow from the pump through the inflow valve, an outflow through the outflow valve to
// the atmosphere, and intravasation that rises steeply once the intrauterine pressure passes the mean arterial
// pressure (Vulgaropulos et al., Am J Obstet Gynecol 1992;167:386-91). Pressures kPa, volumes mL, times s.

#include "hs/sim/Trial.h"
#include "hs/sim/World.h"

namespace hs::sim::detail {

/// Valve conductances, mL/(s kPa): fully open, the inflow gives about 5 mL/s (300 mL/min, a hysteroscopy pump's
/// range) into an empty cavity at the default 10.7 kPa (80 mmHg) set pressure.
inline constexpr double kInflowConductance = 0.45;
inline constexpr double kOutflowConductance = 0.35;
/// Intravasation, mL/(s kPa): a small leak below the mean arterial pressure and a steep one above it.
inline constexpr double kIntravasationBelowMap = 0.002;
inline constexpr double kIntravasationAboveMap = 0.08;
/// Below this pressure the walls close on the lens (the lowest cited distension pressures are 25-50 mmHg).
inline constexpr double kWallsClosePressureKpa = 3.3;

class FluidModel {
public:
    /// `complianceMlPerKpa`: the cavity's volume change per kPa (the hydrometra curve's slope).
    void reset(const FluidSettings& settings, double complianceMlPerKpa);
    /// One step of `dt` s with the valves' openings (0..1) and the scope's contact force (N, stirs debris).
    void step(double dt, double inflowValve, double outflowValve, double contactForceN);
    const FluidState& state() const { return state_; }
    double complianceMlPerKpa() const { return compliance_; }

private:
    FluidSettings settings_;
    double compliance_ = 0.1;
    FluidState state_;
};

} // namespace hs::sim::detail
