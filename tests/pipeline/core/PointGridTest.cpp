#include "hs/core/PointGrid.h"
#include "hs/core/Rng.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace {

std::vector<hs::Vec3> randomPoints(std::size_t n, double extent, std::uint64_t seed) {
    hs::Rng rng(seed);
    std::vector<hs::Vec3> points(n);
    for (auto& p : points)
        p = {rng.uniform(-extent, extent), rng.uniform(-extent, extent), rng.uniform(-extent, extent)};
    return points;
}

std::set<std::int32_t> within(const std::vector<hs::Vec3>& points, const hs::Vec3& p, double radius) {
    std::set<std::int32_t> out;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (hs::distance(points[i], p) <= radius)
            out.insert(static_cast<std::int32_t>(i));
    return out;
}

} // namespace

TEST(PointGrid, FindsEveryPointOfABallAndTheNearestAsABruteForceSearchDoes) {
    const auto points = randomPoints(2000, 10.0, 3);
    const hs::PointGrid grid = hs::PointGrid::of(points, 1.5);
    const auto queries = randomPoints(300, 12.0, 4); // some beyond the grid's box
    for (const hs::Vec3& q : queries) {
        for (double radius : {0.4, 1.5, 3.7}) {
            std::set<std::int32_t> found;
            grid.forEachNear(q, radius, [&](std::int32_t id) { EXPECT_TRUE(found.insert(id).second) << id; });
            for (std::int32_t id : within(points, q, radius))
                EXPECT_TRUE(found.count(id)) << "point " << id << " within " << radius << " mm was not visited";
            std::int32_t brute = -1;
            double best = radius * radius;
            for (std::size_t i = 0; i < points.size(); ++i)
                if (hs::norm2(points[i] - q) < best) {
                    best = hs::norm2(points[i] - q);
                    brute = static_cast<std::int32_t>(i);
                }
            EXPECT_EQ(grid.nearest(q, radius, points), brute);
        }
        std::set<std::int32_t> around;
        grid.forEachInCellsAround(q, [&](std::int32_t id) { around.insert(id); });
        for (std::int32_t id : within(points, q, grid.cellSize()))
            EXPECT_TRUE(around.count(id)) << "point " << id << " within one cell was not visited";
    }
}

TEST(PointGrid, FindsPointsInsertedBeyondItsBoxAndKeepsInsertionOrderInACell) {
    hs::Bounds box;
    box.add({0, 0, 0});
    box.add({1, 1, 1});
    hs::PointGrid grid(box, 1.0);
    grid.insert(7, {0.5, 0.5, 0.5});
    grid.insert(3, {40.0, -20.0, 0.5}); // far outside: kept in a border cell
    grid.insert(5, {0.6, 0.4, 0.5});
    EXPECT_EQ(grid.size(), 3u);
    std::vector<std::int32_t> order;
    grid.forEachNear({0.5, 0.5, 0.5}, 0.2, [&](std::int32_t id) { order.push_back(id); });
    EXPECT_EQ(order, (std::vector<std::int32_t>{7, 5}));
    const std::vector<hs::Vec3> points{{}, {}, {}, {40.0, -20.0, 0.5}, {}, {0.6, 0.4, 0.5}, {}, {0.5, 0.5, 0.5}};
    EXPECT_EQ(grid.nearest({40.0, -20.0, 0.4}, 0.5, points), 3);
    // A set inserted at once, then one more point: still in insertion order within the cell.
    hs::PointGrid mixed(box, 1.0);
    mixed.insertAll({{0.5, 0.5, 0.5}, {0.2, 0.2, 0.2}, {3.0, 0.5, 0.5}});
    mixed.insert(9, {0.4, 0.4, 0.4});
    order.clear();
    mixed.forEachNear({0.5, 0.5, 0.5}, 0.2, [&](std::int32_t id) { order.push_back(id); });
    EXPECT_EQ(order, (std::vector<std::int32_t>{0, 1, 9}));
    EXPECT_EQ(mixed.size(), 4u);
    // Equal distances go to the lower id.
    hs::PointGrid tie(box, 1.0);
    tie.insert(6, {0.4, 0.5, 0.5});
    tie.insert(2, {0.6, 0.5, 0.5});
    const std::vector<hs::Vec3> tiePoints{{}, {}, {0.6, 0.5, 0.5}, {}, {}, {}, {0.4, 0.5, 0.5}};
    EXPECT_EQ(tie.nearest({0.5, 0.5, 0.5}, 1.0, tiePoints), 2);
}

TEST(PointGrid, CoarsensItsCellsRatherThanAllocatingAnAbsurdGrid) {
    hs::Bounds box;
    box.add({-1e6, -1e6, -1e6});
    box.add({1e6, 1e6, 1e6});
    hs::PointGrid grid(box, 0.001);
    EXPECT_GT(grid.cellSize(), 0.001);
    grid.insert(0, {5.0, 5.0, 5.0});
    std::vector<std::int32_t> found;
    grid.forEachNear({5.0, 5.0, 5.0}, 0.001, [&](std::int32_t id) { found.push_back(id); });
    EXPECT_EQ(found, (std::vector<std::int32_t>{0}));
    // A non-finite cell size or an empty box gives a usable grid.
    hs::PointGrid empty(hs::Bounds{}, std::nan(""));
    empty.insert(1, {2.0, 3.0, 4.0});
    int visits = 0;
    empty.forEachNear({2.0, 3.0, 4.0}, 1.0, [&](std::int32_t) { ++visits; });
    EXPECT_EQ(visits, 1);
}
