// The scope passage on the generated default scene: its landmarks come from the scene's labels, its narrowest width
// is measured and printed, and a 2.9 mm office hysteroscope gets through (docs/scene-format.md, "Scope passage").
#include "hs/generate/Generate.h"
#include "hs/scene/ScopePassage.h"
#include "hs/scene/ScopeView.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <optional>

using namespace hs;

namespace {

/// The default scene, generated once for the tests of this file.
const scene::Scene* defaultScene() {
    static const std::optional<scene::Scene> generated = []() -> std::optional<scene::Scene> {
        auto spec = scene::loadCase(HS_DEFAULT_CASE_FILE);
        if (!spec.ok())
            return std::nullopt;
        scene::CaseSpec s = *spec;
        s.texture.sizePx = 256; // the tets are those of the default scene; only the maps are smaller
        auto result = generate::generateScene(s, {HS_DEFAULT_CASE_FILE, 2, {}});
        if (!result.ok() || !result->scene)
            return std::nullopt;
        return std::move(*result->scene);
    }();
    return generated ? &*generated : nullptr;
}

} // namespace

TEST(ScopePassageScene, MeasuresTheNarrowestWidthOfTheDefaultScene) {
    ASSERT_NE(defaultScene(), nullptr) << "the default case did not generate";
    const scene::Scene& sc = *defaultScene();

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

// The default case's polyp is asked for in the right cornu and its myoma on the left wall: both grow beside the
// ostium of their side, so the scope sees both ostia from the cavity's middle (before, the polyp covered the right
// ostium, which had no faces left, and the exploration exercise could not be completed).
TEST(ScopePassageScene, TheDefaultSceneShowsBothOstiaFromTheCavitysMiddle) {
    ASSERT_NE(defaultScene(), nullptr) << "the default case did not generate";
    auto landmarks = scene::findScopeLandmarks(*defaultScene());
    ASSERT_TRUE(landmarks.ok()) << landmarks.error().message();
    EXPECT_EQ(landmarks->ostiaFound, 2);
    auto passage = scene::checkScopePassage(defaultScene()->tets, *landmarks);
    ASSERT_TRUE(passage.ok()) << passage.error().message();
    auto ostia = scene::ostiaInSight(*defaultScene(), scene::cavityViewpoint(*defaultScene(), *passage));
    ASSERT_TRUE(ostia.ok()) << ostia.error().message();
    ASSERT_EQ(ostia->size(), 2u);
    for (const auto& o : *ostia) {
        std::printf("default scene: %s ostium at (%.1f, %.1f, %.1f) mm, %zu faces, %.0f %% in sight\n", o.side.c_str(),
                    o.centreMm.x, o.centreMm.y, o.centreMm.z, o.faces, 100.0 * o.visibleFraction);
        EXPECT_GE(o.visibleFraction, 0.9) << o.side;
    }
}
