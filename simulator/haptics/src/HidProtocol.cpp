// The HID protocol's codec (docs/haptics-protocol.md). Pure functions on bytes.
#include "hs/haptics/HidProtocol.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace hs::haptics::hid {

// clang-format off
const std::array<std::uint8_t, 238> kReportDescriptor = {
    0x06, 0x00, 0xFF,             // Usage Page (Vendor Defined 0xFF00)
    0x09, 0x01,                   // Usage (0x01: hysteroscope)
    0xA1, 0x01,                   // Collection (Application)
    // Input report 1: the device's state, 36 bytes (protocol 1: 28, without the items from offset 106 to 130)
    0x85, 0x01,                   //   Report ID (1)
    0x09, 0x10,                   //   Usage (0x10: sequence)
    0x15, 0x00,                   //   Logical Minimum (0)
    0x27, 0xFF, 0xFF, 0x00, 0x00, //   Logical Maximum (65535)
    0x75, 0x10,                   //   Report Size (16)
    0x95, 0x01,                   //   Report Count (1)
    0x81, 0x02,                   //   Input (Data, Variable, Absolute)
    0x09, 0x11,                   //   Usage (0x11: insertion, micrometres)
    0x17, 0xB0, 0x3C, 0xFF, 0xFF, //   Logical Minimum (-50000)
    0x27, 0xF0, 0x49, 0x02, 0x00, //   Logical Maximum (150000)
    0x75, 0x20,                   //   Report Size (32)
    0x95, 0x01,                   //   Report Count (1)
    0x81, 0x02,                   //   Input (Data, Variable, Absolute)
    0x09, 0x12,                   //   Usage (0x12: pitch, millidegrees)
    0x09, 0x13,                   //   Usage (0x13: yaw, millidegrees)
    0x17, 0xA0, 0x15, 0xFF, 0xFF, //   Logical Minimum (-60000)
    0x27, 0x60, 0xEA, 0x00, 0x00, //   Logical Maximum (60000)
    0x95, 0x02,                   //   Report Count (2)
    0x81, 0x02,                   //   Input (Data, Variable, Absolute)
    0x09, 0x14,                   //   Usage (0x14: roll, millidegrees)
    0x09, 0x15,                   //   Usage (0x15: camera roll, millidegrees)
    0x17, 0xE0, 0x40, 0xFD, 0xFF, //   Logical Minimum (-180000)
    0x27, 0x20, 0xBF, 0x02, 0x00, //   Logical Maximum (180000)
    0x81, 0x02,                   //   Input (Data, Variable, Absolute)
    0x09, 0x16,                   //   Usage (0x16: inflow valve, 1/10000)
    0x09, 0x17,                   //   Usage (0x17: outflow valve, 1/10000)
    0x15, 0x00,                   //   Logical Minimum (0)
    0x26, 0x10, 0x27,             //   Logical Maximum (10000)
    0x75, 0x10,                   //   Report Size (16)
    0x81, 0x02,                   //   Input (Data, Variable, Absolute)
    0x05, 0x09,                   //   Usage Page (Button)
    0x19, 0x01,                   //   Usage Minimum (1)
    0x29, 0x10,                   //   Usage Maximum (16)
    0x25, 0x01,                   //   Logical Maximum (1)
    0x75, 0x01,                   //   Report Size (1)
    0x95, 0x10,                   //   Report Count (16)
    0x81, 0x02,                   //   Input (Data, Variable, Absolute)
    0x06, 0x00, 0xFF,             //   Usage Page (Vendor Defined 0xFF00)
    0x09, 0x18,                   //   Usage (0x18: working element, micrometres; protocol 2)
    0x15, 0x00,                   //   Logical Minimum (0)
    0x27, 0x20, 0x4E, 0x00, 0x00, //   Logical Maximum (20000)
    0x75, 0x20,                   //   Report Size (32)
    0x95, 0x01,                   //   Report Count (1)
    0x81, 0x02,                   //   Input (Data, Variable, Absolute)
    0x09, 0x19,                   //   Usage (0x19: instrument; protocol 2)
    0x25, 0x03,                   //   Logical Maximum (3)
    0x75, 0x10,                   //   Report Size (16)
    0x81, 0x02,                   //   Input (Data, Variable, Absolute)
    0x81, 0x03,                   //   Input (Constant): reserved, 0
    // Output report 2: the force, 20 bytes
    0x85, 0x02,                   //   Report ID (2)
    0x09, 0x20,                   //   Usage (0x20: sequence echo)
    0x27, 0xFF, 0xFF, 0x00, 0x00, //   Logical Maximum (65535)
    0x75, 0x10,                   //   Report Size (16)
    0x95, 0x01,                   //   Report Count (1)
    0x91, 0x02,                   //   Output (Data, Variable, Absolute)
    0x09, 0x21,                   //   Usage (0x21: force enable)
    0x25, 0x01,                   //   Logical Maximum (1)
    0x75, 0x01,                   //   Report Size (1)
    0x91, 0x02,                   //   Output (Data, Variable, Absolute)
    0x75, 0x0F,                   //   Report Size (15)
    0x91, 0x03,                   //   Output (Constant): reserved flags, 0
    0x09, 0x22,                   //   Usage (0x22: insertion force, mN)
    0x09, 0x23,                   //   Usage (0x23: pitch torque, mN*mm)
    0x09, 0x24,                   //   Usage (0x24: yaw torque, mN*mm)
    0x09, 0x25,                   //   Usage (0x25: roll torque, mN*mm)
    0x17, 0x00, 0x00, 0x00, 0x80, //   Logical Minimum (-2147483648)
    0x27, 0xFF, 0xFF, 0xFF, 0x7F, //   Logical Maximum (2147483647)
    0x75, 0x20,                   //   Report Size (32)
    0x95, 0x04,                   //   Report Count (4)
    0x91, 0x02,                   //   Output (Data, Variable, Absolute)
    // Feature report 3: limits, 12 bytes
    0x85, 0x03,                   //   Report ID (3)
    0x09, 0x30,                   //   Usage (0x30: protocol version)
    0x09, 0x31,                   //   Usage (0x31: flags; bit 0 actuated)
    0x15, 0x00,                   //   Logical Minimum (0)
    0x26, 0xFF, 0x00,             //   Logical Maximum (255)
    0x75, 0x08,                   //   Report Size (8)
    0x95, 0x02,                   //   Report Count (2)
    0xB1, 0x02,                   //   Feature (Data, Variable, Absolute)
    0x75, 0x10,                   //   Report Size (16)
    0x95, 0x01,                   //   Report Count (1)
    0xB1, 0x03,                   //   Feature (Constant): reserved, 0
    0x09, 0x32,                   //   Usage (0x32: maximum force, mN)
    0x09, 0x33,                   //   Usage (0x33: maximum torque, mN*mm)
    0x27, 0xFF, 0xFF, 0xFF, 0x7F, //   Logical Maximum (2147483647)
    0x75, 0x20,                   //   Report Size (32)
    0x95, 0x02,                   //   Report Count (2)
    0xB1, 0x02,                   //   Feature (Data, Variable, Absolute)
    // Feature report 4: calibration, 56 bytes
    0x85, 0x04,                   //   Report ID (4)
    0x19, 0x40,                   //   Usage Minimum (0x40: insertion zero offset)
    0x29, 0x4D,                   //   Usage Maximum (0x4D: outflow scale)
    0x17, 0x00, 0x00, 0x00, 0x80, //   Logical Minimum (-2147483648)
    0x75, 0x20,                   //   Report Size (32)
    0x95, 0x0E,                   //   Report Count (14)
    0xB1, 0x02,                   //   Feature (Data, Variable, Absolute)
    0xC0,                         // End Collection
};
// clang-format on

namespace {

Error refused(const char* report, const std::string& what) {
    return Error{ErrorCode::InvalidInput, std::string(report) + ": " + what};
}

std::uint16_t getU16(const std::uint8_t* p) {
    return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}
std::uint32_t getU32(const std::uint8_t* p) {
    return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
           (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}
std::int32_t getI32(const std::uint8_t* p) {
    return static_cast<std::int32_t>(getU32(p));
}
void putU16(std::vector<std::uint8_t>& out, std::uint16_t v) {
    out.push_back(static_cast<std::uint8_t>(v));
    out.push_back(static_cast<std::uint8_t>(v >> 8));
}
void putU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}
void putI32(std::vector<std::uint8_t>& out, std::int32_t v) {
    putU32(out, static_cast<std::uint32_t>(v));
}

/// `value / unit` rounded to the nearest count and clamped into [lo, hi] (non-finite: 0 clamped).
std::int32_t toCounts(double value, double unit, std::int32_t lo, std::int32_t hi) {
    const double counts = std::isfinite(value) ? std::round(value / unit) : 0.0;
    return static_cast<std::int32_t>(std::clamp(counts, static_cast<double>(lo), static_cast<double>(hi)));
}
/// Towards zero, so |counts * unit| <= |value| <= limit.
std::int32_t toCountsTowardsZero(double value, double unit) {
    const double counts = std::isfinite(value) ? std::trunc(value / unit) : 0.0;
    return static_cast<std::int32_t>(std::clamp(counts, -2147483647.0, 2147483647.0));
}

struct AxisRange {
    const char* name;
    std::int32_t lo, hi;
    double unit;
};
constexpr AxisRange kAxes[kAxisCount] = {
    {"insertion", kInsertionMinCount, kInsertionMaxCount, kMmPerCount},
    {"pitch", -kPivotMaxCount, kPivotMaxCount, kDegPerCount},
    {"yaw", -kPivotMaxCount, kPivotMaxCount, kDegPerCount},
    {"roll", -kRollMaxCount, kRollMaxCount, kDegPerCount},
    {"cameraRoll", -kRollMaxCount, kRollMaxCount, kDegPerCount},
    {"inflow", 0, kValveMaxCount, kValvePerCount},
    {"outflow", 0, kValveMaxCount, kValvePerCount},
};

std::string sizeText(std::size_t got, std::size_t expected) {
    return std::to_string(got) + " bytes (expected " + std::to_string(expected) + " with the report ID)";
}

std::string idText(std::uint8_t got, std::uint8_t expected) {
    return "report ID " + std::to_string(got) + " (expected " + std::to_string(expected) + ")";
}

} // namespace

Result<DecodedInput> decodeInputReport(const std::uint8_t* data, std::size_t size, const Calibration& calibration,
                                       std::uint8_t version) {
    if (version != kProtocolVersion1 && version != kProtocolVersion2)
        return refused("input report", "protocol version " + std::to_string(version) + " (1 or 2)");
    const bool resectoscope = version == kProtocolVersion2;
    const std::size_t expected = resectoscope ? kInputReportBytes : kInputReportBytesV1;
    if (!data || size != expected)
        return refused("input report", sizeText(data ? size : 0, expected));
    if (data[0] != kInputReportId)
        return refused("input report", idText(data[0], kInputReportId));
    DecodedInput in;
    in.sequence = getU16(data + 1);
    std::int32_t raw[kAxisCount] = {};
    for (std::size_t a = 0; a < 5; ++a)
        raw[a] = getI32(data + 3 + 4 * a);
    raw[kAxisInflow] = getU16(data + 23);
    raw[kAxisOutflow] = getU16(data + 25);
    for (std::size_t a = 0; a < kAxisCount; ++a)
        if (raw[a] < kAxes[a].lo || raw[a] > kAxes[a].hi)
            return refused("input report", std::string(kAxes[a].name) + " " + std::to_string(raw[a]) +
                                               " counts is outside " + std::to_string(kAxes[a].lo) + ".." +
                                               std::to_string(kAxes[a].hi));
    const std::uint16_t buttons = getU16(data + 27);
    const std::uint16_t mask = resectoscope ? kButtonMask : kButtonMaskV1;
    if (buttons & ~mask)
        return refused("input report", "buttons " + std::to_string(buttons) + " has reserved bits set (only bits 0-" +
                                           std::string(resectoscope ? "5" : "1") + " in protocol " +
                                           std::to_string(version) + ")");
    std::int32_t workingElement = 0;
    std::uint16_t instrument = sim::kInstrumentNone;
    if (resectoscope) {
        workingElement = getI32(data + 29);
        if (workingElement < 0 || workingElement > kWorkingElementMaxCount)
            return refused("input report", "workingElement " + std::to_string(workingElement) +
                                               " counts is outside 0.." + std::to_string(kWorkingElementMaxCount));
        instrument = getU16(data + 33);
        if (instrument > sim::kMaxInstrument)
            return refused("input report", "instrument " + std::to_string(instrument) + " is not one of 0.." +
                                               std::to_string(sim::kMaxInstrument));
        if (getU16(data + 35) != 0)
            return refused("input report", "the reserved bytes 35-36 are not 0");
    }
    double value[kAxisCount] = {};
    for (std::size_t a = 0; a < kAxisCount; ++a) {
        const AxisCalibration& c = calibration.axes[a];
        const double scale = std::isfinite(c.scale) ? c.scale : 1.0;
        value[a] = (static_cast<double>(raw[a]) - static_cast<double>(c.zeroCount)) * scale * kAxes[a].unit;
    }
    sim::DeviceSample s;
    s.insertionMm = value[kAxisInsertion];
    s.pitchDeg = value[kAxisPitch];
    s.yawDeg = value[kAxisYaw];
    s.rollDeg = value[kAxisRoll];
    s.cameraRollDeg = value[kAxisCameraRoll];
    s.inflow = value[kAxisInflow];
    s.outflow = value[kAxisOutflow];
    s.buttons = buttons;
    s.workingElementMm = workingElement * kMmPerCount;
    s.instrument = instrument;
    in.sample = sim::clamped(s);
    return in;
}

std::vector<std::uint8_t> encodeInputReport(const sim::DeviceSample& s, std::uint16_t sequence, std::uint8_t version) {
    const bool resectoscope = version == kProtocolVersion2;
    std::vector<std::uint8_t> out;
    out.reserve(kInputReportBytes);
    out.push_back(kInputReportId);
    putU16(out, sequence);
    const double values[5] = {s.insertionMm, s.pitchDeg, s.yawDeg, s.rollDeg, s.cameraRollDeg};
    for (std::size_t a = 0; a < 5; ++a)
        putI32(out, toCounts(values[a], kAxes[a].unit, kAxes[a].lo, kAxes[a].hi));
    putU16(out, static_cast<std::uint16_t>(toCounts(s.inflow, kValvePerCount, 0, kValveMaxCount)));
    putU16(out, static_cast<std::uint16_t>(toCounts(s.outflow, kValvePerCount, 0, kValveMaxCount)));
    putU16(out, static_cast<std::uint16_t>(s.buttons & (resectoscope ? kButtonMask : kButtonMaskV1)));
    if (resectoscope) {
        putI32(out, toCounts(s.workingElementMm, kMmPerCount, 0, kWorkingElementMaxCount));
        putU16(out, static_cast<std::uint16_t>(std::min<std::uint32_t>(s.instrument, sim::kMaxInstrument)));
        putU16(out, 0);
    }
    return out;
}

std::vector<std::uint8_t> encodeOutputReport(const ForceCommand& command, const DeviceLimits& limits,
                                             std::uint16_t sequenceEcho) {
    const ForceCommand c = clampForce(command, limits);
    std::vector<std::uint8_t> out;
    out.reserve(kOutputReportBytes);
    out.push_back(kOutputReportId);
    putU16(out, sequenceEcho);
    putU16(out, c.enabled ? kFlagForceEnable : 0);
    putI32(out, toCountsTowardsZero(c.insertionForceN, kNPerCount));
    putI32(out, toCountsTowardsZero(c.pitchTorqueNmm, kNmmPerCount));
    putI32(out, toCountsTowardsZero(c.yawTorqueNmm, kNmmPerCount));
    putI32(out, toCountsTowardsZero(c.rollTorqueNmm, kNmmPerCount));
    return out;
}

Result<DecodedOutput> decodeOutputReport(const std::uint8_t* data, std::size_t size, const DeviceLimits& limits) {
    if (!data || size != kOutputReportBytes)
        return refused("output report", sizeText(data ? size : 0, kOutputReportBytes));
    if (data[0] != kOutputReportId)
        return refused("output report", idText(data[0], kOutputReportId));
    const std::uint16_t flags = getU16(data + 3);
    if (flags & ~kFlagForceEnable)
        return refused("output report", "flags " + std::to_string(flags) + " has reserved bits set (only bit 0)");
    DecodedOutput out;
    out.sequenceEcho = getU16(data + 1);
    ForceCommand c;
    c.enabled = (flags & kFlagForceEnable) != 0;
    c.insertionForceN = getI32(data + 5) * kNPerCount;
    c.pitchTorqueNmm = getI32(data + 9) * kNmmPerCount;
    c.yawTorqueNmm = getI32(data + 13) * kNmmPerCount;
    c.rollTorqueNmm = getI32(data + 17) * kNmmPerCount;
    out.command = clampForce(c, limits);
    return out;
}

std::vector<std::uint8_t> encodeLimitsReport(const DeviceLimits& limits) {
    const bool actuated = limits.maxForceN > 0.0 || limits.maxTorqueNmm > 0.0;
    std::vector<std::uint8_t> out;
    out.reserve(kLimitsReportBytes);
    out.push_back(kLimitsReportId);
    out.push_back(limits.resectoscope ? kProtocolVersion2 : kProtocolVersion1);
    out.push_back(actuated ? kLimitsFlagActuated : 0);
    putU16(out, 0);
    putI32(out, toCounts(limits.maxForceN, kNPerCount, 0, std::numeric_limits<std::int32_t>::max()));
    putI32(out, toCounts(limits.maxTorqueNmm, kNmmPerCount, 0, std::numeric_limits<std::int32_t>::max()));
    return out;
}

Result<DeviceLimits> decodeLimitsReport(const std::uint8_t* data, std::size_t size) {
    if (!data || size != kLimitsReportBytes)
        return refused("limits report", sizeText(data ? size : 0, kLimitsReportBytes));
    if (data[0] != kLimitsReportId)
        return refused("limits report", idText(data[0], kLimitsReportId));
    if (data[1] != kProtocolVersion1 && data[1] != kProtocolVersion2)
        return Error{ErrorCode::Unsupported, "limits report: protocol version " + std::to_string(data[1]) +
                                                 " (this build speaks versions 1 and 2)"};
    if (data[2] & ~kLimitsFlagActuated)
        return refused("limits report", "flags " + std::to_string(data[2]) + " has reserved bits set (only bit 0)");
    const double force = getU32(data + 5) * kNPerCount;
    const double torque = getU32(data + 9) * kNmmPerCount;
    if (force > kMaxDeclaredForceN)
        return refused("limits report", "maxForce " + std::to_string(force) + " N is above " +
                                            std::to_string(kMaxDeclaredForceN) + " N");
    if (torque > kMaxDeclaredTorqueNmm)
        return refused("limits report", "maxTorque " + std::to_string(torque) + " N*mm is above " +
                                            std::to_string(kMaxDeclaredTorqueNmm) + " N*mm");
    DeviceLimits limits;
    limits.resectoscope = data[1] == kProtocolVersion2;
    if (data[2] & kLimitsFlagActuated) {
        limits.maxForceN = force;
        limits.maxTorqueNmm = torque;
    }
    return limits;
}

std::vector<std::uint8_t> encodeCalibrationReport(const Calibration& calibration) {
    std::vector<std::uint8_t> out;
    out.reserve(kCalibrationReportBytes);
    out.push_back(kCalibrationReportId);
    for (const AxisCalibration& a : calibration.axes) {
        putI32(out, a.zeroCount);
        putI32(out, toCounts(a.scale, 1.0 / kCalibrationScaleOne, std::numeric_limits<std::int32_t>::min(),
                             std::numeric_limits<std::int32_t>::max()));
    }
    return out;
}

Status checkCalibration(const Calibration& calibration) {
    for (std::size_t a = 0; a < kAxisCount; ++a) {
        const AxisCalibration& c = calibration.axes[a];
        if (c.zeroCount < kAxes[a].lo || c.zeroCount > kAxes[a].hi)
            return refused("calibration", std::string(kAxes[a].name) + " zero offset " + std::to_string(c.zeroCount) +
                                              " counts is outside " + std::to_string(kAxes[a].lo) + ".." +
                                              std::to_string(kAxes[a].hi));
        const double m = std::abs(c.scale);
        if (!(m >= 0.5 && m <= 2.0))
            return refused("calibration", std::string(kAxes[a].name) + " scale " + std::to_string(c.scale) +
                                              " is outside 0.5 <= |scale| <= 2");
    }
    return {};
}

Result<Calibration> decodeCalibrationReport(const std::uint8_t* data, std::size_t size) {
    if (!data || size != kCalibrationReportBytes)
        return refused("calibration report", sizeText(data ? size : 0, kCalibrationReportBytes));
    if (data[0] != kCalibrationReportId)
        return refused("calibration report", idText(data[0], kCalibrationReportId));
    Calibration c;
    for (std::size_t a = 0; a < kAxisCount; ++a) {
        c.axes[a].zeroCount = getI32(data + 1 + 8 * a);
        c.axes[a].scale = getI32(data + 5 + 8 * a) / kCalibrationScaleOne;
    }
    HS_TRY(checkCalibration(c));
    return c;
}

Result<std::vector<DescriptorItem>> parseDescriptor(const std::uint8_t* data, std::size_t size) {
    std::vector<DescriptorItem> items;
    for (std::size_t i = 0; i < size;) {
        const std::uint8_t prefix = data[i];
        if (prefix == 0xFE)
            return refused("report descriptor", "long item at byte " + std::to_string(i) + " (not used)");
        DescriptorItem item;
        item.offset = i;
        item.size = static_cast<std::uint8_t>((prefix & 0x3) == 3 ? 4 : (prefix & 0x3));
        item.type = static_cast<std::uint8_t>((prefix >> 2) & 0x3);
        item.tag = static_cast<std::uint8_t>(prefix >> 4);
        // bType 3 is reserved (HID 1.11, 6.2.2.2); its only use, the long item 0xFE, is refused above.
        if (item.type == 3)
            return refused("report descriptor", "item at byte " + std::to_string(i) +
                                                    " has the reserved type 3 (prefix " + std::to_string(prefix) + ")");
        if (size - i - 1 < item.size)
            return refused("report descriptor", "item at byte " + std::to_string(i) + " is truncated");
        for (std::uint8_t b = 0; b < item.size; ++b)
            item.data |= static_cast<std::uint32_t>(data[i + 1 + b]) << (8 * b);
        items.push_back(item);
        i += 1u + item.size;
    }
    return items;
}

Result<DeclaredReportSizes> declaredReportSizes(const std::vector<DescriptorItem>& items) {
    // Bits per report; the global state (report ID, size, count) carries over from item to item (HID 1.11, 6.2.2.7).
    std::array<std::size_t, 256> bits[3] = {};
    std::uint32_t reportId = 0, reportSize = 0, reportCount = 0;
    for (const DescriptorItem& item : items) {
        if (item.type == 1 && item.tag == 0x8)
            reportId = item.data & 0xFF;
        else if (item.type == 1 && item.tag == 0x7)
            reportSize = item.data;
        else if (item.type == 1 && item.tag == 0x9)
            reportCount = item.data;
        else if (item.type == 1 && (item.tag == 0xA || item.tag == 0xB))
            return refused("report descriptor", "Push/Pop at byte " + std::to_string(item.offset) + " (not used)");
        else if (item.type == 0 && (item.tag == 0x8 || item.tag == 0x9 || item.tag == 0xB)) {
            const int kind = item.tag == 0x8 ? 0 : (item.tag == 0x9 ? 1 : 2);
            bits[kind][reportId] += static_cast<std::size_t>(reportSize) * reportCount;
        }
    }
    DeclaredReportSizes sizes;
    std::array<std::size_t, 256>* out[3] = {&sizes.input, &sizes.output, &sizes.feature};
    for (int kind = 0; kind < 3; ++kind)
        for (std::size_t id = 0; id < 256; ++id) {
            if (bits[kind][id] % 8 != 0)
                return refused("report descriptor", "report " + std::to_string(id) + " declares " +
                                                        std::to_string(bits[kind][id]) + " bits, not whole bytes");
            (*out[kind])[id] = bits[kind][id] / 8;
        }
    return sizes;
}

} // namespace hs::haptics::hid
