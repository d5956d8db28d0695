#pragma once
/// The local runner: the whole manifest on this machine, N jobs at a time, each in its own process running the job
/// contract (`EXECUTABLE batch run BATCH --task-index I`), so that a crash, an abort or memory exhaustion in one job
/// costs that job only, and peak memory is measured per job; each job process is held to a wall-clock and a memory
/// limit. Resumable: jobs already done are skipped without
/// starting a process, and every job skips what is complete (hs/batch/Job.h).

#include "hs/batch/Manifest.h"
#include "hs/core/Result.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hs::batch {

struct LocalRunParams {
    int jobs = 1;                     ///< job processes at a time (>= 1)
    std::string executable;           ///< the command-line tool to start for each job
    std::optional<int> threadsPerJob; ///< passed as --threads; unset: the case's meshing.threads
    /// Per job process, as Slurm's --time and --mem hold an array task (the same defaults as `batch slurm`): a job
    /// over either is killed (SIGKILL), its unfinished package removed, and it is recorded failed (LimitExceeded,
    /// naming the limit). 0: no limit. Memory is the resident set, sampled every kPollSeconds.
    double timeLimitSeconds = 3600.0;
    double memoryLimitMib = 4096.0;
};

/// How often the runner looks at its job processes' clocks and resident memory.
constexpr double kPollSeconds = 0.05;

/// Where the run stands; reported after every job that finishes and once before the first starts.
struct RunnerProgress {
    std::size_t total = 0;
    std::size_t alreadyDone = 0; ///< skipped: done before this run
    std::size_t ok = 0;          ///< finished ok in this run
    std::size_t failed = 0;
    std::size_t busy = 0; ///< held by another runner
    std::size_t running = 0;
    const Job* finished = nullptr; ///< the job that just finished, if any
};

struct LocalRunResult {
    RunnerProgress counts;
    double seconds = 0.0;                ///< wall-clock time of the run
    std::vector<std::string> failedJobs; ///< names, in manifest order
    /// Jobs with an ok record for a package made from other inputs, run again: name, why (DoneCheck::rerunReason).
    std::vector<std::pair<std::string, std::string>> rerunJobs;
};

/// Runs every job of `manifest` that is not done. A job process that ends without an ok record (killed, crashed,
/// or failed) counts as failed; when it left no record at all, the runner writes a failed one naming how the
/// process ended. A job process over its limits is killed and recorded failed with the limit it broke. Fails only when
/// no job process can be started (IoError).
[[nodiscard]] Result<LocalRunResult> runLocally(const std::string& batchFolder, const Manifest& manifest,
                                                const LocalRunParams& params,
                                                const std::function<void(const RunnerProgress&)>& onProgress = {});

} // namespace hs::batch
