// The scene model: SHA-256, hydrometra, material assignment and the consistency check.

#include "SyntheticScene.h"
#include "hs/scene/Hydrometra.h"
#include "hs/scene/Scene.h"
#include "hs/scene/Sha256.h"

#include <gtest/gtest.h>

#include <string>

using namespace hs;
using namespace hs::scene;

TEST(Sha256, MatchesTheNistTestVectors) {
    EXPECT_EQ(sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    EXPECT_EQ(sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    EXPECT_EQ(sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
              "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    EXPECT_EQ(sha256Hex(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, GivesTheSameDigestWhateverTheChunking) {
    const std::string text(1000, 'x');
    Sha256 sha;
    for (std::size_t i = 0; i < text.size(); i += 7)
        sha.update(std::string_view(text).substr(i, 7));
    const auto digest = sha.finish();
    std::string hex;
    for (const auto b : digest) {
        static const char* kHex = "0123456789abcdef";
        hex += kHex[b >> 4];
        hex += kHex[b & 15];
    }
    EXPECT_EQ(hex, sha256Hex(text));
}

TEST(Hydrometra, FollowsTheQuadraticFitAtTwentyKilopascal) {
    const auto h = computeHydrometra(100.0, 20.0);
    ASSERT_TRUE(h.ok());
    EXPECT_NEAR(h->cavityVolumeMl, 0.00037 * 100.0 * 100.0 + 0.036 * 100.0, 1e-12);
    EXPECT_FALSE(h->extrapolated);
}

TEST(Hydrometra, ScalesLinearlyBelowTheMeasuredPressureAndIsEmptyAtZero) {
    EXPECT_NEAR(computeHydrometra(100.0, 10.0)->cavityVolumeMl, computeHydrometra(100.0, 20.0)->cavityVolumeMl / 2,
                1e-12);
    EXPECT_EQ(computeHydrometra(100.0, 0.0)->cavityVolumeMl, 0.0);
}

TEST(Hydrometra, FlagsVolumesOutsideTheMeasuredRangeAndRefusesBadInput) {
    EXPECT_TRUE(computeHydrometra(5.0, 20.0)->extrapolated);
    EXPECT_TRUE(computeHydrometra(500.0, 20.0)->extrapolated);
    EXPECT_EQ(computeHydrometra(-1.0, 8.0).error().code, ErrorCode::InvalidInput);
    EXPECT_EQ(computeHydrometra(80.0, 25.0).error().code, ErrorCode::InvalidInput);
}

TEST(AssignMaterials, GivesEachRegionItsTissueDefaultAndWritesTheMaterialArray) {
    const Scene scene = test::syntheticScene();
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[0].material.youngsModulusKpa,
              defaultMaterial(clinical::Tissue::Myometrium).youngsModulusKpa);
    EXPECT_EQ(scene.materials[1].material.youngsModulusKpa, defaultMaterial(clinical::Tissue::Myoma).youngsModulusKpa);
    const auto& ids = scene.tets.tetLabels.at(kMaterialLabel);
    for (std::size_t t = 0; t < scene.tets.tetCount(); ++t)
        EXPECT_EQ(ids[t], scene.tets.regionOf(t) == 1 ? 1 : 0);
    EXPECT_EQ(scene.tets.tetLabels.count(kYoungsModulusLabel), 0u);
    EXPECT_TRUE(checkScene(scene).ok()) << checkScene(scene).error().message();
}

TEST(AssignMaterials, AppliesTheCaseOverrides) {
    Scene scene = test::syntheticScene();
    SceneParams params;
    params.materials[static_cast<std::size_t>(clinical::Tissue::Myoma)].youngsModulusKpa = 100.0;
    const auto materials = assignMaterials(scene.tets, scene.regions, params);
    ASSERT_TRUE(materials.ok());
    EXPECT_EQ((*materials)[1].material.youngsModulusKpa, 100.0);
}

TEST(AssignMaterials, DrawsSeededHeterogeneityInsideTheTissueRange) {
    test::SyntheticSceneOptions options;
    options.heterogeneity = 0.3;
    const Scene a = test::syntheticScene(options);
    const Scene b = test::syntheticScene(options);
    const auto& e = a.tets.tetLabels.at(kYoungsModulusLabel);
    EXPECT_EQ(e, b.tets.tetLabels.at(kYoungsModulusLabel));
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t t = 0; t < a.tets.tetCount(); ++t) {
        const auto& m = a.materials[static_cast<std::size_t>(a.tets.tetLabels.at(kMaterialLabel)[t])];
        EXPECT_GE(e[t], m.youngsModulusRangeKpa.min * 1000.0 - 1);
        EXPECT_LE(e[t], m.youngsModulusRangeKpa.max * 1000.0 + 1);
        if (m.tissue == clinical::Tissue::Myometrium) {
            sum += e[t];
            ++count;
        }
    }
    EXPECT_NEAR(sum / static_cast<double>(count) / 1000.0, 30.0, 3.0); // mean-preserving draw
    options.seed = 8;
    EXPECT_NE(e, test::syntheticScene(options).tets.tetLabels.at(kYoungsModulusLabel));
}

TEST(AssignMaterials, RefusesTetsInARegionWithoutMaterial) {
    Scene scene = test::syntheticScene();
    scene.tets.regions[0] = 5;
    const auto materials = assignMaterials(scene.tets, scene.regions, SceneParams{});
    ASSERT_FALSE(materials.ok());
    EXPECT_NE(materials.error().detail.find("region 5"), std::string::npos);
}

TEST(CheckScene, NamesTheFirstInconsistency) {
    Scene scene = test::syntheticScene();
    scene.surface.uvs.pop_back();
    EXPECT_NE(checkScene(scene).error().detail.find("UVs"), std::string::npos);
    scene = test::syntheticScene();
    scene.labels[0].indices.push_back(0);
    EXPECT_NE(checkScene(scene).error().detail.find("ascending"), std::string::npos);
    scene = test::syntheticScene();
    scene.labels[1].name = "../evil";
    EXPECT_EQ(checkScene(scene).error().code, ErrorCode::InvalidInput);
}
