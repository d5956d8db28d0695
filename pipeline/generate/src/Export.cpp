#include "hs/generate/Export.h"

#include "hs/scene/ScopePassage.h"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <mutex>
#include <thread>

namespace hs::generate {
namespace {

namespace fs = std::filesystem;

/// Upper bounds of the parameters, as `generate --variants/--jobs` take them.
constexpr std::size_t kMaxVariants = 10000;
constexpr std::size_t kMaxJobs = 256;

ScopeVerdict sweepScope(const scene::Scene& scene, Progress& progress, Status& status) {
    ScopeVerdict verdict;
    const scene::ScopePassageParams params;
    verdict.scopeDiameterMm = params.scopeDiameterMm;
    auto landmarks = scene::findScopeLandmarks(scene);
    if (!landmarks) {
        verdict.uncheckedBecause = landmarks.error().detail;
        return verdict;
    }
    auto passage = scene::checkScopePassage(scene.tets, *landmarks, params, progress);
    if (!passage) {
        if (passage.error().code == ErrorCode::Cancelled)
            status = passage.failure();
        verdict.uncheckedBecause = passage.error().detail;
        return verdict;
    }
    verdict.checked = true;
    verdict.passes = passage->canalPasses;
    verdict.canalNarrowestMm = passage->narrowestCanal.freeWidthMm;
    verdict.reachesFundus = passage->ballPasses;
    verdict.narrowestMm = passage->narrowest.freeWidthMm;
    return verdict;
}

/// Generates, writes and checks one package; fills `out` (its error too).
Status exportOne(const scene::CaseSpec& variant, const GenerateParams& generateParams, const ExportParams& params,
                 Progress& progress, ExportedPackage& out) {
    Generated base;
    if (params.variants == 1 && params.previous)
        base = *params.previous;
    else
        base.spec = variant;
    auto generateSub = progress.sub(0.0, 0.8);
    auto generated = updateThrough(Stage::Scene, std::move(base), variant, generateParams, generateSub);
    if (!generated)
        return generated.failure();
    out.timings = generated->timings;
    const scene::Scene& scene = *generated->scene;
    out.warnings = scene.warnings;
    {
        ScopedStepTimer timer(out.timings, "package");
        auto writeSub = progress.sub(0.8, 0.9);
        auto written = scene::writeScenePackage(scene, out.folder, params.formats, writeSub);
        if (!written)
            return written.failure();
        auto verified = scene::verifyScenePackage(out.folder);
        if (!verified)
            return verified.failure();
        out.files = verified->files.size();
        if (params.zip) {
            out.zipPath = out.folder + ".zip";
            HS_TRY(scene::zipScenePackage(out.folder, out.zipPath));
        }
    }
    HS_TRY(progress.check("export", "writing the package"));
    if (params.checkScope) {
        ScopedStepTimer timer(out.timings, "scope");
        auto scopeSub = progress.sub(0.9, 1.0);
        Status status;
        out.scope = sweepScope(scene, scopeSub, status);
        HS_TRY(status);
    }
    progress.report("done", 1.0);
    if (params.onExported)
        params.onExported(out, std::move(generated).value());
    return {};
}

} // namespace

Result<std::vector<ExportedPackage>> exportScenes(const scene::CaseSpec& spec, const GenerateParams& generateParams,
                                                  const ExportParams& params, Progress& progress) {
    if (params.folder.empty())
        return fail(ErrorCode::InvalidInput, "export: no folder given for the package");
    if (params.variants < 1 || params.variants > kMaxVariants)
        return fail(ErrorCode::InvalidInput, "export: variants " + std::to_string(params.variants) +
                                                 " is out of range (1 to " + std::to_string(kMaxVariants) + ")");
    if (params.jobs < 1 || params.jobs > kMaxJobs)
        return fail(ErrorCode::InvalidInput, "export: jobs " + std::to_string(params.jobs) + " is out of range (1 to " +
                                                 std::to_string(kMaxJobs) + ")");
    const std::size_t n = params.variants;
    std::vector<ExportedPackage> packages(n);
    for (std::size_t i = 0; i < n; ++i) {
        packages[i].index = i;
        packages[i].seed = exportSeed(spec.seed, i, n);
        packages[i].folder = n == 1 ? params.folder : (fs::path(params.folder) / variantFolderName(i)).string();
    }
    { // the folder that holds the package (or the variants)
        const fs::path out(params.folder);
        const fs::path holder = n > 1 ? out : out.parent_path();
        std::error_code ec;
        if (!holder.empty())
            fs::create_directories(holder, ec);
        if (ec)
            return fail(ErrorCode::IoError, holder.string() + ": cannot create the folder: " + ec.message());
    }

    // Variants are claimed in order by `jobs` workers; each writes only its own entry of `packages`.
    std::atomic<std::size_t> next{0};
    std::mutex cancelMutex;
    std::optional<Error> cancelled;
    auto worker = [&] {
        for (std::size_t i = next++; i < n; i = next++) {
            ExportedPackage& out = packages[i];
            Progress::Callback observer;
            if (params.variantProgress)
                observer = [&params, i](std::string_view stage, double f) { params.variantProgress(i, stage, f); };
            auto part = progress.sub(double(i) / double(n), double(i + 1) / double(n), observer);
            if (progress.cancelled()) {
                std::lock_guard<std::mutex> lock(cancelMutex);
                cancelled = Error{ErrorCode::Cancelled, "export cancelled"};
                return;
            }
            scene::CaseSpec variant = spec;
            variant.seed = out.seed;
            const Status status = exportOne(variant, generateParams, params, part, out);
            if (!status.ok()) {
                if (status.error().code == ErrorCode::Cancelled) {
                    std::lock_guard<std::mutex> lock(cancelMutex);
                    cancelled = status.error();
                    return;
                }
                out.error = status.error();
            }
        }
    };
    const std::size_t jobs = std::min(params.jobs, n);
    std::vector<std::thread> threads;
    for (std::size_t j = 1; j < jobs; ++j)
        threads.emplace_back(worker);
    worker();
    for (auto& thread : threads)
        thread.join();
    if (cancelled)
        return fail(*cancelled);
    return packages;
}

Status firstFailure(const std::vector<ExportedPackage>& packages) {
    for (const ExportedPackage& p : packages)
        if (p.error) {
            if (packages.size() == 1)
                return fail(*p.error);
            return fail(p.error->code, "variant " + std::to_string(p.index) + ": " + p.error->detail);
        }
    return {};
}

} // namespace hs::generate
