// runLocally: a pool of job processes, each the job contract of one manifest line.
#include "hs/batch/LocalRunner.h"

#include "hs/batch/Job.h"
#include "hs/batch/JobStatus.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <map>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace hs::batch {

namespace {

struct Child {
    const Job* job = nullptr;
    std::chrono::steady_clock::time_point start;
};

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

/// What a finished job process left: ok, failed (with a record written here when it left none) or busy.
enum class Outcome { Ok, Failed, Busy };

Outcome collect(const std::string& batchFolder, const Child& child, int status, const rusage& usage) {
    const Job& job = *child.job;
    auto record = readStatus(batchFolder, job.name);
    const bool fresh = record && *record && (*record)->seed == job.seed;
    if (fresh && (*record)->state == JobState::Ok && WIFEXITED(status) && WEXITSTATUS(status) == 0)
        return Outcome::Ok;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !fresh)
        return Outcome::Busy; // the job process found the job locked by another runner
    if (fresh && (*record)->state == JobState::Failed)
        return Outcome::Failed;
    StatusRecord failed;
    failed.job = job.name;
    failed.index = job.index;
    failed.seed = job.seed;
    failed.output = job.output;
    failed.state = JobState::Failed;
    failed.error =
        Error{ErrorCode::Internal, "the job process " + describeEnd(status) + " without recording a status (see " +
                                       std::string(kLogsFolder) + "/" + job.name + ".log)"};
    failed.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - child.start).count();
    failed.peakMemoryMb = static_cast<double>(usage.ru_maxrss) / 1024.0;
    failed.host = hostName();
    failed.finishedUtc = utcNow();
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
        if (jobIsDone(batchFolder, job))
            ++counts.alreadyDone;
        else
            pending.push_back(&job);
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
            running[*pid] = Child{job, std::chrono::steady_clock::now()};
            counts.running = running.size();
        }
        if (running.empty())
            break;
        int status = 0;
        rusage usage{};
        const pid_t pid = wait4(-1, &status, 0, &usage);
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
