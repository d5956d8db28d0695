// `info FILE`: a summary of a mesh (surface or tetrahedral) or a case file.
#include "CliCommon.h"
#include "Commands.h"
#include "MeshSummary.h"

#include "hs/io/MeshIO.h"
#include "hs/scene/CaseSpec.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <memory>

namespace hs::cli {
namespace {

struct InfoOptions {
    std::string path;
    CommonOptions common;
};

bool isCasePath(const std::string& path) {
    auto ext = std::filesystem::path(path).extension().string();
    for (auto& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".json";
}

int runCaseInfo(const InfoOptions& options) {
    auto spec = scene::loadCase(options.path);
    if (!spec.ok())
        return reportError("info", spec.error());
    if (options.common.json) {
        nlohmann::ordered_json j;
        j["file"] = options.path;
        j["kind"] = "case";
        j["case"] = nlohmann::ordered_json::parse(scene::toJson(*spec));
        printJson(std::cout, j);
    } else {
        std::cout << "file        " << options.path << "\nkind        case\n";
        for (const auto& line : scene::describe(*spec))
            std::cout << line << '\n';
    }
    return kExitOk;
}

int runMeshInfo(const InfoOptions& options) {
    auto mesh = io::readMesh(options.path);
    if (!mesh.ok())
        return reportError("info", mesh.error());
    const auto format = io::formatFromPath(options.path);
    const MeshSummary summary = summarize(*mesh);
    if (options.common.json) {
        nlohmann::ordered_json j;
        j["file"] = options.path;
        j["format"] = format.ok() ? io::formatName(*format) : "";
        toJson(summary, j);
        printJson(std::cout, j);
    } else {
        std::cout << "file        " << options.path << '\n';
        std::cout << "format      " << (format.ok() ? io::formatName(*format) : "") << '\n';
        printText(std::cout, summary);
    }
    return kExitOk;
}

} // namespace

void addInfoCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<InfoOptions>();
    auto* sub = app.add_subcommand("info", "Summarise a mesh (surface or tetrahedral) or a case file");
    sub->add_option("FILE", options->path, "mesh file (.obj .stl .ply .off .vtp .vtu .msh .mesh) or case .json")
        ->required();
    sub->add_flag("--json", options->common.json, "print JSON for scripts");
    sub->callback(
        [options, &exitCode] { exitCode = isCasePath(options->path) ? runCaseInfo(*options) : runMeshInfo(*options); });
}

} // namespace hs::cli
