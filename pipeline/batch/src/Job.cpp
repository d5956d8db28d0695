// runJob: one job of a plan, idempotent, locked, with its status record.
#include "hs/batch/Job.h"

#include "hs/generate/Assembly.h"
#include "hs/generate/Export.h"
#include "hs/generate/Generate.h"
#include "hs/scene/CaseSpec.h"
#include "hs/scene/ScenePackage.h"
#include "hs/scene/Sha256.h"

#include <chrono>
#include <exception>
#include <fcntl.h>
#include <filesystem>
#include <sys/file.h>
#include <sys/resource.h>
#include <unistd.h>

namespace hs::batch {

namespace {

namespace fs = std::filesystem;

/// An exclusive, non-blocking flock on a file; released when the object dies (or the process does).
class JobLock {
public:
    explicit JobLock(const std::string& path) {
        m_fd = ::open(path.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
        if (m_fd >= 0 && ::flock(m_fd, LOCK_EX | LOCK_NB) != 0) {
            ::close(m_fd);
            m_fd = -1;
        }
    }
    ~JobLock() {
        if (m_fd >= 0)
            ::close(m_fd);
    }
    JobLock(const JobLock&) = delete;
    JobLock& operator=(const JobLock&) = delete;
    bool held() const { return m_fd >= 0; }

private:
    int m_fd = -1;
};

Result<std::string> manifestSha256(const std::string& packageFolder) {
    auto digest = scene::sha256File((fs::path(packageFolder) / std::string(scene::kManifestName)).string(),
                                    scene::PackageReadLimits{}.maxManifestBytes);
    if (!digest)
        return digest.failure();
    return digest->sha256;
}

/// The folders a job reads from and writes into must be real folders inside the batch folder: a symbolic link
/// planted there would lead the job's writes elsewhere.
Status checkFolders(const std::string& batchFolder) {
    for (std::string_view sub : {kCasesFolder, kPackagesFolder, kStatusFolder}) {
        const fs::path path = batchPath(batchFolder, sub);
        std::error_code ec;
        const fs::file_status status = fs::symlink_status(path, ec);
        if (ec || status.type() != fs::file_type::directory)
            return fail(ErrorCode::InvalidInput, path.string() + ": not a folder (a batch folder's " +
                                                     std::string(sub) + "/ must be a real folder, not a link)");
    }
    return {};
}

/// "name version, name version, ..." in name order.
std::string toolsText(const LibraryVersions& versions) {
    std::string text;
    for (const auto& [name, version] : versions)
        text += (text.empty() ? "" : ", ") + name + " " + version;
    return text;
}

/// An ok record for a package that is already complete and valid, and was made from this job's case and tools.
std::optional<StatusRecord> adoptExistingPackage(const std::string& batchFolder, const Job& job, const JobKey& key) {
    const std::string output = batchPath(batchFolder, job.output);
    std::error_code ec;
    if (!fs::exists(fs::path(output) / std::string(scene::kManifestName), ec))
        return std::nullopt;
    auto manifest = scene::verifyScenePackage(output);
    if (!manifest || toolsText(manifest->toolVersions) != key.tools)
        return std::nullopt;
    auto packaged = scene::sha256File((fs::path(output) / "case.json").string(), scene::kMaxCaseFileBytes);
    if (!packaged || packaged->sha256 != key.caseSha256)
        return std::nullopt;
    auto sha = manifestSha256(output);
    if (!sha)
        return std::nullopt;
    StatusRecord record;
    record.state = JobState::Ok;
    record.reused = true;
    record.packageManifestSha256 = *sha;
    return record;
}

SceneSummary summarise(const generate::Generated& generated) {
    const scene::Scene& s = *generated.scene;
    SceneSummary summary;
    summary.organLengthMm = s.clinical.organ.lengthMm;
    summary.organWidthMm = s.clinical.organ.widthMm;
    summary.organApMm = s.clinical.organ.apMm;
    summary.uterineVolumeMl = s.clinical.organ.uterineVolumeMl;
    summary.vertices = s.tets.points.size();
    summary.tetrahedra = s.tets.tets.size();
    summary.meanRadiusRatio = s.quality.meanRadiusRatio;
    summary.minDihedralDeg = s.quality.minDihedralDeg;
    summary.slivers = s.quality.sliverCount;
    for (const scene::PathologyDescriptor& p : s.clinical.pathologies)
        summary.pathologies.push_back({p.id, std::string(clinical::toString(p.kind)), p.sizeMm,
                                       p.figo ? p.figo->toString() : std::string(), p.lasmar ? p.lasmar->total() : -1});
    for (const StepTiming& step : generated.timings.steps)
        summary.stageSeconds.emplace_back(step.name, step.seconds);
    summary.warnings = s.warnings;
    return summary;
}

/// Generates the package and fills the ok part of `record`.
Status generatePackage(const std::string& batchFolder, const Job& job, const RunJobParams& params, StatusRecord& record,
                       Progress& progress) {
    HS_TRY(checkFolders(batchFolder));
    const std::string caseFile = batchPath(batchFolder, job.caseFile);
    auto spec = scene::loadCase(caseFile);
    if (!spec)
        return spec.failure();
    spec->seed = job.seed;
    generate::GenerateParams generateParams;
    generateParams.caseFile = caseFile;
    generateParams.threads = params.threads;
    generate::ExportParams exportParams;
    const std::string output = batchPath(batchFolder, job.output);
    exportParams.folder = output;
    exportParams.onExported = [&record](const generate::ExportedPackage& package, generate::Generated&& generated) {
        record.scene = summarise(generated);
        if (package.scope.checked) {
            record.scene->scopePasses = package.scope.passes;
            record.scene->scopeNarrowestMm = package.scope.canalNarrowestMm;
        }
    };
    auto exported = generate::exportScenes(*spec, generateParams, exportParams, progress);
    if (!exported)
        return exported.failure();
    HS_TRY(generate::firstFailure(*exported));
    auto sha = manifestSha256(output);
    if (!sha)
        return sha.failure();
    record.packageManifestSha256 = *sha;
    return {};
}

} // namespace

std::string lockPath(const std::string& batchFolder, const std::string& job) {
    return batchPath(batchFolder, std::string(kStatusFolder) + "/" + job + ".lock");
}

bool jobIsLocked(const std::string& batchFolder, const std::string& job) {
    std::error_code ec;
    if (!fs::exists(lockPath(batchFolder, job), ec))
        return false;
    return !JobLock(lockPath(batchFolder, job)).held();
}

double peakMemoryMb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0; // Linux reports kB
}

Result<JobKey> jobKey(const std::string& batchFolder, const Job& job) {
    auto spec = scene::loadCase(batchPath(batchFolder, job.caseFile));
    if (!spec)
        return spec.failure();
    spec->seed = job.seed;
    return JobKey{scene::sha256Hex(scene::toJson(*spec)), toolsText(generate::toolVersionsFor(*spec))};
}

DoneCheck checkJobDone(const std::string& batchFolder, const Job& job) {
    DoneCheck check;
    if (auto key = jobKey(batchFolder, job))
        check.key = std::move(key).value();
    auto record = readStatus(batchFolder, job.name);
    if (!record || !*record || (*record)->state != JobState::Ok || (*record)->seed != job.seed)
        return check;
    const StatusRecord& ok = **record;
    const std::optional<JobKey>& key = check.key;
    if (!key)
        return check; // the job runs and records why its case cannot be read
    if (ok.caseSha256.empty())
        check.rerunReason = "its status record predates content keys (status schema version 1)";
    else if (ok.caseSha256 != key->caseSha256)
        check.rerunReason = "its case was edited after its package was written";
    else if (ok.tools != key->tools)
        check.rerunReason =
            "the tools changed since its package was written (was: " + ok.tools + "; now: " + key->tools + ")";
    if (!check.rerunReason.empty())
        return check;
    auto sha = manifestSha256(batchPath(batchFolder, job.output));
    check.done = sha && *sha == ok.packageManifestSha256;
    return check;
}

StatusRecord recordOf(const Job& job, JobState state) {
    StatusRecord record;
    record.job = job.name;
    record.index = job.index;
    record.seed = job.seed;
    record.output = job.output;
    record.state = state;
    return record;
}

bool jobIsDone(const std::string& batchFolder, const Job& job) {
    return checkJobDone(batchFolder, job).done;
}

JobRun runJob(const std::string& batchFolder, const Job& job, const RunJobParams& params, Progress& progress) {
    JobRun run;
    const JobLock lock(lockPath(batchFolder, job.name));
    if (!lock.held()) {
        run.action = JobAction::Busy;
        return run;
    }
    const auto start = std::chrono::steady_clock::now();
    StatusRecord& record = run.record;
    const DoneCheck done = checkJobDone(batchFolder, job);
    if (done.done) {
        run.action = JobAction::Skipped;
        record = **readStatus(batchFolder, job.name);
        return run;
    }
    run.rerunReason = done.rerunReason;
    const std::optional<JobKey>& key = done.key;
    // A package already in place is adopted only when its own case.json and tool versions are the job's now.
    std::optional<StatusRecord> adopted = key ? adoptExistingPackage(batchFolder, job, *key) : std::nullopt;
    if (adopted) {
        run.action = JobAction::Skipped;
        record = std::move(*adopted);
    } else {
        run.action = JobAction::Generated;
        record.state = JobState::Ok;
        Status status;
        try {
            status = generatePackage(batchFolder, job, params, record, progress);
        } catch (const std::exception& e) { // e.g. std::bad_alloc: recorded, never thrown to the runner
            status = fail(ErrorCode::Internal, std::string("unexpected exception: ") + e.what());
        }
        if (!status.ok()) {
            record.state = JobState::Failed;
            record.error = status.error();
            record.scene.reset();
        }
    }
    record.job = job.name;
    record.index = job.index;
    record.seed = job.seed;
    record.output = job.output;
    if (key) {
        record.caseSha256 = key->caseSha256;
        record.tools = key->tools;
    }
    record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    record.peakMemoryMb = peakMemoryMb();
    record.host = hostName();
    record.finishedUtc = utcNow();
    if (auto written = writeStatus(batchFolder, record); !written) {
        record.state = JobState::Failed;
        record.error = written.error();
    }
    return run;
}

} // namespace hs::batch
