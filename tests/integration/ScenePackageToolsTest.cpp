// Outside tools read the scene package: the Khronos glTF validator accepts surface.glb, meshio reads tets.vtu and
// mesh.msh, ParaView reads tets.vtu, each with the region ids intact. A test skips when its tool is not installed
// (tools/setup.sh installs them; see docs/scene-format.md).

#include "SyntheticScene.h"
#include "TestSupport.h"
#include "hs/scene/ScenePackage.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>

using namespace hs;
namespace fs = std::filesystem;

namespace {

struct CommandRun {
    int exitCode = -1;
    std::string output;
};

/// Runs a shell command (arguments single-quoted by the caller) and captures its standard output.
CommandRun run(const std::string& command) {
    CommandRun result;
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen((command + " 2>/dev/null").c_str(), "r"), &::pclose);
    if (!pipe)
        return result;
    std::array<char, 4096> buffer{};
    std::size_t n = 0;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe.get())) > 0)
        result.output.append(buffer.data(), n);
    const int status = ::pclose(pipe.release());
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

std::string quoted(const std::string& text) {
    return "'" + text + "'";
}

class ScenePackageTools : public ::testing::Test {
protected:
    void SetUp() override {
        m_scene = test::syntheticScene();
        const auto written = scene::writeScenePackage(m_scene, m_dir.file("scene"));
        ASSERT_TRUE(written.ok()) << written.error().message();
    }
    std::string file(const char* name) const { return (m_dir.path() / "scene" / name).string(); }

    /// Runs mesh_check.py and compares the region ids (in order when `ordered`, else as counts).
    void expectRegions(const std::string& python, const std::string& args, bool ordered) {
        const CommandRun r = run(python + " " + quoted(HS_INTEGRATION_DIR "/mesh_check.py") + " " + args);
        if (r.exitCode == 3 || r.exitCode == 127)
            GTEST_SKIP() << "the Python library is not installed";
        ASSERT_EQ(r.exitCode, 0) << r.output;
        const auto j = nlohmann::json::parse(r.output);
        EXPECT_EQ(j["tets"].get<std::size_t>(), m_scene.tets.tetCount());
        auto regions = j["regions"].get<std::vector<std::int32_t>>();
        auto expected = m_scene.tets.regions;
        if (!ordered) {
            std::sort(regions.begin(), regions.end());
            std::sort(expected.begin(), expected.end());
        }
        EXPECT_EQ(regions, expected);
    }

    test::TempDir m_dir{"hs-scene-tools"};
    scene::Scene m_scene;
};

} // namespace

TEST_F(ScenePackageTools, SurfaceGlbPassesTheKhronosValidatorWithoutErrors) {
    const std::string moduleDir = HS_GLTF_VALIDATOR_DIR;
    if (run("command -v node").exitCode != 0 || !fs::exists(fs::path(moduleDir) / "node_modules" / "gltf-validator"))
        GTEST_SKIP() << "node or the npm package gltf-validator (in " << moduleDir << ") is missing";
    const CommandRun r = run("node " + quoted(HS_INTEGRATION_DIR "/gltf_validate.js") + " " + quoted(moduleDir) + " " +
                             quoted(file("surface.glb")));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto report = nlohmann::json::parse(r.output);
    EXPECT_EQ(report["errors"].get<int>(), 0) << r.output;
    EXPECT_EQ(report["warnings"].get<int>(), 0) << r.output;
    std::cout << "gltf-validator: " << r.output << '\n';
}

TEST_F(ScenePackageTools, TetsVtuLoadsInMeshioWithTheRegionIds) {
    expectRegions(HS_PYTHON, quoted(file("tets.vtu")), true);
}

TEST_F(ScenePackageTools, MeshMshLoadsInMeshioWithTheRegionIds) {
    expectRegions(HS_PYTHON, quoted(file("mesh.msh")), false);
}

// ParaView's Python (python3-paraview) cannot be installed next to libvtk9-dev on Debian 12: the two conflict. VTK's
// own Python reader is the reader ParaView wraps, so this checks the same thing where pvpython is missing.
TEST_F(ScenePackageTools, TetsVtuLoadsInVtkPythonWithTheRegionIds) {
    expectRegions(HS_PYTHON, "--vtk " + quoted(file("tets.vtu")), true);
}

TEST_F(ScenePackageTools, TetsVtuLoadsInParaViewWithTheRegionIds) {
    std::string interpreter;
    for (const char* candidate : {"pvpython", "pvbatch"})
        if (run(std::string("command -v ") + candidate).exitCode == 0) {
            interpreter = candidate;
            break;
        }
    if (interpreter.empty())
        GTEST_SKIP() << "neither pvpython nor pvbatch is installed";
    expectRegions(interpreter, "--paraview " + quoted(file("tets.vtu")), true);
}

TEST_F(ScenePackageTools, CliValidateAcceptsThePackageAndRefusesATamperedOne) {
    const std::string folder = (m_dir.path() / "scene").string();
    const CommandRun ok = run(quoted(HS_CLI_PATH) + " validate " + quoted(folder));
    EXPECT_EQ(ok.exitCode, 0) << ok.output;
    EXPECT_NE(ok.output.find("scene package"), std::string::npos) << ok.output;
    const CommandRun viaManifest = run(quoted(HS_CLI_PATH) + " validate --json " + quoted(file("manifest.json")));
    EXPECT_EQ(viaManifest.exitCode, 0) << viaManifest.output;
    EXPECT_EQ(nlohmann::json::parse(viaManifest.output)["kind"], "scene-package");

    { std::ofstream(file("report.json"), std::ios::app) << ' '; }
    const CommandRun bad = run(quoted(HS_CLI_PATH) + " validate --json " + quoted(folder));
    EXPECT_EQ(bad.exitCode, 3) << bad.output;
    const auto j = nlohmann::json::parse(bad.output);
    EXPECT_FALSE(j["valid"].get<bool>());
    EXPECT_NE(j["error"]["detail"].get<std::string>().find("report.json"), std::string::npos);
}
