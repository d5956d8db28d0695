// `validate PATH`: checks a case file or a scene package folder and says what is wrong.
#include "CliCommon.h"
#include "Commands.h"

#include "hs/scene/CaseSpec.h"
#include "hs/scene/ScenePackage.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <memory>

namespace hs::cli {
namespace {

struct ValidateOptions {
    std::string path;
    CommonOptions common;
};

int runValidateCase(const ValidateOptions& options) {
    auto spec = scene::loadCase(options.path);
    if (options.common.json) {
        nlohmann::ordered_json j;
        j["file"] = options.path;
        j["kind"] = "case";
        j["valid"] = spec.ok();
        if (!spec.ok()) {
            j["error"] = {{"code", std::string(errorCodeKey(spec.error().code))}, {"detail", spec.error().detail}};
        }
        printJson(std::cout, j);
        return spec.ok() ? kExitOk : exitCodeFor(spec.error());
    }
    if (!spec.ok())
        return reportError("validate", spec.error());
    std::cout << "valid: " << options.path << " (case)\n";
    for (const auto& line : scene::describe(*spec))
        std::cout << line << '\n';
    return kExitOk;
}

/// A package folder (or its manifest.json): every path, size and checksum, then every file parsed.
int runValidatePackage(const ValidateOptions& options, const std::string& folder) {
    auto manifest = scene::verifyScenePackage(folder);
    Result<scene::Scene> scene =
        manifest.ok() ? scene::readScenePackage(folder) : Result<scene::Scene>(manifest.failure());
    if (options.common.json) {
        nlohmann::ordered_json j;
        j["file"] = options.path;
        j["kind"] = "scene-package";
        j["valid"] = scene.ok();
        if (manifest.ok()) {
            j["schemaVersion"] = manifest->schemaVersion;
            j["toolVersion"] = manifest->toolVersion;
            j["files"] = manifest->files.size();
        }
        if (scene.ok()) {
            j["tets"] = scene->tets.tetCount();
            j["regions"] = scene->regions.size();
            j["labels"] = scene->labels.size();
        } else {
            j["error"] = {{"code", std::string(errorCodeKey(scene.error().code))}, {"detail", scene.error().detail}};
        }
        printJson(std::cout, j);
        return scene.ok() ? kExitOk : exitCodeFor(scene.error());
    }
    if (!scene.ok())
        return reportError("validate", scene.error());
    std::int64_t bytes = 0;
    for (const auto& f : manifest->files)
        bytes += f.bytes;
    std::cout << "valid: " << folder << " (scene package, schema " << manifest->schemaVersion << ", written by "
              << manifest->toolVersion << ")\n"
              << "files       " << manifest->files.size() << " plus manifest.json, " << bytes
              << " bytes, every SHA-256 checked\n"
              << "tets        " << scene->tets.tetCount() << " tetrahedra, " << scene->tets.vertexCount() << " points\n"
              << "surface     " << scene->surface.mesh.faceCount() << " triangles\n";
    for (const auto& m : scene->materials)
        std::cout << "material    " << m.name << " (" << clinical::toString(m.tissue) << "): E "
                  << m.material.youngsModulusKpa << " kPa, nu " << m.material.poissonRatio << ", "
                  << m.material.densityKgPerM3 << " kg/m^3\n";
    std::cout << "labels      " << scene->labels.size() << '\n'
              << "hydrometra  " << scene->hydrometra.cavityVolumeMl << " mL at " << scene->hydrometra.pressureKpa
              << " kPa\n";
    return kExitOk;
}

int runValidate(const ValidateOptions& options) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path path(options.path);
    if (fs::is_directory(path, ec))
        return runValidatePackage(options, options.path);
    if (path.filename() == std::string(scene::kManifestName))
        return runValidatePackage(options, path.parent_path().empty() ? "." : path.parent_path().string());
    return runValidateCase(options);
}

} // namespace

void addValidateCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<ValidateOptions>();
    auto* sub = app.add_subcommand("validate", "Check a case file (every error names the field and its allowed range) "
                                               "or a scene package folder (paths, sizes, checksums, contents)");
    sub->add_option("PATH", options->path, "case .json, or a scene package folder or its manifest.json")->required();
    sub->add_flag("--json", options->common.json, "print JSON for scripts");
    sub->callback([options, &exitCode] { exitCode = runValidate(*options); });
}

} // namespace hs::cli
