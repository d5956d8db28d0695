// `mesh SURFACE... -o OUT.vtu`: tetrahedral mesh of one or more nested closed surfaces (one region each).
#include "CliCommon.h"
#include "Commands.h"

#include "hs/core/RegionModel.h"
#include "hs/io/MeshIO.h"
#include "hs/meshing/BaselineMeshers.h"
#include "hs/meshing/ParticleMesher.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

namespace hs::cli {

nlohmann::ordered_json qualityJson(const meshing::QualityReport& q); // QualityCommand.cpp
void printQuality(std::ostream& out, const meshing::QualityReport& q);

namespace {

struct MeshOptions {
    std::vector<std::string> surfaces;
    std::string output;
    std::string method = "particle";
    double targetEdge = 0.0;
    std::int64_t vertices = 0;
    std::uint64_t seed = 1;
    int threads = 0;
    std::string report;
    CommonOptions common;
};

Error withFile(const std::string& file, const Error& e) {
    return Error{e.code, file + ": " + e.detail};
}

int runMesh(const MeshOptions& options, CLI::App& sub) {
    const auto method = meshing::parseMethod(options.method);
    if (!method)
        return reportError(
            "mesh", Error{ErrorCode::InvalidInput, "unknown method '" + options.method + "' (particle, tetgen, cgal)"});
    if (sub.count("--target-edge") > 0 && !(options.targetEdge > 0.0))
        return reportError("mesh", Error{ErrorCode::InvalidInput, "--target-edge must be a positive length in mm"});
    if (sub.count("--vertices") > 0 && options.vertices <= 0)
        return reportError("mesh", Error{ErrorCode::InvalidInput, "--vertices must be a positive count"});
    std::vector<SurfaceMesh> surfaces;
    std::vector<std::string> names;
    for (const std::string& path : options.surfaces) {
        auto surface = io::readSurface(path);
        if (!surface.ok())
            return reportError("mesh", surface.error());
        surfaces.push_back(std::move(surface.value()));
        names.push_back(path);
    }
    const RegionModel body = RegionModel::fromSurfaces(std::move(surfaces), names);
    if (auto status = validate(body); !status.ok())
        return reportError("mesh", status.error()); // the detail names the surface file

    meshing::MeshParams params;
    params.targetEdgeLength = options.targetEdge;
    params.targetVertices = options.vertices;
    params.seed = options.seed;
    params.threads = options.threads;
    auto result = meshing::meshWith(*method, body, params);
    if (!result.ok())
        return reportError("mesh", result.error());
    if (auto st = io::writeTetMesh(result->mesh, options.output); !st.ok())
        return reportError("mesh", withFile(options.output, st.error()));
    if (!options.report.empty()) {
        nlohmann::ordered_json j;
        j["method"] = std::string(meshing::methodName(*method));
        j["targetEdgeLength"] = result->targetEdgeLength;
        j["seed"] = options.seed;
        j["quality"] = qualityJson(result->quality);
        nlohmann::ordered_json steps = nlohmann::ordered_json::array();
        for (const auto& s : result->timings.steps)
            steps.push_back({{"step", s.name}, {"seconds", s.seconds}});
        j["timings"] = steps;
        std::ofstream out(options.report);
        out << j.dump(2) << '\n';
        if (!out)
            return reportError("mesh", Error{ErrorCode::IoError, options.report + ": cannot write the report"});
    }
    for (const auto& w : result->warnings)
        std::cerr << "hysteroscene-cli: mesh: warning: " << w << '\n';
    std::cout << "wrote " << options.output << ": " << result->mesh.vertexCount() << " vertices, "
              << result->mesh.tetCount() << " tetrahedra (" << meshing::methodName(*method) << ", edge "
              << result->targetEdgeLength << " mm)\n";
    if (options.common.verbose) {
        printQuality(std::cout, result->quality);
        for (const auto& s : result->timings.steps) {
            std::printf("step %-16s %8.3f s", s.name.c_str(), s.seconds);
            for (const auto& [k, v] : s.counts)
                std::printf("  %s %lld", k.c_str(), static_cast<long long>(v));
            std::printf("\n");
        }
        std::printf("total               %8.3f s\n", result->timings.totalSeconds());
    }
    return kExitOk;
}

} // namespace

void addMeshCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<MeshOptions>();
    auto* sub = app.add_subcommand("mesh", "Tetrahedral mesh of nested closed surfaces (one region per surface; "
                                           "later surfaces nested in the first)");
    sub->add_option("SURFACE", options->surfaces, "closed surfaces (.obj .stl .ply .off .vtp)")->required();
    sub->add_option("-o,--output", options->output, "output tetrahedral mesh (.vtu .msh .mesh)")->required();
    sub->add_option("--method", options->method, "particle (default), tetgen or cgal");
    auto* edge = sub->add_option("--target-edge", options->targetEdge, "target edge length, mm");
    sub->add_option("--vertices", options->vertices, "approximate vertex count")->excludes(edge);
    sub->add_option("--seed", options->seed, "random seed (same seed, same mesh)");
    sub->add_option("--threads", options->threads, "worker threads (0: all cores; never changes the result)");
    sub->add_option("--report", options->report, "write the quality report and timings as JSON");
    sub->add_flag("--verbose", options->common.verbose, "print quality and per-step timings");
    sub->callback([options, sub, &exitCode] { exitCode = runMesh(*options, *sub); });
}

} // namespace hs::cli
