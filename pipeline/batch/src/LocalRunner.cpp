// runLocally: a pool of job processes, each the job contract of one manifest line.
#include "hs/batch/LocalRunner.h"

#include "hs/batch/Job.h"
#include "hs/batch/JobStatus.h"
#include "hs/scene/ScenePackage.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <map>
#include <optional>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace hs::batch {

namespace {

struct Child {
    const Job* job = nullptr;
    std::chrono::steady_clock::time_point start;
    double peakResidentMib = 0.0;   ///< the largest resident set sampled
    std::optional<Error> overLimit; ///< set when the runner killed it for a limit
};

/// The resident set of a process (MiB) from /proc/PID/statm; 0 when it cannot be read (the process ended).
double residentMib(pid_t pid) {
    const std::string path = "/proc/" + std::to_string(pid) + "/statm";
    std::FILE* file = std::fopen(path.c_str(), "r");
    if (!file)
        return 0.0;
    unsigned long long size = 0, resident = 0;
    const int read = std::fscanf(file, "%llu %llu", &size, &resident);
    std::fclose(file);
    if (read != 2)
        return 0.0;
    return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

/// "3600 s", "0.5 s"; "4096 MiB".
std::string amount(double value, const char* unit) {
    char text[48];
    std::snprintf(text, sizeof text, "%.4g %s", value, unit);
    return text;
}

/// Kills every job process over its wall-clock or memory limit, noting which limit.
void enforceLimits(std::map<pid_t, Child>& running, const LocalRunParams& params) {
    const auto now = std::chrono::steady_clock::now();
    for (auto& [pid, child] : running) {
        if (child.overLimit)
            continue;
        const double seconds = std::chrono::duration<double>(now - child.start).count();
        const double resident = residentMib(pid);
        child.peakResidentMib = std::max(child.peakResidentMib, resident);
        if (params.timeLimitSeconds > 0.0 && seconds > params.timeLimitSeconds)
            child.overLimit = Error{ErrorCode::LimitExceeded, "killed after " + amount(seconds, "s") +
                                                                  ": over its wall-clock limit of " +
                                                                  amount(params.timeLimitSeconds, "s")};
        else if (params.memoryLimitMib > 0.0 && resident > params.memoryLimitMib)
            child.overLimit = Error{ErrorCode::LimitExceeded, "killed at " + amount(resident, "MiB") +
                                                                  " resident: over its memory limit of " +
                                                                  amount(params.memoryLimitMib, "MiB")};
        if (child.overLimit)
            kill(pid, SIGKILL);
    }
}

Result<pid_t> startJob(const std::string& batchFolder, const Job& job, const LocalRunParams& params) {
    std::vector<std::string> args{params.executable, "batch",        "run",
                                  batchFolder,       "--task-index", std::to_string(job.index)};
    if (params.threadsPerJob) {
        args.push_back("--threads");
        args.push_back(std::to_string(*params.threadsPerJob));
    }
    std::vector<char*> argv;
    for (std::string& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);

    const std::string log = batchPath(batchFolder, std::string(kLogsFolder) + "/" + job.name + ".log");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    pid_t pid = 0;
    const int error = posix_spawn(&pid, params.executable.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0)
        return fail(ErrorCode::IoError, params.executable + ": cannot start a job process: " + std::strerror(error));
    return pid;
}

/// "exit code 4", "killed by signal 9 (Killed)".
std::string describeEnd(int status) {
    if (WIFEXITED(status))
        return "exit code " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status))
        return "killed by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
    return "ended with status " + std::to_string(status);
}

/// A failed record of a job process as the runner saw it (the error is the caller's).
StatusRecord processRecord(const Job& job, const Child& child, const rusage& usage) {
    StatusRecord failed = recordOf(job, JobState::Failed);
    failed.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - child.start).count();
    failed.peakMemoryMb = std::max(static_cast<double>(usage.ru_maxrss) / 1024.0, child.peakResidentMib);
    failed.host = hostName();
    failed.finishedUtc = utcNow();
    return failed;
}

/// What a finished job process left: ok, failed (with a record written here when it left none) or busy.
enum class Outcome { Ok, Failed, Busy };

Outcome collect(const std::string& batchFolder, const Child& child, int status, const rusage& usage) {
    const Job& job = *child.job;
    if (child.overLimit) {
        // Whatever the process had begun is gone: its temporary package folder, and an interrupted replace undone.
        (void)scene::recoverScenePackage(batchPath(batchFolder, job.output));
        StatusRecord failed = processRecord(job, child, usage);
        failed.error = child.overLimit;
        (void)writeStatus(batchFolder, failed);
        return Outcome::Failed;
    }
    auto record = readStatus(batchFolder, job.name);
    const bool fresh = record && *record && (*record)->seed == job.seed;
    if (fresh && (*record)->state == JobState::Ok && WIFEXITED(status) && WEXITSTATUS(status) == 0)
        return Outcome::Ok;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !fresh)
        return Outcome::Busy; // the job process found the job locked by another runner
    if (fresh && (*record)->state == JobState::Failed)
        return Outcome::Failed;
    StatusRecord failed = processRecord(job, child, usage);
    failed.error =
        Error{ErrorCode::Internal, "the job process " + describeEnd(status) + " without recording a status (see " +
                                       std::string(kLogsFolder) + "/" + job.name + ".log)"};
    (void)writeStatus(batchFolder, failed); // best effort: the runner reports the failure either way
    return Outcome::Failed;
}

} // namespace

Result<LocalRunResult> runLocally(const std::string& batchFolder, const Manifest& manifest,
                                  const LocalRunParams& params,
                                  const std::function<void(const RunnerProgress&)>& onProgress) {
    const auto start = std::chrono::steady_clock::now();
    LocalRunResult result;
    RunnerProgress& counts = result.counts;
    counts.total = manifest.jobs.size();
    std::vector<const Job*> pending;
    for (const Job& job : manifest.jobs) {
        const DoneCheck done = checkJobDone(batchFolder, job);
        if (done.done) {
            ++counts.alreadyDone;
            continue;
        }
        pending.push_back(&job);
        if (!done.rerunReason.empty())
            result.rerunJobs.emplace_back(job.name, done.rerunReason);
    }
    const auto report = [&](const Job* finished) {
        counts.finished = finished;
        if (onProgress)
            onProgress(counts);
    };
    report(nullptr);

    std::map<pid_t, Child> running;
    std::vector<const Job*> failedJobs;
    std::size_t next = 0;
    const auto jobs = static_cast<std::size_t>(std::max(params.jobs, 1));
    while (next < pending.size() || !running.empty()) {
        while (next < pending.size() && running.size() < jobs) {
            const Job* job = pending[next++];
            auto pid = startJob(batchFolder, *job, params);
            if (!pid) {
                if (running.empty() && counts.ok + counts.failed == 0)
                    return pid.failure();
                failedJobs.push_back(job);
                ++counts.failed;
                continue;
            }
            Child& child = running[*pid];
            child.job = job;
            child.start = std::chrono::steady_clock::now();
            counts.running = running.size();
        }
        if (running.empty())
            break;
        int status = 0;
        rusage usage{};
        const pid_t pid = wait4(-1, &status, WNOHANG, &usage);
        if (pid == 0) {
            enforceLimits(running, params);
            std::this_thread::sleep_for(std::chrono::duration<double>(kPollSeconds));
            continue;
        }
        if (pid < 0) {
            if (errno == EINTR)
                continue;
            return fail(ErrorCode::Internal, std::string("waiting for job processes: ") + std::strerror(errno));
        }
        const auto it = running.find(pid);
        if (it == running.end())
            continue;
        const Child child = it->second;
        running.erase(it);
        counts.running = running.size();
        switch (collect(batchFolder, child, status, usage)) {
        case Outcome::Ok:
            ++counts.ok;
            break;
        case Outcome::Failed:
            ++counts.failed;
            failedJobs.push_back(child.job);
            break;
        case Outcome::Busy:
            ++counts.busy;
            break;
        }
        report(child.job);
    }
    std::sort(failedJobs.begin(), failedJobs.end(), [](const Job* a, const Job* b) { return a->index < b->index; });
    for (const Job* job : failedJobs)
        result.failedJobs.push_back(job->name);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace hs::batch
