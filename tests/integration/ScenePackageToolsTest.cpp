// Outside tools read the package of the generated default scene (resources/cases/default.json through
// hs::generate::generateScene, the chain the CLI's generate runs): the Khronos glTF validator accepts surface.glb,
// meshio and VTK read tets.vtu and mesh.msh with the region ids intact, Gmsh opens mesh.msh, and the SOFA scene holds
// the body and puts every force field on its one mechanical object. A test skips when its tool is not installed
// (tools/setup.sh installs them; see docs/scene-format.md).

#include "TestSupport.h"
#include "hs/generate/Generate.h"
#include "hs/scene/CaseSpec.h"
#include "hs/scene/ScenePackage.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

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

bool installed(const std::string& tool) {
    return run("command -v " + quoted(tool)).exitCode == 0;
}

using Tet = std::array<std::int32_t, 4>;

/// The default scene, generated once for the suite (about 5 s), and its package with every optional file.
class ScenePackageTools : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        s_dir = std::make_unique<test::TempDir>("hs-scene-tools");
        auto spec = scene::loadCase(HS_DEFAULT_CASE_FILE);
        ASSERT_TRUE(spec.ok()) << spec.error().message();
        generate::GenerateParams params;
        params.caseFile = HS_DEFAULT_CASE_FILE;
        auto generated = generate::generateScene(*spec, params);
        ASSERT_TRUE(generated.ok()) << generated.error().message();
        s_generated = std::make_unique<generate::Generated>(std::move(generated).value());
        const auto written =
            scene::writeScenePackage(*s_generated->scene, s_dir->file("scene"), scene::PackageWriteOptions::all());
        ASSERT_TRUE(written.ok()) << written.error().message();
    }
    static void TearDownTestSuite() {
        s_generated.reset();
        s_dir.reset();
    }
    void SetUp() override { ASSERT_TRUE(s_generated && s_generated->scene) << "the default scene was not generated"; }

    static const scene::Scene& theScene() { return *s_generated->scene; }
    static std::string folder() { return (s_dir->path() / "scene").string(); }
    static std::string file(const char* name) { return (s_dir->path() / "scene" / name).string(); }

    /// Runs mesh_check.py and compares the region ids (in order when `ordered`, else as counts).
    void expectRegions(const std::string& python, const std::string& args, bool ordered) {
        const CommandRun r = run(python + " " + quoted(HS_INTEGRATION_DIR "/mesh_check.py") + " " + args);
        if (r.exitCode == 3 || r.exitCode == 127)
            GTEST_SKIP() << "the Python library is not installed";
        ASSERT_EQ(r.exitCode, 0) << r.output;
        const auto j = nlohmann::json::parse(r.output);
        EXPECT_EQ(j["tets"].get<std::size_t>(), theScene().tets.tetCount());
        auto regions = j["regions"].get<std::vector<std::int32_t>>();
        auto expected = theScene().tets.regions;
        if (!ordered) {
            std::sort(regions.begin(), regions.end());
            std::sort(expected.begin(), expected.end());
        }
        EXPECT_EQ(regions, expected);
    }

    /// sofa_check.py's reading of scene.scn (Python's xml.etree).
    static nlohmann::json sofaReading() {
        const CommandRun r = run(std::string(HS_PYTHON) + " " + quoted(HS_INTEGRATION_DIR "/sofa_check.py") + " " +
                                 quoted(file("scene.scn")));
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return r.exitCode == 0 ? nlohmann::json::parse(r.output) : nlohmann::json::object();
    }

    static std::unique_ptr<test::TempDir> s_dir;
    static std::unique_ptr<generate::Generated> s_generated;
};

std::unique_ptr<test::TempDir> ScenePackageTools::s_dir;
std::unique_ptr<generate::Generated> ScenePackageTools::s_generated;

} // namespace

TEST_F(ScenePackageTools, SurfaceGlbPassesTheKhronosValidatorWithoutErrors) {
    const std::string moduleDir = HS_GLTF_VALIDATOR_DIR;
    if (!installed("node") || !fs::exists(fs::path(moduleDir) / "node_modules" / "gltf-validator"))
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
        if (installed(candidate)) {
            interpreter = candidate;
            break;
        }
    if (interpreter.empty())
        GTEST_SKIP() << "neither pvpython nor pvbatch is installed";
    expectRegions(interpreter, "--paraview " + quoted(file("tets.vtu")), true);
}

// Gmsh's own reader: a .geo script merges mesh.msh and prints its physical volumes; Gmsh's reader reports the node
// and element counts it read ("Info    : 25604 nodes"). -parse_and_exit stops after the script (no meshing, no GUI).
TEST_F(ScenePackageTools, MeshMshOpensInGmshWithItsNodesElementsAndPhysicalGroups) {
    if (!installed("gmsh"))
        GTEST_SKIP() << "gmsh is not installed";
    const fs::path geo = s_dir->path() / "count.geo";
    {
        std::ofstream out(geo);
        out << "Merge \"" << file("mesh.msh") << "\";\n"
            << "volumes() = Physical Volume{:};\n"
            << "Printf(\"physical-volumes %g\", #volumes());\n"
            << "For i In {0:#volumes()-1}\n  Printf(\"physical-volume %g\", volumes(i));\nEndFor\n";
    }
    const CommandRun r = run("gmsh " + quoted(geo.string()) + " -parse_and_exit");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    long nodes = -1, elements = -1, groupCount = -1;
    std::set<long> groups;
    std::istringstream lines(r.output);
    for (std::string line; std::getline(lines, line);) {
        long n = 0;
        char word[32] = {};
        if (std::sscanf(line.c_str(), "Info : %ld %31s", &n, word) == 2) { // a blank in the format skips any run
            if (std::string(word) == "nodes")
                nodes = n;
            else if (std::string(word) == "elements")
                elements = n;
        } else if (std::sscanf(line.c_str(), "physical-volumes %ld", &n) == 1) {
            groupCount = n;
        } else if (std::sscanf(line.c_str(), "physical-volume %ld", &n) == 1) {
            groups.insert(n);
        }
    }
    const auto& tets = theScene().tets;
    EXPECT_EQ(nodes, static_cast<long>(tets.points.size())) << r.output;
    EXPECT_EQ(elements, static_cast<long>(tets.tetCount())) << r.output;
    std::set<long> regions;
    for (const auto& region : theScene().regions)
        regions.insert(region.id);
    EXPECT_EQ(groupCount, static_cast<long>(regions.size())) << r.output;
    EXPECT_EQ(groups, regions) << "one physical volume per region, tagged with the region id";
}

TEST_F(ScenePackageTools, SofaSceneHoldsTheBodyAtTheCervix) {
    const auto sofa = sofaReading();
    ASSERT_EQ(sofa["mechanicalObjects"].size(), 1u) << sofa["mechanicalObjects"];
    const std::string dofs = sofa["mechanicalObjects"][0];
    ASSERT_EQ(sofa["fixed"].size(), 1u) << "one FixedProjectiveConstraint";
    EXPECT_EQ(sofa["fixed"][0]["mstate"], dofs);
    const auto fixed = sofa["fixed"][0]["indices"].get<std::vector<std::int32_t>>();
    ASSERT_FALSE(fixed.empty());
    EXPECT_TRUE(std::is_sorted(fixed.begin(), fixed.end()));
    EXPECT_EQ(std::adjacent_find(fixed.begin(), fixed.end()), fixed.end()) << "each point once";
    const auto& tets = theScene().tets;
    // The external os is the organ frame's origin (anatomy/UterusGenerator.h); the held points lie within one cervix
    // length of it, so none lies in the corpus near the fundus.
    const auto& organ = s_generated->organ->dimensions;
    ASSERT_GT(organ.cervixLengthMm, 0.0);
    EXPECT_LT(organ.cervixLengthMm, 0.6 * organ.lengthMm);
    double farthest = 0.0;
    for (const std::int32_t v : fixed) {
        ASSERT_GE(v, 0);
        ASSERT_LT(static_cast<std::size_t>(v), tets.points.size());
        const Vec3& p = tets.points[static_cast<std::size_t>(v)];
        farthest = std::max(farthest, std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z));
    }
    EXPECT_LE(farthest, organ.cervixLengthMm + 1e-9);
    // The points nearest the external os are held, and a part of the body large enough to carry it, not a few nodes.
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < tets.points.size(); ++i) {
        const Vec3& a = tets.points[i];
        const Vec3& b = tets.points[nearest];
        if (a.x * a.x + a.y * a.y + a.z * a.z < b.x * b.x + b.y * b.y + b.z * b.z)
            nearest = i;
    }
    EXPECT_TRUE(std::binary_search(fixed.begin(), fixed.end(), static_cast<std::int32_t>(nearest)));
    EXPECT_GT(fixed.size(), tets.points.size() / 20);
    EXPECT_LT(fixed.size(), tets.points.size() / 2);
    EXPECT_NE(std::find(sofa["plugins"].begin(), sofa["plugins"].end(), "Sofa.Component.Constraint.Projective"),
              sofa["plugins"].end());
}

TEST_F(ScenePackageTools, SofaForceFieldsActOnTheOneMechanicalObjectAndCoverEveryTetOnce) {
    const auto sofa = sofaReading();
    ASSERT_EQ(sofa["mechanicalObjects"].size(), 1u);
    const std::string dofs = sofa["mechanicalObjects"][0];
    const auto& scene = theScene();
    ASSERT_EQ(sofa["forceFields"].size(), scene.materials.size()) << "one force field per material";
    std::map<Tet, std::int32_t> regionOf;
    for (std::size_t t = 0; t < scene.tets.tetCount(); ++t)
        regionOf[scene.tets.tets[t]] = scene.tets.regionOf(t);
    ASSERT_EQ(regionOf.size(), scene.tets.tetCount()) << "the mesh has no duplicate tets";
    std::map<Tet, int> seen;
    for (std::size_t f = 0; f < sofa["forceFields"].size(); ++f) {
        const auto& ff = sofa["forceFields"][f];
        EXPECT_EQ(ff["mstate"], dofs) << ff["node"];
        EXPECT_EQ(ff["topologyType"], "TetrahedronSetTopologyContainer") << ff["node"];
        const auto& material = scene.materials[f];
        EXPECT_EQ(ff["node"], "root/tissue/region" + std::to_string(material.regionId));
        EXPECT_DOUBLE_EQ(ff["youngModulus"].get<double>(), material.material.youngsModulusKpa);
        const auto flat = ff["tetrahedra"].get<std::vector<std::int32_t>>();
        ASSERT_EQ(flat.size() % 4, 0u);
        ASSERT_FALSE(flat.empty()) << ff["node"];
        for (std::size_t i = 0; i < flat.size(); i += 4) {
            const Tet tet{flat[i], flat[i + 1], flat[i + 2], flat[i + 3]};
            const auto it = regionOf.find(tet);
            ASSERT_NE(it, regionOf.end()) << "a tet that is not in the mesh";
            EXPECT_EQ(it->second, material.regionId) << "a tet in the wrong region's force field";
            ++seen[tet];
        }
    }
    EXPECT_EQ(seen.size(), scene.tets.tetCount()) << "every tet has a force field";
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](const auto& entry) { return entry.second == 1; }))
        << "no tet has two";
}

TEST_F(ScenePackageTools, ManifestNamesTheVersionOfEveryLibraryThatShapesThePackage) {
    std::ifstream in(file("manifest.json"));
    const auto manifest = nlohmann::json::parse(in);
    const auto& versions = manifest.at("toolVersions");
    for (const char* library : {"hysteroscene", "compiler", "cgal", "eigen", "hdf5", "minizip", "nlohmann-json",
                                "opencv", "openimageio", "tinygltf", "vtk", "zlib"}) {
        ASSERT_TRUE(versions.contains(library)) << library;
        ASSERT_TRUE(versions[library].is_string()) << library;
        EXPECT_FALSE(versions[library].get<std::string>().empty()) << library;
    }
    std::map<std::string, std::string> fromManifest = versions.get<std::map<std::string, std::string>>();
    EXPECT_EQ(fromManifest, theScene().toolVersions) << "manifest.json and scene.json agree";
}

TEST_F(ScenePackageTools, CliValidateAcceptsThePackageAndRefusesATamperedOne) {
    const CommandRun ok = run(quoted(HS_CLI_PATH) + " validate " + quoted(folder()));
    EXPECT_EQ(ok.exitCode, 0) << ok.output;
    EXPECT_NE(ok.output.find("scene package"), std::string::npos) << ok.output;
    const CommandRun viaManifest = run(quoted(HS_CLI_PATH) + " validate --json " + quoted(file("manifest.json")));
    EXPECT_EQ(viaManifest.exitCode, 0) << viaManifest.output;
    EXPECT_EQ(nlohmann::json::parse(viaManifest.output)["kind"], "scene-package");

    // A copy is tampered with, so the other tests keep the package as written.
    const fs::path copy = s_dir->path() / "tampered";
    fs::copy(folder(), copy, fs::copy_options::recursive);
    { std::ofstream((copy / "report.json").string(), std::ios::app) << ' '; }
    const CommandRun bad = run(quoted(HS_CLI_PATH) + " validate --json " + quoted(copy.string()));
    EXPECT_EQ(bad.exitCode, 3) << bad.output;
    const auto j = nlohmann::json::parse(bad.output);
    EXPECT_FALSE(j["valid"].get<bool>());
    EXPECT_NE(j["error"]["detail"].get<std::string>().find("report.json"), std::string::npos);
}
