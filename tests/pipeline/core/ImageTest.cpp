#include "hs/core/Image.h"

#include <gtest/gtest.h>

TEST(Image, StoresInterleavedChannelsRowMajor) {
    auto img = hs::ImageU8::create(3, 2, 3);
    ASSERT_TRUE(img.ok());
    img->at(2, 1, 1) = 200;
    EXPECT_EQ(img->data()[(1 * 3 + 2) * 3 + 1], 200);
}

TEST(Image, RefusesEmptyAndHugeImages) {
    EXPECT_FALSE(hs::ImageF32::create(0, 10, 1).ok());
    EXPECT_EQ(hs::ImageF32::create(100000, 100000, 1).error().code, hs::ErrorCode::LimitExceeded);
    EXPECT_FALSE(hs::ImageF32::create(4, 4, 5).ok());
}
