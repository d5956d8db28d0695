// The HID protocol's codec: round trips, the report descriptor against the codec, and malformed bytes (fuzzed).
#include "hs/haptics/HidProtocol.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace hs::haptics::hid {
namespace {

const DeviceLimits kLimits{4.0, 250.0};

TEST(HidDescriptor, DeclaresTheReportSizesTheCodecUses) {
    auto items = parseDescriptor(kReportDescriptor.data(), kReportDescriptor.size());
    ASSERT_TRUE(items.ok()) << items.error().detail;
    auto sizes = declaredReportSizes(*items);
    ASSERT_TRUE(sizes.ok()) << sizes.error().detail;
    EXPECT_EQ(sizes->input[kInputReportId], kInputPayloadBytes);
    EXPECT_EQ(sizes->output[kOutputReportId], kOutputPayloadBytes);
    EXPECT_EQ(sizes->feature[kLimitsReportId], kLimitsPayloadBytes);
    EXPECT_EQ(sizes->feature[kCalibrationReportId], kCalibrationPayloadBytes);
    // No other report is declared, and nothing outside a report ID.
    std::size_t declared = 0;
    for (std::size_t id = 0; id < 256; ++id)
        declared += (sizes->input[id] ? 1 : 0) + (sizes->output[id] ? 1 : 0) + (sizes->feature[id] ? 1 : 0);
    EXPECT_EQ(declared, 4u);
    // The encoders agree with the declared sizes.
    EXPECT_EQ(encodeInputReport({}, 0, kProtocolVersion2).size(), 1 + sizes->input[kInputReportId]);
    EXPECT_EQ(encodeInputReport({}, 0, kProtocolVersion1).size(), kInputReportBytesV1);
    EXPECT_EQ(encodeOutputReport({}, kLimits).size(), 1 + sizes->output[kOutputReportId]);
    EXPECT_EQ(encodeLimitsReport(kLimits).size(), 1 + sizes->feature[kLimitsReportId]);
    EXPECT_EQ(encodeCalibrationReport({}).size(), 1 + sizes->feature[kCalibrationReportId]);
    // The collection is opened and closed, on the vendor page.
    EXPECT_EQ((*items)[0].type, 1);
    EXPECT_EQ((*items)[0].tag, 0x0);
    EXPECT_EQ((*items)[0].data, kUsagePage);
    EXPECT_EQ(items->back().tag, 0xC);
}

TEST(HidDescriptor, TruncatedItemsAreRefused) {
    const std::uint8_t cut[] = {0x06, 0x00};
    EXPECT_FALSE(parseDescriptor(cut, sizeof cut).ok());
}

TEST(HidDescriptor, ItemsOfTheReservedTypeAreRefusedByName) {
    // Found by fuzzing: prefix 0x3C (bType 3, reserved in HID 1.11) was parsed as an item of type 3.
    const std::uint8_t reserved[] = {0x05, 0x09, 0x3C, 0xFF};
    const auto items = parseDescriptor(reserved, sizeof reserved);
    ASSERT_FALSE(items.ok());
    EXPECT_NE(items.error().detail.find("reserved type 3"), std::string::npos) << items.error().detail;
    EXPECT_NE(items.error().detail.find("byte 2"), std::string::npos) << items.error().detail;
}

TEST(HidInput, RoundTripsToTheCount) {
    sim::DeviceSample s;
    s.insertionMm = 42.1234;
    s.pitchDeg = -12.5;
    s.yawDeg = 33.3333;
    s.rollDeg = 179.9;
    s.cameraRollDeg = -90.0;
    s.inflow = 0.75;
    s.outflow = 0.3333;
    s.buttons = sim::kButtonMark;
    const auto bytes = encodeInputReport(s, 65535);
    auto in = decodeInputReport(bytes.data(), bytes.size(), Calibration{});
    ASSERT_TRUE(in.ok()) << in.error().detail;
    EXPECT_EQ(in->sequence, 65535);
    EXPECT_NEAR(in->sample.insertionMm, s.insertionMm, 0.0005);
    EXPECT_NEAR(in->sample.pitchDeg, s.pitchDeg, 0.0005);
    EXPECT_NEAR(in->sample.yawDeg, s.yawDeg, 0.0005);
    EXPECT_NEAR(in->sample.rollDeg, s.rollDeg, 0.0005);
    EXPECT_NEAR(in->sample.cameraRollDeg, s.cameraRollDeg, 0.0005);
    EXPECT_NEAR(in->sample.inflow, s.inflow, 0.00005);
    EXPECT_NEAR(in->sample.outflow, s.outflow, 0.00005);
    EXPECT_EQ(in->sample.buttons, sim::kButtonMark);
}

TEST(HidInput, HasTheDocumentedByteLayout) {
    sim::DeviceSample s;
    s.insertionMm = 1.0; // 1000 um = 0x3E8
    s.pitchDeg = -0.001; // -1 mdeg
    s.inflow = 1.0;      // 10000 = 0x2710
    s.buttons = 3;
    const std::vector<std::uint8_t> expected = {
        0x01, 0x02, 0x01,                                           // ID, sequence 0x0102
        0xE8, 0x03, 0x00, 0x00, 0xFF, 0xFF, 0xFF, 0xFF,             // insertion, pitch
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,             // yaw, roll
        0x00, 0x00, 0x00, 0x00, 0x10, 0x27, 0x00, 0x00, 0x03, 0x00, // camera roll, inflow, outflow, buttons
    };
    EXPECT_EQ(encodeInputReport(s, 0x0102), expected);
}

TEST(HidInput, CalibrationOffsetsAndScales) {
    Calibration c;
    c.axes[kAxisInsertion] = {1000, 2.0}; // raw 1000 um is the zero; twice the counts
    c.axes[kAxisRoll] = {0, -1.0};        // the encoder turns the other way
    ASSERT_TRUE(checkCalibration(c).ok());
    sim::DeviceSample raw;
    raw.insertionMm = 11.0;
    raw.rollDeg = 30.0;
    const auto bytes = encodeInputReport(raw, 1);
    auto in = decodeInputReport(bytes.data(), bytes.size(), c);
    ASSERT_TRUE(in.ok());
    EXPECT_NEAR(in->sample.insertionMm, 20.0, 1e-9);
    EXPECT_NEAR(in->sample.rollDeg, -30.0, 1e-9);
    // A calibration that would carry a value out of range is clamped, never refused or passed through.
    c.axes[kAxisInsertion] = {-50000, 2.0};
    raw.insertionMm = 150.0;
    const auto far = encodeInputReport(raw, 2);
    auto clamped = decodeInputReport(far.data(), far.size(), c);
    ASSERT_TRUE(clamped.ok());
    EXPECT_EQ(clamped->sample.insertionMm, sim::kMaxInsertionMm);
}

TEST(HidInput, MalformedReportsAreRefusedNamingTheField) {
    const auto good = encodeInputReport({}, 7);
    const Calibration c;
    const auto refusedWith = [&](std::vector<std::uint8_t> bytes, const std::string& word) {
        auto in = decodeInputReport(bytes.data(), bytes.size(), c);
        ASSERT_FALSE(in.ok());
        EXPECT_EQ(in.error().code, ErrorCode::InvalidInput);
        EXPECT_NE(in.error().detail.find(word), std::string::npos) << in.error().detail;
    };
    refusedWith({good.begin(), good.end() - 1}, "bytes");
    auto longer = good;
    longer.push_back(0);
    refusedWith(longer, "bytes");
    refusedWith({}, "bytes");
    auto id = good;
    id[0] = kOutputReportId;
    refusedWith(id, "report ID");
    auto pitch = good;
    pitch[7] = 0x61; // pitch = 0x..EA61 > 60000
    pitch[8] = 0xEA;
    refusedWith(pitch, "pitch");
    auto valve = good;
    valve[23] = 0x11; // inflow 10001
    valve[24] = 0x27;
    refusedWith(valve, "inflow");
    auto buttons = good;
    buttons[27] = 0x04;
    refusedWith(buttons, "buttons");
    EXPECT_FALSE(decodeInputReport(nullptr, kInputReportBytes, c).ok());
}

TEST(HidOutput, ClampsToTheLimitAndHasTheDocumentedLayout) {
    ForceCommand c;
    c.enabled = true;
    c.insertionForceN = 9.0;    // above 4 N
    c.pitchTorqueNmm = -1.2345; // -1234.5 mN*mm, towards zero: -1234
    c.yawTorqueNmm = -1000.0;   // below -250
    c.rollTorqueNmm = 0.0005;   // below one count: 0
    const std::vector<std::uint8_t> expected = {
        0x02, 0x34, 0x12, 0x01, 0x00, // ID, sequence echo 0x1234, flags: force enable
        0xA0, 0x0F, 0x00, 0x00,       // 4000 mN
        0x2E, 0xFB, 0xFF, 0xFF,       // -1234 mN*mm
        0x70, 0x2F, 0xFC, 0xFF,       // -250000 mN*mm
        0x00, 0x00, 0x00, 0x00,       // 0
    };
    EXPECT_EQ(encodeOutputReport(c, kLimits, 0x1234), expected);
    auto back = decodeOutputReport(expected.data(), expected.size(), kLimits);
    ASSERT_TRUE(back.ok());
    EXPECT_TRUE(back->command.enabled);
    EXPECT_DOUBLE_EQ(back->command.insertionForceN, 4.0);
    EXPECT_DOUBLE_EQ(back->command.yawTorqueNmm, -250.0);
    EXPECT_EQ(back->sequenceEcho, 0x1234);
}

TEST(HidOutput, DisabledOrNonFiniteCommandsSendNoForce) {
    ForceCommand c;
    c.enabled = false;
    c.insertionForceN = 3.0;
    const auto off = encodeOutputReport(c, kLimits);
    for (std::size_t i = 3; i < off.size(); ++i)
        EXPECT_EQ(off[i], 0) << "byte " << i;
    c.enabled = true;
    c.pitchTorqueNmm = std::numeric_limits<double>::quiet_NaN();
    const auto nan = encodeOutputReport(c, kLimits);
    for (std::size_t i = 3; i < nan.size(); ++i)
        EXPECT_EQ(nan[i], 0) << "byte " << i;
}

TEST(HidInput, ProtocolTwoCarriesTheResectoscope) {
    sim::DeviceSample s;
    s.insertionMm = 61.5;
    s.workingElementMm = 12.3456;
    s.instrument = sim::kInstrumentLoop;
    s.buttons = sim::kButtonCut | sim::kButtonPumpUp;
    const auto bytes = encodeInputReport(s, 9, kProtocolVersion2);
    ASSERT_EQ(bytes.size(), kInputReportBytes);
    auto in = decodeInputReport(bytes.data(), bytes.size(), Calibration{}, kProtocolVersion2);
    ASSERT_TRUE(in.ok()) << in.error().detail;
    EXPECT_NEAR(in->sample.workingElementMm, 12.346, 1e-12); // micrometres on the wire
    EXPECT_EQ(in->sample.instrument, sim::kInstrumentLoop);
    EXPECT_EQ(in->sample.buttons, sim::kButtonCut | sim::kButtonPumpUp);
    EXPECT_EQ(in->sample.insertionMm, 61.5);
    // A protocol-1 device's report of the same: the diagnostic scope (no loop, no pedals), 29 bytes.
    const auto v1 = encodeInputReport(s, 9, kProtocolVersion1);
    ASSERT_EQ(v1.size(), kInputReportBytesV1);
    auto diagnostic = decodeInputReport(v1.data(), v1.size(), Calibration{});
    ASSERT_TRUE(diagnostic.ok()) << diagnostic.error().detail;
    EXPECT_EQ(diagnostic->sample.instrument, sim::kInstrumentNone);
    EXPECT_EQ(diagnostic->sample.workingElementMm, 0.0);
    EXPECT_EQ(diagnostic->sample.buttons, 0u);
    // Each version's report is refused as the other's (by its size).
    EXPECT_FALSE(decodeInputReport(bytes.data(), bytes.size(), Calibration{}, kProtocolVersion1).ok());
    EXPECT_FALSE(decodeInputReport(v1.data(), v1.size(), Calibration{}, kProtocolVersion2).ok());
    EXPECT_FALSE(decodeInputReport(bytes.data(), bytes.size(), Calibration{}, 3).ok());
}

TEST(HidInput, AnImpossibleWorkingElementOrInstrumentIsRefusedByName) {
    sim::DeviceSample s;
    s.instrument = sim::kInstrumentLoop;
    const auto good = encodeInputReport(s, 1, kProtocolVersion2);
    const auto refusedNaming = [](std::vector<std::uint8_t> bytes, const std::string& field) {
        auto in = decodeInputReport(bytes.data(), bytes.size(), Calibration{}, kProtocolVersion2);
        if (in.ok())
            return ::testing::AssertionFailure() << "accepted";
        if (in.error().detail.find(field) == std::string::npos)
            return ::testing::AssertionFailure() << in.error().detail;
        return ::testing::AssertionSuccess();
    };
    const auto putI32 = [](std::vector<std::uint8_t>& bytes, std::size_t at, std::int32_t v) {
        for (int i = 0; i < 4; ++i)
            bytes[at + static_cast<std::size_t>(i)] =
                static_cast<std::uint8_t>((static_cast<std::uint32_t>(v) >> (8 * i)) & 0xFFu);
    };
    auto negative = good;
    putI32(negative, 29, -1);
    EXPECT_TRUE(refusedNaming(negative, "workingElement"));
    auto far = good;
    putI32(far, 29, kWorkingElementMaxCount + 1);
    EXPECT_TRUE(refusedNaming(far, "workingElement"));
    auto unknown = good;
    unknown[33] = 4; // no such instrument
    EXPECT_TRUE(refusedNaming(unknown, "instrument"));
    auto grasper = good;
    grasper[33] = 3; // the office scope's grasper, the last instrument
    auto taken = decodeInputReport(grasper.data(), grasper.size(), Calibration{}, kProtocolVersion2);
    ASSERT_TRUE(taken) << taken.error().detail;
    EXPECT_EQ(taken->sample.instrument, sim::kInstrumentGrasper);
    auto reserved = good;
    reserved[35] = 1;
    EXPECT_TRUE(refusedNaming(reserved, "reserved"));
    auto button = good;
    button[27] = 0x40; // bit 6
    EXPECT_TRUE(refusedNaming(button, "buttons"));
}

TEST(HidFeatures, LimitsAndCalibrationRoundTrip) {
    const auto limitsBytes = encodeLimitsReport(kLimits);
    auto limits = decodeLimitsReport(limitsBytes.data(), limitsBytes.size());
    ASSERT_TRUE(limits.ok()) << limits.error().detail;
    EXPECT_DOUBLE_EQ(limits->maxForceN, 4.0);
    EXPECT_DOUBLE_EQ(limits->maxTorqueNmm, 250.0);
    EXPECT_FALSE(limits->resectoscope);
    EXPECT_EQ(limitsBytes[1], kProtocolVersion1);
    DeviceLimits operative = kLimits;
    operative.resectoscope = true;
    const auto v2 = encodeLimitsReport(operative);
    EXPECT_EQ(v2[1], kProtocolVersion2);
    auto declared = decodeLimitsReport(v2.data(), v2.size());
    ASSERT_TRUE(declared.ok()) << declared.error().detail;
    EXPECT_TRUE(declared->resectoscope);

    Calibration c;
    c.axes[kAxisYaw] = {-1200, 0.98};
    c.axes[kAxisOutflow] = {37, -1.5};
    const auto calBytes = encodeCalibrationReport(c);
    auto cal = decodeCalibrationReport(calBytes.data(), calBytes.size());
    ASSERT_TRUE(cal.ok()) << cal.error().detail;
    EXPECT_EQ(cal->axes[kAxisYaw].zeroCount, -1200);
    EXPECT_NEAR(cal->axes[kAxisYaw].scale, 0.98, 1.0 / 65536);
    EXPECT_EQ(cal->axes[kAxisOutflow].scale, -1.5);
}

TEST(HidFeatures, ImplausibleFeatureReportsAreRefused) {
    auto limits = encodeLimitsReport(kLimits);
    limits[1] = 3; // protocol version
    EXPECT_EQ(decodeLimitsReport(limits.data(), limits.size()).error().code, ErrorCode::Unsupported);
    auto strong = encodeLimitsReport({80.0, 250.0});
    auto refused = decodeLimitsReport(strong.data(), strong.size());
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().detail.find("maxForce"), std::string::npos);
    auto passive = encodeLimitsReport(kLimits);
    passive[2] = 0; // not actuated: no force whatever it declares
    auto none = decodeLimitsReport(passive.data(), passive.size());
    ASSERT_TRUE(none.ok());
    EXPECT_EQ(none->maxForceN, 0.0);

    Calibration c;
    c.axes[kAxisPitch].scale = 3.0;
    const auto bytes = encodeCalibrationReport(c);
    auto cal = decodeCalibrationReport(bytes.data(), bytes.size());
    ASSERT_FALSE(cal.ok());
    EXPECT_NE(cal.error().detail.find("pitch scale"), std::string::npos) << cal.error().detail;
}

/// ~100k random byte strings and commands: never a crash, never an accepted sample out of range, never a force
/// above the limit on the wire.
TEST(HidFuzz, RandomBytesNeverCrashNorExceedTheLimit) {
    std::mt19937_64 rng(20240501);
    std::uniform_int_distribution<int> byte(0, 255);
    std::uniform_int_distribution<int> length(0, 70);
    const double specials[] = {std::numeric_limits<double>::quiet_NaN(),
                               std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity(),
                               1e300,
                               -1e300,
                               4.0000001,
                               -250.0000001,
                               std::numeric_limits<double>::denorm_min()};
    std::uniform_real_distribution<double> wide(-1000.0, 1000.0);
    std::size_t accepted = 0;
    Calibration calibration;
    calibration.axes[kAxisInsertion] = {-50000, 2.0};
    calibration.axes[kAxisPitch] = {60000, -2.0};
    for (int i = 0; i < 100000; ++i) {
        std::vector<std::uint8_t> bytes(static_cast<std::size_t>(length(rng)));
        for (auto& b : bytes)
            b = static_cast<std::uint8_t>(byte(rng));
        if (i % 2 == 0) { // half of them a valid report with one byte changed, to reach the range checks
            sim::DeviceSample s;
            s.insertionMm = wide(rng) * 0.1;
            s.rollDeg = wide(rng) * 0.1;
            s.inflow = 0.5;
            bytes = encodeInputReport(s, static_cast<std::uint16_t>(i));
            bytes[static_cast<std::size_t>(byte(rng)) % bytes.size()] = static_cast<std::uint8_t>(byte(rng));
        }
        auto in = decodeInputReport(bytes.data(), bytes.size(), i % 4 == 0 ? calibration : Calibration{});
        if (in.ok()) {
            ++accepted;
            ASSERT_TRUE(sim::isValid(in->sample)) << "iteration " << i;
        }
        (void)decodeLimitsReport(bytes.data(), bytes.size());
        (void)decodeCalibrationReport(bytes.data(), bytes.size());
        auto out = decodeOutputReport(bytes.data(), bytes.size(), kLimits);
        if (out.ok()) {
            ASSERT_LE(loadFraction(out->command, kLimits), 1.0);
        }

        ForceCommand c;
        c.enabled = byte(rng) != 0;
        const auto pick = [&] { return byte(rng) < 32 ? specials[byte(rng) % 8] : wide(rng); };
        c.insertionForceN = pick();
        c.pitchTorqueNmm = pick();
        c.yawTorqueNmm = pick();
        c.rollTorqueNmm = pick();
        const auto wire = encodeOutputReport(c, kLimits, static_cast<std::uint16_t>(i));
        // Read back without a device-side clamp: what is on the wire must already be within the limit.
        auto back = decodeOutputReport(wire.data(), wire.size(), DeviceLimits{1e9, 1e12});
        ASSERT_TRUE(back.ok());
        ASSERT_LE(std::abs(back->command.insertionForceN), kLimits.maxForceN) << "iteration " << i;
        ASSERT_LE(std::abs(back->command.pitchTorqueNmm), kLimits.maxTorqueNmm);
        ASSERT_LE(std::abs(back->command.yawTorqueNmm), kLimits.maxTorqueNmm);
        ASSERT_LE(std::abs(back->command.rollTorqueNmm), kLimits.maxTorqueNmm);
    }
    EXPECT_GT(accepted, 0u); // the well-framed half does reach the decoder's value checks
}

} // namespace
} // namespace hs::haptics::hid
