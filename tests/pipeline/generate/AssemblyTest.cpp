#include "hs/generate/Assembly.h"

#include "hs/anatomy/UterusGenerator.h"
#include "hs/meshing/BaselineMeshers.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace hs;
using namespace hs::generate;

namespace {

scene::CaseSpec twoPathologyCase() {
    scene::CaseSpec spec = scene::defaultCase(); // myoma-1 (FIGO 2, left lateral), polyp-1 (sessile, right cornual)
    return spec;
}

/// Two tets sharing the face (1, 2, 3): tet 0 in body region 0 (wall), tet 1 in body region 1 (the first
/// pathology), and a third tet of region 2 touching only tet 1 at a vertex.
TetMesh threeTets() {
    TetMesh m;
    m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {2, 2, 2}, {3, 2, 2}, {2, 3, 2}};
    m.tets = {{0, 1, 2, 3}, {1, 3, 2, 4}, {4, 5, 6, 7}};
    m.regions = {0, 1, 2};
    return m;
}

} // namespace

TEST(Assembly, RegionsAreTheWallTissuesPresentThenOnePerPathologyInCaseOrder) {
    TetMesh tets = threeTets();
    tets.regions = {kMyometriumRegion, kCervixRegion, pathologyRegion(0)};
    const auto regions = sceneRegions(twoPathologyCase(), tets);
    ASSERT_EQ(regions.size(), 4u);
    EXPECT_EQ(regions[0].id, kMyometriumRegion);
    EXPECT_EQ(regions[0].name, "myometrium");
    EXPECT_EQ(regions[0].tissue, clinical::Tissue::Myometrium);
    EXPECT_EQ(regions[1].id, kCervixRegion); // no endometrium tet: no endometrium region
    EXPECT_EQ(regions[1].tissue, clinical::Tissue::Cervix);
    EXPECT_EQ(regions[2].id, 4);
    EXPECT_EQ(regions[2].name, "myoma-1");
    EXPECT_EQ(regions[2].tissue, clinical::Tissue::Myoma);
    EXPECT_EQ(regions[2].pathologyId, "myoma-1");
    EXPECT_EQ(regions[3].id, 5);
    EXPECT_EQ(regions[3].tissue, clinical::Tissue::Polyp);
    EXPECT_EQ(pathologyRegion(1), 5);
}

TEST(Assembly, SceneTetsGiveTheWallItsLayersAndThePathologiesTheirOwnIds) {
    const TetMesh plain = sceneTets(threeTets());
    EXPECT_EQ(plain.regions, (std::vector<std::int32_t>{1, 4, 5}));
    EXPECT_EQ(plain.tets, threeTets().tets);
    const TetMesh layered = sceneTets(threeTets(), {WallLayer::Cervix, WallLayer::Endometrium, WallLayer::Myometrium});
    EXPECT_EQ(layered.regions, (std::vector<std::int32_t>{kCervixRegion, kEndometriumRegion, 5}));
}

TEST(Assembly, TetsTouchingFindsOnlyTetsSharingAFace) {
    const TetMesh m = sceneTets(threeTets());
    EXPECT_EQ(tetsTouching(m, 4, 1), (std::vector<std::int32_t>{1}));
    EXPECT_EQ(tetsTouching(m, 1, 4), (std::vector<std::int32_t>{0}));
    EXPECT_TRUE(tetsTouching(m, 5, 4).empty()); // shares a vertex only
    EXPECT_TRUE(tetsTouching(m, 6, 1).empty()); // no such region
}

TEST(Assembly, FacesWithListsMatchingFacesAscendingAndNothingForAMissingLabel) {
    SurfaceMesh s;
    s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    s.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    s.faceLabels["tissue"] = {2, 4, 2, 3};
    EXPECT_EQ(facesWith(s, "tissue", 2), (std::vector<std::int32_t>{0, 2}));
    EXPECT_TRUE(facesWith(s, "tissue", 9).empty());
    EXPECT_TRUE(facesWith(s, "absent", 2).empty());
}

TEST(Assembly, LabelsComeInContactBaseOstiaCanalOrderAndEmptySetsAreLeftOut) {
    const auto spec = twoPathologyCase();
    const TetMesh tets = sceneTets(threeTets());
    SurfaceMesh visual;
    visual.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    visual.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    const auto ostium = clinical::labelValue(clinical::SurfaceTissue::TubalOstium);
    const auto canal = clinical::labelValue(clinical::SurfaceTissue::CervicalCanal);
    visual.faceLabels[clinical::kSurfaceTissueLabel] = {ostium, 2, canal, canal};
    visual.faceLabels[merge::kPathologyLabel] = {0, 1, 1, 0}; // faces 1, 2 over the myoma; none over the polyp
    const auto labels = sceneLabels(spec, tets, visual);
    ASSERT_EQ(labels.size(), 4u);
    EXPECT_EQ(labels[0].name, "contact:myoma-1");
    EXPECT_EQ(labels[0].kind, scene::LabelKind::Contact);
    EXPECT_EQ(labels[0].element, scene::LabelElement::SurfaceFace);
    EXPECT_EQ(labels[0].indices, (std::vector<std::int32_t>{1, 2}));
    EXPECT_EQ(labels[1].name, "base:myoma-1"); // the polyp's region (5) shares no face with the wall
    EXPECT_EQ(labels[1].element, scene::LabelElement::Tet);
    EXPECT_EQ(labels[1].indices, (std::vector<std::int32_t>{1}));
    EXPECT_EQ(labels[2].name, "ostia");
    EXPECT_EQ(labels[2].indices, (std::vector<std::int32_t>{0}));
    EXPECT_EQ(labels[3].name, "cervical-canal");
    EXPECT_EQ(labels[3].indices, (std::vector<std::int32_t>{2, 3}));
}

TEST(Assembly, DescriptorsTakeTheMeasuredSizeAndTheMeshedVolume) {
    const auto spec = twoPathologyCase();
    pathology::PathologyResult grown;
    grown.pathologies.resize(2);
    grown.pathologies[0].id = "myoma-1";
    grown.pathologies[0].kind = clinical::PathologyKind::Myoma;
    grown.pathologies[0].descriptors.sizeMm = 19.5;
    grown.pathologies[0].descriptors.figo = clinical::FigoType{2, -1};
    grown.pathologies[0].descriptors.lasmar = clinical::LasmarScore{0, 1, 1, 2, 1};
    grown.pathologies[1].id = "polyp-1";
    grown.pathologies[1].kind = clinical::PathologyKind::Polyp;
    grown.pathologies[1].descriptors.sizeMm = 9.8;
    anatomy::UterusDimensions organ;
    organ.lengthMm = 70.0;
    organ.ellipsoidVolumeMl = 80.0;
    const TetMesh tets = threeTets(); // body region ids
    const auto c = clinicalDescriptors(spec, organ, grown, tets);
    EXPECT_EQ(c.organ.lengthMm, 70.0);
    EXPECT_EQ(c.organ.uterineVolumeMl, 80.0);
    ASSERT_EQ(c.pathologies.size(), 2u);
    const auto& myoma = c.pathologies[0];
    EXPECT_EQ(myoma.regionId, 4);
    EXPECT_EQ(myoma.sizeMm, 19.5);
    EXPECT_NEAR(myoma.volumeMl, std::abs(signedVolume(tets, 1)) / 1000.0, 1e-12);
    ASSERT_TRUE(myoma.figo && myoma.lasmar);
    EXPECT_EQ(myoma.figo->toString(), "2");
    EXPECT_EQ(myoma.lasmar->total(), 5);
    EXPECT_EQ(myoma.location, "left-lateral");
    const auto& polyp = c.pathologies[1];
    EXPECT_EQ(polyp.kind, clinical::PathologyKind::Polyp);
    EXPECT_FALSE(polyp.figo.has_value());
    EXPECT_EQ(polyp.location, "cornual-right");
}

TEST(Assembly, QualityCarriesEveryFigureOfTheReport) {
    meshing::QualityReport q;
    q.vertexCount = 10;
    q.tetCount = 20;
    q.meanRadiusRatio = 0.9;
    q.minDihedralDeg = 17.0;
    q.radiusRatioHistogram[9] = 20;
    q.sliverCount = 1;
    q.hasReference = true;
    q.hausdorffDistance = 0.5;
    q.hausdorffRelative = 0.01;
    q.volumeError = 0.002;
    const auto m = qualityOf(q);
    EXPECT_EQ(m.vertexCount, 10u);
    EXPECT_EQ(m.tetCount, 20u);
    EXPECT_EQ(m.meanRadiusRatio, 0.9);
    EXPECT_EQ(m.minDihedralDeg, 17.0);
    ASSERT_EQ(m.radiusRatioHistogram.size(), 10u);
    EXPECT_EQ(m.radiusRatioHistogram[9], 20u);
    EXPECT_EQ(m.minDihedralHistogram.size(), 9u);
    EXPECT_EQ(m.sliverCount, 1u);
    EXPECT_TRUE(m.hasReference);
    EXPECT_EQ(m.hausdorffDistanceMm, 0.5);
    EXPECT_EQ(m.hausdorffRelative, 0.01);
    EXPECT_EQ(m.volumeError, 0.002);
}

TEST(Assembly, ToolVersionsNameEveryLibraryThatShapesTheScene) {
    const auto versions = toolVersionsFor(twoPathologyCase());
    for (const char* library : {"hysteroscene", "compiler", "cgal", "eigen", "hdf5", "minizip", "nlohmann-json",
                                "opencv", "openimageio", "tinygltf", "vtk", "zlib"}) {
        const auto it = versions.find(library);
        ASSERT_NE(it, versions.end()) << library;
        EXPECT_FALSE(it->second.empty()) << library;
        EXPECT_LE(it->second.size(), 64u) << library;
    }
    EXPECT_EQ(versions.at("hysteroscene"), HS_VERSION);
    EXPECT_EQ(versions.count("tetgen"), 0u) << "the default case meshes with the particle mesher";
    EXPECT_EQ(toolVersionsFor(twoPathologyCase()), versions) << "one build, the same versions every time";
}

TEST(Assembly, ToolVersionsNameTetGenWhenTheCaseMeshesWithIt) {
    scene::CaseSpec spec = twoPathologyCase();
    spec.meshing.method = scene::MeshingMethod::TetGen;
    if (!meshing::methodAvailable(meshing::MeshMethod::TetGen))
        GTEST_SKIP() << "this build has no TetGen";
    const auto versions = toolVersionsFor(spec);
    ASSERT_EQ(versions.count("tetgen"), 1u);
    EXPECT_FALSE(versions.at("tetgen").empty());
}

TEST(Assembly, SupportLabelMarksTheTetsWithinTheCervixLengthOfTheExternalOs) {
    const auto label = supportLabel(threeTets(), 1.8); // tets 0 and 1 reach at most sqrt(3) from the origin
    EXPECT_EQ(label.name, scene::kSupportLabel);
    EXPECT_EQ(label.kind, scene::LabelKind::Other);
    EXPECT_EQ(label.element, scene::LabelElement::Tet);
    EXPECT_EQ(label.indices, (std::vector<std::int32_t>{0, 1}));
    EXPECT_EQ(supportLabel(threeTets(), 1.0).indices, (std::vector<std::int32_t>{0}));
    EXPECT_TRUE(supportLabel(threeTets(), 0.5).indices.empty());
}
