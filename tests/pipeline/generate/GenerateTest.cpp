// The chain on a light version of the default case: every stage's result is kept, an edit reruns only the stages
// it touches and gives the same package bytes as a full run, edits that reach back are refused.
#include "hs/generate/Generate.h"
#include "hs/core/TetEmbedding.h"
#include "hs/generate/Export.h"
#include "hs/generate/Simulation.h"
#include "hs/generate/TissueLayers.h"

#include "TestSupport.h"

#include "hs/scene/ScenePackage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <mutex>
#include <string>

using namespace hs;
using namespace hs::generate;
namespace fs = std::filesystem;

namespace {

/// The default case with fewer vertices and smaller maps (a few seconds per run).
scene::CaseSpec lightCase() {
    auto spec = scene::loadCase(HS_DEFAULT_CASE_FILE);
    EXPECT_TRUE(spec.ok()) << spec.error().message();
    scene::CaseSpec s = *spec;
    s.meshing.targetVertices = 5000;
    s.texture.sizePx = 256;
    s.meshing.threads = 2;
    return s;
}

/// Every file of a package folder, by relative path.
std::map<std::string, std::string> packageFiles(const std::string& folder) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(folder))
        if (e.is_regular_file()) {
            std::ifstream in(e.path(), std::ios::binary);
            files[fs::relative(e.path(), folder).string()] =
                std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        }
    return files;
}

std::map<std::string, std::string> written(const Generated& g, const test::TempDir& tmp, const std::string& name) {
    EXPECT_TRUE(g.scene.has_value());
    auto w = scene::writeScenePackage(*g.scene, tmp.file(name));
    EXPECT_TRUE(w.ok()) << w.error().message();
    return packageFiles(tmp.file(name));
}

void expectSameBytes(const std::map<std::string, std::string>& a, const std::map<std::string, std::string>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (const auto& [name, bytes] : a) {
        const auto it = b.find(name);
        ASSERT_NE(it, b.end()) << name;
        EXPECT_TRUE(bytes == it->second) << name << " differs";
    }
}

/// One full run of the light case, shared by the tests (the chain takes a few seconds).
const Generated& baseRun() {
    static const Generated g = [] {
        auto r = generateScene(lightCase());
        EXPECT_TRUE(r.ok()) << r.error().message();
        return r.ok() ? std::move(r).value() : Generated{};
    }();
    return g;
}

} // namespace

TEST(Generate, KeepsEveryStageResultAndTimesEachStage) {
    const Generated& g = baseRun();
    for (int i = 0; i < kStageCount; ++i)
        EXPECT_TRUE(g.has(static_cast<Stage>(i))) << toString(static_cast<Stage>(i));
    ASSERT_TRUE(g.scene.has_value());
    EXPECT_EQ(g.scene->regions.size(), 5u);
    EXPECT_EQ(g.scene->tets.tets.size(), g.mesh->mesh.tets.size());
    EXPECT_EQ(g.scene->caseSpec, lightCase());
    std::vector<std::string> steps;
    for (const auto& s : g.timings.steps)
        steps.push_back(s.name);
    EXPECT_EQ(steps,
              (std::vector<std::string>{"organ", "pathology", "merge", "meshing", "tissue", "texture", "scene"}));
}

// The fitted hydrometra is the final body's (pathologies included), not the organ's before them.
TEST(Generate, ComputesTheHydrometraOnTheFinalBody) {
    const Generated& g = baseRun();
    ASSERT_TRUE(g.scene.has_value());
    EXPECT_GT(g.scene->clinical.organ.uterineVolumeMl, 0.0);
    EXPECT_EQ(g.scene->hydrometra.uterineVolumeMl, g.scene->clinical.organ.uterineVolumeMl);
    EXPECT_NE(g.scene->hydrometra.uterineVolumeMl, g.organ->dimensions.ellipsoidVolumeMl);
    for (const auto& w : g.scene->warnings)
        EXPECT_EQ(w.rfind("hydrometra:", 0), std::string::npos) << w;
}

TEST(Generate, RegeneratingTheTextureGivesTheBytesOfAFullRunOfTheEditedCase) {
    test::TempDir tmp;
    scene::CaseSpec edited = lightCase();
    edited.texture.sizePx = 128;
    edited.texture.vesselDensity = 0.5;
    std::vector<std::string> keys;
    double lowest = 1.0, highest = 0.0;
    Progress watched([&](std::string_view key, double f) {
        keys.emplace_back(key);
        lowest = std::min(lowest, f);
        highest = std::max(highest, f);
    });
    auto again = regenerateFrom(Stage::Texture, baseRun(), edited, {}, watched);
    ASSERT_TRUE(again.ok()) << again.error().message();
    // Only the texture and scene stages ran; the earlier results are the previous run's.
    ASSERT_EQ(again->timings.steps.size(), 2u);
    EXPECT_EQ(again->timings.steps[0].name, "texture");
    EXPECT_EQ(again->organ->mesh.points, baseRun().organ->mesh.points);
    EXPECT_EQ(again->mesh->mesh.tets, baseRun().mesh->mesh.tets);
    EXPECT_EQ(std::count(keys.begin(), keys.end(), "organ"), 0);
    // The rerun's own stages fill the whole progress range.
    EXPECT_LT(lowest, 0.2);
    EXPECT_DOUBLE_EQ(highest, 1.0);
    EXPECT_EQ(again->scene->surface.albedo.width(), 128);

    auto full = generateScene(edited);
    ASSERT_TRUE(full.ok()) << full.error().message();
    expectSameBytes(written(*again, tmp, "regenerated"), written(*full, tmp, "full"));
}

TEST(Generate, RegeneratingTheSceneAppliesAMaterialEdit) {
    scene::CaseSpec edited = lightCase();
    edited.scene.materials[static_cast<std::size_t>(clinical::Tissue::Myoma)].youngsModulusKpa = 100.0;
    edited.scene.hydrometraPressureKpa = 10.0;
    edited.title = "stiffer myoma";
    auto again = regenerateFrom(Stage::Scene, baseRun(), edited);
    ASSERT_TRUE(again.ok()) << again.error().message();
    ASSERT_EQ(again->timings.steps.size(), 1u);
    const auto& materials = again->scene->materials;
    ASSERT_EQ(materials.size(), 5u);
    EXPECT_EQ(materials[3].material.youngsModulusKpa, 100.0);
    EXPECT_EQ(again->scene->caseSpec.title, "stiffer myoma");
    EXPECT_NE(again->scene->hydrometra.pressureKpa, baseRun().scene->hydrometra.pressureKpa);
}

TEST(Generate, RefusesToRegenerateFromAStageAfterTheOneTheEditChanges) {
    scene::CaseSpec edited = lightCase();
    edited.pathologies[0].sizeMm = 22.0;
    auto refused = regenerateFrom(Stage::Meshing, baseRun(), edited);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(refused.error().detail.find("/pathologies"), std::string::npos) << refused.error().detail;
    EXPECT_NE(refused.error().detail.find("regenerate from 'pathology'"), std::string::npos) << refused.error().detail;

    edited = lightCase();
    edited.seed = 2;
    auto seedRefused = regenerateFrom(Stage::Pathology, baseRun(), edited);
    ASSERT_FALSE(seedRefused.ok());
    EXPECT_NE(seedRefused.error().detail.find("/seed"), std::string::npos) << seedRefused.error().detail;
}

TEST(Generate, RefusesToRegenerateWithoutTheEarlierResults) {
    Generated partial;
    partial.spec = lightCase();
    auto refused = regenerateFrom(Stage::Texture, partial, lightCase());
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(refused.error().detail.find("organ"), std::string::npos) << refused.error().detail;
}

TEST(Generate, UpdatingThroughAStageRunsOnlyFromTheEditAndClearsWhatFollows) {
    // From nothing, through the merge: the first three stages run, nothing after them.
    Generated empty;
    empty.spec = lightCase();
    auto merged = updateThrough(Stage::Merge, empty, lightCase());
    ASSERT_TRUE(merged.ok()) << merged.error().message();
    ASSERT_EQ(merged->timings.steps.size(), 3u);
    EXPECT_TRUE(merged->has(Stage::Merge));
    EXPECT_FALSE(merged->has(Stage::Meshing));
    EXPECT_EQ(merged->body->body.surfaces[0].surface.points, baseRun().body->body.surfaces[0].surface.points);

    // Up to date through the organ: nothing runs and the later results stay.
    auto same = updateThrough(Stage::Organ, baseRun(), lightCase());
    ASSERT_TRUE(same.ok()) << same.error().message();
    EXPECT_TRUE(same->has(Stage::Scene));

    // A texture edit, updated through the meshing: nothing runs, but the texture and scene are gone.
    scene::CaseSpec edited = lightCase();
    edited.texture.sizePx = 128;
    auto meshed = updateThrough(Stage::Meshing, baseRun(), edited);
    ASSERT_TRUE(meshed.ok()) << meshed.error().message();
    EXPECT_TRUE(meshed->has(Stage::Tissue));
    EXPECT_FALSE(meshed->has(Stage::Texture));
    EXPECT_FALSE(meshed->has(Stage::Scene));
    EXPECT_EQ(meshed->spec, edited);

    // A pathology edit, through the pathology stage: only it runs, the organ is the previous one.
    edited = lightCase();
    edited.pathologies[0].sizeMm = 22.0;
    auto grown = updateThrough(Stage::Pathology, baseRun(), edited);
    ASSERT_TRUE(grown.ok()) << grown.error().message();
    ASSERT_EQ(grown->timings.steps.size(), 1u);
    EXPECT_EQ(grown->timings.steps[0].name, "pathology");
    EXPECT_FALSE(grown->has(Stage::Merge));
}

TEST(Generate, FirstChangedStageNamesTheEarliestStageAndField) {
    const scene::CaseSpec a = lightCase();
    EXPECT_FALSE(firstChangedStage(a, a).has_value());
    scene::CaseSpec b = a;
    b.meshing.threads = 1; // never changes a result
    EXPECT_FALSE(firstChangedStage(a, b).has_value());
    b.title = "x";
    EXPECT_EQ(firstChangedStage(a, b)->stage, Stage::Scene);
    EXPECT_EQ(firstChangedStage(a, b)->field, "/title");
    b.texture.sizePx = 512;
    EXPECT_EQ(firstChangedStage(a, b)->stage, Stage::Texture);
    b.meshing.relaxationIterations = 10;
    EXPECT_EQ(firstChangedStage(a, b)->stage, Stage::Meshing);
    b.pathologies.pop_back();
    EXPECT_EQ(firstChangedStage(a, b)->stage, Stage::Pathology);
    b.patient.ageYears = 50.0;
    EXPECT_EQ(firstChangedStage(a, b)->stage, Stage::Organ);
    EXPECT_EQ(firstChangedStage(a, b)->field, "/patient");
}

// A myoma of FIGO 4-7 is placed clear of the lining the tissue stage lays later: the case's thickness, when it gives
// one, is then the pathology stage's input; the cycle phase is not (placement clears the cycle's thickest lining).
TEST(Generate, TheEndometrialThicknessReachesBackToThePathologies) {
    scene::CaseSpec a = lightCase();
    a.patient.menopausal = false;
    a.patient.cyclePhase = clinical::CyclePhase::Proliferative;
    a.anatomy.endometrialThicknessMm.reset();
    scene::CaseSpec b = a;
    b.patient.cyclePhase = clinical::CyclePhase::Secretory;
    ASSERT_TRUE(firstChangedStage(a, b));
    EXPECT_EQ(firstChangedStage(a, b)->stage, Stage::Tissue);
    EXPECT_EQ(placementLiningMm(a), placementLiningMm(b));
    EXPECT_GE(placementLiningMm(a), tissueLayerParamsFor(b).endometriumThicknessMm);
    EXPECT_EQ(pathologyParamsFor(a).endometriumThicknessMm, placementLiningMm(a));
    b.anatomy.endometrialThicknessMm = 14.0;
    EXPECT_EQ(firstChangedStage(a, b)->stage, Stage::Pathology);
    EXPECT_EQ(firstChangedStage(a, b)->field, "/anatomy/endometrialThicknessMm");
    EXPECT_EQ(placementLiningMm(b), 7.0);
    b.pathologies.clear();
    a.pathologies.clear();
    EXPECT_EQ(firstChangedStage(a, b)->stage, Stage::Tissue); // nothing to place
}

TEST(Generate, RefusesAnInvalidCaseNamingTheField) {
    scene::CaseSpec bad = lightCase();
    bad.pathologies[0].figo = clinical::FigoType{9, -1};
    GenerateParams params;
    params.caseFile = "bad.json";
    auto refused = generateScene(bad, params);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(refused.error().detail.find("bad.json: /pathologies/0/figo"), std::string::npos)
        << refused.error().detail;
}

TEST(Generate, StopsWhenCancelled) {
    Progress progress;
    progress.requestCancel();
    auto cancelled = generateScene(lightCase(), {}, progress);
    ASSERT_FALSE(cancelled.ok());
    EXPECT_EQ(cancelled.error().code, ErrorCode::Cancelled);
}

TEST(Generate, SplitsTheWallIntoMyometriumEndometriumAndCervixWithTheirOwnMaterials) {
    const Generated& g = baseRun();
    const auto& tissue = *g.tissue;
    const auto& regions = g.scene->regions;
    ASSERT_EQ(regions.size(), 5u);
    EXPECT_EQ(regions[0].tissue, clinical::Tissue::Myometrium);
    EXPECT_EQ(regions[1].tissue, clinical::Tissue::Endometrium);
    EXPECT_EQ(regions[2].tissue, clinical::Tissue::Cervix);
    EXPECT_EQ(regions[3].tissue, clinical::Tissue::Myoma);
    EXPECT_EQ(regions[4].tissue, clinical::Tissue::Polyp);
    const auto volumes = regionVolumes(g.scene->tets);
    for (const auto& r : regions)
        EXPECT_GT(volumes.at(r.id), 0.0) << r.name;
    // The lining's volume per area is within about an edge of the lining asked (it runs high where the cavity curves).
    const double edge = g.mesh->targetEdgeLength;
    const double asked = tissueLayerParamsFor(g.spec).endometriumThicknessMm;
    EXPECT_NEAR(tissue.layers.endometriumVolumePerLiningAreaMm(), asked, edge);
    // The merged body drapes the wall over what reaches into the cavity (the FIGO 2 myoma, the sessile polyp), so the
    // lining covers them.
    EXPECT_FALSE(tetsTouching(g.scene->tets, pathologyRegion(0), kEndometriumRegion).empty());
    EXPECT_FALSE(tetsTouching(g.scene->tets, pathologyRegion(1), kEndometriumRegion).empty());
    // The cervix: about the volume of a cylinder of the organ's cervix (30 mm x 28.5 mm), less the canal.
    EXPECT_GT(tissue.layers.cervixVolumeMm3, 5000.0);
    EXPECT_LT(tissue.layers.cervixVolumeMm3, 25000.0);
    // Each tissue region gets its tissue's material.
    const auto& materials = g.scene->materials;
    ASSERT_EQ(materials.size(), regions.size());
    EXPECT_EQ(materials[1].material.youngsModulusKpa,
              scene::defaultMaterial(clinical::Tissue::Endometrium).youngsModulusKpa);
    EXPECT_EQ(materials[2].material.youngsModulusKpa,
              scene::defaultMaterial(clinical::Tissue::Cervix).youngsModulusKpa);
    // Every tet is in exactly one region, and the pathologies keep their meshed volume (cover included).
    EXPECT_EQ(g.scene->tets.tets.size(), g.mesh->mesh.tets.size());
    std::printf("layers: endometrium %zu tets (%.0f mm3, %.2f mm thick for %.2f asked, edge %.2f mm), cover %zu tets, "
                "cervix %zu tets (%.0f mm3)\n",
                tissue.layers.endometriumTets, tissue.layers.endometriumVolumeMm3,
                tissue.layers.endometriumVolumePerLiningAreaMm(), asked, edge, tissue.layers.coverTets,
                tissue.layers.cervixTets, tissue.layers.cervixVolumeMm3);
}

// Where the coarse simulation mesh is thinner than the visual surface, a point's weights are clamped and it is bound
// off its tet: the scene says so (it did not), with the count and the largest offset; a point on its tet says nothing.
TEST(Generate, NamesTheVisualPointsBoundOffTheirSimulationTet) {
    scene::SimulationMesh sim;
    sim.tets.points = {{0.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 4.0, 0.0}, {0.0, 0.0, 4.0}};
    sim.tets.tets = {{0, 1, 2, 3}};
    SurfaceMesh visual;
    visual.points = {{1.0, 1.0, 1.0}};
    sim.surfaceEmbedding = {TetEmbedding{0, {0.25, 0.25, 0.25, 0.25}}};
    EXPECT_EQ(generate::simulationBindingWarning(visual, sim), "");
    visual.points.push_back({1.0, 1.0, 3.5}); // bound to the tet's centre (1, 1, 1), 2.5 mm away
    sim.surfaceEmbedding.push_back(TetEmbedding{0, {0.25, 0.25, 0.25, 0.25}});
    const std::string w = generate::simulationBindingWarning(visual, sim);
    EXPECT_EQ(w.rfind("simulation: 1 of 2 visual surface points are bound up to 2.50 mm off their simulation tet", 0),
              0u)
        << w;
}

// The one export (CLI, workstation, batch): each variant generated, written, read back against its manifest, zipped
// and swept by the scope; progress per variant; the same bytes as the chain written by hand; parallel jobs change
// nothing.
TEST(Export, WritesReadsBackZipsAndSweepsEachVariant) {
    test::TempDir tmp;
    scene::CaseSpec spec = lightCase();
    spec.pathologies.clear(); // two new patients: keep them light
    ExportParams params;
    params.folder = tmp.file("variants");
    params.variants = 2;
    params.jobs = 2;
    params.zip = true;
    std::mutex mutex;
    std::map<std::size_t, double> lastFraction;
    params.variantProgress = [&](std::size_t i, std::string_view, double f) {
        std::lock_guard<std::mutex> lock(mutex);
        lastFraction[i] = f;
    };
    std::map<std::size_t, std::size_t> tets;
    params.onExported = [&](const ExportedPackage& p, Generated&& g) {
        std::lock_guard<std::mutex> lock(mutex);
        tets[p.index] = g.scene->tets.tets.size();
    };
    auto exported = exportScenes(spec, {}, params);
    ASSERT_TRUE(exported.ok()) << exported.error().message();
    ASSERT_EQ(exported->size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        const ExportedPackage& p = (*exported)[i];
        ASSERT_FALSE(p.error) << p.error->message();
        EXPECT_EQ(p.index, i);
        EXPECT_EQ(p.seed, exportSeed(spec.seed, i, 2));
        EXPECT_EQ(p.folder, tmp.file("variants/" + variantFolderName(i)));
        auto manifest = scene::verifyScenePackage(p.folder);
        ASSERT_TRUE(manifest.ok()) << manifest.error().message();
        EXPECT_EQ(p.files, manifest->files.size());
        EXPECT_TRUE(fs::is_regular_file(p.zipPath)) << p.zipPath;
        EXPECT_TRUE(p.scope.checked) << p.scope.uncheckedBecause;
        EXPECT_EQ(p.scope.scopeDiameterMm, 2.9);
        EXPECT_GT(p.scope.narrowestMm, 0.0);
        EXPECT_EQ(lastFraction[i], 1.0);
        EXPECT_GT(tets[i], 0u);
        for (const char* step : {"organ", "scene", "package", "scope"})
            EXPECT_TRUE(std::any_of(p.timings.steps.begin(), p.timings.steps.end(), [&](const StepTiming& t) {
                return t.name == step;
            })) << step;
    }
    EXPECT_NE((*exported)[0].seed, (*exported)[1].seed);
    EXPECT_TRUE(firstFailure(*exported).ok());

    // Variant 1 is the chain on its seed, written by hand, byte for byte.
    scene::CaseSpec variant = spec;
    variant.seed = exportSeed(spec.seed, 1, 2);
    auto direct = generateScene(variant);
    ASSERT_TRUE(direct.ok()) << direct.error().message();
    expectSameBytes(packageFiles((*exported)[1].folder), written(*direct, tmp, "direct"));
}

// A session's earlier results are brought up to date rather than rerun; the package is the same as a fresh one.
TEST(Export, FromPreviousResultsGivesTheSameBytes) {
    test::TempDir tmp;
    ExportParams params;
    params.folder = tmp.file("deep/er/scene"); // the folders that hold it are created
    params.checkScope = false;
    params.previous = std::make_shared<const Generated>(baseRun());
    auto exported = exportScenes(lightCase(), {}, params);
    ASSERT_TRUE(exported.ok()) << exported.error().message();
    ASSERT_FALSE((*exported)[0].error) << (*exported)[0].error->message();
    EXPECT_FALSE((*exported)[0].scope.checked);
    // Nothing was rerun: the timings are the previous run's stages plus the package.
    EXPECT_EQ((*exported)[0].timings.steps.size(), baseRun().timings.steps.size() + 1);
    expectSameBytes(packageFiles(params.folder), written(baseRun(), tmp, "fresh"));
}

// A variant that cannot be written fails alone and is named; the others are written. Out-of-range parameters and a
// cancel are refused before anything is written.
TEST(Export, NamesAFailedVariantAndRefusesBadParametersAndACancel) {
    test::TempDir tmp;
    scene::CaseSpec spec = lightCase();
    spec.pathologies.clear();
    fs::create_directories(tmp.file("variants"));
    std::ofstream(tmp.file("variants/variant-001")) << "a file where variant 1's folder goes";
    ExportParams params;
    params.folder = tmp.file("variants");
    params.variants = 2;
    params.checkScope = false;
    params.previous = std::make_shared<const Generated>(baseRun()); // ignored: variants are new patients
    auto exported = exportScenes(spec, {}, params);
    ASSERT_TRUE(exported.ok()) << exported.error().message();
    EXPECT_FALSE((*exported)[0].error);
    EXPECT_TRUE(scene::verifyScenePackage((*exported)[0].folder).ok());
    ASSERT_TRUE((*exported)[1].error);
    const Status first = firstFailure(*exported);
    ASSERT_FALSE(first.ok());
    EXPECT_EQ(first.error().detail.rfind("variant 1: ", 0), 0u) << first.error().detail;
    EXPECT_TRUE(fs::is_regular_file(tmp.file("variants/variant-001"))); // left as it was

    ExportParams bad;
    bad.folder = tmp.file("bad");
    bad.variants = 0;
    auto refused = exportScenes(spec, {}, bad);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(refused.error().detail.find("variants 0 is out of range (1 to 10000)"), std::string::npos)
        << refused.error().detail;
    bad.variants = 1;
    bad.folder.clear();
    EXPECT_EQ(exportScenes(spec, {}, bad).error().code, ErrorCode::InvalidInput);

    Progress cancelled;
    cancelled.requestCancel();
    ExportParams params2;
    params2.folder = tmp.file("cancelled");
    auto stopped = exportScenes(spec, {}, params2, cancelled);
    ASSERT_FALSE(stopped.ok());
    EXPECT_EQ(stopped.error().code, ErrorCode::Cancelled);
    EXPECT_FALSE(fs::exists(params2.folder));
}

// A cancel is taken between the steps that report no progress of their own (found by bench_jobs in the window: the
// scene's hydrometra solves held a cancel for seconds, the close-up surface and the mesher's cleaning for 370 ms):
// cancelled as each step begins, the chain stops there and names it.
TEST(Generate, StopsOnACancelBetweenStepsThatReportNoProgress) {
    const struct {
        Stage from;
        const char* key;
        const char* named;
    } cases[] = {{Stage::Meshing, "meshing.clean", "meshing cancelled while cleaning the tetrahedra"},
                 {Stage::Texture, "texture.closeUp", "texture cancelled while refining the close-up surface"},
                 {Stage::Texture, "texture.bind", "texture cancelled while binding the visual surface to the tets"},
                 {Stage::Scene, "scene.hydrometra", "hydrometra curve cancelled"}};
    for (const auto& c : cases) {
        Progress* self = nullptr;
        Progress progress([&](std::string_view key, double) {
            if (key == c.key)
                self->requestCancel();
        });
        self = &progress;
        auto stopped = regenerateFrom(c.from, baseRun(), lightCase(), {}, progress);
        ASSERT_FALSE(stopped.ok()) << c.key;
        EXPECT_EQ(stopped.error().code, ErrorCode::Cancelled) << c.key;
        EXPECT_NE(stopped.error().detail.find(c.named), std::string::npos) << c.key << ": " << stopped.error().detail;
    }
}
