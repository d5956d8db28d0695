#pragma once
/// The one job contract: every engine (the local runner, a Slurm array task, a shell loop) runs a job through
/// runJob(), so they differ only in who calls it (docs/batch.md, "The job contract").
///
/// A job is idempotent: a job whose ok record matches its package's manifest and its content key (JobKey), or whose
/// output already holds a complete, valid package made from the same case and tools, is skipped. The package is written
/// atomically (scene::writeScenePackage), then verified, then the status record is written atomically. A job holds an
/// exclusive lock on BATCH/status/JOB.lock while it runs, so two runners never write the same package; a locked job is
/// reported busy.

#include "hs/batch/JobStatus.h"
#include "hs/batch/Manifest.h"
#include "hs/core/Progress.h"

#include <optional>
#include <string>

namespace hs::batch {

struct RunJobParams {
    std::optional<int> threads; ///< threads per stage instead of the case's meshing.threads; never changes a result
};

enum class JobAction {
    Generated, ///< this call generated the package (record ok) or failed (record failed)
    Skipped,   ///< the package was already complete and valid (record ok, possibly written by this call)
    Busy,      ///< another process holds the job's lock; nothing was written
};

struct JobRun {
    JobAction action = JobAction::Generated;
    StatusRecord record;     ///< the job's record after the call (empty when busy)
    std::string rerunReason; ///< DoneCheck::rerunReason when an ok record was set aside
};

/// What a job's package is made from, so that resuming never keeps a package made from other inputs: the case as the
/// job runs it (its file read, the job's seed put in, written in the case format's canonical form) and the versions
/// of the tools that make the scene (the scene's toolVersions, "hysteroscene 0.1.0, cgal 5.5.1, ...").
struct JobKey {
    std::string caseSha256;
    std::string tools;
};

/// The job's key now; fails when its case file cannot be read (the job itself then fails, naming the problem).
[[nodiscard]] Result<JobKey> jobKey(const std::string& batchFolder, const Job& job);

/// Whether a job is done, and when it has an ok record that no longer stands, why it runs again.
struct DoneCheck {
    bool done = false;
    /// "" unless an ok record exists for a package made from other inputs: "its case was edited after its package
    /// was written", "the tools changed since its package was written (was: ...; now: ...)".
    std::string rerunReason;
    std::optional<JobKey> key; ///< the job's key now; unset when its case cannot be read
};

/// Whether `job` has an ok record made with its key now, whose package manifest still has the recorded checksum (a
/// cheap check, without verifying every file: runJob verified them before it wrote the record).
DoneCheck checkJobDone(const std::string& batchFolder, const Job& job);

/// A record of `job` in `state` with the job's name, index, seed and output filled in.
StatusRecord recordOf(const Job& job, JobState state);

/// Runs `job` of the plan in `batchFolder`. Never fails as a call: every failure (an unreadable case, a pathology
/// that does not fit the drawn organ, an I/O error, an exception) is recorded in the job's status record as
/// failed, with the error, and returned.
JobRun runJob(const std::string& batchFolder, const Job& job, const RunJobParams& params = {},
              Progress& progress = Progress::none());

/// checkJobDone(batchFolder, job).done
bool jobIsDone(const std::string& batchFolder, const Job& job);

/// BATCH/status/JOB.lock, and whether some process holds it now.
std::string lockPath(const std::string& batchFolder, const std::string& job);
bool jobIsLocked(const std::string& batchFolder, const std::string& job);

/// Peak resident memory of this process so far (MiB).
double peakMemoryMb();

} // namespace hs::batch
