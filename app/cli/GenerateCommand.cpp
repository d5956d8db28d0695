// `generate CASE.json -o SCENE`: the whole pipeline into a scene package, with a progress bar and per-stage timings;
// --variants N makes N scenes with derived seeds. The chain itself is hs::generate::generateScene; this file holds
// the options, the progress printing, the package writing and the report.
#include "CliCommon.h"
#include "Commands.h"

#include "hs/core/Timings.h"
#include "hs/generate/Generate.h"
#include "hs/generate/Seeds.h"
#include "hs/scene/Scene.h"
#include "hs/scene/ScenePackage.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <thread>
#include <unistd.h>

namespace hs::cli {
namespace {

struct GenerateOptions {
    std::string casePath;
    std::string output;
    int variants = 1;
    std::optional<std::uint64_t> seed;
    int jobs = 1;
    std::optional<int> threads;
    bool zip = false;
    std::string formats;                       ///< --formats as given
    scene::PackageWriteOptions packageFormats; ///< parsed from it
    CommonOptions common;
};

struct VariantReport {
    int index = 0;
    std::uint64_t seed = 0;
    std::string folder;
    std::optional<Error> error;
    StageTimings timings;
    std::size_t vertices = 0;
    std::size_t tets = 0;
    scene::MeshQuality quality;
    std::vector<scene::PathologyDescriptor> pathologies;
    scene::OrganDimensions organ;
    std::vector<std::string> warnings;
    double liningAskedMm = 0.0;  ///< mm, one wall's endometrium as the case asks for it
    double liningMeshedMm = 0.0; ///< mm, the endometrium's volume per lining area (docs/anatomy.md)
    double endometriumMl = 0.0;  ///< mL
    double cervixMl = 0.0;       ///< mL
};

/// Generates one variant (`spec` already carries its seed) and writes its package.
Status generateVariant(const scene::CaseSpec& spec, const GenerateOptions& options, VariantReport& report,
                       Progress& progress) {
    auto generateSub = progress.sub(0.0, 0.85);
    generate::GenerateParams params;
    params.caseFile = options.casePath;
    params.threads = options.threads;
    auto generated = generate::generateScene(spec, params, generateSub);
    if (!generated)
        return generated.failure();
    report.timings = generated->timings;
    const scene::Scene& s = *generated->scene;

    auto writeSub = progress.sub(0.85, 1.0);
    {
        ScopedStepTimer timer(report.timings, "package");
        auto written = scene::writeScenePackage(s, report.folder, options.packageFormats, writeSub);
        if (!written)
            return written.failure();
        if (options.zip)
            HS_TRY(scene::zipScenePackage(report.folder, report.folder + ".zip"));
    }
    progress.report("done", 1.0);
    report.vertices = s.tets.points.size();
    report.tets = s.tets.tets.size();
    report.quality = s.quality;
    report.pathologies = s.clinical.pathologies;
    report.organ = s.clinical.organ;
    report.warnings = s.warnings;
    const auto& layers = generated->tissue->layers;
    report.liningAskedMm = generate::tissueLayerParamsFor(spec).endometriumThicknessMm;
    report.liningMeshedMm = layers.endometriumVolumePerLiningAreaMm();
    report.endometriumMl = layers.endometriumVolumeMm3 / 1000.0;
    report.cervixMl = layers.cervixVolumeMm3 / 1000.0;
    return {};
}

/// Terminal progress: one bar over all variants on a terminal, a line per stage change otherwise.
class ProgressPrinter {
public:
    ProgressPrinter(std::size_t variants, bool quiet)
        : m_fractions(variants, 0.0), m_quiet(quiet), m_tty(isatty(STDERR_FILENO) != 0) {}

    void update(std::size_t variant, std::string_view stage, double fraction) {
        if (m_quiet)
            return;
        std::lock_guard<std::mutex> lock(m_mutex);
        m_fractions[variant] = fraction;
        double total = 0.0;
        for (double f : m_fractions)
            total += f;
        total /= static_cast<double>(m_fractions.size());
        const int percent = static_cast<int>(total * 100.0);
        const std::string key(stage.substr(0, stage.find('.')));
        if (m_tty) {
            if (percent == m_lastPercent && key == m_lastKey)
                return;
            const int filled = percent * 30 / 100;
            std::fprintf(stderr, "\r[%-30s] %3d%% %-12s", std::string(static_cast<std::size_t>(filled), '#').c_str(),
                         percent, key.c_str());
            std::fflush(stderr);
        } else if (key != m_lastKey) {
            std::fprintf(stderr, "[%3d%%] %s\n", percent, key.c_str());
        }
        m_lastPercent = percent;
        m_lastKey = key;
    }
    void finish() {
        if (!m_quiet && m_tty)
            std::fprintf(stderr, "\n");
    }

private:
    std::mutex m_mutex;
    std::vector<double> m_fractions;
    bool m_quiet;
    bool m_tty;
    int m_lastPercent = -1;
    std::string m_lastKey;
};

nlohmann::ordered_json reportJson(const VariantReport& r) {
    nlohmann::ordered_json j;
    j["variant"] = r.index;
    j["seed"] = r.seed;
    j["folder"] = r.folder;
    j["ok"] = !r.error.has_value();
    if (r.error) {
        j["error"] = {{"code", std::string(errorCodeKey(r.error->code))}, {"detail", r.error->detail}};
        return j;
    }
    auto steps = nlohmann::ordered_json::array();
    for (const auto& s : r.timings.steps)
        steps.push_back({{"stage", s.name}, {"seconds", s.seconds}});
    j["timings"] = steps;
    j["seconds"] = r.timings.totalSeconds();
    j["vertices"] = r.vertices;
    j["tetrahedra"] = r.tets;
    j["quality"] = {{"meanRadiusRatio", r.quality.meanRadiusRatio},
                    {"minDihedralDeg", r.quality.minDihedralDeg},
                    {"slivers", r.quality.sliverCount},
                    {"inverted", r.quality.invertedCount},
                    {"hausdorffRelative", r.quality.hausdorffRelative},
                    {"volumeError", r.quality.volumeError}};
    j["organ"] = {{"lengthMm", r.organ.lengthMm},
                  {"widthMm", r.organ.widthMm},
                  {"apMm", r.organ.apMm},
                  {"uterineVolumeMl", r.organ.uterineVolumeMl}};
    auto pathologies = nlohmann::ordered_json::array();
    for (const auto& p : r.pathologies) {
        nlohmann::ordered_json pj{{"id", p.id}, {"sizeMm", p.sizeMm}, {"volumeMl", p.volumeMl}};
        if (p.figo)
            pj["figo"] = p.figo->toString();
        if (p.lasmar)
            pj["lasmar"] = p.lasmar->total();
        pathologies.push_back(pj);
    }
    j["pathologies"] = pathologies;
    j["tissue"] = {{"endometriumLiningMm", r.liningAskedMm},
                   {"endometriumVolumePerLiningAreaMm", r.liningMeshedMm},
                   {"endometriumMl", r.endometriumMl},
                   {"cervixMl", r.cervixMl}};
    j["warnings"] = r.warnings;
    return j;
}

void printReport(const VariantReport& r) {
    if (r.error) {
        std::printf("variant %d (seed %llu): failed: %s\n", r.index, static_cast<unsigned long long>(r.seed),
                    r.error->message().c_str());
        return;
    }
    std::printf("wrote       %s (seed %llu)\n", r.folder.c_str(), static_cast<unsigned long long>(r.seed));
    std::printf("organ       %.1f x %.1f x %.1f mm (L x W x AP), %.1f mL\n", r.organ.lengthMm, r.organ.widthMm,
                r.organ.apMm, r.organ.uterineVolumeMl);
    for (const auto& p : r.pathologies)
        std::printf("pathology   %-10s %.1f mm, %.2f mL%s%s\n", p.id.c_str(), p.sizeMm, p.volumeMl,
                    p.figo ? (", FIGO " + p.figo->toString()).c_str() : "",
                    p.lasmar ? (", Lasmar " + std::to_string(p.lasmar->total())).c_str() : "");
    std::printf("tissue      endometrium %.2f mL (%.1f mm per lining area, lining asked %.1f mm), cervix %.2f mL\n",
                r.endometriumMl, r.liningMeshedMm, r.liningAskedMm, r.cervixMl);
    std::printf("mesh        %zu vertices, %zu tetrahedra, mean radius ratio %.3f, min dihedral %.1f deg, "
                "%zu slivers\n",
                r.vertices, r.tets, r.quality.meanRadiusRatio, r.quality.minDihedralDeg, r.quality.sliverCount);
    std::printf("timings    ");
    for (const auto& s : r.timings.steps)
        std::printf(" %s %.2f s,", s.name.c_str(), s.seconds);
    std::printf(" total %.2f s\n", r.timings.totalSeconds());
    for (const auto& w : r.warnings)
        std::printf("warning     %s\n", w.c_str());
}

int runGenerate(GenerateOptions& options) {
    auto formats = scene::parsePackageFormats(options.formats);
    if (!formats)
        return reportError("generate", formats.error());
    options.packageFormats = *formats;
    auto loaded = scene::loadCase(options.casePath);
    if (!loaded)
        return reportError("generate", loaded.error());
    const std::uint64_t baseSeed = options.seed.value_or(loaded->seed);
    const auto n = static_cast<std::size_t>(options.variants);
    std::vector<VariantReport> reports(n);
    for (std::size_t i = 0; i < n; ++i) {
        reports[i].index = static_cast<int>(i);
        reports[i].seed = generate::exportSeed(baseSeed, i, n);
        reports[i].folder =
            n == 1 ? options.output : (std::filesystem::path(options.output) / generate::variantFolderName(i)).string();
    }
    { // the folder that will hold the package (or the variants)
        std::error_code ec;
        const std::filesystem::path out(options.output);
        const std::filesystem::path holder = n > 1 ? out : out.parent_path();
        if (!holder.empty())
            std::filesystem::create_directories(holder, ec);
        if (ec)
            return reportError("generate", Error{ErrorCode::IoError, options.output + ": " + ec.message()});
    }

    ProgressPrinter printer(n, options.common.json);
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t i = next++; i < n; i = next++) {
            scene::CaseSpec spec = *loaded;
            spec.seed = reports[i].seed;
            Progress progress([&printer, i](std::string_view stage, double f) { printer.update(i, stage, f); });
            const Status status = generateVariant(spec, options, reports[i], progress);
            if (!status.ok())
                reports[i].error = status.error();
            printer.update(i, "done", 1.0);
        }
    };
    const auto jobs = std::min<std::size_t>(static_cast<std::size_t>(std::max(options.jobs, 1)), n);
    std::vector<std::thread> threads;
    for (std::size_t j = 1; j < jobs; ++j)
        threads.emplace_back(worker);
    worker();
    for (auto& th : threads)
        th.join();
    printer.finish();

    int exitCode = kExitOk;
    for (const auto& r : reports)
        if (r.error && exitCode == kExitOk)
            exitCode = exitCodeFor(*r.error);
    if (options.common.json) {
        nlohmann::ordered_json j;
        j["case"] = options.casePath;
        j["output"] = options.output;
        auto variants = nlohmann::ordered_json::array();
        for (const auto& r : reports)
            variants.push_back(reportJson(r));
        j["variants"] = variants;
        printJson(std::cout, j);
    } else {
        for (const auto& r : reports)
            printReport(r);
        for (const auto& r : reports)
            if (r.error)
                reportError("generate",
                            Error{r.error->code, "variant " + std::to_string(r.index) + ": " + r.error->detail});
    }
    return exitCode;
}

} // namespace

void addGenerateCommand(CLI::App& app, int& exitCode) {
    auto o = std::make_shared<GenerateOptions>();
    auto* sub = app.add_subcommand("generate", "Run the whole pipeline on a case and write the scene package");
    sub->add_option("CASE", o->casePath, "case file")->required();
    sub->add_option("-o,--output", o->output, "scene package folder (with --variants: folder of variant-NNN)")
        ->required();
    sub->add_option("--variants", o->variants, "number of scenes, each with a seed derived from the case's")
        ->check(CLI::Range(1, 10000));
    sub->add_option("--seed", o->seed, "seed instead of the case's");
    sub->add_option("--jobs", o->jobs, "variants generated at the same time")->check(CLI::Range(1, 256));
    sub->add_option("--threads", o->threads, "threads per stage instead of the case's (never changes the result)")
        ->check(CLI::Range(0, 256));
    sub->add_flag("--zip", o->zip, "also write SCENE.zip");
    sub->add_option("--formats", o->formats,
                    "also write formats for other tools: gltf (surface.glb), msh (mesh.msh), obj (surface.obj), sofa "
                    "(scene.scn with mesh.msh and surface.obj), all; comma-separated");
    sub->add_flag("--json", o->common.json, "print a JSON summary (and no progress bar)");
    sub->callback([o, &exitCode] { exitCode = runGenerate(*o); });
}

} // namespace hs::cli
