#include "hs/scene/MeshBars.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

hs::scene::MeshQuality goodMesh() {
    hs::scene::MeshQuality q;
    q.meanRadiusRatio = 0.92;
    q.minDihedralDeg = 20.0;
    q.hasReference = true;
    q.hausdorffRelative = 0.008;
    q.hausdorffDistanceMm = 0.9;
    q.boundaryNonManifoldEdges = 0;
    q.boundaryNonManifoldVertices = 0;
    return q;
}

std::vector<std::string> missedNames(const hs::scene::MeshQuality& q) {
    std::vector<std::string> names;
    for (const auto& b : hs::scene::meshBars(q))
        if (!b.met)
            names.push_back(b.name);
    return names;
}

} // namespace

TEST(MeshBars, AMeshAtEveryBarMeetsThemAll) {
    auto q = goodMesh();
    EXPECT_EQ(hs::scene::meshBars(q).size(), 6u);
    EXPECT_TRUE(missedNames(q).empty());
    // Exactly at the bars is still met.
    q.meanRadiusRatio = hs::scene::kBarMeanRadiusRatio;
    q.minDihedralDeg = hs::scene::kBarMinDihedralDeg;
    q.hausdorffRelative = hs::scene::kBarHausdorffRelative;
    EXPECT_TRUE(missedNames(q).empty());
    EXPECT_TRUE(hs::scene::missedMeshBars(q).empty());
}

TEST(MeshBars, NamesEveryBarMissedWithItsValue) {
    auto q = goodMesh();
    q.meanRadiusRatio = 0.87;
    q.minDihedralDeg = 15.2;
    q.sliverCount = 2;
    q.invertedCount = 1;
    q.hausdorffRelative = 0.0195;
    q.boundaryNonManifoldEdges = 3;
    EXPECT_EQ(missedNames(q), (std::vector<std::string>{"mesh-radius-ratio", "mesh-min-dihedral", "mesh-slivers",
                                                        "mesh-inverted", "mesh-hausdorff", "mesh-non-manifold"}));
    const auto warnings = hs::scene::missedMeshBars(q);
    ASSERT_EQ(warnings.size(), 6u);
    EXPECT_EQ(warnings[0], "mesh-radius-ratio: mean radius ratio 0.870: below the bar of 0.90");
    EXPECT_EQ(warnings[1], "mesh-min-dihedral: smallest dihedral angle 15.20 degrees: below the bar of 17 degrees");
    EXPECT_NE(warnings[4].find("1.95 % of its bounding-box diagonal: above the bar of 1 % (0.90 mm)"),
              std::string::npos)
        << warnings[4];
    EXPECT_NE(warnings[5].find("3 non-manifold edges and 0 non-manifold vertices"), std::string::npos) << warnings[5];
}

TEST(MeshBars, LeavesOutWhatAPackageDidNotMeasure) {
    auto q = goodMesh();
    q.hasReference = false;
    q.boundaryNonManifoldEdges.reset();
    q.boundaryNonManifoldVertices.reset();
    const auto bars = hs::scene::meshBars(q);
    EXPECT_EQ(bars.size(), 4u);
    EXPECT_TRUE(std::none_of(bars.begin(), bars.end(), [](const auto& b) {
        return b.name == "mesh-hausdorff" || b.name == "mesh-non-manifold";
    }));
}
