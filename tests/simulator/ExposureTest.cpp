// The camera head's automatic exposure (hs/simrender/Exposure.h): the circle's statistics on images made for them,
// and the loop's approach to its target on a model of a camera looking at a wall.

#include "hs/simrender/Exposure.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace hs::simrender {
namespace {

/// An RGBA image of `size` x `size`: `inside` within the circle of radius size/2 about the centre, black outside.
std::vector<std::uint8_t> disc(int size, std::array<std::uint8_t, 3> inside) {
    std::vector<std::uint8_t> image(static_cast<std::size_t>(size * size * 4), 0);
    const double r = 0.5 * size;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double dx = x + 0.5 - r, dy = y + 0.5 - r;
            if (dx * dx + dy * dy > r * r)
                continue;
            std::uint8_t* p = &image[static_cast<std::size_t>((y * size + x) * 4)];
            p[0] = inside[0];
            p[1] = inside[1];
            p[2] = inside[2];
            p[3] = 255;
        }
    return image;
}

TEST(Exposure, TheCircleStatisticsCountOnlyThePixelsInsideIt) {
    const auto image = disc(100, {255, 128, 64});
    const CircleStats s = circleStats(image.data(), 100, 100, 4, 50.0, 50.0, 50.0);
    EXPECT_NEAR(static_cast<double>(s.pixels), 3.14159 * 2500.0, 60.0);
    EXPECT_NEAR(s.meanLuminance, (0.2126 * 255 + 0.7152 * 128 + 0.0722 * 64) / 255.0, 1e-9); // black corners left out
    EXPECT_DOUBLE_EQ(s.clippedFraction, 1.0);                                                // red at full scale
    EXPECT_DOUBLE_EQ(s.highlightFraction, 0.0);
    // A stride samples the same picture.
    EXPECT_NEAR(circleStats(image.data(), 100, 100, 4, 50.0, 50.0, 50.0, 3).meanLuminance, s.meanLuminance, 1e-9);
    // Nothing to measure: no pixels, no circle.
    EXPECT_EQ(circleStats(nullptr, 100, 100, 4, 50, 50, 50).pixels, 0u);
    EXPECT_EQ(circleStats(image.data(), 100, 100, 4, 50, 50, 0.0).pixels, 0u);
    EXPECT_EQ(circleStats(image.data(), 100, 100, 2, 50, 50, 50).pixels, 0u);
}

/// A camera looking at a wall that gives `wall` per channel at exposure 1: the displayed value of each channel is
/// the exposure times it through the view's tone curve (linear to the knee 0.7, a shoulder above it:
/// EndoscopicLook::toneKnee); returns the statistics of a uniform circle of it.
CircleStats shoot(double exposure, std::array<double, 3> wall) {
    constexpr double knee = 0.7;
    std::array<std::uint8_t, 3> c{};
    for (std::size_t k = 0; k < 3; ++k) {
        const double x = exposure * wall[k];
        const double over = std::max(0.0, x - knee) / (1.0 - knee);
        const double shown = std::min(x, knee) + (1.0 - knee) * over / (1.0 + over);
        c[k] = static_cast<std::uint8_t>(std::lround(255.0 * shown));
    }
    const auto image = disc(64, c);
    return circleStats(image.data(), 64, 64, 4, 32.0, 32.0, 32.0);
}

TEST(Exposure, TheLoopReachesItsTargetInAFewHundredMillisecondsWithoutOvershoot) {
    // A dark wall far off, then the scope close to a bright one (7 stops brighter): at 30 frames a second the mean
    // luminance comes within 0.05 of the target in under a second.
    const AutoExposureSettings settings;
    AutoExposure camera(settings, 1.0);
    const std::array<double, 3> far{0.01, 0.004, 0.003}, near{1.5, 0.6, 0.5};
    double t = 0.0;
    for (const auto& wall : {far, near}) {
        double reached = -1.0;
        const double start = t;
        // The first frame of a new view is shot with the last view's exposure: too dark or too bright. From there the
        // picture approaches the target from that side and never overshoots it by more than 0.05.
        const double side = shoot(camera.exposure(), wall).meanLuminance > settings.targetLuminance ? 1.0 : -1.0;
        for (int frame = 0; frame < 90; ++frame, t += 1.0 / 30.0) {
            const CircleStats s = shoot(camera.exposure(), wall);
            if (reached < 0.0 && std::abs(s.meanLuminance - settings.targetLuminance) < 0.05)
                reached = t - start;
            EXPECT_GT((s.meanLuminance - settings.targetLuminance) * side, -0.05) << "frame " << frame;
            camera.update(s, 1.0 / 30.0);
        }
        EXPECT_GE(reached, 0.0);
        EXPECT_LT(reached, 1.0);
        EXPECT_NEAR(shoot(camera.exposure(), wall).meanLuminance, settings.targetLuminance, 0.02);
        EXPECT_TRUE(camera.settled());
    }
}

/// A near wall over 40 % of the circle, brighter towards its edge (0.3..0.6 at exposure 1, a pale mucosa's colour),
/// beside a dark far one: the near-white share rises steeply with the exposure while the mean still wants more.
CircleStats shootNearWall(double exposure) {
    constexpr int kSize = 64;
    constexpr double knee = 0.7;
    std::vector<std::uint8_t> image = disc(kSize, {2, 1, 1});
    const auto shown = [&](double x) {
        const double over = std::max(0.0, x - knee) / (1.0 - knee);
        return static_cast<std::uint8_t>(std::lround(255.0 * (std::min(x, knee) + (1.0 - knee) * over / (1.0 + over))));
    };
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize * 2 / 5; ++x) {
            const double b = exposure * (0.3 + 0.3 * x / (kSize * 0.4));
            std::uint8_t* p = &image[static_cast<std::size_t>((y * kSize + x) * 4)];
            if (p[3] == 0)
                continue;
            p[0] = shown(b);
            p[1] = shown(0.8 * b);
            p[2] = shown(0.75 * b);
        }
    return circleStats(image.data(), kSize, kSize, 4, kSize / 2.0, kSize / 2.0, kSize / 2.0);
}

TEST(Exposure, ANearWallAtTheNearWhiteLimitDoesNotSetTheLoopHunting) {
    // The mean wants more light than the near wall's white share allows. The loop settles at the limit: over the
    // last second of 3 s at 30 frames a second the exposure moves by less than a tenth of a stop and the near-white
    // share stays within 1.5 times its limit. (With half a stop down over the limit and the mean's full pace up below
    // it, the loop swung by 0.54 stop and the near-white share reached 0.095.)
    const AutoExposureSettings settings;
    AutoExposure camera(settings, 1.0);
    double lowest = 1e9, highest = 0.0, whitest = 0.0;
    for (int frame = 0; frame < 90; ++frame) {
        const CircleStats s = shootNearWall(camera.exposure());
        if (frame >= 60) {
            lowest = std::min(lowest, camera.exposure());
            highest = std::max(highest, camera.exposure());
            whitest = std::max(whitest, s.highlightFraction);
        }
        camera.update(s, 1.0 / 30.0);
    }
    std::printf("near wall: exposure %.3f..%.3f over the last second (%.3f stop), near white up to %.3f (limit %.2f)\n",
                lowest, highest, std::log2(highest / lowest), whitest, settings.nearWhiteLimit);
    ASSERT_GT(whitest, 0.5 * settings.nearWhiteLimit) << "the wall never reaches the limit: the test shows nothing";
    EXPECT_LT(std::log2(highest / lowest), 0.1);
    EXPECT_LT(whitest, 1.5 * settings.nearWhiteLimit);
}

TEST(Exposure, MoreClippedThanTheLimitStopsDownWhateverTheMean) {
    // A mostly dark circle with a bright spot (a third of it at full scale): the mean says open up, the clipped share
    // says stop down, and the camera stops down.
    std::vector<std::uint8_t> image = disc(60, {20, 10, 10});
    for (int y = 0; y < 20; ++y)
        for (int x = 20; x < 40; ++x)
            for (int k = 0; k < 3; ++k)
                image[static_cast<std::size_t>(((y + 20) * 60 + x) * 4 + k)] = 255;
    const CircleStats s = circleStats(image.data(), 60, 60, 4, 30, 30, 30);
    ASSERT_GT(s.clippedFraction, 0.1);
    ASSERT_LT(s.meanLuminance, 0.45);
    AutoExposure camera({}, 4.0);
    CircleStats grey;
    grey.pixels = 100;
    grey.meanLuminance = AutoExposureSettings{}.targetLuminance;
    camera.update(grey, 0.0); // the first frame moves the whole way by its mean: here nowhere
    EXPECT_DOUBLE_EQ(camera.exposure(), 4.0);
    camera.update(s, 1.0 / 30.0);
    EXPECT_LT(camera.exposure(), 4.0 / std::exp2(0.5 * 0.4)); // a stop a doubling over the limit, four times the pace
    // Bad frames change nothing: no pixels, a time that is not a time.
    const double e = camera.exposure();
    EXPECT_EQ(camera.update(CircleStats{}, 0.1), e);
    EXPECT_EQ(camera.update(s, std::nan("")), e);
    EXPECT_EQ(camera.update(s, -1.0), e);
    // And the exposure stays within the camera's range.
    AutoExposure dark({}, 1.0);
    CircleStats black;
    black.pixels = 100;
    for (int k = 0; k < 100; ++k)
        dark.update(black, 1.0);
    EXPECT_EQ(dark.exposure(), AutoExposureSettings{}.maxExposure);
}

} // namespace
} // namespace hs::simrender
