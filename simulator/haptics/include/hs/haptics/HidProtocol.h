#pragma once
/// The hysteroscope's HID protocol (docs/haptics-protocol.md): report layouts, fixed-point scales and the codec.
/// Pure functions on bytes, no I/O: every decoder takes any byte string (fuzzed in the tests), refuses what breaks a
/// rule with InvalidInput naming the field, and never reads outside `size`; the output encoder never emits a force
/// above the device's limit.
///
/// Byte strings include the report ID as their first byte, as hidapi reads and writes them.

#include "hs/core/Result.h"
#include "hs/haptics/HapticDevice.h"
#include "hs/sim/Device.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hs::haptics::hid {

/// USB IDs the HID device looks for unless told otherwise: pid.codes' open-source vendor ID and its test product ID.
/// A builder registers a product ID of their own (pid.codes) and passes it as `--device hid:1209:PPPP`.
inline constexpr std::uint16_t kDefaultVendorId = 0x1209;
inline constexpr std::uint16_t kDefaultProductId = 0x0001;
/// Vendor-defined usage page and the application collection's usage.
inline constexpr std::uint16_t kUsagePage = 0xFF00;
inline constexpr std::uint16_t kUsage = 0x0001;
/// Protocol versions: 1 the diagnostic scope; 2 adds the resectoscope to input report 1 (the working element, the
/// pedals, the pump's buttons, the instrument). The host speaks both; a device declares its own in feature report 3.
inline constexpr std::uint8_t kProtocolVersion1 = 1;
inline constexpr std::uint8_t kProtocolVersion2 = 2;
inline constexpr std::uint8_t kProtocolVersion = kProtocolVersion2; ///< the newest this build speaks

/// Report IDs.
inline constexpr std::uint8_t kInputReportId = 0x01;
inline constexpr std::uint8_t kOutputReportId = 0x02;
inline constexpr std::uint8_t kLimitsReportId = 0x03;
inline constexpr std::uint8_t kCalibrationReportId = 0x04;

/// Report sizes in bytes without the report ID (what the report descriptor declares) and with it (on the wire).
inline constexpr std::size_t kInputPayloadBytesV1 = 28;
inline constexpr std::size_t kInputPayloadBytes = 36; ///< protocol 2: the v1 fields, then the resectoscope's
inline constexpr std::size_t kOutputPayloadBytes = 20;
inline constexpr std::size_t kLimitsPayloadBytes = 12;
inline constexpr std::size_t kCalibrationPayloadBytes = 56;
inline constexpr std::size_t kInputReportBytesV1 = 1 + kInputPayloadBytesV1;
inline constexpr std::size_t kInputReportBytes = 1 + kInputPayloadBytes;
inline constexpr std::size_t kOutputReportBytes = 1 + kOutputPayloadBytes;
inline constexpr std::size_t kLimitsReportBytes = 1 + kLimitsPayloadBytes;
inline constexpr std::size_t kCalibrationReportBytes = 1 + kCalibrationPayloadBytes;

/// Fixed-point scales on the wire.
inline constexpr double kMmPerCount = 0.001;            ///< insertion: micrometres
inline constexpr double kDegPerCount = 0.001;           ///< angles: millidegrees
inline constexpr double kValvePerCount = 0.0001;        ///< valves: 0..10000 = closed..open
inline constexpr double kNPerCount = 0.001;             ///< force: millinewtons
inline constexpr double kNmmPerCount = 0.001;           ///< torque: mN*mm
inline constexpr double kCalibrationScaleOne = 65536.0; ///< calibration scales: Q16.16

/// Logical ranges of the input report's fields (the report descriptor declares the same); outside: refused.
inline constexpr std::int32_t kInsertionMinCount = -50000;
inline constexpr std::int32_t kInsertionMaxCount = 150000;
inline constexpr std::int32_t kPivotMaxCount = 60000;
inline constexpr std::int32_t kRollMaxCount = 180000;
inline constexpr std::uint16_t kValveMaxCount = 10000;
inline constexpr std::int32_t kWorkingElementMaxCount = 20000; ///< micrometres (sim::kMaxWorkingElementMm)
/// Button bits defined: protocol 1 mark and capture (sim::kButtonMark, sim::kButtonCapture); protocol 2 also the
/// cutting and coagulating pedals and the pump's up and down buttons (bits 2-5, as sim::DeviceButton). The others
/// must be 0.
inline constexpr std::uint16_t kButtonMaskV1 = 0x0003;
inline constexpr std::uint16_t kButtonMask = 0x003F;
/// Output report flags.
inline constexpr std::uint16_t kFlagForceEnable = 0x0001;
/// Limits report flags.
inline constexpr std::uint8_t kLimitsFlagActuated = 0x01;
/// The largest limits a device may declare (a hand-held scope needs far less).
inline constexpr double kMaxDeclaredForceN = 50.0;
inline constexpr double kMaxDeclaredTorqueNmm = 5000.0;

/// The HID report descriptor (docs/haptics-protocol.md annotates every item).
/// Protocol 2's; a protocol-1 device's declares input report 1 without the items at offsets 106-130 (28 bytes).
extern const std::array<std::uint8_t, 238> kReportDescriptor;

/// Input axes in report order, for the calibration report.
enum Axis : std::size_t {
    kAxisInsertion,
    kAxisPitch,
    kAxisYaw,
    kAxisRoll,
    kAxisCameraRoll,
    kAxisInflow,
    kAxisOutflow,
    kAxisCount
};

/// The host-side correction of each input axis: value = (raw - zeroCount) * scale, in the axis' wire units. A device
/// keeps its calibration in its own memory (feature report 4); the calibration tool writes it.
struct AxisCalibration {
    std::int32_t zeroCount = 0; ///< raw counts at the axis' zero; within the axis' logical range
    double scale = 1.0;         ///< 0.5 <= |scale| <= 2 (negative flips the axis); Q16.16 on the wire
};
struct Calibration {
    std::array<AxisCalibration, kAxisCount> axes{};
};

struct DecodedInput {
    std::uint16_t sequence = 0; ///< the device's report counter (wraps at 65536)
    sim::DeviceSample sample;   ///< calibrated and clamped into Device.h's ranges; tick 0
};

/// Input report 1 of a device of protocol `version` (1 or 2). Refused (InvalidInput naming the field): a size other
/// than the version's (kInputReportBytesV1, kInputReportBytes), another report ID, a field outside its logical range
/// (an impossible working element or an unknown instrument among them), a reserved bit or byte set. A protocol-1
/// sample carries the diagnostic scope (instrument 0, working element 0).
[[nodiscard]] Result<DecodedInput> decodeInputReport(const std::uint8_t* data, std::size_t size,
                                                     const Calibration& calibration,
                                                     std::uint8_t version = kProtocolVersion1);
/// The input report a device of protocol `version` sends for `sample` (values rounded to counts and clamped to the
/// logical ranges; no calibration; the fields the version lacks left out): what a device's firmware does, for tests
/// and the reference implementation.
std::vector<std::uint8_t> encodeInputReport(const sim::DeviceSample& sample, std::uint16_t sequence,
                                            std::uint8_t version = kProtocolVersion1);

/// The output report for `command`: clamped to `limits` first (clampForce), then rounded towards zero to counts,
/// so the wire value never exceeds the limit. `sequenceEcho` is the sequence of the newest input report the force
/// was computed from (the device measures the loop's latency with it).
std::vector<std::uint8_t> encodeOutputReport(const ForceCommand& command, const DeviceLimits& limits,
                                             std::uint16_t sequenceEcho = 0);
struct DecodedOutput {
    std::uint16_t sequenceEcho = 0;
    ForceCommand command; ///< tipForceN is not on the wire (zero)
};
/// What a device does with an output report (firmware reference and tests): refused for a wrong size or ID or
/// reserved flags; the values are clamped to `limits` again.
[[nodiscard]] Result<DecodedOutput> decodeOutputReport(const std::uint8_t* data, std::size_t size,
                                                       const DeviceLimits& limits);

/// Feature report 3: the device's limits and capabilities (read at open); protocol version 2 when
/// `limits.resectoscope`, else 1.
std::vector<std::uint8_t> encodeLimitsReport(const DeviceLimits& limits);
/// Refused: wrong size or ID, a protocol version other than 1 and 2 (Unsupported), limits above
/// kMaxDeclaredForceN/kMaxDeclaredTorqueNmm. A device without the "actuated" flag gets zero limits; one of
/// protocol 2 reports the resectoscope.
[[nodiscard]] Result<DeviceLimits> decodeLimitsReport(const std::uint8_t* data, std::size_t size);

/// Feature report 4: zero offsets and scales of the seven axes.
std::vector<std::uint8_t> encodeCalibrationReport(const Calibration& calibration);
/// Refused: wrong size or ID, a zero offset outside the axis' logical range, a scale outside 0.5 <= |s| <= 2.
[[nodiscard]] Result<Calibration> decodeCalibrationReport(const std::uint8_t* data, std::size_t size);
[[nodiscard]] Status checkCalibration(const Calibration& calibration);

/// One item of a HID report descriptor (HID 1.11, section 6.2.2.2, short items).
struct DescriptorItem {
    std::uint8_t type = 0; ///< 0 main, 1 global, 2 local
    std::uint8_t tag = 0;
    std::uint8_t size = 0;  ///< data bytes: 0, 1, 2 or 4
    std::uint32_t data = 0; ///< unsigned, little-endian
    std::size_t offset = 0; ///< of the prefix byte in the descriptor
};
/// The items of a descriptor; InvalidInput for a truncated item or a long item (the protocol uses none).
[[nodiscard]] Result<std::vector<DescriptorItem>> parseDescriptor(const std::uint8_t* data, std::size_t size);
/// Bytes each report declares, by kind and ID: what Input, Output and Feature main items add up to (bits / 8).
struct DeclaredReportSizes {
    std::array<std::size_t, 256> input{};
    std::array<std::size_t, 256> output{};
    std::array<std::size_t, 256> feature{};
};
/// InvalidInput when a report's bits are not whole bytes.
[[nodiscard]] Result<DeclaredReportSizes> declaredReportSizes(const std::vector<DescriptorItem>& items);

} // namespace hs::haptics::hid
