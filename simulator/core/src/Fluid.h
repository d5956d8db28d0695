#pragma once
// The distension fluid, two-way coupled to the tissue (docs/simulator.md, "Distension"). The fluid in the cavity is a
// volume: the pump's inflow through the inflow valve adds to it, the outflow through the outflow valve to the
// atmosphere and intravasation (rising steeply once the intrauterine pressure passes the mean arterial pressure;
// Vulgaropulos et al., Am J Obstet Gynecol 1992;167:386-91) take from it. The pressure is what makes the cavity in the
// deformed tissue hold that volume: each step it is solved, implicitly in the flows, from the cavity's volume as the
// tissue left it and the tissue's own compliance over one step (dV/dp of the solver's matrix), and then loads the
// cavity's faces. No gain is fitted: the cavity opens as far as the tissue model lets it. Pressures kPa, volumes mL,
// times s.

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
/// kPa, the pressure in the venules a cut opens: about 10 mmHg at the venous end of the capillaries (Guyton & Hall,
/// Textbook of Medical Physiology; docs/references.md [GuytonHall]). Above it the fluid flows into them.
inline constexpr double kVenulePressureKpa = 10.0 * units::kKpaPerMmHg;

/// The vessels a cut surface has opened and nothing has sealed, as two conductances, mL/(s kPa): the arterioles,
/// which bleed into the cavity while its pressure is below the mean arterial pressure (tamponade above it), and the
/// venules, into which the fluid flows while the cavity's pressure is above kVenulePressureKpa (docs/simulator.md,
/// "Bleeding").
struct OpenVessels {
    double arterialMlPerSKpa = 0.0;
    double venousMlPerSKpa = 0.0;
    /// mm, where the arterioles bleed: the open faces' centroids weighted by their arterial conductance.
    Vec3 bleedingMm;
};

class FluidModel {
public:
    void reset(const FluidSettings& settings);
    /// The pump's set pressure from now on, kPa, held in 2.7-20 (the pump's buttons).
    void setPumpPressure(double kpa);
    /// The pressure for the coming step of `dt` s (kPa) with the valves' openings (0..1): the cavity holds
    /// `cavityMl` beyond its rest volume as the tissue lies now, under the pressure of the last step, and gives
    /// `complianceMlPerKpa` more per kPa over one step. Updates the fluid's volume and totals with the flows at that
    /// pressure, the open vessels' included; `contactForceN` (the scope on the wall) stirs debris.
    double step(double dt, double inflowValve, double outflowValve, double cavityMl, double complianceMlPerKpa,
                double contactForceN, const OpenVessels& vessels = {});
    const FluidState& state() const { return m_state; }

private:
    FluidSettings m_settings;
    FluidState m_state;
    double m_fluidMl = 0.0; ///< the fluid in the cavity beyond the cavity's rest volume
};

/// mm, how far behind the tip the outer sheath's outflow holes draw the fluid in (a continuous-flow sheath's holes lie
/// round its last centimetre; this project's choice of their centre).
inline constexpr double kOutflowBehindTipMm = 8.0;

/// The distension fluid's velocity at `pointMm`, mm/s: the inflow leaving the scope's tip as a point source and the
/// outflow drawn into the sheath's holes, kOutflowBehindTipMm behind the tip along `shaft` (unit, handle to tip), as
/// a point sink; the irrotational flow of a source and a sink in unbounded fluid ([Batchelor1967]): each gives
/// Q / (4 pi r^2) along the line from it. Flows in mL/s (1 mL = 1000 mm^3). Closer than `coreMm` to either (inside
/// the sheath, where the cavity's fluid is not) the speed is that at `coreMm`, so the field stays bounded. Walls are
/// not in it: a chip stops where the wall stops it (World::Impl::moveChips).
Vec3 flowVelocityMmPerS(const Vec3& pointMm, const Vec3& tipMm, const Vec3& shaft, double inflowMlPerS,
                        double outflowMlPerS, double coreMm);

/// Blood clouds (docs/simulator.md, "Blood clouds"). Blood leaves a cut arteriole as a thin jet and spreads through
/// the fluid the pump keeps stirring; a cloud starts as wide as kBloodCloudStartMm at the bleeding point, spreads as
/// sigma^2 += 2 D dt with an eddy diffusivity D, and counts as mixed through the cavity once kBloodCloudMixedMm
/// wide (about the distended cavity's half-width). D is this project's choice: no measurement of the mixing in a
/// distended cavity was found (Zatonyi et al. 2005 solve the flow instead); with it a cloud takes about 4 s to mix.
inline constexpr double kBloodCloudStartMm = 0.5;
inline constexpr double kBloodEddyDiffusivityMm2PerS = 4.0;
inline constexpr double kBloodCloudMixedMm = 6.0;
/// s of bleeding each cloud gathers before the next one starts.
inline constexpr double kBloodCloudIntervalS = 0.5;

/// The distension fluid's flow as a step leaves it (flowVelocityMmPerS's arguments).
struct FlowField {
    Vec3 tipMm;
    Vec3 shaft;
    double inflowMlPerS = 0.0;
    double outflowMlPerS = 0.0;
    double coreMm = 1.0;
};

/// One step of `dt` s of the blood clouds. The `bledMl` the vessels gave over the step joins the newest cloud while it
/// is younger than kBloodCloudIntervalS, else a new one at `bleedingMm`; every cloud drifts with the flow at its
/// centre and spreads; the outflow washes out the same share of every cloud's blood as of the cavity's (`keep`, the
/// share of the cavity's blood that stays over the step); a cloud as wide as kBloodCloudMixedMm (or the oldest, to
/// make room) joins the mixed blood. `bloodInCavityMl` and `bloodFraction` are the fluid's after the step (its
/// clouds' and its mixed blood together): the mixed share is what the clouds do not hold.
void advanceBloodClouds(BloodClouds& blood, double dt, double bledMl, const Vec3& bleedingMm, const FlowField& flow,
                        double keep, double bloodInCavityMl, double bloodFraction);

} // namespace hs::sim::detail
