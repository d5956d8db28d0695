#include "hs/core/TetMesh.h"

#include <gtest/gtest.h>

namespace {

/// Two tets sharing face (1,2,3): regions 1 and 2.
hs::TetMesh twoTets() {
    hs::TetMesh m;
    m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    m.tets = {{0, 1, 2, 3}, {1, 4, 2, 3}};
    m.regions = {1, 2};
    return m;
}

} // namespace

TEST(TetMesh, VolumesOfHandComputedTets) {
    const auto m = twoTets();
    ASSERT_TRUE(hs::validate(m).ok());
    EXPECT_NEAR(hs::signedVolume(m, 0), 1.0 / 6.0, 1e-15);
    EXPECT_GT(hs::signedVolume(m, 1), 0.0);
    EXPECT_EQ(hs::invertedTetCount(m), 0u);
    const auto rv = hs::regionVolumes(m);
    EXPECT_NEAR(rv.at(1), 1.0 / 6.0, 1e-15);
    EXPECT_NEAR(hs::totalVolume(m), rv.at(1) + rv.at(2), 1e-15);
}

TEST(TetMesh, BoundaryIsClosedAndEnclosesTheVolume) {
    const auto m = twoTets();
    const auto surface = hs::extractBoundary(m);
    EXPECT_EQ(surface.triangles.size(), 6u);
    EXPECT_TRUE(hs::analyzeTopology(surface).isWatertight());
    EXPECT_NEAR(hs::enclosedVolume(surface), hs::totalVolume(m), 1e-12);
}

TEST(TetMesh, InterfacesAreExtractedOnceBetweenRegions) {
    const auto m = twoTets();
    const auto surface = hs::extractBoundary(m, true);
    ASSERT_EQ(surface.triangles.size(), 7u);
    const auto& other = surface.faceLabels.at("otherRegion");
    EXPECT_EQ(std::count(other.begin(), other.end(), 2), 1);
}

TEST(TetMesh, InvertedTetIsCounted) {
    auto m = twoTets();
    std::swap(m.tets[0][0], m.tets[0][1]);
    EXPECT_EQ(hs::invertedTetCount(m), 1u);
}

TEST(TetMesh, ValidateRejectsOutOfRangeIndicesAndWrongRegionCount) {
    auto m = twoTets();
    m.tets[1][2] = 5;
    EXPECT_FALSE(hs::validate(m).ok());
    m = twoTets();
    m.regions.push_back(3);
    EXPECT_FALSE(hs::validate(m).ok());
    m = twoTets();
    m.points[2].x = 1e300; // finite, beyond kMaxCoordinate
    const auto s = hs::validate(m);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().detail.find("point 2 has coordinate 1e+300"), std::string::npos) << s.error().detail;
}

TEST(TetMesh, NeighboursAreTheTetsAcrossEachFaceAndMinusOneOnTheBoundary) {
    auto m = twoTets();
    auto n = hs::tetNeighbours(m);
    ASSERT_EQ(n.size(), 2u);
    // Tet 0's face 0 (points 1, 2, 3) is tet 1's face 1 (the face opposite its point 4).
    EXPECT_EQ(n[0], (std::array<std::int32_t, 4>{1, -1, -1, -1}));
    EXPECT_EQ(n[1], (std::array<std::int32_t, 4>{-1, 0, -1, -1}));
    // A third tet on the same face (a non-manifold mesh) is not linked; the first two stay paired.
    m.points.push_back({0.5, 0.5, 0.5});
    m.tets.push_back({1, 2, 3, 5});
    n = hs::tetNeighbours(m);
    EXPECT_EQ(n[0][0], 1);
    EXPECT_EQ(n[1][1], 0);
    EXPECT_EQ(n[2], (std::array<std::int32_t, 4>{-1, -1, -1, -1}));
}
