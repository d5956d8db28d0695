// The headless simulator: a script or a recorded trial through the world, as fast as it steps.
#include "hs/simapp/Headless.h"

#include "hs/core/ExitCode.h"
#include "hs/simapp/PhysicsLoop.h"

#include <cmath>
#include <cstdint>
#include <ctime>
#include <iostream>

namespace hs::simapp {

Result<ScriptedRun> runScripted(const SimOptions& options, const std::string& startedUtc) {
    const bool demo = options.device.kind == DeviceSpec::Kind::Demo;
    auto script = demo ? Result<sim::Script>(sim::Script{}) : sim::readScript(options.device.scriptPath);
    if (!script)
        return script.failure();
    auto world = sim::World::load(options.scene, options.world);
    if (!world)
        return world.failure();
    if (demo) {
        auto planned = sim::demonstrationScript(**world); // the world's own demonstration, planned on its scene
        if (!planned)
            return planned.failure();
        *script = std::move(*planned);
    }
    ScriptedRun run;
    run.trial.header = (*world)->trialHeader();
    run.trial.header.device = options.device.text();
    run.trial.header.startedUtc = startedUtc;
    const std::uint64_t tickLimit = options.stopAfterS > 0.0
                                        ? static_cast<std::uint64_t>(std::ceil(options.stopAfterS * sim::kDeviceRateHz))
                                        : UINT64_MAX;
    ScriptSource source(std::move(*script), tickLimit);
    auto steps = runSteps(**world, source, &run.trial.samples);
    if (!steps)
        return steps.failure();
    run.report = (*world)->report();
    // The report carries the header the trial records, so the trial's replay reports the same bytes.
    run.report.header = run.trial.header;
    return run;
}

Result<sim::TrialReport> runReplay(const SimOptions& options, sim::Trial* trialOut) {
    auto trial = sim::readTrial(options.replayPath);
    if (!trial)
        return trial.failure();
    auto report = sim::replayTrial(options.scene, *trial);
    if (!report) {
        Error error = report.error();
        if (error.detail.find(options.replayPath) == std::string::npos)
            error.detail = options.replayPath + ": " + error.detail;
        return fail(error.code, error.detail);
    }
    report->header = trial->header;
    if (trialOut)
        *trialOut = std::move(*trial);
    return report;
}

namespace {

int failWith(const Error& error) {
    std::cerr << "hysteroscene-sim: " << error.message() << '\n';
    return exitCodeFor(error);
}

} // namespace

int writeDemonstration(const SimOptions& options) {
    auto world = sim::World::load(options.scene, options.world);
    if (!world)
        return failWith(world.error());
    auto planned = sim::demonstrationScript(**world);
    if (!planned)
        return failWith(planned.error());
    if (auto written = sim::writeScript(*planned, options.writeDemoPath); !written)
        return failWith(written.error());
    std::cout << "demonstration " << options.writeDemoPath << " (" << planned->keyframes.size() << " key frames, "
              << static_cast<double>(planned->tickCount()) / sim::kDeviceRateHz << " s)\n";
    return kExitOk;
}

int runHeadless(const SimOptions& options) {
    sim::Trial trial;
    sim::TrialReport report;
    if (!options.replayPath.empty()) {
        auto replayed = runReplay(options, &trial);
        if (!replayed)
            return failWith(replayed.error());
        report = std::move(*replayed);
    } else {
        auto run = runScripted(options);
        if (!run)
            return failWith(run.error());
        trial = std::move(run->trial);
        report = std::move(run->report);
    }
    if (!options.recordPath.empty())
        if (auto written = sim::writeTrial(trial, options.recordPath); !written)
            return failWith(written.error());
    if (options.reportPath.empty()) {
        std::cout << sim::reportJson(report);
        return kExitOk;
    }
    if (auto written = sim::writeReport(report, options.reportPath, options.htmlPath); !written)
        return failWith(written.error());
    std::cout << "report      " << options.reportPath << (options.htmlPath.empty() ? "" : ", " + options.htmlPath)
              << "\n";
    return kExitOk;
}

} // namespace hs::simapp
