#pragma once
/// The hysteroscope over USB HID through hidapi (hidraw backend): docs/haptics-protocol.md is the protocol. open()
/// finds the device by vendor and product ID (or a path), reads its limits and calibration (feature reports 3 and 4);
/// read() drains every input report that arrived since the last call and returns the newest valid one; writeForce()
/// sends one output report, clamped to the device's limits. A read or write error means the device is gone
/// (unplugged): read() reports Disconnected from then on.
///
/// This library leaves hidapi's symbols unresolved: link hs::haptics_hidraw (the real library) or the tests' fake.

#include "hs/haptics/HapticDevice.h"
#include "hs/haptics/HidProtocol.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace hs::haptics {

struct HidDeviceOptions {
    std::uint16_t vendorId = hid::kDefaultVendorId;
    std::uint16_t productId = hid::kDefaultProductId;
    std::string path;                   ///< a device path from enumerateHidDevices(); empty: the first with the IDs
    std::size_t maxReportsPerRead = 64; ///< reports drained per read() at most (a device sending faster is throttled)
};

struct HidDeviceInfo {
    std::string path;
    std::uint16_t vendorId = 0;
    std::uint16_t productId = 0;
    std::uint16_t usagePage = 0;
    std::string product;
    std::string serial;
};

/// Devices with the IDs (0 matches any) that expose the protocol's usage page (hidraw reports it).
[[nodiscard]] Result<std::vector<HidDeviceInfo>> enumerateHidDevices(std::uint16_t vendorId, std::uint16_t productId);

/// Counters of what the device sent; read them from the thread that calls read() (or after it stopped).
struct HidDeviceStats {
    std::uint64_t reports = 0;      ///< valid input reports decoded
    std::uint64_t refused = 0;      ///< input reports refused (size, ID, range): ignored
    std::uint64_t superseded = 0;   ///< valid reports replaced by a newer one within one read() (sent too fast)
    std::uint64_t sequenceGaps = 0; ///< reports lost on the way, by the sequence counter
    std::uint64_t writes = 0;       ///< output reports sent
    std::string lastRefusal;        ///< the newest refusal's message
};

class HidDevice final : public HapticDevice {
public:
    explicit HidDevice(HidDeviceOptions options = {});
    ~HidDevice() override;
    HidDevice(const HidDevice&) = delete;
    HidDevice& operator=(const HidDevice&) = delete;

    /// NotFound without a matching device; BackendFailure when hidapi cannot open it; InvalidInput/Unsupported when
    /// its feature reports break the protocol (naming the report and field).
    [[nodiscard]] Status open() override;
    void close() override;
    ReadStatus read(sim::DeviceSample& out) override;
    [[nodiscard]] Status writeForce(const ForceCommand& command) override;
    DeviceLimits limits() const override;
    std::string name() const override;

    const hid::Calibration& calibration() const;
    /// Sends a new calibration (feature report 4) to the open device, which keeps it; used from then on.
    [[nodiscard]] Status writeCalibration(const hid::Calibration& calibration);
    const HidDeviceStats& stats() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace hs::haptics
