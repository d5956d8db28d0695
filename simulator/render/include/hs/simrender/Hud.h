#pragma once
/// The heads-up text of the simulator's view: what the pump's display and the exercise's progress would tell the
/// trainee (docs/simulator.md, "Endoscopic view").

#include "hs/sim/Metrics.h"
#include "hs/sim/World.h"
#include "hs/simrender/EndoscopicView.h"

namespace hs::simrender {

/// What the exercise has achieved so far (copied from the world's metrics by the physics thread).
struct ExerciseProgress {
    sim::Exercise exercise = sim::Exercise::Exploration;
    int targetsSeen = 0;
    int targets = 0;
    int pathologiesFound = 0;
    int pathologies = 0;
    double visualizedPercent = 0.0;
    double removedPercent = 0.0; ///< the operative exercises: of the pathologies' volume, cut away
};
ExerciseProgress progressOf(sim::Exercise exercise, const sim::TrialMetrics& metrics);

/// Pressure in mmHg and kPa with the pump's set pressure, inflow and outflow (mL/min), deficit against its limit and
/// the medium, time, exercise progress (the operative exercises: the share removed, bleeding and blood loss) and
/// contact force; the warning line names a perforation, a reached deficit warning or limit, bleeding, or a pressure
/// above the mean arterial pressure.
HudText hudText(const sim::WorldState& state, const sim::FluidSettings& fluid, const ExerciseProgress& progress);

} // namespace hs::simrender
