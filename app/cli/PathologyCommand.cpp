// `pathology --case CASE.json -o DIR`: grows the case's pathologies in its organ, merges them into one multi-region
// body, writes one surface per region plus manifest.json, and prints the descriptors measured from the geometry.
#include "CliCommon.h"
#include "Commands.h"
#include "hs/generate/CaseStages.h"

#include "hs/core/Rng.h"
#include "hs/io/AtomicFile.h"
#include "hs/io/MeshIO.h"
#include "hs/merge/Merge.h"
#include "hs/pathology/Pathology.h"
#include "hs/scene/CaseSpec.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

namespace hs::cli {
namespace {

struct PathologyOptions {
    std::string casePath;
    std::string outDir;
    std::string model; ///< overrides every pathology's growth model when set
    CommonOptions common;
};

nlohmann::ordered_json descriptorJson(const pathology::GrownPathology& g) {
    const auto& d = g.descriptors;
    nlohmann::ordered_json j;
    j["id"] = g.id;
    j["kind"] = std::string(clinical::toString(g.kind));
    j["model"] = std::string(clinical::toString(g.model));
    if (g.kind == clinical::PathologyKind::Myoma)
        j["figo"] = d.figo.toString();
    j["sizeMm"] = d.sizeMm;
    j["volumeMm3"] = d.volumeMm3;
    j["intramuralFraction"] = d.intramuralFraction;
    j["cavityFraction"] = d.cavityFraction;
    j["outsideFraction"] = d.outsideFraction;
    j["pedunculated"] = d.pedunculated;
    j["stalkLengthMm"] = d.stalkLengthMm;
    j["baseWidthMm"] = d.baseWidthMm;
    j["baseExtension"] = d.baseExtension;
    j["topography"] = d.topography == 0 ? "lower" : (d.topography == 1 ? "middle" : "upper");
    j["lateralWall"] = d.lateralWall;
    if (g.kind == clinical::PathologyKind::Myoma)
        j["lasmar"] = {{"size", d.lasmar.size},           {"topography", d.lasmar.topography},
                       {"extension", d.lasmar.extension}, {"penetration", d.lasmar.penetration},
                       {"wall", d.lasmar.wall},           {"total", d.lasmar.total()}};
    return j;
}

int run(const PathologyOptions& o) {
    auto spec = scene::loadCase(o.casePath);
    if (!spec.ok())
        return reportError("pathology", spec.error());
    std::optional<clinical::GrowthModel> override;
    if (!o.model.empty()) {
        clinical::GrowthModel m{};
        if (!clinical::fromString(o.model, m))
            return reportError("pathology", Error{ErrorCode::InvalidInput,
                                                  "--model: '" + o.model + "' is not one of ca, skeleton, particles"});
        override = m;
    }
    auto request = generate::organRequestFor(*spec, o.casePath);
    if (!request.ok())
        return reportError("pathology", request.error());
    auto model = anatomy::loadShapeModel(generate::modelPathFor(*spec, o.casePath));
    if (!model.ok())
        return reportError("pathology", model.error());
    auto organ = generate::makeOrgan(*model, *request);
    if (!organ.ok())
        return reportError("pathology", organ.error());
    auto grown = pathology::growPathologies(organ->mesh, generate::pathologyParamsFor(*spec, override));
    if (!grown.ok())
        return reportError("pathology", Error{grown.error().code, o.casePath + ": " + grown.error().detail});
    auto merged = merge::mergeBody(*grown);
    if (!merged.ok())
        return reportError("pathology", Error{merged.error().code, o.casePath + ": " + merged.error().detail});

    std::error_code ec;
    std::filesystem::create_directories(o.outDir, ec);
    if (ec)
        return reportError("pathology", Error{ErrorCode::IoError, o.outDir + ": " + ec.message()});
    nlohmann::ordered_json manifest;
    manifest["format"] = "hysteroscene-regions";
    manifest["version"] = 1;
    manifest["case"] = o.casePath;
    for (const auto& region : merged->body.surfaces) {
        const std::string file = region.name + ".vtp";
        if (auto status = io::writeSurface(region.surface, (std::filesystem::path(o.outDir) / file).string());
            !status.ok())
            return reportError("pathology", status.error());
        manifest["regions"].push_back({{"name", region.name},
                                       {"regionId", region.regionId},
                                       {"file", file},
                                       {"triangles", region.surface.triangles.size()}});
    }
    nlohmann::ordered_json descriptors = nlohmann::ordered_json::array();
    for (const auto& g : grown->pathologies)
        descriptors.push_back(descriptorJson(g));
    manifest["descriptors"] = descriptors;
    manifest["warnings"] = grown->warnings;
    if (auto status = io::writeFileAtomically((std::filesystem::path(o.outDir) / "manifest.json").string(),
                                              manifest.dump(4) + "\n");
        !status.ok())
        return reportError("pathology", status.error());
    if (o.common.json) {
        printJson(std::cout, manifest);
        return kExitOk;
    }
    for (const auto& g : grown->pathologies) {
        const auto& d = g.descriptors;
        std::printf("%-12s%s (%s): %.1f mm", g.id.c_str(), std::string(clinical::toString(g.kind)).c_str(),
                    std::string(clinical::toString(g.model)).c_str(), d.sizeMm);
        if (g.kind == clinical::PathologyKind::Myoma)
            std::printf(", FIGO %s, %.0f %% intramural, base %.1f mm (%.2f of the wall), %s third%s, Lasmar %d",
                        d.figo.toString().c_str(), 100.0 * d.intramuralFraction, d.baseWidthMm, d.baseExtension,
                        d.topography == 0 ? "lower" : (d.topography == 1 ? "middle" : "upper"),
                        d.lateralWall ? ", lateral wall" : "", d.lasmar.total());
        else
            std::printf(", %s, stalk %.1f mm, base %.1f mm", d.pedunculated ? "pedunculated" : "sessile",
                        d.stalkLengthMm, d.baseWidthMm);
        std::printf("\n");
    }
    for (const auto& w : grown->warnings)
        std::printf("warning     %s\n", w.c_str());
    std::printf("wrote       %zu regions to %s\n", merged->body.surfaces.size(), o.outDir.c_str());
    return kExitOk;
}

} // namespace

void addPathologyCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<PathologyOptions>();
    auto* sub = app.add_subcommand("pathology", "Grow a case's pathologies in its organ and merge them into regions");
    sub->add_option("--case", options->casePath, "case file (.json)")->required();
    sub->add_option("-o,--output", options->outDir, "output folder: one .vtp per region and manifest.json")->required();
    sub->add_option("--model", options->model, "growth model for every pathology: ca, skeleton or particles");
    sub->add_flag("--json", options->common.json, "print the manifest (regions and descriptors) as JSON");
    sub->callback([options, &exitCode] { exitCode = run(*options); });
}

} // namespace hs::cli
