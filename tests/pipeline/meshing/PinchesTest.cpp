#include "Pinches.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

using namespace hs;
using namespace hs::meshing;

namespace {

// Vertex ids only matter here: the pinch search is combinatorial.
TEST(Pinches, OpensTwoTetsThatShareOnlyAnEdge) {
    std::vector<Tet> tets = {{0, 1, 2, 3}, {0, 1, 4, 5}};
    std::vector<std::int32_t> region = {0, 0};
    const auto stats = detail::openPinches(tets, region, 0);
    EXPECT_EQ(stats.pinchedBefore, 3u); // the edge and its two vertices
    EXPECT_EQ(stats.removedTets, 1u);
    EXPECT_EQ(stats.pinchedAfter, 0u);
    EXPECT_EQ((region[0] < 0) + (region[1] < 0), 1);
}

TEST(Pinches, OpensTwoTetsThatShareOnlyAVertex) {
    std::vector<Tet> tets = {{0, 1, 2, 3}, {0, 4, 5, 6}};
    std::vector<std::int32_t> region = {0, 0};
    const auto stats = detail::openPinches(tets, region, 0);
    EXPECT_EQ(stats.pinchedBefore, 1u);
    EXPECT_EQ(stats.removedTets, 1u);
    EXPECT_EQ(stats.pinchedAfter, 0u);
}

TEST(Pinches, LeavesAManifoldStarAlone) {
    // Four tets around the edge (0, 1), closed: a manifold ball.
    std::vector<Tet> tets = {{0, 1, 2, 3}, {0, 1, 3, 4}, {0, 1, 4, 5}, {0, 1, 5, 2}};
    std::vector<std::int32_t> region = {0, 0, 0, 0};
    const auto stats = detail::openPinches(tets, region, 0);
    EXPECT_EQ(stats.pinchedBefore, 0u);
    EXPECT_EQ(stats.removedTets, 0u);
    EXPECT_EQ(region, (std::vector<std::int32_t>{0, 0, 0, 0}));
}

TEST(Pinches, NeverRemovesAnotherRegionOrExposesAnInterface) {
    // Tet 1 is a pathology (region 1); tet 2 is wall glued to it by a face; tet 0 is wall touching them along an edge.
    std::vector<Tet> tets = {{0, 1, 2, 3}, {0, 1, 4, 5}, {1, 4, 5, 6}};
    std::vector<std::int32_t> region = {0, 1, 0};
    const auto stats = detail::openPinches(tets, region, 0);
    EXPECT_EQ(region[1], 1);
    EXPECT_EQ(region[2], 0); // removing it would expose the pathology's face (1, 4, 5)
    EXPECT_LT(region[0], 0); // the wall wedge goes instead
    EXPECT_EQ(stats.removedTets, 1u);
}

// A belt of tets round vertex 0: the cone from 0 over a band whose rims are 1-2-3-4 above and 5-6-7-8 below. The tets
// form one fan, but the void reaches vertex 0 from above and from below: the boundary is two cones touching at it.
std::vector<Tet> beltAroundVertex0() {
    std::vector<Tet> tets;
    for (std::int32_t i = 0; i < 4; ++i) {
        const std::int32_t top = 1 + i, nextTop = 1 + (i + 1) % 4, bottom = 5 + i, nextBottom = 5 + (i + 1) % 4;
        tets.push_back({0, top, bottom, nextTop});
        tets.push_back({0, nextTop, bottom, nextBottom});
    }
    return tets;
}

TEST(Pinches, CutsABeltWhoseBoundaryTouchesItselfAtAVertex) {
    std::vector<Tet> tets = beltAroundVertex0();
    std::vector<std::int32_t> region(tets.size(), 0);
    const auto stats = detail::openPinches(tets, region, 0);
    EXPECT_EQ(stats.pinchedBefore, 1u); // vertex 0 alone: every edge has two boundary faces
    EXPECT_EQ(stats.removedTets, 2u);   // the fewest tets from the upper rim to the lower: one each
    EXPECT_EQ(stats.pinchedAfter, 0u);
    // The two removed tets are neighbours: a cut across the belt, not two notches.
    std::vector<std::size_t> removed;
    for (std::size_t t = 0; t < tets.size(); ++t)
        if (region[t] < 0)
            removed.push_back(t);
    ASSERT_EQ(removed.size(), 2u);
    int shared = 0;
    for (std::int32_t x : tets[removed[0]])
        shared += std::find(tets[removed[1]].begin(), tets[removed[1]].end(), x) != tets[removed[1]].end() ? 1 : 0;
    EXPECT_EQ(shared, 3);
}

TEST(Pinches, ABeltOfAnotherRegionIsReportedNotCut) {
    std::vector<Tet> tets = beltAroundVertex0();
    std::vector<std::int32_t> region(tets.size(), 1);
    const auto stats = detail::openPinches(tets, region, 0);
    EXPECT_EQ(stats.pinchedBefore, 1u);
    EXPECT_EQ(stats.removedTets, 0u);
    EXPECT_EQ(stats.pinchedAfter, 1u);
}

/// A `duplicateVertex` for openPinches over vertex ids only: the copy of v is the next id; `copies` records v.
struct Copier {
    std::int32_t next;
    std::vector<std::int32_t> copies;
    std::int32_t operator()(std::int32_t v) {
        copies.push_back(v);
        return next++;
    }
};

/// Two balls of eight tets, each the star of an inner vertex (1 and 7), touching at vertex 0: the top of the first,
/// the bottom of the second. Each of vertex 0's two fans holds its ball's inner vertex.
std::vector<Tet> twoBallsTouchingAtVertex0() {
    std::vector<Tet> tets;
    const auto ball = [&tets](std::int32_t centre, std::int32_t top, std::int32_t bottom, std::int32_t firstRing) {
        for (std::int32_t i = 0; i < 4; ++i) {
            const std::int32_t a = firstRing + i, b = firstRing + (i + 1) % 4;
            tets.push_back({centre, top, a, b});
            tets.push_back({centre, bottom, b, a});
        }
    };
    ball(1, 0, 6, 2);  // inner vertex 1, ring 2-5, bottom 6
    ball(7, 12, 0, 8); // inner vertex 7, ring 8-11, top 12
    return tets;
}

TEST(Pinches, SplitsAVertexWhereEitherConeWouldLeaveANotch) {
    std::vector<Tet> tets = twoBallsTouchingAtVertex0();
    std::vector<std::int32_t> region(tets.size(), 0);
    Copier copier{13, {}};
    const auto stats = detail::openPinches(tets, region, 0, std::ref(copier));
    EXPECT_EQ(stats.pinchedBefore, 1u);
    EXPECT_EQ(stats.splitVertices, 1u);
    EXPECT_EQ(stats.removedTets, 0u);
    EXPECT_EQ(stats.pinchedAfter, 0u);
    EXPECT_EQ(copier.copies, (std::vector<std::int32_t>{0}));
    EXPECT_EQ(region, std::vector<std::int32_t>(tets.size(), 0)); // both balls stay whole
    const std::vector<Tet> before = twoBallsTouchingAtVertex0();
    for (std::size_t t = 0; t < tets.size(); ++t) // the first ball keeps vertex 0, the second gets the copy
        for (std::size_t k = 0; k < 4; ++k)
            EXPECT_EQ(tets[t][k], before[t][k] == 0 && t >= 8 ? 13 : before[t][k]) << t;
    // Without a splitter the smaller fan goes: four tets, and the first ball's inner vertex is bared.
    std::vector<Tet> opened = twoBallsTouchingAtVertex0();
    std::vector<std::int32_t> openedRegion(opened.size(), 0);
    EXPECT_EQ(detail::openPinches(opened, openedRegion, 0).removedTets, 4u);
}

TEST(Pinches, ASpikeTouchingAtAVertexIsRemovedNotSplit) {
    // One tet on its own (every vertex on the boundary) touching the other at vertex 0: removing it leaves no notch.
    std::vector<Tet> tets = {{0, 1, 2, 3}, {0, 4, 5, 6}};
    std::vector<std::int32_t> region = {0, 0};
    Copier copier{7, {}};
    const auto stats = detail::openPinches(tets, region, 0, std::ref(copier));
    EXPECT_EQ(stats.splitVertices, 0u);
    EXPECT_EQ(stats.removedTets, 1u);
    EXPECT_EQ(stats.pinchedAfter, 0u);
}

TEST(Pinches, SplitsWhatMayNotBeRemoved) {
    // Two pathology tets touching at a vertex: neither may go (ReportsWhatCannotBeOpened), a split parts them.
    std::vector<Tet> tets = {{0, 1, 2, 3}, {0, 4, 5, 6}};
    std::vector<std::int32_t> region = {1, 2};
    Copier copier{7, {}};
    const auto stats = detail::openPinches(tets, region, 0, std::ref(copier));
    EXPECT_EQ(stats.splitVertices, 1u);
    EXPECT_EQ(stats.removedTets, 0u);
    EXPECT_EQ(stats.pinchedAfter, 0u);
    EXPECT_EQ(tets[1], (Tet{7, 4, 5, 6}));
}

TEST(Pinches, AVertexCopiedInAPassCountsAsBoundaryForTheNextPinch) {
    // Vertex 0: a pathology tet (0) and a wall fan (1, 2) that touches a pathology (3) beyond it, so neither fan may
    // go and 0 is split; the wall fan gets the copy. Vertex 1: that fan's first tet (1) and a pathology tet (4). Tet 1
    // then has the copy and three boundary vertices, and may go: a spike, removed in the next pass, not split.
    // The copy is not in the pass's table of boundary vertices. It was once looked up there all the same: as vertex
    // 12, the table's last entry, it read "inner"; as a vertex beyond the table's end (the mesher's copies come after
    // all its particles), whatever the heap held, so a scene's simulation mesh differed between two runs (and the
    // ASan build reports the read).
    for (const std::int32_t firstCopy : {12, 40}) {
        std::vector<Tet> tets = {{0, 2, 3, 4}, {0, 1, 5, 6}, {0, 5, 6, 7}, {5, 6, 7, 8}, {1, 9, 10, 11}};
        std::vector<std::int32_t> region = {2, 0, 0, 2, 2};
        Copier copier{firstCopy, {}};
        const auto stats = detail::openPinches(tets, region, 0, std::ref(copier));
        EXPECT_EQ(stats.pinchedBefore, 2u) << firstCopy;
        EXPECT_EQ(copier.copies, (std::vector<std::int32_t>{0})) << firstCopy;
        EXPECT_EQ(stats.splitVertices, 1u) << firstCopy;
        EXPECT_EQ(stats.removedTets, 1u) << firstCopy;
        EXPECT_EQ(stats.pinchedAfter, 0u) << firstCopy;
        EXPECT_EQ(tets[1], (Tet{firstCopy, 1, 5, 6})) << firstCopy;
        EXPECT_EQ(region, (std::vector<std::int32_t>{2, -1, 0, 2, 2})) << firstCopy;
    }
}

TEST(Pinches, ABeltIsCutEvenWhereVerticesMaySplit) {
    // One fan round vertex 0: no copy of it separates the sheets, so the bridge goes as without a splitter.
    std::vector<Tet> tets = beltAroundVertex0();
    std::vector<std::int32_t> region(tets.size(), 0);
    Copier copier{9, {}};
    const auto stats = detail::openPinches(tets, region, 0, std::ref(copier));
    EXPECT_EQ(stats.splitVertices, 0u);
    EXPECT_EQ(stats.removedTets, 2u);
    EXPECT_EQ(stats.pinchedAfter, 0u);
}

TEST(Pinches, ReportsWhatCannotBeOpened) {
    // Two pathology tets touching along an edge: neither fan is wall, nothing may go.
    std::vector<Tet> tets = {{0, 1, 2, 3}, {0, 1, 4, 5}};
    std::vector<std::int32_t> region = {1, 2};
    const auto stats = detail::openPinches(tets, region, 0);
    EXPECT_EQ(stats.removedTets, 0u);
    EXPECT_GT(stats.pinchedAfter, 0u);
    EXPECT_EQ(region, (std::vector<std::int32_t>{1, 2}));
}

} // namespace
