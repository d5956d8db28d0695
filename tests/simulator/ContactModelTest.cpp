// The local contact model: a proxy that stays on the free side of the wall, its spring, the pivot spring.
#include "hs/haptics/ContactModel.h"
#include "hs/haptics/SpscQueue.h"

#include "TestFrames.h"

#include <gtest/gtest.h>

#include <thread>

namespace hs::haptics {
namespace {

sim::DeviceSample straight(double insertionMm) {
    sim::DeviceSample s;
    s.insertionMm = insertionMm;
    return s;
}

constexpr double kRadius = 1.45; // the default 2.9 mm scope

TEST(ContactModel, NoForceAwayFromTheWall) {
    ContactModel model;
    const auto frame = test::wallFrame(40.0);
    const ForceCommand c = model.update(*frame, straight(30.0), 0.001);
    EXPECT_TRUE(c.enabled);
    EXPECT_EQ(c.insertionForceN, 0.0);
    EXPECT_FALSE(model.state().touching);
}

TEST(ContactModel, PushesBackInProportionToTheDepth) {
    ContactModel model;
    const auto frame = test::wallFrame(40.0, 0.3);
    (void)model.update(*frame, straight(30.0), 0.001);
    // Slowly in, so the damping has died away: 2 mm beyond where the sphere touches.
    ForceCommand c;
    for (double z = 30.0; z <= 40.0 - kRadius + 2.0 + 1e-9; z += 0.01)
        c = model.update(*frame, straight(z), 0.001);
    for (int i = 0; i < 200; ++i)
        c = model.update(*frame, straight(40.0 - kRadius + 2.0), 0.001);
    EXPECT_TRUE(model.state().touching);
    EXPECT_NEAR(c.insertionForceN, -0.6, 1e-3);
    EXPECT_NEAR(c.tipForceN.z, -0.6, 1e-3);
    EXPECT_NEAR(model.state().proxyMm.z, 40.0 - kRadius, 1e-3);
    EXPECT_NEAR(c.pitchTorqueNmm, 0.0, 1e-9); // along the shaft: no torque
}

TEST(ContactModel, TheProxyDoesNotTunnelThroughTheWall) {
    ContactModel model;
    const auto frame = test::wallFrame(40.0, 0.3);
    (void)model.update(*frame, straight(30.0), 0.001);
    const ForceCommand c = model.update(*frame, straight(60.0), 0.001); // 20 mm beyond the wall in one tick
    EXPECT_NEAR(model.state().proxyMm.z, 40.0 - kRadius, 1e-3);
    EXPECT_LT(c.insertionForceN, -0.3 * (60.0 - 40.0)); // pushing back, more with the damping of that jump
}

TEST(ContactModel, SlidesAlongTheWallWithATorque) {
    ContactModel model;
    const auto frame = test::wallFrame(40.0, 0.3);
    sim::DeviceSample s = straight(30.0);
    (void)model.update(*frame, s, 0.001);
    s.insertionMm = 45.0;
    s.pitchDeg = 10.0;
    ForceCommand c;
    for (int i = 0; i < 300; ++i)
        c = model.update(*frame, s, 0.001);
    // The wall pushes along -z; the shaft is tilted to anterior, so the push turns it further... and the pivot spring
    // pulls it back by 2 N*mm per degree.
    EXPECT_LT(c.insertionForceN, 0.0);
    EXPECT_NEAR(model.state().proxyMm.z, 40.0 - kRadius, 1e-3);
    const double torqueWithoutPivot = c.pitchTorqueNmm + 2.0 * 10.0;
    EXPECT_GT(torqueWithoutPivot, 0.0);
}

TEST(ContactModel, NoWallForceOncePerforatedButThePivotSpringHolds) {
    ContactModel model;
    auto frame = std::make_shared<sim::HapticFrame>(*test::wallFrame(40.0));
    frame->perforated = true;
    sim::DeviceSample s = straight(60.0);
    s.pitchDeg = 5.0;
    const ForceCommand c = model.update(*frame, s, 0.001);
    EXPECT_EQ(c.insertionForceN, 0.0);
    EXPECT_FALSE(model.state().touching);
    EXPECT_NEAR(c.pitchTorqueNmm, -10.0, 1e-9);
}

TEST(ContactModel, MalformedFramesDoNotCrash) {
    ContactModel model;
    auto frame = std::make_shared<sim::HapticFrame>(*test::wallFrame(40.0));
    auto triangles = std::make_shared<std::vector<Triangle>>(*frame->triangles);
    triangles->push_back({0, 1, 100000});
    triangles->push_back({-1, 0, 1});
    frame->triangles = triangles;
    const ForceCommand c = model.update(*frame, straight(39.0), 0.001);
    EXPECT_TRUE(std::isfinite(c.insertionForceN));
}

TEST(SpscQueue, KeepsOrderAcrossThreads) {
    SpscQueue<std::uint64_t> queue(64);
    constexpr std::uint64_t kCount = 50000;
    std::thread producer([&] {
        for (std::uint64_t i = 0; i < kCount;) {
            if (queue.push(i))
                ++i;
            else
                std::this_thread::yield();
        }
    });
    std::uint64_t expected = 0;
    bool inOrder = true;
    while (expected < kCount) {
        std::uint64_t v = 0;
        if (queue.pop(v)) {
            inOrder = inOrder && v == expected;
            ++expected;
        } else {
            std::this_thread::yield();
        }
    }
    producer.join();
    EXPECT_TRUE(inOrder);
    EXPECT_EQ(queue.size(), 0u);
    std::uint64_t none = 0;
    EXPECT_FALSE(queue.pop(none));
}

} // namespace
} // namespace hs::haptics
