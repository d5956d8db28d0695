// The scope passage on the generated default scene: its landmarks come from the scene's labels, its narrowest width
// is measured and printed, and a 2.9 mm office hysteroscope gets through (docs/scene-format.md, "Scope passage").
#include "hs/generate/Generate.h"
#include "hs/scene/ScopePassage.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace hs;

TEST(ScopePassageScene, MeasuresTheNarrowestWidthOfTheDefaultScene) {
    auto spec = scene::loadCase(HS_DEFAULT_CASE_FILE);
    ASSERT_TRUE(spec.ok()) << spec.error().message();
    scene::CaseSpec s = *spec;
    s.texture.sizePx = 256; // the tets are those of the default scene; only the maps are smaller
    auto generated = generate::generateScene(s, {HS_DEFAULT_CASE_FILE, 2, {}});
    ASSERT_TRUE(generated.ok()) << generated.error().message();
    ASSERT_TRUE(generated->scene.has_value());
    const scene::Scene& sc = *generated->scene;

    auto landmarks = scene::findScopeLandmarks(sc);
    ASSERT_TRUE(landmarks.ok()) << landmarks.error().message();
    const double canalMm = distance(landmarks->externalOsMm, landmarks->internalOsMm);
    EXPECT_GT(canalMm, 15.0); // cervix about 30 mm long (docs/references.md [CervixParity])
    EXPECT_LT(canalMm, 45.0);

    auto passage = scene::checkScopePassage(sc.tets, *landmarks);
    ASSERT_TRUE(passage.ok()) << passage.error().message();
    ASSERT_FALSE(passage->route.empty());
    const auto& n = passage->narrowest;
    std::printf("default scene: narrowest %.2f mm (%s, at %.1f mm along the route, (%.1f, %.1f, %.1f) mm), open %d, "
                "2.9 mm ball %s, straight stretch %.2f mm, route %.1f mm, grid %lld x %lld x %lld of %.2f mm\n",
                n.freeWidthMm, std::string(scene::toString(n.part)).c_str(), n.arcLengthMm, n.positionMm.x,
                n.positionMm.y, n.positionMm.z, int(passage->open), passage->ballPasses ? "passes" : "does not pass",
                passage->straightWidthMm, passage->route.back().arcLengthMm, (long long)passage->gridDims[0],
                (long long)passage->gridDims[1], (long long)passage->gridDims[2], passage->voxelSizeMm);
    EXPECT_GE(n.freeWidthMm, 0.0);
    EXPECT_LT(n.freeWidthMm, 12.0); // the widest real internal os is 11 mm (docs/references.md [Chen2020])
    EXPECT_EQ(passage->ballPasses, n.freeWidthMm >= 2.9);
    EXPECT_TRUE(passage->open);
    EXPECT_GE(n.freeWidthMm, 2.9);
    // The route runs from outside the external os into the cavity and is at least as long as the canal.
    EXPECT_EQ(passage->route.front().part, scene::PassagePart::Outside);
    EXPECT_EQ(passage->route.back().part, scene::PassagePart::Cavity);
    EXPECT_GT(passage->route.back().arcLengthMm, canalMm);
}
