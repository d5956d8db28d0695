// Runs hysteroscene-cli as a user would and checks exit codes and output.
#include "TestSupport.h"

#include "hs/generate/Generate.h"
#include "hs/io/MeshIO.h"
#include "hs/scene/ScenePackage.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <sys/wait.h>

namespace fs = std::filesystem;

namespace {

using Run = hs::test::CommandRun;
using hs::test::shellQuote;

std::string quote(const std::string& s) {
    return shellQuote(s);
}

Run cli(const std::string& args) {
    return hs::test::runCommand(quote(HS_CLI_PATH) + " " + args);
}

std::vector<fs::path> sharedMeshes(bool bad) {
    std::vector<fs::path> files;
    const fs::path dir = hs::test::sharedDataDir();
    if (dir.empty())
        return files;
    const fs::path meshes = bad ? dir / "meshes" / "bad" : dir / "meshes";
    for (const auto& entry : fs::directory_iterator(meshes))
        if (entry.is_regular_file() && entry.path().extension() != ".md")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

const std::string kDefaultCase = std::string(HS_SOURCE_DIR) + "/resources/cases/default.json";
const std::string kDefaultSurface = std::string(HS_SOURCE_DIR) + "/resources/surfaces/default-organ.off";

} // namespace

TEST(Cli, PrintsHelpAndVersion) {
    auto help = cli("--help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("info"), std::string::npos);
    EXPECT_NE(help.out.find("convert"), std::string::npos);
    auto version = cli("--version");
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_NE(version.out.find(HS_VERSION), std::string::npos);
}

TEST(Cli, AnswersUsageErrorsWithExitCodeTwo) {
    EXPECT_EQ(cli("").exitCode, 2);
    EXPECT_EQ(cli("frobnicate").exitCode, 2);
    EXPECT_EQ(cli("info").exitCode, 2);
    EXPECT_EQ(cli("info a b c").exitCode, 2);
}

TEST(Cli, InfoSummarisesEverySharedSurface) {
    const auto files = sharedMeshes(false);
    if (files.empty())
        GTEST_SKIP() << "shared test surfaces not present";
    for (const auto& file : files) {
        auto run = cli("info --json " + quote(file.string()));
        ASSERT_EQ(run.exitCode, 0) << file << "\n" << run.out;
        const auto j = nlohmann::json::parse(run.out);
        EXPECT_EQ(j["kind"], "surface") << file;
        EXPECT_GT(j["vertices"].get<int>(), 100) << file;
        EXPECT_TRUE(j["topology"]["closed"].get<bool>()) << file;
        EXPECT_GT(j["volumeMm3"].get<double>(), 0.0) << file;
    }
}

TEST(Cli, InfoReportsTheDefectsOfTheBadSurfaces) {
    const auto files = sharedMeshes(true);
    if (files.empty())
        GTEST_SKIP() << "shared test surfaces not present";
    for (const auto& file : files) {
        auto run = cli("info " + quote(file.string()));
        ASSERT_EQ(run.exitCode, 0) << file << "\n" << run.out;
        EXPECT_NE(run.out.find("closed no"), std::string::npos) << file << "\n" << run.out;
    }
}

TEST(Cli, ConvertsEverySharedSurfaceToEverySurfaceFormatAndBack) {
    const auto files = sharedMeshes(false);
    if (files.empty())
        GTEST_SKIP() << "shared test surfaces not present";
    hs::test::TempDir tmp;
    for (const auto& file : files) {
        auto original = hs::io::readSurface(file.string());
        ASSERT_TRUE(original.ok()) << original.error().message();
        for (const std::string ext : {".obj", ".stl", ".ply", ".off", ".vtp"}) {
            const std::string out = tmp.file(file.stem().string() + ext);
            auto run = cli("convert " + quote(file.string()) + " " + quote(out));
            ASSERT_EQ(run.exitCode, 0) << file << " -> " << ext << "\n" << run.out;
            auto back = hs::io::readSurface(out);
            ASSERT_TRUE(back.ok()) << back.error().message();
            EXPECT_EQ(back->triangles.size(), original->triangles.size()) << file << " -> " << ext;
            EXPECT_NEAR(hs::enclosedVolume(*back), hs::enclosedVolume(*original),
                        1e-4 * std::fabs(hs::enclosedVolume(*original)))
                << file << " -> " << ext;
        }
    }
}

TEST(Cli, ConvertsBetweenTetrahedralFormatsKeepingRegions) {
    hs::TetMesh m;
    m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    m.tets = {{0, 1, 2, 3}, {1, 4, 2, 3}};
    m.regions = {1, 2};
    hs::test::TempDir tmp;
    ASSERT_TRUE(hs::io::writeTetMesh(m, tmp.file("a.vtu")).ok());
    std::string previous = tmp.file("a.vtu");
    for (const std::string ext : {".msh", ".mesh", ".vtu"}) {
        const std::string out = tmp.file("b" + ext);
        auto run = cli("convert " + quote(previous) + " " + quote(out));
        ASSERT_EQ(run.exitCode, 0) << run.out;
        auto back = hs::io::readTetMesh(out);
        ASSERT_TRUE(back.ok()) << back.error().message();
        EXPECT_EQ(back->regions, m.regions) << ext;
        previous = out;
    }
    // A tetrahedral mesh written to a surface format gives its boundary.
    auto run = cli("convert " + quote(previous) + " " + quote(tmp.file("boundary.stl")));
    ASSERT_EQ(run.exitCode, 0) << run.out;
    EXPECT_NE(run.out.find("boundary"), std::string::npos);
    auto boundary = hs::io::readSurface(tmp.file("boundary.stl"));
    ASSERT_TRUE(boundary.ok());
    EXPECT_EQ(boundary->triangles.size(), 6u);
}

TEST(Cli, RefusesToWriteASurfaceAsTetrahedra) {
    hs::test::TempDir tmp;
    auto run = cli("convert " + quote(kDefaultSurface) + " " + quote(tmp.file("x.msh")));
    EXPECT_EQ(run.exitCode, 3) << run.out;
    EXPECT_NE(run.out.find("mesh"), std::string::npos);
    EXPECT_FALSE(fs::exists(tmp.file("x.msh")));
}

TEST(Cli, NamesTheFileOfAnInvalidInput) {
    hs::test::TempDir tmp;
    {
        std::ofstream f(tmp.file("broken.off"));
        f << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n";
    }
    auto run = cli("info " + quote(tmp.file("broken.off")));
    EXPECT_EQ(run.exitCode, 3) << run.out;
    EXPECT_NE(run.out.find("broken.off"), std::string::npos) << run.out;
    auto missing = cli("info " + quote(tmp.file("nothing.obj")));
    EXPECT_EQ(missing.exitCode, 3) << missing.out;
    auto unknown = cli("info " + quote(tmp.file("file.xyz")));
    EXPECT_EQ(unknown.exitCode, 3) << unknown.out;
}

TEST(Cli, InfoOnTheDefaultSurfaceShowsAClosedOrgan) {
    auto run = cli("info " + quote(kDefaultSurface));
    ASSERT_EQ(run.exitCode, 0) << run.out;
    EXPECT_NE(run.out.find("watertight yes"), std::string::npos) << run.out;
}

TEST(Cli, ValidatesTheDefaultCase) {
    auto run = cli("validate " + quote(kDefaultCase));
    EXPECT_EQ(run.exitCode, 0) << run.out;
    EXPECT_NE(run.out.find("valid"), std::string::npos);
    auto info = cli("info --json " + quote(kDefaultCase));
    ASSERT_EQ(info.exitCode, 0) << info.out;
    EXPECT_EQ(nlohmann::json::parse(info.out)["kind"], "case");
}

TEST(Cli, ValidateNamesTheFieldAndRangeOfABadCase) {
    hs::test::TempDir tmp;
    std::ifstream in(kDefaultCase);
    auto j = nlohmann::json::parse(in);
    j["patient"]["ageYears"] = 130;
    {
        std::ofstream out(tmp.file("old.json"));
        out << j.dump(2);
    }
    auto run = cli("validate " + quote(tmp.file("old.json")));
    EXPECT_EQ(run.exitCode, 3) << run.out;
    EXPECT_NE(run.out.find("/patient/ageYears"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("130"), std::string::npos) << run.out;
    auto asJson = cli("validate --json " + quote(tmp.file("old.json")));
    EXPECT_EQ(asJson.exitCode, 3);
    EXPECT_FALSE(nlohmann::json::parse(asJson.out)["valid"].get<bool>());
}

TEST(Cli, OrganFromTheDefaultCaseWritesALabelledUterusAndItsDimensions) {
    hs::test::TempDir tmp;
    auto run = cli("organ --json --case " + quote(kDefaultCase) + " -o " + quote(tmp.file("organ.vtp")));
    ASSERT_EQ(run.exitCode, 0) << run.out;
    const auto j = nlohmann::json::parse(run.out);
    const double length = j["dimensions"]["lengthMm"].get<double>();
    EXPECT_GT(length, 40.0);
    EXPECT_LT(length, 100.0);
    auto organ = hs::io::readSurface(tmp.file("organ.vtp"));
    ASSERT_TRUE(organ.ok()) << organ.error().message();
    EXPECT_TRUE(hs::analyzeTopology(*organ).isWatertight());
    EXPECT_EQ(organ->faceLabels.count("tissue"), 1u);
    // Same case, same seed: the same organ.
    auto again = cli("organ --case " + quote(kDefaultCase) + " -o " + quote(tmp.file("again.vtp")));
    ASSERT_EQ(again.exitCode, 0) << again.out;
    auto second = hs::io::readSurface(tmp.file("again.vtp"));
    ASSERT_TRUE(second.ok());
    EXPECT_EQ(second->points, organ->points);
}

TEST(Cli, OrganRefusesPatientsOutsideTheSupportedRange) {
    hs::test::TempDir tmp;
    auto run = cli("organ --age 130 -o " + quote(tmp.file("x.vtp")));
    EXPECT_EQ(run.exitCode, 3) << run.out;
    EXPECT_NE(run.out.find("ageYears"), std::string::npos) << run.out;
    EXPECT_FALSE(fs::exists(tmp.file("x.vtp")));
    auto both = cli("organ --case " + quote(kDefaultCase) + " --age 40 -o " + quote(tmp.file("y.vtp")));
    EXPECT_EQ(both.exitCode, 3) << both.out;
}

TEST(Cli, OrganGrowsWithParityForTheMeanOrgan) {
    hs::test::TempDir tmp;
    auto nulli = cli("organ --json --mean --age 35 --parity 0 -o " + quote(tmp.file("a.vtp")));
    auto multi = cli("organ --json --mean --age 35 --parity 3 -o " + quote(tmp.file("b.vtp")));
    ASSERT_EQ(nulli.exitCode, 0) << nulli.out;
    ASSERT_EQ(multi.exitCode, 0) << multi.out;
    EXPECT_GT(nlohmann::json::parse(multi.out)["dimensions"]["lengthMm"].get<double>(),
              nlohmann::json::parse(nulli.out)["dimensions"]["lengthMm"].get<double>());
}

TEST(Cli, ModelInfoSampleBuildAndEvaluate) {
    hs::test::TempDir tmp;
    const std::string bundled = std::string(HS_SOURCE_DIR) + "/resources/models/uterus-default.h5";
    auto info = cli("model info --json " + quote(bundled));
    ASSERT_EQ(info.exitCode, 0) << info.out;
    EXPECT_GT(nlohmann::json::parse(info.out)["modes"].get<int>(), 0);

    auto mode = cli("model sample " + quote(bundled) + " --mode 1 --sd 2 -o " + quote(tmp.file("m.vtp")));
    ASSERT_EQ(mode.exitCode, 0) << mode.out;
    EXPECT_TRUE(fs::exists(tmp.file("m.vtp")));
    EXPECT_EQ(cli("model sample " + quote(bundled) + " --mode 999 --sd 2 -o " + quote(tmp.file("n.vtp"))).exitCode, 3);

    auto build = cli("model build --cohort-size 24 --cohort-seed 3 -o " + quote(tmp.file("small.h5")));
    ASSERT_EQ(build.exitCode, 0) << build.out;
    auto evaluate = cli("model evaluate --json " + quote(tmp.file("small.h5")) +
                        " --cohort-size 24 --cohort-seed 3 --folds 4 --samples 10");
    ASSERT_EQ(evaluate.exitCode, 0) << evaluate.out;
    const auto ev = nlohmann::json::parse(evaluate.out);
    EXPECT_GT(ev["generalization"]["meanMm"].get<double>(), 0.0);
    EXPECT_GT(ev["specificity"]["meanMm"].get<double>(), 0.0);

    EXPECT_EQ(cli("model info " + quote(kDefaultCase)).exitCode, 3);
    EXPECT_EQ(cli("model build --meshes " + quote(tmp.path().string()) + " -o " + quote(tmp.file("x.h5"))).exitCode, 3);
}

namespace {

/// The default case made lighter (fewer vertices, smaller maps), for the tests that generate several scenes.
std::string writeSmallCase(const hs::test::TempDir& tmp, bool withPolyp = true) {
    std::ifstream in(kDefaultCase);
    auto j = nlohmann::json::parse(in);
    j["meshing"]["targetVertices"] = 6000;
    j["texture"]["sizePx"] = 256;
    if (!withPolyp)
        j["pathologies"].erase(1);
    const std::string path = tmp.file(withPolyp ? "small.json" : "small-myoma.json");
    std::ofstream(path) << j.dump(2);
    return path;
}

std::string readText(const std::string& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

} // namespace

TEST(Cli, GenerateWritesAValidPackageForTheDefaultCase) {
    hs::test::TempDir tmp;
    const std::string scene = tmp.file("scene");
    auto run = cli("generate --json " + quote(kDefaultCase) + " -o " + quote(scene));
    ASSERT_EQ(run.exitCode, 0) << run.out;
    const auto j = nlohmann::json::parse(run.out);
    const auto& v = j["variants"][0];
    EXPECT_TRUE(v["ok"].get<bool>());
    EXPECT_GT(v["tetrahedra"].get<int>(), 50000);
    EXPECT_EQ(v["pathologies"].size(), 2u);
    EXPECT_EQ(v["pathologies"][0]["figo"], "2");
    EXPECT_EQ(v["quality"]["inverted"].get<int>(), 0);
    std::vector<std::string> stages;
    for (const auto& t : v["timings"])
        stages.push_back(t["stage"].get<std::string>());
    EXPECT_EQ(stages, (std::vector<std::string>{"organ", "pathology", "merge", "meshing", "tissue", "texture", "scene",
                                                "package", "scope"}));
    // generate read the package back and swept the scope with validate's own criterion (one criterion for both).
    EXPECT_GT(v["files"].get<int>(), 5);
    ASSERT_TRUE(v["scope"]["checked"].get<bool>()) << run.out;
    auto swept = cli("validate --json " + quote(scene));
    const auto sj = nlohmann::json::parse(swept.out);
    EXPECT_EQ(v["scope"]["passes"].get<bool>(), sj["scopePassage"]["passes"].get<bool>());
    EXPECT_EQ(v["scope"]["canalNarrowestMm"].get<double>(),
              sj["scopePassage"]["canal"]["narrowest"]["widthMm"].get<double>());
    EXPECT_EQ(v["scope"]["reachesFundus"].get<bool>(), sj["scopePassage"]["toFundus"]["passes"].get<bool>());
    auto validate = cli("validate " + quote(scene));
    EXPECT_EQ(validate.exitCode, 0) << validate.out;
    // The scope passage is measured and printed whether or not the 2.9 mm scope fits.
    EXPECT_NE(validate.out.find("scope       2.90 mm scope through the canal"), std::string::npos) << validate.out;
    EXPECT_NE(validate.out.find("narrowest "), std::string::npos) << validate.out;
    // A scope wider than any canal of the scene: a named warning, and still exit 0 for a valid package.
    auto wide = cli("validate --json --scope-diameter 9 " + quote(scene));
    EXPECT_EQ(wide.exitCode, 0) << wide.out;
    const auto wj = nlohmann::json::parse(wide.out);
    EXPECT_TRUE(wj["valid"].get<bool>());
    EXPECT_FALSE(wj["scopePassage"]["passes"].get<bool>());
    EXPECT_GT(wj["scopePassage"]["canal"]["narrowest"]["widthMm"].get<double>(), 0.0);
    EXPECT_LT(wj["scopePassage"]["canal"]["narrowest"]["widthMm"].get<double>(), 9.0);
    std::vector<std::string> names;
    for (const auto& w : wj["warnings"])
        names.push_back(w["name"].get<std::string>());
    EXPECT_NE(std::find(names.begin(), names.end(), "scope-passage-narrow"), names.end()) << wide.out;
    // Every mesh quality bar is measured on the organ's scene and recorded; each one missed is a warning by name,
    // in validate and in the scene's own warnings.
    ASSERT_EQ(wj["meshBars"].size(), 6u) << wide.out;
    const auto report = nlohmann::json::parse(readText(scene + "/report.json"));
    ASSERT_EQ(report["quality"]["bars"].size(), 6u);
    for (const auto& bar : wj["meshBars"]) {
        const std::string name = bar["name"].get<std::string>();
        const bool warned = std::find(names.begin(), names.end(), name) != names.end();
        EXPECT_EQ(warned, !bar["met"].get<bool>()) << name;
        bool inScene = false;
        for (const auto& w : report["warnings"])
            inScene = inScene || w.get<std::string>().rfind(name + ": ", 0) == 0;
        EXPECT_EQ(inScene, !bar["met"].get<bool>()) << name;
    }
    EXPECT_NE(validate.out.find("quality bars met (report.json)"), std::string::npos) << validate.out;
    // The bars the default scene meets on its own tets (docs/meshing.md, "Bars on every scene"): all but the
    // Hausdorff distance, which a uniform edge length cannot bring under 1 % at the slit beside the polyp.
    for (const auto& bar : report["quality"]["bars"]) {
        if (bar["name"] != "mesh-hausdorff") {
            EXPECT_TRUE(bar["met"].get<bool>()) << bar.dump();
        }
    }
    EXPECT_EQ(cli("validate --scope-diameter 11 " + quote(scene)).exitCode, 2);
    auto tets = hs::io::readTetMesh(scene + "/tets.vtu");
    ASSERT_TRUE(tets.ok()) << tets.error().message();
    const auto volumes = hs::regionVolumes(*tets);
    // Myometrium, endometrium, cervix, then the myoma and the polyp.
    ASSERT_EQ(volumes.size(), 5u);
    EXPECT_EQ(volumes.begin()->first, 1);
    EXPECT_EQ(volumes.rbegin()->first, 5);
    // The size budget: the default case's package, with everything the simulator and the workstation read, within
    // 20 MB (docs/scene-format.md, "Size"); the other tools' formats only on request.
    std::uintmax_t bytes = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(scene))
        if (entry.is_regular_file())
            bytes += entry.file_size();
    EXPECT_LE(bytes, 20u * 1000u * 1000u);
    EXPECT_FALSE(std::filesystem::exists(scene + "/surface.glb"));
    EXPECT_FALSE(std::filesystem::exists(scene + "/mesh.msh"));
}

TEST(Cli, GenerateGivesTheSamePackageOnRepeatedRunsAndAnyThreadCount) {
    hs::test::TempDir tmp;
    const std::string small = writeSmallCase(tmp);
    ASSERT_EQ(cli("generate " + quote(small) + " -o " + quote(tmp.file("a")) + " --threads 2").exitCode, 0);
    ASSERT_EQ(cli("generate " + quote(small) + " -o " + quote(tmp.file("b")) + " --threads 1").exitCode, 0);
    ASSERT_EQ(cli("generate " + quote(small) + " -o " + quote(tmp.file("a")) + " --threads 2").exitCode, 0);
    const std::string a = readText(tmp.file("a/manifest.json"));
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, readText(tmp.file("b/manifest.json")));
}

TEST(Cli, GenerateWritesTheSameBytesAsTheLibraryChain) {
    // The command is a thin caller of hs::generate::generateScene: options, progress, the package, the report.
    hs::test::TempDir tmp;
    const std::string small = writeSmallCase(tmp);
    ASSERT_EQ(cli("generate " + quote(small) + " -o " + quote(tmp.file("cli"))).exitCode, 0);
    auto spec = hs::scene::loadCase(small);
    ASSERT_TRUE(spec.ok()) << spec.error().message();
    hs::generate::GenerateParams params;
    params.caseFile = small;
    auto generated = hs::generate::generateScene(*spec, params);
    ASSERT_TRUE(generated.ok()) << generated.error().message();
    ASSERT_TRUE(hs::scene::writeScenePackage(*generated->scene, tmp.file("library")).ok());
    std::size_t files = 0;
    for (const auto& e : fs::recursive_directory_iterator(tmp.file("cli"))) {
        if (!e.is_regular_file())
            continue;
        const auto rel = fs::relative(e.path(), tmp.file("cli"));
        EXPECT_EQ(readText(e.path().string()), readText((fs::path(tmp.file("library")) / rel).string())) << rel;
        ++files;
    }
    EXPECT_GT(files, 5u);
}

TEST(Cli, GenerateWritesVariantsWithDerivedSeeds) {
    hs::test::TempDir tmp;
    const std::string small = writeSmallCase(tmp, false);
    auto run = cli("generate --json " + quote(small) + " -o " + quote(tmp.file("batch")) + " --variants 2 --jobs 2");
    ASSERT_EQ(run.exitCode, 0) << run.out;
    const auto j = nlohmann::json::parse(run.out);
    ASSERT_EQ(j["variants"].size(), 2u);
    EXPECT_NE(j["variants"][0]["seed"], j["variants"][1]["seed"]);
    const std::string first = readText(tmp.file("batch/variant-000/manifest.json"));
    const std::string second = readText(tmp.file("batch/variant-001/manifest.json"));
    EXPECT_FALSE(first.empty());
    EXPECT_NE(first, second);
    EXPECT_EQ(cli("validate " + quote(tmp.file("batch/variant-001"))).exitCode, 0);
}

TEST(Cli, GenerateRefusesAnInvalidCaseAndWritesNothing) {
    hs::test::TempDir tmp;
    std::ifstream in(kDefaultCase);
    auto j = nlohmann::json::parse(in);
    j["pathologies"][0]["figo"] = 9;
    std::ofstream(tmp.file("bad.json")) << j.dump(2);
    auto run = cli("generate " + quote(tmp.file("bad.json")) + " -o " + quote(tmp.file("scene")));
    EXPECT_EQ(run.exitCode, 3) << run.out;
    EXPECT_NE(run.out.find("/pathologies/0/figo"), std::string::npos) << run.out;
    EXPECT_FALSE(fs::exists(tmp.file("scene")));
}

TEST(Cli, OrganMeetsTheCaseDimensionsOrSaysWhichOneItCannotReach) {
    hs::test::TempDir tmp;
    std::ifstream in(kDefaultCase);
    auto j = nlohmann::json::parse(in);
    j["anatomy"]["dimensions"]["lengthMm"] = 80.0;
    j["anatomy"]["flexionDeg"] = -20.0;
    std::ofstream(tmp.file("long.json")) << j.dump(2);
    auto run = cli("organ --json --case " + quote(tmp.file("long.json")) + " -o " + quote(tmp.file("o.vtp")));
    ASSERT_EQ(run.exitCode, 0) << run.out;
    const auto dims = nlohmann::json::parse(run.out)["dimensions"];
    EXPECT_NEAR(dims["lengthMm"].get<double>(), 80.0, 1.0);
    EXPECT_NEAR(dims["flexionDeg"].get<double>(), -20.0, 2.0);

    j["anatomy"]["dimensions"]["lengthMm"] = 31.0;
    std::ofstream(tmp.file("short.json")) << j.dump(2);
    auto refused = cli("organ --case " + quote(tmp.file("short.json")) + " -o " + quote(tmp.file("p.vtp")));
    EXPECT_EQ(refused.exitCode, 3) << refused.out;
    EXPECT_NE(refused.out.find("lengthMm"), std::string::npos) << refused.out;
}
