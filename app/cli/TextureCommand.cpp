// `texture synth|bake|quality|exemplars`: exemplar synthesis, baking the maps of a mesh, quality measures, and the
// procedural default exemplars.
#include "CliCommon.h"
#include "Commands.h"

#include "hs/io/MeshIO.h"
#include "hs/texture/Bake.h"
#include "hs/texture/Exemplars.h"
#include "hs/texture/ImageFiles.h"
#include "hs/texture/Quality.h"
#include "hs/texture/Synthesis.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <variant>

namespace hs::cli {
namespace {

struct SynthOptions {
    std::string exemplar;
    std::string tissue;
    std::string output;
    int size = 1024;
    std::uint64_t seed = 1;
    int threads = 0;
    CommonOptions common;
};

struct BakeOptions {
    std::string mesh;
    std::string outDir;
    int size = 2048;
    std::uint64_t seed = 1;
    int threads = 0;
    std::string label = "region";
    std::vector<std::int32_t> myoma;
    std::vector<std::int32_t> polyp;
    std::string canalLabel = "tissue";
    std::vector<std::int32_t> canal;
    std::string exemplarEndometrium, exemplarMyoma, exemplarPolyp, exemplarCanal;
    bool noVessels = false;
    std::string endometrium = "proliferative";
    CommonOptions common;
};

struct QualityOptions {
    std::string exemplar;
    std::string image;
    std::uint64_t seed = 1;
    CommonOptions common;
};

struct ExemplarOptions {
    std::string outDir;
    int size = 256;
    std::uint64_t seed = 1;
};

Result<texture::Appearance> appearanceFromName(const std::string& name) {
    for (texture::Appearance a : texture::kAppearances)
        if (texture::appearanceName(a) == name)
            return a;
    return fail(ErrorCode::InvalidInput,
                "--tissue '" + name + "': expected endometrium, myoma, polyp or cervical-canal");
}

Result<ImageU8> loadExemplar(const SynthOptions& o) {
    if (!o.exemplar.empty()) {
        texture::ImageReadLimits limits;
        limits.minSide = texture::SynthesisParams::kMinExemplarSide;
        limits.maxSide = texture::SynthesisParams::kMaxExemplarSide;
        return texture::readImageRgb8(o.exemplar, limits);
    }
    auto a = appearanceFromName(o.tissue.empty() ? "endometrium" : o.tissue);
    if (!a.ok())
        return a.failure();
    return texture::makeExemplar(*a, 256, o.seed);
}

void printTimings(const StageTimings& timings) {
    for (const auto& step : timings.steps) {
        std::cout << "  " << std::left << std::setw(14) << step.name << std::right << std::fixed << std::setprecision(3)
                  << step.seconds << " s";
        for (const auto& [name, count] : step.counts)
            std::cout << "  " << name << "=" << count;
        std::cout << '\n';
    }
}

nlohmann::ordered_json timingsJson(const StageTimings& timings) {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    for (const auto& step : timings.steps)
        j[step.name] = step.seconds;
    return j;
}

int runSynth(const SynthOptions& o) {
    auto exemplar = loadExemplar(o);
    if (!exemplar.ok())
        return reportError("texture synth", exemplar.error());
    texture::SynthesisParams params;
    params.width = params.height = o.size;
    params.seed = o.seed;
    params.threads = o.threads;
    auto result = texture::synthesizeTexture(*exemplar, params);
    if (!result.ok())
        return reportError("texture synth", result.error());
    if (auto written = texture::writeImage(result->image, o.output); !written.ok())
        return reportError("texture synth", written.error());
    const double seconds = result->timings.totalSeconds();
    if (o.common.json) {
        nlohmann::ordered_json j;
        j["output"] = o.output;
        j["size"] = o.size;
        j["seed"] = o.seed;
        j["levels"] = result->levels;
        j["seconds"] = seconds;
        printJson(std::cout, j);
    } else {
        std::cout << "wrote " << o.output << " (" << o.size << " x " << o.size << ", " << result->levels << " levels, "
                  << std::fixed << std::setprecision(2) << seconds << " s)\n";
        if (o.common.verbose)
            printTimings(result->timings);
    }
    return kExitOk;
}

Result<SurfaceMesh> loadSurface(const std::string& path) {
    auto mesh = io::readMesh(path);
    if (!mesh.ok())
        return mesh.failure();
    if (auto* tets = std::get_if<TetMesh>(&*mesh))
        return extractBoundary(*tets);
    return std::get<SurfaceMesh>(std::move(*mesh));
}

int runBake(const BakeOptions& o) {
    auto surface = loadSurface(o.mesh);
    if (!surface.ok())
        return reportError("texture bake", surface.error());
    texture::BakeParams params;
    params.size = o.size;
    params.seed = o.seed;
    params.threads = o.threads;
    params.vessels = !o.noVessels;
    for (const texture::EndometrialState state : texture::kEndometrialStates)
        if (texture::endometrialStateName(state) == o.endometrium)
            params.endometrium = state;
    params.labels.appearanceLabel = o.label;
    params.labels.myomaValues = o.myoma;
    params.labels.polypValues = o.polyp;
    params.labels.canalLabel = o.canalLabel;
    params.labels.canalValues = o.canal;
    params.exemplarFiles = {o.exemplarEndometrium, o.exemplarMyoma, o.exemplarPolyp, o.exemplarCanal};
    auto result = texture::bakeAppearance(*surface, params);
    if (!result.ok())
        return reportError("texture bake", result.error());
    if (auto written = texture::writeBakeOutputs(*surface, *result, o.outDir); !written.ok())
        return reportError("texture bake", written.error());
    const auto& s = result->stats;
    if (o.common.json) {
        nlohmann::ordered_json j;
        j["output"] = o.outDir;
        j["size"] = o.size;
        j["seed"] = o.seed;
        j["vertices"] = surface->points.size();
        j["faces"] = surface->triangles.size();
        j["charts"] = s.atlas.charts;
        j["l2Stretch"] = s.atlas.l2Stretch;
        j["maxStretch"] = s.atlas.maxStretch;
        j["texelsPerMm"] = s.atlas.texelsPerMm;
        j["fill"] = s.atlas.fill;
        j["coveredTexels"] = s.coveredTexels;
        j["facesWithoutTexels"] = s.facesWithoutTexels;
        j["chartSeamRatio"] = s.chartSeamRatio;
        j["normalSeamRatio"] = s.normalSeams.ratio;
        j["normalSeamP95Deg"] = s.normalSeams.p95Deg;
        j["facesPerClass"] = s.facesPerClass;
        j["vesselSegments"] = s.vesselSegments;
        j["seconds"] = result->timings.totalSeconds();
        j["timings"] = timingsJson(result->timings);
        printJson(std::cout, j);
        return kExitOk;
    }
    std::cout << std::fixed << std::setprecision(3);
    std::cout << "wrote " << o.outDir << " (albedo, normal, roughness " << o.size << "^2; surface.vtp, surface.obj)\n"
              << "surface     " << surface->points.size() << " vertices, " << surface->triangles.size() << " faces ("
              << s.facesPerClass[0] << " endometrium, " << s.facesPerClass[1] << " myoma, " << s.facesPerClass[2]
              << " polyp, " << s.facesPerClass[3] << " cervical canal)\n"
              << "atlas       " << s.atlas.charts << " charts, L2 stretch " << s.atlas.l2Stretch << ", max "
              << s.atlas.maxStretch << ", " << s.atlas.texelsPerMm << " texels/mm, fill " << s.atlas.fill
              << ", padding " << s.atlas.padding << '\n'
              << "coverage    " << s.coveredTexels << " texels, " << s.facesWithoutTexels
              << " faces without own texel\n"
              << "seams       chart seam ratio " << s.chartSeamRatio << " (<= 1: no more visible than a texel step)\n"
              << "            normal map across the seams: p95 " << s.normalSeams.p95Deg << " deg, ratio "
              << s.normalSeams.ratio << " (<= 1: turns no more than a texel into a face)\n"
              << "vessels     " << s.vesselSegments << " segments\n"
              << "time        " << result->timings.totalSeconds() << " s\n";
    if (o.common.verbose)
        printTimings(result->timings);
    for (const auto& w : result->warnings)
        std::cout << "warning: " << w << '\n';
    return kExitOk;
}

int runQuality(const QualityOptions& o) {
    auto exemplar = texture::readImageRgb8(o.exemplar);
    if (!exemplar.ok())
        return reportError("texture quality", exemplar.error());
    auto image = texture::readImageRgb8(o.image);
    if (!image.ok())
        return reportError("texture quality", image.error());
    auto q = texture::measureSynthesis(*exemplar, *image, o.seed);
    if (!q.ok())
        return reportError("texture quality", q.error());
    if (o.common.json) {
        nlohmann::ordered_json j;
        j["exemplar"] = o.exemplar;
        j["image"] = o.image;
        j["histogramDistance"] = q->histogram;
        j["cropHistogramDistance"] = q->cropHistogram;
        j["histogramRatio"] = q->histogramRatio;
        j["gramDistance"] = q->gram;
        j["nearestPatchRms"] = q->nearestPatch;
        j["tileSeamRatio"] = q->tileSeam;
        j["exemplarTileSeamRatio"] = q->exemplarTileSeam;
        printJson(std::cout, j);
        return kExitOk;
    }
    std::cout << std::fixed << std::setprecision(4) << "histogram distance      " << q->histogram
              << "  (random half-size crops of the exemplar: " << q->cropHistogram << ", ratio " << q->histogramRatio
              << ")\n"
              << "Gram distance           " << q->gram << "  (filter-bank statistics, relative)\n"
              << "nearest-patch RMS       " << q->nearestPatch << "  (7x7 patches, 0..255)\n"
              << "tile seam ratio         " << q->tileSeam << "  (exemplar itself: " << q->exemplarTileSeam
              << "; about 1 = seamless)\n";
    return kExitOk;
}

int runExemplars(const ExemplarOptions& o) {
    std::error_code ec;
    std::filesystem::create_directories(o.outDir, ec);
    if (ec)
        return reportError("texture exemplars", Error{ErrorCode::IoError, o.outDir + ": " + ec.message()});
    for (texture::Appearance a : texture::kAppearances) {
        auto image = texture::makeExemplar(a, o.size, o.seed);
        if (!image.ok())
            return reportError("texture exemplars", image.error());
        const std::string path = (std::filesystem::path(o.outDir) / (texture::appearanceName(a) + ".png")).string();
        if (auto written = texture::writeImage(*image, path); !written.ok())
            return reportError("texture exemplars", written.error());
        std::cout << "wrote " << path << '\n';
    }
    // The endometrium's other states (proliferative is endometrium.png).
    for (const texture::EndometrialState state : texture::kEndometrialStates) {
        if (state == texture::EndometrialState::Proliferative)
            continue;
        auto image = texture::makeExemplar(texture::Appearance::Endometrium, o.size, o.seed, state);
        if (!image.ok())
            return reportError("texture exemplars", image.error());
        const std::string path =
            (std::filesystem::path(o.outDir) / ("endometrium-" + texture::endometrialStateName(state) + ".png"))
                .string();
        if (auto written = texture::writeImage(*image, path); !written.ok())
            return reportError("texture exemplars", written.error());
        std::cout << "wrote " << path << '\n';
    }
    return kExitOk;
}

} // namespace

void addTextureCommand(CLI::App& app, int& exitCode) {
    auto* texture = app.add_subcommand("texture", "Texture synthesis, baking of the maps of a mesh, quality measures");
    texture->require_subcommand(1);

    auto synth = std::make_shared<SynthOptions>();
    auto* s = texture->add_subcommand("synth", "Synthesize a tileable texture from an exemplar image");
    auto* ex = s->add_option("--exemplar", synth->exemplar, "exemplar image (PNG, JPEG, EXR; sides 16..4096)");
    s->add_option("--tissue", synth->tissue,
                  "procedural default exemplar instead: endometrium, myoma, polyp, cervical-canal")
        ->excludes(ex);
    s->add_option("-o,--output", synth->output, "output image (.png .jpg .exr .tif)")->required();
    s->add_option("--size", synth->size, "output side in pixels (16..8192)")->capture_default_str();
    s->add_option("--seed", synth->seed, "random seed")->capture_default_str();
    s->add_option("--threads", synth->threads, "worker threads (0: all cores; the result does not depend on it)");
    s->add_flag("--json", synth->common.json, "print JSON for scripts");
    s->add_flag("-v,--verbose", synth->common.verbose, "per-level timings");
    s->callback([synth, &exitCode] { exitCode = runSynth(*synth); });

    auto bake = std::make_shared<BakeOptions>();
    auto* b = texture->add_subcommand("bake", "UV atlas and albedo/normal/roughness maps of a mesh's surface");
    b->add_option("--mesh", bake->mesh, "tetrahedral mesh (.vtu .msh .mesh; its boundary is textured) or surface")
        ->required();
    b->add_option("-o,--output", bake->outDir, "output folder")->required();
    b->add_option("--size", bake->size, "map side in texels (64..8192)")->capture_default_str();
    b->add_option("--seed", bake->seed, "random seed")->capture_default_str();
    b->add_option("--threads", bake->threads, "worker threads (0: all cores; the maps do not depend on it)");
    b->add_option("--label", bake->label, "face label naming the tissue of each face")->capture_default_str();
    b->add_option("--myoma", bake->myoma, "values of --label that are myoma (e.g. --myoma 1 2)");
    b->add_option("--polyp", bake->polyp, "values of --label that are polyp");
    b->add_option("--canal-label", bake->canalLabel, "face label saying which faces line the cervical canal")
        ->capture_default_str();
    b->add_option("--canal", bake->canal, "values of --canal-label that are the cervical canal (e.g. --canal 3)");
    b->add_option("--exemplar-endometrium", bake->exemplarEndometrium, "exemplar image for the endometrium");
    b->add_option("--exemplar-myoma", bake->exemplarMyoma, "exemplar image for myomas");
    b->add_option("--exemplar-polyp", bake->exemplarPolyp, "exemplar image for polyps");
    b->add_option("--exemplar-canal", bake->exemplarCanal, "exemplar image for the cervical canal");
    b->add_flag("--no-vessels", bake->noVessels, "do not grow vessels");
    b->add_option("--endometrium", bake->endometrium, "the endometrium's look: the cycle phase or atrophic")
        ->check(CLI::IsMember({"proliferative", "secretory", "menstrual", "atrophic"}))
        ->capture_default_str();
    b->add_flag("--json", bake->common.json, "print JSON for scripts");
    b->add_flag("-v,--verbose", bake->common.verbose, "per-step timings");
    b->callback([bake, &exitCode] { exitCode = runBake(*bake); });

    auto quality = std::make_shared<QualityOptions>();
    auto* q = texture->add_subcommand("quality", "Histogram, local-statistics and seam measures of a synthesis");
    q->add_option("--exemplar", quality->exemplar, "the exemplar image")->required();
    q->add_option("--image", quality->image, "the synthesized image")->required();
    q->add_option("--seed", quality->seed, "seed of the random crops and patch samples")->capture_default_str();
    q->add_flag("--json", quality->common.json, "print JSON for scripts");
    q->callback([quality, &exitCode] { exitCode = runQuality(*quality); });

    auto exemplars = std::make_shared<ExemplarOptions>();
    auto* e = texture->add_subcommand("exemplars", "Write the procedural default exemplars (endometrium, myoma, polyp, "
                                                   "cervical canal; "
                                                   "the endometrium's secretory, menstrual and atrophic looks)");
    e->add_option("-o,--output", exemplars->outDir, "output folder")->required();
    e->add_option("--size", exemplars->size, "side in pixels (32..4096)")->capture_default_str();
    e->add_option("--seed", exemplars->seed, "random seed")->capture_default_str();
    e->callback([exemplars, &exitCode] { exitCode = runExemplars(*exemplars); });
}

} // namespace hs::cli
