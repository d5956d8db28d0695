// `batch plan|run|status`: curricula at scale. The work is hs::batch's (curriculum, manifest, the job contract, the
// local runner); this file holds the options, the progress printing and the summaries.
#include "CliCommon.h"
#include "Commands.h"

#include "hs/batch/Curriculum.h"
#include "hs/batch/Job.h"
#include "hs/batch/LocalRunner.h"
#include "hs/batch/Manifest.h"
#include "hs/batch/Report.h"
#include "hs/batch/Slurm.h"
#include "hs/io/AtomicFile.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <thread>
#include <unistd.h>

namespace hs::cli {
namespace {

namespace fs = std::filesystem;

struct PlanOptions {
    std::string curriculum;
    std::string output;
    CommonOptions common;
};

struct RunOptions {
    std::string folder;
    std::optional<std::size_t> taskIndex;
    std::size_t tasksPerIndex = 1;
    int jobs = 1;
    std::optional<int> threads;
    std::string time = batch::SlurmParams{}.time;     ///< per job process, a Slurm time
    std::string memory = batch::SlurmParams{}.memory; ///< per job process, a Slurm memory size
    CommonOptions common;
};

struct SlurmOptions {
    std::string folder;
    batch::SlurmParams params;
    bool dryRun = false;
};

struct ReportOptions {
    std::string folder;
    batch::ReportParams params;
    CommonOptions common;
};

struct StatusOptions {
    std::string folder;
    CommonOptions common;
};

int runPlan(const PlanOptions& o) {
    auto loaded = batch::loadCurriculum(o.curriculum);
    if (!loaded)
        return reportError("batch plan", loaded.error());
    auto text = io::readFile(o.curriculum, batch::kMaxCurriculumFileBytes);
    if (!text)
        return reportError("batch plan", text.error());
    auto plan = batch::planBatch(*loaded, *text, o.output);
    if (!plan)
        return reportError("batch plan", plan.error());
    const auto& c = loaded->curriculum;
    if (o.common.json) {
        nlohmann::ordered_json j;
        j["curriculum"] = o.curriculum;
        j["folder"] = o.output;
        j["cases"] = plan->cases;
        j["variants"] = c.variants;
        j["jobs"] = plan->manifest.jobs.size();
        j["unchanged"] = plan->unchanged;
        printJson(std::cout, j);
        return kExitOk;
    }
    std::printf("%s %s: %zu jobs (%zu cases x %d variants), seed %llu\n", plan->unchanged ? "unchanged" : "planned",
                o.output.c_str(), plan->manifest.jobs.size(), plan->cases, c.variants,
                static_cast<unsigned long long>(c.seed));
    for (const auto& t : c.templates)
        std::printf("template    %-20s %d cases\n", t.name.c_str(), t.cases);
    std::printf("manifest    %s\n", batch::batchPath(o.output, batch::kManifestFile).c_str());
    return kExitOk;
}

/// The job contract: jobs [I*K, I*K+K) of the manifest, one after the other in this process.
int runTasks(const RunOptions& o, const batch::Manifest& manifest) {
    const std::size_t first = *o.taskIndex * o.tasksPerIndex;
    if (first >= manifest.jobs.size())
        return reportError("batch run",
                           Error{ErrorCode::InvalidInput,
                                 "--task-index " + std::to_string(*o.taskIndex) + " x --tasks-per-index " +
                                     std::to_string(o.tasksPerIndex) + " starts at job " + std::to_string(first) +
                                     ", beyond the manifest's " + std::to_string(manifest.jobs.size()) + " jobs"});
    const std::size_t last = std::min(first + o.tasksPerIndex, manifest.jobs.size());
    int exitCode = kExitOk;
    batch::RunJobParams params;
    params.threads = o.threads;
    for (std::size_t i = first; i < last; ++i) {
        const batch::Job& job = manifest.jobs[i];
        const batch::JobRun run = batch::runJob(o.folder, job, params);
        if (!run.rerunReason.empty())
            std::printf("rerun       %s: %s\n", job.name.c_str(), run.rerunReason.c_str());
        if (run.action == batch::JobAction::Busy) {
            std::printf("busy        %s (another process runs it)\n", job.name.c_str());
        } else if (run.record.state == batch::JobState::Ok) {
            std::printf("%-11s %s -> %s (%.1f s, %.0f MiB)\n",
                        run.action == batch::JobAction::Skipped ? "skipped" : "ok", job.name.c_str(),
                        job.output.c_str(), run.record.seconds, run.record.peakMemoryMb);
        } else {
            std::printf("failed      %s: %s\n", job.name.c_str(), run.record.error->message().c_str());
            const int code =
                reportError("batch run", Error{run.record.error->code, job.name + ": " + run.record.error->detail});
            if (exitCode == kExitOk)
                exitCode = code;
        }
        std::fflush(stdout);
    }
    return exitCode;
}

/// One bar on a terminal, a line per finished job otherwise.
void printRunnerProgress(const batch::RunnerProgress& p, bool tty) {
    const std::size_t finished = p.alreadyDone + p.ok + p.failed + p.busy;
    const int percent = p.total ? static_cast<int>(100 * finished / p.total) : 100;
    if (tty) {
        const int filled = percent * 30 / 100;
        std::fprintf(stderr, "\r[%-30s] %3d%% %zu/%zu done, %zu failed, %zu running ",
                     std::string(static_cast<std::size_t>(filled), '#').c_str(), percent, finished, p.total, p.failed,
                     p.running);
    } else if (p.finished) {
        std::fprintf(stderr, "[%3d%%] %s finished (%zu/%zu done, %zu failed)\n", percent, p.finished->name.c_str(),
                     finished, p.total, p.failed);
    }
    std::fflush(stderr);
}

/// This program's absolute path, for the job processes and the sbatch scripts to run.
Result<std::string> thisProgram() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec)
        return fail(ErrorCode::Internal, "cannot find this program: " + ec.message());
    return self.string();
}

int runLocal(const RunOptions& o, const batch::Manifest& manifest) {
    auto self = thisProgram();
    if (!self)
        return reportError("batch run", self.error());
    batch::LocalRunParams params;
    const auto timeLimit = batch::slurmTimeSeconds(o.time);
    const auto memoryLimit = batch::slurmMemoryMib(o.memory);
    if (!timeLimit)
        return reportError("batch run", Error{ErrorCode::InvalidInput,
                                              "--time " + o.time +
                                                  ": not a Slurm time (minutes, MM:SS, HH:MM:SS, D-HH or D-HH:MM:SS; "
                                                  "0 for no limit)"});
    if (!memoryLimit)
        return reportError("batch run", Error{ErrorCode::InvalidInput,
                                              "--mem " + o.memory +
                                                  ": not a Slurm memory size (a whole number, optionally K, M, G or "
                                                  "T; 0 for no limit)"});
    params.timeLimitSeconds = *timeLimit;
    params.memoryLimitMib = *memoryLimit;
    params.jobs = o.jobs;
    params.executable = *self;
    params.threadsPerJob = o.threads;
    if (!params.threadsPerJob && o.jobs > 1) // share the cores between the job processes
        params.threadsPerJob = std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / o.jobs);
    const bool tty = !o.common.json && isatty(STDERR_FILENO) != 0;
    auto result = batch::runLocally(o.folder, manifest, params, [&](const batch::RunnerProgress& p) {
        if (!o.common.json)
            printRunnerProgress(p, tty);
    });
    if (tty)
        std::fprintf(stderr, "\n");
    if (!result)
        return reportError("batch run", result.error());
    const auto& c = result->counts;
    const double perHour = result->seconds > 0.0 ? 3600.0 * static_cast<double>(c.ok) / result->seconds : 0.0;
    if (o.common.json) {
        nlohmann::ordered_json j;
        j["folder"] = o.folder;
        j["jobs"] = c.total;
        j["alreadyDone"] = c.alreadyDone;
        j["ok"] = c.ok;
        j["failed"] = c.failed;
        j["busy"] = c.busy;
        j["seconds"] = result->seconds;
        j["scenesPerHour"] = perHour;
        j["parallelJobs"] = o.jobs;
        j["timeLimitSeconds"] = params.timeLimitSeconds;
        j["memoryLimitMib"] = params.memoryLimitMib;
        j["failedJobs"] = result->failedJobs;
        auto rerun = nlohmann::ordered_json::array();
        for (const auto& [name, reason] : result->rerunJobs)
            rerun.push_back({{"job", name}, {"reason", reason}});
        j["rerunJobs"] = rerun;
        printJson(std::cout, j);
    } else {
        std::printf("ran         %s: %zu jobs, %zu already done, %zu ok, %zu failed, %zu busy\n", o.folder.c_str(),
                    c.total, c.alreadyDone, c.ok, c.failed, c.busy);
        std::printf("throughput  %zu scenes in %.1f s with %d jobs at a time: %.0f scenes/hour\n", c.ok,
                    result->seconds, o.jobs, perHour);
        const std::string timeText =
            params.timeLimitSeconds > 0.0 ? std::to_string(std::lround(params.timeLimitSeconds)) + " s" : "none";
        const std::string memoryText =
            params.memoryLimitMib > 0.0 ? std::to_string(std::lround(params.memoryLimitMib)) + " MiB" : "none";
        std::printf("limits      per job: wall clock %s, resident memory %s\n", timeText.c_str(), memoryText.c_str());
        for (const auto& [name, reason] : result->rerunJobs)
            std::printf("rerun       %s: %s\n", name.c_str(), reason.c_str());
        for (const auto& name : result->failedJobs)
            std::printf("failed      %s (see %s)\n", name.c_str(), batch::statusPath(o.folder, name).c_str());
    }
    return c.failed ? kExitFailed : kExitOk;
}

int runRun(const RunOptions& o) {
    auto manifest = batch::readManifest(o.folder);
    if (!manifest)
        return reportError("batch run", manifest.error());
    return o.taskIndex ? runTasks(o, *manifest) : runLocal(o, *manifest);
}

int runSlurm(SlurmOptions o) {
    auto manifest = batch::readManifest(o.folder);
    if (!manifest)
        return reportError("batch slurm", manifest.error());
    auto self = thisProgram();
    if (!self)
        return reportError("batch slurm", self.error());
    o.params.executable = *self;
    if (const auto maxArraySize = batch::clusterMaxArraySize(); maxArraySize && o.params.arrayChunk > *maxArraySize) {
        std::printf("note        the cluster's MaxArraySize is %zu: %zu array tasks per script\n", *maxArraySize,
                    *maxArraySize);
        o.params.arrayChunk = *maxArraySize;
    }
    auto scripts = batch::planSlurmScripts(o.folder, *manifest, o.params);
    if (!scripts)
        return reportError("batch slurm", scripts.error());
    if (scripts->empty()) {
        std::printf("nothing     every job of %s is done\n", o.folder.c_str());
        return kExitOk;
    }
    if (auto written = batch::writeSlurmScripts(*scripts); !written)
        return reportError("batch slurm", written.error());
    for (const batch::SlurmScript& script : *scripts) {
        if (o.dryRun) {
            std::printf("would run   sbatch --parsable %s (%zu array tasks: --array=%s)\n", script.path.c_str(),
                        script.tasks, script.arraySpec.c_str());
            continue;
        }
        auto id = batch::submitSlurmScript(o.folder, script);
        if (!id)
            return reportError("batch slurm", id.error());
        std::printf("submitted   %s as Slurm job %s (%zu array tasks)\n", script.path.c_str(), id->c_str(),
                    script.tasks);
        std::fflush(stdout);
    }
    return kExitOk;
}

/// sacct's view of the submitted array tasks, "" when nothing was submitted or sacct cannot say.
std::string slurmLine(const std::string& folder, nlohmann::ordered_json& j) {
    const auto ids = batch::submittedSlurmJobs(folder);
    if (ids.empty())
        return {};
    auto states = batch::slurmTaskStates(ids);
    if (!states) {
        j["slurm"] = {{"jobs", ids}, {"error", states.error().message()}};
        return "slurm       " + std::to_string(ids.size()) + " submitted; sacct: " + states.error().message();
    }
    std::string line = "slurm       " + std::to_string(ids.size()) + " submitted;";
    nlohmann::ordered_json counts = nlohmann::ordered_json::object();
    for (const auto& [state, count] : *states) {
        line += " " + std::to_string(count) + " " + state;
        counts[state] = count;
    }
    j["slurm"] = {{"jobs", ids}, {"states", counts}};
    return line;
}

int runStatus(const StatusOptions& o) {
    auto manifest = batch::readManifest(o.folder);
    if (!manifest)
        return reportError("batch status", manifest.error());
    std::size_t ok = 0, failed = 0, running = 0, pending = 0;
    double okSeconds = 0.0, peakMb = 0.0;
    auto failures = nlohmann::ordered_json::array();
    auto stale = nlohmann::ordered_json::array();
    std::vector<std::string> lines;
    for (const batch::Job& job : manifest->jobs) {
        auto record = batch::readStatus(o.folder, job.name);
        if (!record)
            return reportError("batch status", record.error());
        if (batch::jobIsLocked(o.folder, job.name)) {
            ++running;
        } else if (!*record || (*record)->seed != job.seed) {
            ++pending;
        } else if ((*record)->state == batch::JobState::Ok) {
            const batch::DoneCheck done = batch::checkJobDone(o.folder, job);
            if (!done.done) { // made from other inputs, or its package changed since: the next run redoes it
                ++pending;
                if (!done.rerunReason.empty()) {
                    stale.push_back({{"job", job.name}, {"reason", done.rerunReason}});
                    lines.push_back("stale       " + job.name + ": " + done.rerunReason);
                }
                continue;
            }
            ++ok;
            okSeconds += (*record)->seconds;
            peakMb = std::max(peakMb, (*record)->peakMemoryMb);
        } else {
            ++failed;
            const Error& e = *(*record)->error;
            failures.push_back({{"job", job.name}, {"code", std::string(errorCodeKey(e.code))}, {"detail", e.detail}});
            lines.push_back("failed      " + job.name + ": " + e.message());
        }
    }
    const double mean = ok ? okSeconds / static_cast<double>(ok) : 0.0;
    nlohmann::ordered_json slurm;
    const std::string slurmText = slurmLine(o.folder, slurm);
    if (o.common.json) {
        nlohmann::ordered_json j;
        j["folder"] = o.folder;
        j["jobs"] = manifest->jobs.size();
        j["ok"] = ok;
        j["failed"] = failed;
        j["running"] = running;
        j["pending"] = pending;
        j["meanSecondsPerJob"] = mean;
        j["peakMemoryMb"] = peakMb;
        j["failures"] = failures;
        j["stale"] = stale;
        if (slurm.contains("slurm"))
            j["slurm"] = slurm["slurm"];
        printJson(std::cout, j);
    } else {
        std::printf("batch       %s: %zu jobs\n", o.folder.c_str(), manifest->jobs.size());
        std::printf("status      %zu ok, %zu failed, %zu running, %zu pending\n", ok, failed, running, pending);
        if (ok)
            std::printf("jobs        %.1f s per ok job on average, peak memory %.0f MiB\n", mean, peakMb);
        if (!slurmText.empty())
            std::printf("%s\n", slurmText.c_str());
        for (const auto& line : lines)
            std::printf("%s\n", line.c_str());
    }
    return kExitOk;
}

int runReport(const ReportOptions& o) {
    auto manifest = batch::readManifest(o.folder);
    if (!manifest)
        return reportError("batch report", manifest.error());
    auto report = batch::writeBatchReport(o.folder, *manifest, o.params);
    if (!report)
        return reportError("batch report", report.error());
    if (o.common.json) {
        nlohmann::ordered_json j;
        j["csv"] = report->csvPath;
        j["html"] = report->htmlPath;
        j["rows"] = report->rows;
        j["pages"] = report->pages;
        j["charts"] = report->charts;
        j["warnings"] = report->warnings;
        printJson(std::cout, j);
        return kExitOk;
    }
    std::printf("wrote       %s (%zu rows)\n", report->csvPath.c_str(), report->rows);
    std::printf("wrote       %s (%zu charts, %zu page%s of cases in %s)\n", report->htmlPath.c_str(), report->charts,
                report->pages, report->pages == 1 ? "" : "s",
                (fs::path(report->htmlPath).parent_path() / "pages").string().c_str());
    for (const auto& w : report->warnings)
        std::printf("warning     %s\n", w.c_str());
    return kExitOk;
}

} // namespace

void addBatchCommand(CLI::App& app, int& exitCode) {
    auto* batch = app.add_subcommand("batch", "Curricula at scale: plan, run and follow batches of scenes");
    batch->require_subcommand(1);

    auto plan = std::make_shared<PlanOptions>();
    auto* planCmd = batch->add_subcommand("plan", "Expand a curriculum into case files and a manifest of jobs");
    planCmd->add_option("CURRICULUM", plan->curriculum, "curriculum file (docs/batch.md)")->required();
    planCmd->add_option("-o,--output", plan->output, "batch folder")->required();
    planCmd->add_flag("--json", plan->common.json, "print a JSON summary");
    planCmd->callback([plan, &exitCode] { exitCode = runPlan(*plan); });

    auto run = std::make_shared<RunOptions>();
    auto* runCmd = batch->add_subcommand("run", "Run jobs of a planned batch: one task (the job contract) or all");
    runCmd->add_option("BATCH", run->folder, "batch folder")->required();
    auto* task = runCmd->add_option("--task-index", run->taskIndex,
                                    "run jobs I*K .. I*K+K-1 of the manifest in this process (the job contract)");
    runCmd->add_option("--tasks-per-index", run->tasksPerIndex, "K: jobs per task index")
        ->check(CLI::Range(std::size_t{1}, batch::kMaxJobs))
        ->needs(task);
    runCmd->add_option("--jobs", run->jobs, "local runner: job processes at a time")
        ->check(CLI::Range(1, 256))
        ->excludes(task);
    runCmd->add_option("--threads", run->threads, "threads per stage (never changes the result)")
        ->check(CLI::Range(0, 256));
    runCmd->add_option("--time", run->time, "local runner: wall-clock limit per job (a Slurm time; 0: none)")
        ->excludes(task)
        ->capture_default_str();
    runCmd->add_option("--mem", run->memory, "local runner: resident memory limit per job (a Slurm size; 0: none)")
        ->excludes(task)
        ->capture_default_str();
    runCmd->add_flag("--json", run->common.json, "local runner: print a JSON summary (and no progress bar)");
    runCmd->callback([run, &exitCode] { exitCode = runRun(*run); });

    auto slurm = std::make_shared<SlurmOptions>();
    auto* slurmCmd = batch->add_subcommand("slurm", "Write sbatch array scripts for the jobs not done and submit them");
    slurmCmd->add_option("BATCH", slurm->folder, "batch folder")->required();
    slurmCmd->add_option("--partition", slurm->params.partition, "partition (default: the cluster's)");
    slurmCmd->add_option("--time", slurm->params.time, "time limit per array task")->capture_default_str();
    slurmCmd->add_option("--mem", slurm->params.memory, "memory per array task")->capture_default_str();
    slurmCmd->add_option("--array-chunk", slurm->params.arrayChunk, "array tasks per script (<= MaxArraySize)")
        ->check(CLI::Range(std::size_t{1}, std::size_t{1000000}))
        ->capture_default_str();
    slurmCmd->add_option("--tasks-per-index", slurm->params.tasksPerIndex, "jobs per array task")
        ->check(CLI::Range(std::size_t{1}, batch::kMaxJobs))
        ->capture_default_str();
    slurmCmd->add_option("--threads", slurm->params.threads, "CPUs per array task and threads per stage")
        ->check(CLI::Range(1, 256))
        ->capture_default_str();
    slurmCmd->add_flag("--dry-run", slurm->dryRun, "write the scripts and print the sbatch commands; submit nothing");
    slurmCmd->callback([slurm, &exitCode] { exitCode = runSlurm(*slurm); });

    auto report = std::make_shared<ReportOptions>();
    auto* reportCmd =
        batch->add_subcommand("report", "Write BATCH/report/: report.csv, report.html (the index) and pages/ of cases");
    reportCmd->add_option("BATCH", report->folder, "batch folder")->required();
    reportCmd->add_option("--chart-library", report->params.chartLibrary, "Chart.js to inline in the page")
        ->capture_default_str();
    reportCmd->add_option("--rows-per-page", report->params.rowsPerPage, "cases per page of the table")
        ->check(CLI::Range(std::size_t{1}, batch::kMaxJobs))
        ->capture_default_str();
    reportCmd->add_flag("--json", report->common.json, "print JSON");
    reportCmd->callback([report, &exitCode] { exitCode = runReport(*report); });

    auto status = std::make_shared<StatusOptions>();
    auto* statusCmd = batch->add_subcommand("status", "Summarise a batch from its status records");
    statusCmd->add_option("BATCH", status->folder, "batch folder")->required();
    statusCmd->add_flag("--json", status->common.json, "print JSON");
    statusCmd->callback([status, &exitCode] { exitCode = runStatus(*status); });
}

} // namespace hs::cli
