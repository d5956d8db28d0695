// `generate CASE.json -o SCENE`: the whole pipeline into a scene package, with a progress bar and per-stage timings;
// --variants N makes N scenes with derived seeds. The export itself (the chain, the package written, read back and
// swept by the scope) is hs::generate::exportScenes, as in the workstation and a batch job; this file holds the
// options, the progress printing and the report.
#include "CliCommon.h"
#include "Commands.h"

#include "hs/core/Timings.h"
#include "hs/generate/Export.h"
#include "hs/generate/Generate.h"
#include "hs/scene/Scene.h"
#include "hs/scene/ScenePackage.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <mutex>
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
    generate::ExportedPackage package; ///< where it went, its error, timings, warnings and scope verdict
    std::size_t vertices = 0;
    std::size_t tets = 0;
    scene::MeshQuality quality;
    std::vector<scene::PathologyDescriptor> pathologies;
    scene::OrganDimensions organ;
    double liningAskedMm = 0.0;  ///< mm, one wall's endometrium as the case asks for it
    double liningMeshedMm = 0.0; ///< mm, the endometrium's volume per lining area (docs/anatomy.md)
    double endometriumMl = 0.0;  ///< mL
    double cervixMl = 0.0;       ///< mL
};

/// What the report needs of a variant's results (the results themselves are freed once it is written).
void summarise(const scene::CaseSpec& spec, const generate::Generated& generated, VariantReport& report) {
    const scene::Scene& s = *generated.scene;
    report.vertices = s.tets.points.size();
    report.tets = s.tets.tets.size();
    report.quality = s.quality;
    report.pathologies = s.clinical.pathologies;
    report.organ = s.clinical.organ;
    const auto& layers = generated.tissue->layers;
    report.liningAskedMm = generate::tissueLayerParamsFor(spec).endometriumThicknessMm;
    report.liningMeshedMm = layers.endometriumVolumePerLiningAreaMm();
    report.endometriumMl = layers.endometriumVolumeMm3 / 1000.0;
    report.cervixMl = layers.cervixVolumeMm3 / 1000.0;
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

nlohmann::ordered_json scopeJson(const generate::ScopeVerdict& scope) {
    if (!scope.checked)
        return {{"checked", false}, {"reason", scope.uncheckedBecause}};
    return {{"checked", true},
            {"scopeDiameterMm", scope.scopeDiameterMm},
            {"passes", scope.passes},
            {"canalNarrowestMm", scope.canalNarrowestMm},
            {"reachesFundus", scope.reachesFundus},
            {"narrowestMm", scope.narrowestMm}};
}

nlohmann::ordered_json reportJson(const VariantReport& r) {
    const generate::ExportedPackage& package = r.package;
    nlohmann::ordered_json j;
    j["variant"] = package.index;
    j["seed"] = package.seed;
    j["folder"] = package.folder;
    j["ok"] = !package.error.has_value();
    if (package.error) {
        j["error"] = {{"code", std::string(errorCodeKey(package.error->code))}, {"detail", package.error->detail}};
        return j;
    }
    if (!package.zipPath.empty())
        j["zip"] = package.zipPath;
    j["files"] = package.files;
    auto steps = nlohmann::ordered_json::array();
    for (const auto& s : package.timings.steps)
        steps.push_back({{"stage", s.name}, {"seconds", s.seconds}});
    j["timings"] = steps;
    j["seconds"] = package.timings.totalSeconds();
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
    j["scope"] = scopeJson(package.scope);
    j["warnings"] = package.warnings;
    return j;
}

void printReport(const VariantReport& r) {
    const generate::ExportedPackage& package = r.package;
    if (package.error) {
        std::printf("variant %zu (seed %llu): failed: %s\n", package.index,
                    static_cast<unsigned long long>(package.seed), package.error->message().c_str());
        return;
    }
    std::printf("wrote       %s (seed %llu), %zu files read back with matching checksums%s\n", package.folder.c_str(),
                static_cast<unsigned long long>(package.seed), package.files,
                package.zipPath.empty() ? "" : ", and its .zip");
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
    if (!package.scope.checked)
        std::printf("scope       not checked: %s\n", package.scope.uncheckedBecause.c_str());
    else
        std::printf("scope       a %.1f mm scope %s the cervical canal (narrowest %.2f mm) and %s the fundus "
                    "(narrowest %.2f mm)\n",
                    package.scope.scopeDiameterMm, package.scope.passes ? "passes" : "does not pass",
                    package.scope.canalNarrowestMm, package.scope.reachesFundus ? "reaches" : "does not reach",
                    package.scope.narrowestMm);
    std::printf("timings    ");
    for (const auto& s : package.timings.steps)
        std::printf(" %s %.2f s,", s.name.c_str(), s.seconds);
    std::printf(" total %.2f s\n", package.timings.totalSeconds());
    for (const auto& w : package.warnings)
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
    scene::CaseSpec spec = *loaded;
    spec.seed = options.seed.value_or(loaded->seed);
    const auto n = static_cast<std::size_t>(options.variants);
    std::vector<VariantReport> reports(n);

    generate::GenerateParams generateParams;
    generateParams.caseFile = options.casePath;
    generateParams.threads = options.threads;
    generate::ExportParams params;
    params.folder = options.output;
    params.variants = n;
    params.jobs = static_cast<std::size_t>(std::max(options.jobs, 1));
    params.zip = options.zip;
    params.formats = options.packageFormats;
    ProgressPrinter printer(n, options.common.json);
    params.variantProgress = [&printer](std::size_t i, std::string_view stage, double f) {
        printer.update(i, stage, f);
    };
    params.onExported = [&reports, &spec](const generate::ExportedPackage& p, const generate::Generated& generated) {
        summarise(spec, generated, reports[p.index]);
    };
    auto exported = generate::exportScenes(spec, generateParams, params);
    printer.finish();
    if (!exported)
        return reportError("generate", exported.error());
    for (std::size_t i = 0; i < n; ++i)
        reports[i].package = std::move((*exported)[i]);

    int exitCode = kExitOk;
    for (const auto& r : reports)
        if (r.package.error && exitCode == kExitOk)
            exitCode = exitCodeFor(*r.package.error);
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
            if (r.package.error)
                reportError("generate", Error{r.package.error->code, "variant " + std::to_string(r.package.index) +
                                                                         ": " + r.package.error->detail});
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
