// The heads-up text: the pump's figures, the exercise's progress and the contact force.
#include "hs/simrender/Hud.h"

#include "hs/core/Units.h"

#include <cstdio>

namespace hs::simrender {

namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
    char text[160];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

/// Blood's share of the fluid from which the HUD names the bleeding: about where the view turns visibly red
/// (EndoscopicView's blood absorption over a 10-20 mm cavity).
constexpr double kBloodInViewFraction = 0.002;

} // namespace

ExerciseProgress progressOf(sim::Exercise exercise, const sim::TrialMetrics& metrics) {
    ExerciseProgress p;
    p.exercise = exercise;
    p.targets = static_cast<int>(metrics.targets.size());
    for (const sim::ExplorationTarget& t : metrics.targets)
        p.targetsSeen += t.seen ? 1 : 0;
    p.pathologies = static_cast<int>(metrics.pathologies.size());
    for (const sim::PathologyFinding& f : metrics.pathologies)
        p.pathologiesFound += f.found ? 1 : 0;
    p.visualizedPercent = metrics.cavitySurfaceVisualizedPercent;
    // The exercise's pathologies: the polyps of a polypectomy, the myomas of a myomectomy.
    const std::string kind = exercise == sim::Exercise::Polypectomy ? "polyp" : "myoma";
    double volume = 0.0, removed = 0.0;
    for (const sim::PathologyResection& r : metrics.resection.pathologies) {
        if (r.kind != kind)
            continue;
        volume += r.volumeMl;
        removed += r.removedMl;
    }
    p.removedPercent = volume > 0.0 ? 100.0 * removed / volume : 0.0;
    return p;
}

HudText hudText(const sim::WorldState& state, const sim::FluidSettings& fluid, const ExerciseProgress& progress) {
    const sim::FluidState& f = state.fluid;
    HudText hud;
    const auto minutes = static_cast<int>(state.timeS / 60.0);
    const double secondsPart = state.timeS - 60.0 * minutes;
    hud.status = format("P   %3.0f mmHg  %5.2f kPa  (set %3.0f)", f.pressureKpa / units::kKpaPerMmHg, f.pressureKpa,
                        f.pumpSetKpa / units::kKpaPerMmHg) +
                 "\n" + format("in  %4.0f mL/min   out %4.0f mL/min", f.inflowMlPerS * 60.0, f.outflowMlPerS * 60.0) +
                 "\n" + format("deficit %5.0f mL of %.0f ", f.deficitMl, fluid.deficitLimitMl) +
                 std::string(sim::toString(fluid.medium)) + "\n" + format("time %02.0f:%04.1f", minutes, secondsPart) +
                 "\n";
    const bool operative = sim::isOperative(progress.exercise);
    if (progress.exercise == sim::Exercise::Exploration)
        hud.status += format("explored %.0f/%.0f targets, %.0f%% of the cavity", progress.targetsSeen, progress.targets,
                             progress.visualizedPercent);
    else if (operative)
        hud.status += format("removed %.0f%%   bleeding %.1f mL/min   blood %.1f mL", progress.removedPercent,
                             f.bleedingMlPerS * 60.0, f.bloodLossMl);
    else
        hud.status += format("found %.0f/%.0f pathologies", progress.pathologiesFound, progress.pathologies);
    hud.status += "\n" + format("force %4.2f N", state.contact.forceN);
    if (operative) {
        // The instrument in hand, and what it does.
        const sim::LoopState& tool = state.loop;
        hud.status += "   " + std::string(sim::instrumentName(tool.out ? tool.instrument : sim::kInstrumentNone));
        if (tool.cutting)
            hud.status += tool.instrument == sim::kInstrumentLoop ? " cutting" : " closing";
        else if (tool.coagulating)
            hud.status += " coagulating";
        else if (tool.holding)
            hud.status += " holding a chip";
    }
    if (state.contact.perforated)
        hud.warning = "PERFORATION";
    else if (f.deficitLimit)
        hud.warning = format("FLUID DEFICIT LIMIT (%.0f mL): STOP", fluid.deficitLimitMl);
    else if (f.deficitWarning)
        hud.warning = format("fluid deficit above %.0f mL", fluid.deficitWarningMl);
    else if (operative && f.bloodFraction > kBloodInViewFraction)
        hud.warning = "bleeding: raise the pressure or coagulate";
    else if (f.pressureKpa > fluid.meanArterialPressureKpa)
        hud.warning = "pressure above mean arterial pressure";
    return hud;
}

} // namespace hs::simrender
