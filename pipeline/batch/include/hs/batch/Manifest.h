#pragma once
/// The batch folder and its manifest: one line per job (index, job name, case file, seed, output), written by
/// planBatch() and read, untrusted, by every runner. docs/batch.md describes the folder and the file.
///
///     BATCH/curriculum.json          the curriculum as given (the report compares the draws with it)
///     BATCH/cases/NAME-CCCC.json     one case file per drawn case
///     BATCH/manifest.tsv             the jobs; written last, so a folder with a manifest holds a whole plan
///     BATCH/packages/JOB/            a scene package per job
///     BATCH/status/JOB.json          the status record of a job (hs/batch/JobStatus.h)
///     BATCH/logs/JOB.log             what the job printed (local runner)

#include "hs/batch/Curriculum.h"
#include "hs/core/Result.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hs::batch {

constexpr std::string_view kManifestFile = "manifest.tsv";
constexpr std::string_view kCurriculumFile = "curriculum.json";
constexpr std::string_view kCasesFolder = "cases";
constexpr std::string_view kPackagesFolder = "packages";
constexpr std::string_view kStatusFolder = "status";
constexpr std::string_view kLogsFolder = "logs";
/// First line of a manifest; the second names the columns.
constexpr std::string_view kManifestMagic = "# hysteroscene-batch-manifest 1";
constexpr std::string_view kManifestColumns = "index\tjob\tcase\tseed\toutput";
/// A manifest of kMaxJobs lines stays far below this.
constexpr std::int64_t kMaxManifestBytes = 64 * 1024 * 1024;

struct Job {
    std::size_t index = 0;  ///< line number among the jobs, from 0; the task index runners pass
    std::string name;       ///< unique; "<template>-<case>-v<variant>", e.g. "myoma-0003-v01"
    std::string caseFile;   ///< relative to the batch folder, under cases/
    std::uint64_t seed = 0; ///< replaces the case file's seed
    std::string output;     ///< the package folder, relative to the batch folder, under packages/
};

struct Manifest {
    std::vector<Job> jobs;
};

/// The text of a manifest: the magic line, the column line, one tab-separated line per job.
std::string formatManifest(const Manifest& manifest);

/// Reads a manifest as untrusted text. Refuses (InvalidInput, naming the source, the line and the field): a wrong
/// magic or column line, a line without exactly five fields, an index out of order, a job name that is not
/// [A-Za-z0-9][A-Za-z0-9_-]* (<= 64 bytes) or repeats, a seed that is not an unsigned 64-bit integer, and any path
/// that is absolute, climbs with "..", holds "." or empty components, backslashes or other characters than
/// [A-Za-z0-9._-/], or lies outside its folder (cases/ for cases, packages/ for outputs): such a path escapes the
/// batch folder. Two outputs that are equal (also ignoring case, for file systems that fold it) or nested collide
/// and are refused, naming both lines.
[[nodiscard]] Result<Manifest> parseManifest(std::string_view text, const std::string& sourceName);

/// Reads and parses BATCH/manifest.tsv; NotFound when the folder holds no plan.
[[nodiscard]] Result<Manifest> readManifest(const std::string& batchFolder);

/// BATCH/<relative> as a path string.
std::string batchPath(const std::string& batchFolder, std::string_view relative);

struct PlanResult {
    Manifest manifest;
    std::size_t cases = 0;  ///< case files
    bool unchanged = false; ///< the folder already held this very plan
};

/// Expands `loaded` into `batchFolder` (created when missing): a case file per drawn case (sampleCase), the
/// curriculum text, and the manifest, every file written atomically, the manifest last. Jobs are ordered by
/// template, case and variant; variant v of a case has generate::variantSeed(case seed, v), or the case's own seed
/// when the curriculum asks for one variant, as `generate --variants` does. The same curriculum gives the same
/// bytes. A folder that already holds a different plan is refused (InvalidInput): plan into a new folder.
[[nodiscard]] Result<PlanResult> planBatch(const LoadedCurriculum& loaded, const std::string& curriculumText,
                                           const std::string& batchFolder);

} // namespace hs::batch
