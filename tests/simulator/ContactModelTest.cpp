// The local contact model: the solver's last contact problem re-solved with the device's pose, through the coupling.
#include "hs/haptics/ContactModel.h"
#include "hs/haptics/SpscQueue.h"

#include "TestFrames.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <thread>

namespace hs::haptics {
namespace {

sim::DeviceSample straight(double insertionMm) {
    sim::DeviceSample s;
    s.insertionMm = insertionMm;
    return s;
}

constexpr double kRadius = 1.45; // the default 2.9 mm scope

/// The force of the virtual coupling (1 N/mm) in series with the wall (k N/mm) pressed `depthMm` beyond touching.
double seriesForceN(double depthMm, double wallNPerMm) {
    return depthMm / (1.0 + 1.0 / wallNPerMm);
}

TEST(ContactModel, NoForceAwayFromTheWall) {
    ContactModel model;
    const auto frame = test::wallFrame(40.0);
    const ForceCommand c = model.update(*frame, straight(30.0), 0.001);
    EXPECT_TRUE(c.enabled);
    EXPECT_EQ(c.insertionForceN, 0.0);
    EXPECT_FALSE(model.state().touching);
}

TEST(ContactModel, GivesTheSolversReactionThroughTheCoupling) {
    // Held 2 mm beyond touching: the coupling and the wall's compliance (as the solver computed it) in series.
    ContactModel model;
    const auto frame = test::wallFrame(40.0, 0.3);
    ForceCommand c;
    for (int i = 0; i < 200; ++i)
        c = model.update(*frame, straight(40.0 - kRadius + 2.0), 0.001);
    EXPECT_TRUE(model.state().touching);
    EXPECT_NEAR(c.insertionForceN, -seriesForceN(2.0, 0.3), 1e-6);
    EXPECT_NEAR(model.state().largestForceN, seriesForceN(2.0, 0.3), 1e-6);
    EXPECT_NEAR(c.tipForceN.z, -seriesForceN(2.0, 0.3), 1e-6);
    EXPECT_NEAR(c.pitchTorqueNmm, 0.0, 1e-9); // along the shaft: no torque
}

TEST(ContactModel, TheTipsGiveIsOneDimpleInSeriesHoweverManyFacesTheTipMeets) {
    // The tip's sub-element give (m/N) in series with the coupling and the wall; split over two faces of the same
    // wall (each carrying half, their compliances coupled), it is still one dimple, not two springs side by side.
    constexpr double kGiveMmPerN = 4.0;
    auto one = std::make_shared<sim::HapticFrame>(*test::wallFrame(40.0, 0.3));
    one->tipComplianceMPerN = kGiveMmPerN * 1e-3;
    auto two = std::make_shared<sim::HapticFrame>(*one);
    two->contacts.push_back(two->contacts.front());
    const double w = 1e-3 / 0.3; // the two faces' points move together under the tip: each row sees the whole wall
    two->compliance = {w, w, w, w};
    ContactModel a, b;
    ForceCommand ca, cb;
    for (int i = 0; i < 200; ++i) {
        ca = a.update(*one, straight(40.0 - kRadius + 2.0), 0.001);
        cb = b.update(*two, straight(40.0 - kRadius + 2.0), 0.001);
    }
    const double expected = 2.0 / (1.0 + 1.0 / 0.3 + kGiveMmPerN); // N: coupling, wall and give in series
    EXPECT_NEAR(-ca.insertionForceN, expected, 1e-6);
    EXPECT_NEAR(-cb.insertionForceN, expected, 1e-4);
    EXPECT_LT(-ca.insertionForceN, seriesForceN(2.0, 0.3)); // softer than without the give
}

TEST(ContactModel, AStifferTissuePushesBackHarderByItsStiffness) {
    // A myoma (65 kPa) against the wall (30 kPa): the same press, forces in the ratio of the series stiffnesses.
    ContactModel soft, stiff;
    ForceCommand a, b;
    for (int i = 0; i < 200; ++i) {
        a = soft.update(*test::wallFrame(40.0, 0.3), straight(40.0 - kRadius + 3.0), 0.001);
        b = stiff.update(*test::wallFrame(40.0, 0.65), straight(40.0 - kRadius + 3.0), 0.001);
    }
    EXPECT_NEAR(b.insertionForceN / a.insertionForceN, seriesForceN(3.0, 0.65) / seriesForceN(3.0, 0.3), 1e-9);
    EXPECT_GT(b.insertionForceN / a.insertionForceN, 1.5);
}

TEST(ContactModel, ForceIsContinuousAsTheDeviceMoves) {
    ContactModel model;
    const auto frame = test::wallFrame(40.0, 0.3);
    double last = 0.0, largestJump = 0.0;
    for (double z = 35.0; z <= 42.0; z += 0.005) {
        const ForceCommand c = model.update(*frame, straight(z), 0.001);
        largestJump = std::max(largestJump, std::abs(c.insertionForceN - last));
        last = c.insertionForceN;
    }
    EXPECT_LT(largestJump, 0.01); // 5 um a tick: no step at first contact
}

TEST(ContactModel, TurningIntoTheWallGivesATorque) {
    auto frame = std::make_shared<sim::HapticFrame>(*test::wallFrame(40.0, 0.3));
    frame->contacts[0].scopeGradient = {-1.0, -0.04, 0.0}; // a wall beside the tip, 40 mm beyond the pivot
    ContactModel model;
    sim::DeviceSample s = straight(40.0 - kRadius);
    s.pitchDeg = 2.0;
    ForceCommand c;
    for (int i = 0; i < 200; ++i)
        c = model.update(*frame, s, 0.001);
    EXPECT_LT(c.pitchTorqueNmm, 0.0);
    EXPECT_NEAR(c.pitchTorqueNmm, 40.0 * c.insertionForceN, 1e-6);
}

TEST(ContactModel, NoWallForceOncePerforated) {
    ContactModel model;
    auto frame = std::make_shared<sim::HapticFrame>(*test::wallFrame(40.0));
    frame->perforated = true;
    sim::DeviceSample s = straight(60.0);
    s.pitchDeg = 5.0;
    const ForceCommand c = model.update(*frame, s, 0.001);
    EXPECT_EQ(c.insertionForceN, 0.0);
    EXPECT_EQ(c.pitchTorqueNmm, 0.0);
    EXPECT_FALSE(model.state().touching);
}

TEST(ContactModel, MalformedFramesGiveNoForce) {
    ContactModel model;
    auto frame = std::make_shared<sim::HapticFrame>(*test::wallFrame(40.0));
    frame->compliance.push_back(1.0); // sizes disagree
    ForceCommand c = model.update(*frame, straight(45.0), 0.001);
    EXPECT_EQ(c.insertionForceN, 0.0);
    frame->compliance = {std::nan("")};
    c = model.update(*frame, straight(45.0), 0.001);
    EXPECT_TRUE(std::isfinite(c.insertionForceN));
    EXPECT_EQ(c.insertionForceN, 0.0);
    frame->compliance = {1e-3};
    frame->couplingStiffness[0] = 0.0;
    c = model.update(*frame, straight(45.0), 0.001);
    EXPECT_EQ(c.insertionForceN, 0.0);
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
