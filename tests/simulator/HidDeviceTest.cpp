// The HID device through the hidapi fake: byte traces in, output reports out, no hardware.
#include "hs/haptics/HidDevice.h"

#include "FakeHidapi.h"

#include <gtest/gtest.h>

namespace hs::haptics {
namespace {

namespace fake = test::fakehid;

const DeviceLimits kLimits{3.0, 200.0};

fake::Trace deviceTrace() {
    fake::Trace trace;
    trace.manualClock = true;
    trace.featureReports[hid::kLimitsReportId] = hid::encodeLimitsReport(kLimits);
    trace.featureReports[hid::kCalibrationReportId] = hid::encodeCalibrationReport({});
    return trace;
}

sim::DeviceSample pose(double insertionMm, double pitchDeg = 0.0) {
    sim::DeviceSample s;
    s.insertionMm = insertionMm;
    s.pitchDeg = pitchDeg;
    s.inflow = 0.5;
    return s;
}

TEST(HidDevice, EnumeratesOnlyTheProtocolsDevices) {
    fake::Trace trace = deviceTrace();
    fake::FakeDevice other;
    other.path = "/dev/hidraw-fake1";
    other.productId = 0x0002;
    fake::FakeDevice keyboard;
    keyboard.path = "/dev/hidraw-fake2";
    keyboard.usagePage = 0x0001; // the same IDs, another interface (generic desktop)
    trace.devices.push_back(other);
    trace.devices.push_back(keyboard);
    fake::install(trace);
    auto found = enumerateHidDevices(hid::kDefaultVendorId, hid::kDefaultProductId);
    ASSERT_TRUE(found.ok());
    ASSERT_EQ(found->size(), 1u);
    EXPECT_EQ(found->front().path, "/dev/hidraw-fake0");
    EXPECT_EQ(found->front().product, "Fake hysteroscope");
    auto any = enumerateHidDevices(0, 0);
    ASSERT_TRUE(any.ok());
    EXPECT_EQ(any->size(), 2u);
}

TEST(HidDevice, OpenReadsLimitsAndCalibration) {
    fake::Trace trace = deviceTrace();
    hid::Calibration c;
    c.axes[hid::kAxisInsertion] = {500, 1.0};
    trace.featureReports[hid::kCalibrationReportId] = hid::encodeCalibrationReport(c);
    fake::install(trace);
    HidDevice device;
    ASSERT_TRUE(device.open().ok());
    EXPECT_EQ(fake::openDevices(), 1);
    EXPECT_EQ(device.name(), "hid:1209:0001");
    EXPECT_DOUBLE_EQ(device.limits().maxForceN, 3.0);
    EXPECT_DOUBLE_EQ(device.limits().maxTorqueNmm, 200.0);
    EXPECT_EQ(device.calibration().axes[hid::kAxisInsertion].zeroCount, 500);
    device.close();
    EXPECT_EQ(fake::openDevices(), 0);
    // Closing sends one last report with the force off.
    const auto written = fake::outputs();
    ASSERT_EQ(written.size(), 1u);
    EXPECT_EQ(written[0].bytes[3] & hid::kFlagForceEnable, 0);
}

TEST(HidDevice, OpenRefusesMissingDevicesAndBadFeatureReports) {
    fake::Trace none = deviceTrace();
    none.devices.clear();
    fake::install(none);
    HidDevice device;
    auto status = device.open();
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().code, ErrorCode::NotFound);
    EXPECT_NE(status.error().detail.find("1209:0001"), std::string::npos);

    fake::Trace bad = deviceTrace();
    bad.featureReports[hid::kLimitsReportId] = hid::encodeLimitsReport({500.0, 200.0});
    fake::install(bad);
    status = device.open();
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().detail.find("limits report"), std::string::npos) << status.error().detail;
    EXPECT_NE(status.error().detail.find("/dev/hidraw-fake0"), std::string::npos);
    EXPECT_EQ(fake::openDevices(), 0);

    fake::Trace missing = deviceTrace();
    missing.featureReports.erase(hid::kCalibrationReportId);
    fake::install(missing);
    EXPECT_FALSE(device.open().ok());
    EXPECT_EQ(fake::openDevices(), 0);
}

TEST(HidDevice, DecodesInputAndWritesTheExpectedOutputBytes) {
    fake::Trace trace = deviceTrace();
    trace.inputs.push_back({0, hid::encodeInputReport(pose(25.0, -4.0), 0x0A0B)});
    fake::install(trace);
    HidDevice device;
    ASSERT_TRUE(device.open().ok());
    sim::DeviceSample s;
    ASSERT_EQ(device.read(s), ReadStatus::Sample);
    EXPECT_DOUBLE_EQ(s.insertionMm, 25.0);
    EXPECT_DOUBLE_EQ(s.pitchDeg, -4.0);
    EXPECT_DOUBLE_EQ(s.inflow, 0.5);
    EXPECT_EQ(device.read(s), ReadStatus::NoNewData);

    ForceCommand c;
    c.enabled = true;
    c.insertionForceN = -1.5;
    c.pitchTorqueNmm = 300.0; // above the 200 N*mm limit
    ASSERT_TRUE(device.writeForce(c).ok());
    const std::vector<std::uint8_t> expected = {
        0x02, 0x0B, 0x0A, 0x01, 0x00, // ID, the newest input's sequence, force enable
        0x24, 0xFA, 0xFF, 0xFF,       // -1500 mN
        0x40, 0x0D, 0x03, 0x00,       // 200000 mN*mm: clamped
        0x00, 0x00, 0x00, 0x00,       // yaw
        0x00, 0x00, 0x00, 0x00,       // roll
    };
    const auto written = fake::outputs();
    ASSERT_EQ(written.size(), 1u);
    EXPECT_EQ(written[0].bytes, expected);
}

TEST(HidDevice, AProtocolTwoDeviceDrivesTheResectoscopeAndAVersionOneDeviceTheDiagnosticScopeOnly) {
    sim::DeviceSample loop = pose(40.0);
    loop.workingElementMm = 8.5;
    loop.instrument = sim::kInstrumentLoop;
    loop.buttons = sim::kButtonCut;
    // Protocol 2: the limits report says so, its input reports carry the loop.
    fake::Trace trace = deviceTrace();
    DeviceLimits operative = kLimits;
    operative.resectoscope = true;
    trace.featureReports[hid::kLimitsReportId] = hid::encodeLimitsReport(operative);
    trace.inputs.push_back({0, hid::encodeInputReport(loop, 1, hid::kProtocolVersion2)});
    fake::install(trace);
    {
        HidDevice device;
        ASSERT_TRUE(device.open().ok());
        EXPECT_TRUE(device.limits().resectoscope);
        sim::DeviceSample s;
        ASSERT_EQ(device.read(s), ReadStatus::Sample);
        EXPECT_DOUBLE_EQ(s.workingElementMm, 8.5);
        EXPECT_EQ(s.instrument, sim::kInstrumentLoop);
        EXPECT_EQ(s.buttons, sim::kButtonCut);
    }
    // Protocol 1: the same device state in a version-2 report is refused (counted, no sample); its own reports
    // give the diagnostic scope.
    fake::Trace old = deviceTrace();
    old.inputs.push_back({0, hid::encodeInputReport(loop, 1, hid::kProtocolVersion2)});
    old.inputs.push_back({1000, hid::encodeInputReport(loop, 2, hid::kProtocolVersion1)});
    fake::install(old);
    HidDevice device;
    ASSERT_TRUE(device.open().ok());
    EXPECT_FALSE(device.limits().resectoscope);
    sim::DeviceSample s;
    fake::setTimeUs(0);
    EXPECT_EQ(device.read(s), ReadStatus::NoNewData);
    EXPECT_EQ(device.stats().refused, 1u);
    EXPECT_NE(device.stats().lastRefusal.find("37 bytes"), std::string::npos) << device.stats().lastRefusal;
    fake::setTimeUs(1000);
    ASSERT_EQ(device.read(s), ReadStatus::Sample);
    EXPECT_EQ(s.instrument, sim::kInstrumentNone);
    EXPECT_EQ(s.workingElementMm, 0.0);
    EXPECT_DOUBLE_EQ(s.insertionMm, 40.0);
}

TEST(HidDevice, ReportsArrivingTooFastYieldTheNewest) {
    fake::Trace trace = deviceTrace();
    for (std::uint16_t i = 0; i < 5; ++i)
        trace.inputs.push_back({200 * i, hid::encodeInputReport(pose(10.0 + i), i)});
    trace.inputs.push_back({1000, hid::encodeInputReport(pose(20.0), 9)}); // 5..8 lost on the way
    fake::install(trace);
    HidDevice device;
    ASSERT_TRUE(device.open().ok());
    fake::setTimeUs(999);
    sim::DeviceSample s;
    ASSERT_EQ(device.read(s), ReadStatus::Sample);
    EXPECT_DOUBLE_EQ(s.insertionMm, 14.0);
    EXPECT_EQ(device.stats().superseded, 4u);
    fake::setTimeUs(1000);
    ASSERT_EQ(device.read(s), ReadStatus::Sample);
    EXPECT_DOUBLE_EQ(s.insertionMm, 20.0);
    EXPECT_EQ(device.stats().sequenceGaps, 4u);
    EXPECT_EQ(device.stats().reports, 6u);
}

TEST(HidDevice, MalformedReportsAreIgnoredNotCrashed) {
    fake::Trace trace = deviceTrace();
    auto good = hid::encodeInputReport(pose(30.0), 1);
    const std::vector<std::uint8_t> shortReport(good.begin(), good.begin() + 20);
    auto wrongId = good;
    wrongId[0] = 0x07;
    auto outOfRange = good;
    outOfRange[6] = 0x7F; // insertion above 150000 um
    std::vector<std::uint8_t> longReport(80, 0x01);
    for (const auto& bytes : {shortReport, wrongId, outOfRange, longReport})
        trace.inputs.push_back({0, bytes});
    fake::install(trace);
    HidDevice device;
    ASSERT_TRUE(device.open().ok());
    sim::DeviceSample s;
    EXPECT_EQ(device.read(s), ReadStatus::NoNewData);
    EXPECT_EQ(device.stats().refused, 4u);
    EXPECT_NE(device.stats().lastRefusal.find("bytes"), std::string::npos) << device.stats().lastRefusal;
    fake::install([&] {
        fake::Trace t = deviceTrace();
        t.inputs.push_back({0, wrongId});
        t.inputs.push_back({0, good});
        return t;
    }());
    HidDevice again;
    ASSERT_TRUE(again.open().ok());
    ASSERT_EQ(again.read(s), ReadStatus::Sample);
    EXPECT_DOUBLE_EQ(s.insertionMm, 30.0);
}

TEST(HidDevice, UnplugIsReportedAsDisconnected) {
    fake::Trace trace = deviceTrace();
    trace.inputs.push_back({0, hid::encodeInputReport(pose(5.0), 1)});
    trace.unplugAtUs = 5000;
    fake::install(trace);
    HidDevice device;
    ASSERT_TRUE(device.open().ok());
    sim::DeviceSample s;
    EXPECT_EQ(device.read(s), ReadStatus::Sample);
    fake::setTimeUs(5000);
    EXPECT_EQ(device.read(s), ReadStatus::Disconnected);
    EXPECT_EQ(device.read(s), ReadStatus::Disconnected);
    ForceCommand c;
    c.enabled = true;
    EXPECT_FALSE(device.writeForce(c).ok());
    device.close();
    EXPECT_EQ(fake::openDevices(), 0);
}

} // namespace
} // namespace hs::haptics
