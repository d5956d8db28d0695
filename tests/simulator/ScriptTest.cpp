// Scripts: key frames interpolated at 1 kHz; malformed scripts refused with the file and the field named.
#include "hs/sim/Script.h"
#include "hs/sim/Scope.h"
#include "hs/sim/World.h"

#include "TestFrames.h"
#include "TestSupport.h"

#include <gtest/gtest.h>

namespace hs::sim {
namespace {

const std::string kTwoFrames = R"({"format": "hysteroscene-script", "version": 1, "keyframes": [
    {"t": 0, "insertionMm": -5, "inflow": 1, "buttons": 1},
    {"t": 1.0, "insertionMm": 15, "pitchDeg": 10, "buttons": 2}]})";

void expectRefused(const std::string& text, const std::string& field) {
    auto result = parseScript(text, "probe.json");
    ASSERT_FALSE(result.ok()) << text;
    EXPECT_NE(result.error().detail.find("probe.json"), std::string::npos) << result.error().detail;
    EXPECT_NE(result.error().detail.find(field), std::string::npos) << result.error().detail;
}

TEST(Scope, APivotAtTheIntroitusKeepsTheInsertionCountedFromTheOs) {
    // The external os at the origin, the introitus 63 mm behind it on the axis: the same insertion puts the tip at
    // the same depth along the axis, and aiming at a tip gives back that tip.
    ScopeFrame frame = test::testPivot();
    frame.introitusMm = 63.0;
    frame.pivotMm = frame.axis * -63.0;
    const ScopeConfig config;
    DeviceSample s;
    s.insertionMm = 10.0;
    const ScopePose axial = scopePose(frame, config, s);
    EXPECT_NEAR(distance(axial.tipMm, Vec3{0.0, 0.0, 10.0}), 0.0, 1e-12);
    for (const Vec3& tip : {Vec3{5.0, 3.0, 20.0}, Vec3{-4.0, 1.0, 35.0}, Vec3{0.0, 0.0, -5.0}}) {
        const DeviceSample aimed = sampleAiming(frame, tip);
        EXPECT_NEAR(distance(scopePose(frame, config, aimed).tipMm, tip), 0.0, 1e-9);
    }
    WorldOptions options;
    EXPECT_TRUE(checkWorldOptions(options).ok());
    options.introitusMm = 63.0;
    EXPECT_TRUE(checkWorldOptions(options).ok());
    for (const double bad : {20.0, 200.0, -1.0}) {
        options.introitusMm = bad;
        const Status refused = checkWorldOptions(options);
        ASSERT_FALSE(refused.ok());
        EXPECT_NE(refused.error().detail.find("introitusMm"), std::string::npos);
    }
}

TEST(Script, InterpolatesBetweenKeyFramesAndHoldsButtons) {
    auto script = parseScript(kTwoFrames, "two.json");
    ASSERT_TRUE(script.ok()) << script.error().detail;
    EXPECT_EQ(script->tickCount(), 1001u);
    const DeviceSample mid = script->sampleAt(500);
    EXPECT_EQ(mid.tick, 500u);
    EXPECT_DOUBLE_EQ(mid.insertionMm, 5.0);
    EXPECT_DOUBLE_EQ(mid.pitchDeg, 5.0);
    EXPECT_DOUBLE_EQ(mid.inflow, 1.0); // missing in the second key frame: kept
    EXPECT_EQ(mid.buttons, 1u);        // held until the next key frame
    EXPECT_EQ(script->sampleAt(1000).buttons, 2u);
    EXPECT_DOUBLE_EQ(script->sampleAt(5000).insertionMm, 15.0); // clamped to the last key frame
    EXPECT_EQ(script->sampleAt(5000).tick, 5000u);
}

TEST(Script, JsonReadsBackToTheSameKeyFrames) {
    Script script;
    for (int i = 0; i < 20; ++i) {
        KeyFrame k;
        k.timeS = 0.1 * i;
        k.sample.insertionMm = 1.0 / 3.0 * i;
        k.sample.yawDeg = -0.7 * i;
        k.sample.outflow = 0.05 * i;
        k.sample.buttons = static_cast<std::uint32_t>(i % 3);
        script.keyframes.push_back(k);
    }
    auto back = parseScript(scriptJson(script), "round.json");
    ASSERT_TRUE(back.ok()) << back.error().detail;
    ASSERT_EQ(back->keyframes.size(), script.keyframes.size());
    for (std::size_t i = 0; i < script.keyframes.size(); ++i) {
        EXPECT_EQ(back->keyframes[i].timeS, script.keyframes[i].timeS);
        EXPECT_EQ(back->keyframes[i].sample.insertionMm, script.keyframes[i].sample.insertionMm);
        EXPECT_EQ(back->keyframes[i].sample.yawDeg, script.keyframes[i].sample.yawDeg);
        EXPECT_EQ(back->keyframes[i].sample.outflow, script.keyframes[i].sample.outflow);
        EXPECT_EQ(back->keyframes[i].sample.buttons, script.keyframes[i].sample.buttons);
    }
    test::TempDir dir("hs-script");
    ASSERT_TRUE(writeScript(script, dir.file("s.json")).ok());
    auto read = readScript(dir.file("s.json"));
    ASSERT_TRUE(read.ok()) << read.error().detail;
    EXPECT_EQ(read->tickCount(), script.tickCount());
}

TEST(Script, RefusesMalformedScripts) {
    const std::string head = R"({"format": "hysteroscene-script", "version": 1, "keyframes": )";
    expectRefused(head + R"([{"t": 0}, {"t": 0}]})", "/keyframes/1/t");
    expectRefused(head + R"([{"t": 0.5}]})", "/keyframes/0/t");
    expectRefused(head + R"([{"t": 0}, {"t": 1e9}]})", "/keyframes/1/t");
    expectRefused(head + R"([{"t": 0, "pitchDeg": 75}]})", "/keyframes/0/pitchDeg");
    expectRefused(head + R"([{"t": 0, "inflow": -0.1}]})", "/keyframes/0/inflow");
    expectRefused(head + R"([{"t": 0, "insertionMm": 1e999}]})", "insertionMm");
    expectRefused(head + R"([{"t": 0, "insertionMm": "deep"}]})", "/keyframes/0/insertionMm");
    expectRefused(head + R"([{"t": 0, "buttons": 64}]})", "/keyframes/0/buttons");
    expectRefused(head + R"([{"t": 0, "instrument": 4}]})", "/keyframes/0/instrument");
    expectRefused(head + R"([{"t": 0, "workingElementMm": 21}]})", "/keyframes/0/workingElementMm");
    expectRefused(head + R"([{"t": 0, "force": 1}]})", "/keyframes/0/force");
    expectRefused(head + R"([{"insertionMm": 1}]})", "/keyframes/0/t");
    expectRefused(head + "[]}", "/keyframes");
    expectRefused(head + "{}}", "/keyframes");
    expectRefused(R"({"format": "hysteroscene-case", "version": 1, "keyframes": [{"t": 0}]})", "/format");
    expectRefused(R"({"format": "hysteroscene-script", "version": 2, "keyframes": [{"t": 0}]})", "/version");
    expectRefused(R"({"format": "hysteroscene-script", "version": 1, "keyframes": [{"t": 0}])", "probe.json");
}

TEST(Script, RefusesTooManyKeyFrames) {
    std::string text = R"({"format": "hysteroscene-script", "version": 1, "keyframes": [)";
    for (std::size_t i = 0; i <= kMaxKeyFrames; ++i)
        text += (i ? ",{\"t\":" : "{\"t\":") + std::to_string(i) + "}";
    text += "]}";
    expectRefused(text, "/keyframes");
}

} // namespace
} // namespace hs::sim
