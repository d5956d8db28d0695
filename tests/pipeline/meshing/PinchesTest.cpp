#include "Pinches.h"

#include <gtest/gtest.h>

using namespace hs;
using namespace hs::meshing;

namespace {

// Vertex ids only matter here: the pinch search is combinatorial.
TEST(Pinches, OpensTwoTetsThatShareOnlyAnEdge) {
    const std::vector<Tet> tets = {{0, 1, 2, 3}, {0, 1, 4, 5}};
    std::vector<std::int32_t> region = {0, 0};
    const auto stats = detail::openPinches(tets, region, 0);
    EXPECT_EQ(stats.pinchedBefore, 3u); // the edge and its two vertices
    EXPECT_EQ(stats.removedTets, 1u);
    EXPECT_EQ(stats.pinchedAfter, 0u);
    EXPECT_EQ((region[0] < 0) + (region[1] < 0), 1);
}

TEST(Pinches, OpensTwoTetsThatShareOnlyAVertex) {
    const std::vector<Tet> tets = {{0, 1, 2, 3}, {0, 4, 5, 6}};
    std::vector<std::int32_t> region = {0, 0};
    const auto stats = detail::openPinches(tets, region, 0);
    EXPECT_EQ(stats.pinchedBefore, 1u);
    EXPECT_EQ(stats.removedTets, 1u);
    EXPECT_EQ(stats.pinchedAfter, 0u);
}

TEST(Pinches, LeavesAManifoldStarAlone) {
    // Four tets around the edge (0, 1), closed: a manifold ball.
    const std::vector<Tet> tets = {{0, 1, 2, 3}, {0, 1, 3, 4}, {0, 1, 4, 5}, {0, 1, 5, 2}};
    std::vector<std::int32_t> region = {0, 0, 0, 0};
    const auto stats = detail::openPinches(tets, region, 0);
    EXPECT_EQ(stats.pinchedBefore, 0u);
    EXPECT_EQ(stats.removedTets, 0u);
    EXPECT_EQ(region, (std::vector<std::int32_t>{0, 0, 0, 0}));
}

TEST(Pinches, NeverRemovesAnotherRegionOrExposesAnInterface) {
    // Tet 1 is a pathology (region 1); tet 2 is wall glued to it by a face; tet 0 is wall touching them along an edge.
    const std::vector<Tet> tets = {{0, 1, 2, 3}, {0, 1, 4, 5}, {1, 4, 5, 6}};
    std::vector<std::int32_t> region = {0, 1, 0};
    const auto stats = detail::openPinches(tets, region, 0);
    EXPECT_EQ(region[1], 1);
    EXPECT_EQ(region[2], 0); // removing it would expose the pathology's face (1, 4, 5)
    EXPECT_LT(region[0], 0); // the wall wedge goes instead
    EXPECT_EQ(stats.removedTets, 1u);
}

TEST(Pinches, ReportsWhatCannotBeOpened) {
    // Two pathology tets touching along an edge: neither fan is wall, nothing may go.
    const std::vector<Tet> tets = {{0, 1, 2, 3}, {0, 1, 4, 5}};
    std::vector<std::int32_t> region = {1, 2};
    const auto stats = detail::openPinches(tets, region, 0);
    EXPECT_EQ(stats.removedTets, 0u);
    EXPECT_GT(stats.pinchedAfter, 0u);
    EXPECT_EQ(region, (std::vector<std::int32_t>{1, 2}));
}

} // namespace
