#pragma once
/// A link-time fake of the hidapi calls HidDevice uses, driven by a byte trace: the devices to enumerate, the feature
/// reports to answer, the input reports to return and when, and when the device is unplugged. It records what the
/// host wrote (output and feature reports, with monotonicNs() timestamps). Tests link it instead of libhidapi.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace hs::test::fakehid {

struct FakeDevice {
    std::string path = "/dev/hidraw-fake0";
    std::uint16_t vendorId = 0x1209;
    std::uint16_t productId = 0x0001;
    std::uint16_t usagePage = 0xFF00;
    std::wstring product = L"Fake hysteroscope";
    std::wstring serial = L"0001";
};

/// An input report the device sends `atUs` microseconds after hid_open_path.
struct TimedReport {
    std::int64_t atUs = 0;
    std::vector<std::uint8_t> bytes;
};

struct Trace {
    std::vector<FakeDevice> devices{FakeDevice{}};
    std::map<std::uint8_t, std::vector<std::uint8_t>> featureReports; ///< by report ID, with the ID byte
    std::vector<TimedReport> inputs;                                  ///< in time order
    std::int64_t unplugAtUs = -1; ///< from then on reads and writes fail (-1: never)
    bool manualClock = false;     ///< time is what setTimeUs() says, not the real time since open
};

struct Written {
    std::int64_t timeNs = 0; ///< monotonicNs() at the write
    std::int64_t atUs = 0;   ///< the trace's time at the write
    std::vector<std::uint8_t> bytes;
};

/// Replaces the trace and forgets everything recorded.
void install(Trace trace);
void setTimeUs(std::int64_t us);
std::vector<Written> outputs();
std::vector<std::vector<std::uint8_t>> featuresSent();
std::size_t inputsDelivered();
int openDevices(); ///< opened and not yet closed

} // namespace hs::test::fakehid
