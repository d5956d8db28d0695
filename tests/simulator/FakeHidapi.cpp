// The hidapi fake (FakeHidapi.h). Implements the C functions of <hidapi.h> that HidDevice calls.
#include "FakeHidapi.h"

#include "hs/haptics/Clock.h"

#include <hidapi.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <mutex>
#include <thread>

struct hid_device_ {
    int id = 0;
};

namespace hs::test::fakehid {
namespace {

struct State {
    std::mutex mutex;
    Trace trace;
    std::vector<Written> outputs;
    std::vector<std::vector<std::uint8_t>> featuresSent;
    std::size_t nextInput = 0;
    std::int64_t openNs = 0;
    std::int64_t manualUs = 0;
    int open = 0;
    hid_device_ device;
};

} // namespace

State& state() {
    static State s;
    return s;
}

namespace {

std::int64_t nowUs(const State& s) {
    return s.trace.manualClock ? s.manualUs : (haptics::monotonicNs() - s.openNs) / 1000;
}

bool unplugged(const State& s) {
    return s.trace.unplugAtUs >= 0 && nowUs(s) >= s.trace.unplugAtUs;
}

} // namespace

wchar_t* copyWide(const std::wstring& text) {
    auto* out = new wchar_t[text.size() + 1];
    std::wmemcpy(out, text.c_str(), text.size() + 1);
    return out;
}

void install(Trace trace) {
    State& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    s.trace = std::move(trace);
    s.outputs.clear();
    s.featuresSent.clear();
    s.nextInput = 0;
    s.manualUs = 0;
    s.openNs = haptics::monotonicNs();
}

void setTimeUs(std::int64_t us) {
    State& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    s.manualUs = us;
}

std::vector<Written> outputs() {
    State& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    return s.outputs;
}

std::vector<std::vector<std::uint8_t>> featuresSent() {
    State& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    return s.featuresSent;
}

std::size_t inputsDelivered() {
    State& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    return s.nextInput;
}

int openDevices() {
    State& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    return s.open;
}

} // namespace hs::test::fakehid

using hs::test::fakehid::copyWide;
using hs::test::fakehid::state;

extern "C" {

int HID_API_EXPORT HID_API_CALL hid_init(void) {
    return 0;
}

int HID_API_EXPORT HID_API_CALL hid_exit(void) {
    return 0;
}

struct hid_device_info HID_API_EXPORT* HID_API_CALL hid_enumerate(unsigned short vendor_id, unsigned short product_id) {
    auto& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    hid_device_info* head = nullptr;
    hid_device_info** tail = &head;
    for (const auto& d : s.trace.devices) {
        if ((vendor_id && d.vendorId != vendor_id) || (product_id && d.productId != product_id))
            continue;
        auto* info = new hid_device_info{};
        info->path = new char[d.path.size() + 1];
        std::memcpy(info->path, d.path.c_str(), d.path.size() + 1);
        info->vendor_id = d.vendorId;
        info->product_id = d.productId;
        info->usage_page = d.usagePage;
        info->product_string = copyWide(d.product);
        info->serial_number = copyWide(d.serial);
        info->manufacturer_string = copyWide(L"fake");
        *tail = info;
        tail = &info->next;
    }
    return head;
}

void HID_API_EXPORT HID_API_CALL hid_free_enumeration(struct hid_device_info* devs) {
    while (devs) {
        hid_device_info* next = devs->next;
        delete[] devs->path;
        delete[] devs->product_string;
        delete[] devs->serial_number;
        delete[] devs->manufacturer_string;
        delete devs;
        devs = next;
    }
}

HID_API_EXPORT hid_device* HID_API_CALL hid_open_path(const char* path) {
    auto& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    const bool known =
        std::any_of(s.trace.devices.begin(), s.trace.devices.end(), [&](const auto& d) { return d.path == path; });
    if (!known)
        return nullptr;
    ++s.open;
    s.openNs = hs::haptics::monotonicNs();
    return &s.device;
}

void HID_API_EXPORT HID_API_CALL hid_close(hid_device*) {
    auto& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    --s.open;
}

int HID_API_EXPORT HID_API_CALL hid_read_timeout(hid_device*, unsigned char* data, size_t length, int milliseconds) {
    auto& s = state();
    const auto giveUpNs = hs::haptics::monotonicNs() + static_cast<std::int64_t>(std::max(milliseconds, 0)) * 1000000;
    for (;;) {
        {
            std::lock_guard<std::mutex> lock(s.mutex);
            if (unplugged(s))
                return -1;
            if (s.nextInput < s.trace.inputs.size() && s.trace.inputs[s.nextInput].atUs <= nowUs(s)) {
                const auto& bytes = s.trace.inputs[s.nextInput++].bytes;
                const std::size_t n = std::min(length, bytes.size()); // hidraw truncates long reports too
                std::memcpy(data, bytes.data(), n);
                return static_cast<int>(n);
            }
        }
        if (hs::haptics::monotonicNs() >= giveUpNs)
            return 0;
        std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
}

int HID_API_EXPORT HID_API_CALL hid_write(hid_device*, const unsigned char* data, size_t length) {
    auto& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    if (unplugged(s))
        return -1;
    s.outputs.push_back({hs::haptics::monotonicNs(), nowUs(s), std::vector<std::uint8_t>(data, data + length)});
    return static_cast<int>(length);
}

int HID_API_EXPORT HID_API_CALL hid_send_feature_report(hid_device*, const unsigned char* data, size_t length) {
    auto& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    if (unplugged(s) || length == 0)
        return -1;
    s.featuresSent.emplace_back(data, data + length);
    s.trace.featureReports[data[0]] = std::vector<std::uint8_t>(data, data + length);
    return static_cast<int>(length);
}

int HID_API_EXPORT HID_API_CALL hid_get_feature_report(hid_device*, unsigned char* data, size_t length) {
    auto& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    if (unplugged(s) || length == 0)
        return -1;
    const auto it = s.trace.featureReports.find(data[0]);
    if (it == s.trace.featureReports.end())
        return -1;
    const std::size_t n = std::min(length, it->second.size());
    std::memcpy(data, it->second.data(), n);
    return static_cast<int>(n);
}

HID_API_EXPORT const wchar_t* HID_API_CALL hid_error(hid_device*) {
    return L"fake hidapi: the trace says so";
}

} // extern "C"
