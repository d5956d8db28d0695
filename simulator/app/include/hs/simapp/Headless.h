#pragma once
/// hysteroscene-sim --headless: no window, the world stepped as fast as it goes through a recorded trial
/// (sim::replayTrial) or a script (Script::sampleAt per tick), then the report (JSON, and the page with --html) and,
/// with --record, the trial file.

#include "hs/core/Result.h"
#include "hs/core/Timings.h"
#include "hs/sim/Metrics.h"
#include "hs/sim/Trial.h"
#include "hs/simapp/SimOptions.h"

#include <string>

namespace hs::simapp {

/// Now in UTC (hs::utcNow).
using hs::utcNow;

/// The trial a scripted run feeds: the world's header with the device text, stamped with `startedUtc`.
struct ScriptedRun {
    sim::Trial trial;
    sim::TrialReport report;
};
/// Runs `options.device`'s script on `options.scene` with `options.world`.
[[nodiscard]] Result<ScriptedRun> runScripted(const SimOptions& options, const std::string& startedUtc = utcNow());

/// Replays `options.replayPath` on `options.scene`.
[[nodiscard]] Result<sim::TrialReport> runReplay(const SimOptions& options, sim::Trial* trialOut = nullptr);

/// The whole headless command: runs, writes the report (stdout when no --report) and the trial; returns the exit
/// code, printing errors as "hysteroscene-sim: <message>" to stderr.
int runHeadless(const SimOptions& options);

/// --write-demo: writes the exercise's demonstration on `options.scene` as a script to options.writeDemoPath (to
/// edit and play as a scripted device); the exit code, errors printed as runHeadless does.
int writeDemonstration(const SimOptions& options);

} // namespace hs::simapp
