#pragma once
/// Slurm job arrays for a planned batch: sbatch scripts whose array tasks each run the job contract
/// (`batch run BATCH --task-index I --tasks-per-index K`), chunked so that no array index reaches the cluster's
/// MaxArraySize, submitted with sbatch; and what sacct says about them. Slurm is the scheduler; nothing here
/// schedules. docs/batch.md, "Slurm".

#include "hs/batch/Manifest.h"
#include "hs/core/Result.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hs::batch {

constexpr std::string_view kSlurmFolder = "slurm";
/// Slurm's default MaxArraySize is 1001 (slurm.conf(5)): array indices 0..1000. Chunks stay below it.
constexpr std::size_t kDefaultArrayChunk = 1000;

struct SlurmParams {
    std::string executable;        ///< the command-line tool the array tasks run (an absolute path)
    std::string partition;         ///< --partition; empty: the cluster's default
    std::string time = "01:00:00"; ///< --time per array task (Slurm's formats, e.g. "30", "01:00:00", "1-00:00:00")
    std::string memory = "4G";     ///< --mem per array task (e.g. "4G", "4000M")
    std::size_t arrayChunk = kDefaultArrayChunk; ///< array tasks per sbatch script, at most MaxArraySize
    std::size_t tasksPerIndex = 1;               ///< jobs per array task, run one after the other
    int threads = 1;                             ///< --cpus-per-task, and --threads of every job
};

/// One sbatch script: array tasks `taskOffset + i` for each array index i in `arrayIndices`.
struct SlurmScript {
    std::string path;           ///< BATCH/slurm/array-NNN.sbatch
    std::size_t taskOffset = 0; ///< the script runs task index taskOffset + SLURM_ARRAY_TASK_ID
    std::string arraySpec;      ///< sbatch --array value, e.g. "0-999" or "0-3,7,9-12"
    std::size_t tasks = 0;      ///< array tasks in it
    std::string text;
};

/// A Slurm time limit (sbatch(1) --time: "minutes", "minutes:seconds", "hours:minutes:seconds", "days-hours",
/// "days-hours:minutes", "days-hours:minutes:seconds") in seconds; std::nullopt for anything else.
std::optional<double> slurmTimeSeconds(std::string_view time);
/// A Slurm memory size (sbatch(1) --mem: a whole number with an optional unit K, M, G or T; megabytes without one)
/// in MiB; std::nullopt for anything else.
std::optional<double> slurmMemoryMib(std::string_view memory);

/// Checks the values that go into the scripts (a partition name, time and memory in Slurm's formats, chunk and
/// tasks per index >= 1): InvalidInput naming the option and the allowed form.
[[nodiscard]] Status checkSlurmParams(const SlurmParams& params);

/// Scripts for the task indices that still have a job not done (jobIsDone), so that resubmitting runs only what is
/// missing or failed. Task index I covers jobs I*K .. I*K+K-1. Empty when every job is done.
[[nodiscard]] Result<std::vector<SlurmScript>> planSlurmScripts(const std::string& batchFolder,
                                                                const Manifest& manifest, const SlurmParams& params);

/// Writes each script atomically (BATCH/slurm/ created).
[[nodiscard]] Status writeSlurmScripts(const std::vector<SlurmScript>& scripts);

/// The cluster's MaxArraySize from `scontrol show config`; std::nullopt when scontrol is missing or says nothing.
std::optional<std::size_t> clusterMaxArraySize();

/// Submits a script with `sbatch --parsable` and returns the Slurm job id; records it in BATCH/slurm/submitted.tsv.
[[nodiscard]] Result<std::string> submitSlurmScript(const std::string& batchFolder, const SlurmScript& script);

/// Slurm job ids submitted for this batch (BATCH/slurm/submitted.tsv), oldest first.
std::vector<std::string> submittedSlurmJobs(const std::string& batchFolder);

/// What sacct says about the array tasks of `jobIds`: state -> count (e.g. "COMPLETED" -> 6). NotFound when sacct is
/// missing; BackendFailure when it fails (e.g. no accounting storage).
[[nodiscard]] Result<std::vector<std::pair<std::string, std::size_t>>>
slurmTaskStates(const std::vector<std::string>& jobIds);

} // namespace hs::batch
