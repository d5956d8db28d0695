#include "hs/core/VoxelGrid.h"

#include <gtest/gtest.h>

TEST(VoxelGrid, MapsPointsToVoxelsAndBack) {
    auto grid = hs::VoxelGrid<int>::create({-1, -1, -1}, 0.5, {4, 4, 4}, 7);
    ASSERT_TRUE(grid.ok());
    EXPECT_EQ(grid->size(), 64u);
    const hs::Index3 ijk = grid->voxelOf({0.1, -0.9, 0.9});
    EXPECT_EQ(ijk, (hs::Index3{2, 0, 3}));
    EXPECT_EQ(grid->unlinear(grid->linear(ijk)), ijk);
    EXPECT_EQ(grid->at(ijk), 7);
    EXPECT_NEAR(grid->center(ijk).x, 0.25, 1e-15);
    EXPECT_FALSE(grid->contains({4, 0, 0}));
}

TEST(VoxelGrid, RefusesAbsurdSizesWithoutAllocating) {
    auto grid = hs::VoxelGrid<float>::create({0, 0, 0}, 1.0, {100000, 100000, 100000});
    ASSERT_FALSE(grid.ok());
    EXPECT_EQ(grid.error().code, hs::ErrorCode::LimitExceeded);
    EXPECT_FALSE(hs::VoxelGrid<float>::create({0, 0, 0}, 0.0, {2, 2, 2}).ok());
    EXPECT_FALSE(hs::VoxelGrid<float>::create({0, 0, 0}, 1.0, {2, -2, 2}).ok());
}
