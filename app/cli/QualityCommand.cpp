// `quality MESH [--json]`: shape quality of any tetrahedral mesh (ours or another tool's).
#include "CliCommon.h"
#include "Commands.h"

#include "hs/io/MeshIO.h"
#include "hs/meshing/QualityReport.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

namespace hs::cli {

/// The quality report as JSON (also used by `mesh --report`).
nlohmann::ordered_json qualityJson(const meshing::QualityReport& q) {
    nlohmann::ordered_json j;
    j["vertices"] = q.vertexCount;
    j["tetrahedra"] = q.tetCount;
    j["meanRadiusRatio"] = q.meanRadiusRatio;
    j["minRadiusRatio"] = q.minRadiusRatio;
    j["minDihedralDeg"] = q.minDihedralDeg;
    j["maxDihedralDeg"] = q.maxDihedralDeg;
    j["meanEdgeRatio"] = q.meanEdgeRatio;
    j["maxEdgeRatio"] = q.maxEdgeRatio;
    j["radiusRatioHistogram"] = q.radiusRatioHistogram;
    j["minDihedralHistogram"] = q.minDihedralHistogram;
    j["slivers"] = q.sliverCount;
    j["inverted"] = q.invertedCount;
    j["degenerate"] = q.degenerateCount;
    if (q.hasReference) {
        j["boundingBoxDiagonal"] = q.boundingBoxDiagonal;
        j["hausdorffDistance"] = q.hausdorffDistance;
        j["hausdorffRelative"] = q.hausdorffRelative;
        j["volumeError"] = q.volumeError;
        nlohmann::ordered_json regions = nlohmann::ordered_json::array();
        for (const auto& r : q.regions)
            regions.push_back({{"region", r.regionId},
                               {"meshVolume", r.meshVolume},
                               {"inputVolume", r.inputVolume},
                               {"relativeError", r.relativeError}});
        j["regions"] = regions;
    }
    return j;
}

/// The quality report as aligned text lines.
void printQuality(std::ostream& out, const meshing::QualityReport& q) {
    char line[160];
    auto put = [&](const char* fmt, auto... args) {
        std::snprintf(line, sizeof line, fmt, args...);
        out << line << '\n';
    };
    put("vertices          %zu", q.vertexCount);
    put("tetrahedra        %zu", q.tetCount);
    put("radius ratio      mean %.4f, min %.4f", q.meanRadiusRatio, q.minRadiusRatio);
    put("dihedral angle    min %.2f deg, max %.2f deg", q.minDihedralDeg, q.maxDihedralDeg);
    put("edge ratio        mean %.3f, max %.3f", q.meanEdgeRatio, q.maxEdgeRatio);
    put("slivers (<%.0f deg) %zu", meshing::kSliverDihedralDeg, q.sliverCount);
    put("inverted          %zu, degenerate %zu", q.invertedCount, q.degenerateCount);
    out << "radius ratio histogram (0.1 buckets):";
    for (auto c : q.radiusRatioHistogram)
        out << ' ' << c;
    out << "\nmin dihedral histogram (10 deg buckets):";
    for (auto c : q.minDihedralHistogram)
        out << ' ' << c;
    out << '\n';
    if (q.hasReference) {
        put("hausdorff         %.4g mm (%.3f %% of the bbox diagonal)", q.hausdorffDistance,
            100.0 * q.hausdorffRelative);
        for (const auto& r : q.regions)
            put("region %-4d       volume %.6g mm^3, input %.6g mm^3, error %.3f %%", r.regionId, r.meshVolume,
                r.inputVolume, 100.0 * r.relativeError);
    }
}

namespace {

struct QualityOptions {
    std::string path;
    CommonOptions common;
};

int runQuality(const QualityOptions& options) {
    auto mesh = io::readTetMesh(options.path);
    if (!mesh.ok())
        return reportError("quality", mesh.error());
    const meshing::QualityReport q = meshing::measureQuality(*mesh);
    if (options.common.json) {
        nlohmann::ordered_json j;
        j["file"] = options.path;
        j["quality"] = qualityJson(q);
        printJson(std::cout, j);
    } else {
        std::cout << "file              " << options.path << '\n';
        printQuality(std::cout, q);
    }
    return kExitOk;
}

} // namespace

void addQualityCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<QualityOptions>();
    auto* sub = app.add_subcommand("quality", "Element quality of a tetrahedral mesh (radius ratio, dihedral angles, "
                                              "slivers, inverted tets)");
    sub->add_option("MESH", options->path, "tetrahedral mesh (.vtu .msh .mesh)")->required();
    sub->add_flag("--json", options->common.json, "print JSON for scripts");
    sub->callback([options, &exitCode] { exitCode = runQuality(*options); });
}

} // namespace hs::cli
