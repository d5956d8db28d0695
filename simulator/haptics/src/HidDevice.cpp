// The hysteroscope over hidapi (docs/haptics-protocol.md).
#include "hs/haptics/HidDevice.h"

#include <hidapi.h>

#include <cstdio>
#include <cwchar>

namespace hs::haptics {

namespace {

/// hidapi's wide strings as ASCII ('?' for anything else): names for messages and the trial header.
std::string narrow(const wchar_t* text) {
    std::string out;
    for (; text && *text; ++text)
        out += (*text > 0 && *text < 128) ? static_cast<char>(*text) : '?';
    return out;
}

std::string hexId(std::uint16_t id) {
    char text[8];
    std::snprintf(text, sizeof text, "%04x", static_cast<unsigned>(id));
    return text;
}

std::string lastError(hid_device* device) {
    const std::string text = narrow(hid_error(device));
    return text.empty() ? "no detail from hidapi" : text;
}

} // namespace

Result<std::vector<HidDeviceInfo>> enumerateHidDevices(std::uint16_t vendorId, std::uint16_t productId) {
    if (hid_init() != 0)
        return fail(ErrorCode::BackendFailure, "hidapi: cannot initialise: " + lastError(nullptr));
    std::vector<HidDeviceInfo> found;
    hid_device_info* list = hid_enumerate(vendorId, productId);
    for (const hid_device_info* d = list; d; d = d->next) {
        // hidraw reports the top-level usage page; 0 when the backend does not know it.
        if (d->usage_page != 0 && d->usage_page != hid::kUsagePage)
            continue;
        HidDeviceInfo info;
        info.path = d->path ? d->path : "";
        info.vendorId = d->vendor_id;
        info.productId = d->product_id;
        info.usagePage = d->usage_page;
        info.product = narrow(d->product_string);
        info.serial = narrow(d->serial_number);
        found.push_back(std::move(info));
    }
    hid_free_enumeration(list);
    return found;
}

struct HidDevice::Impl {
    HidDeviceOptions options;
    hid_device* device = nullptr;
    bool lost = false;
    DeviceLimits limits;
    hid::Calibration calibration;
    HidDeviceStats stats;
    bool haveSequence = false;
    std::uint16_t lastSequence = 0;
    std::string path;

    /// Reads feature report `id` (the bytes hidapi returns, with the ID; the decoder checks the size).
    Result<std::vector<std::uint8_t>> getFeature(std::uint8_t id) {
        std::vector<std::uint8_t> buffer(64, 0);
        buffer[0] = id;
        const int n = hid_get_feature_report(device, buffer.data(), buffer.size());
        if (n < 0)
            return fail(ErrorCode::BackendFailure,
                        path + ": feature report " + std::to_string(id) + " cannot be read: " + lastError(device));
        buffer.resize(static_cast<std::size_t>(n));
        return buffer;
    }

    void countSequence(std::uint16_t sequence) {
        if (haveSequence) {
            const std::uint16_t step = static_cast<std::uint16_t>(sequence - lastSequence);
            if (step > 1 && step < 0x8000)
                stats.sequenceGaps += step - 1u;
        }
        haveSequence = true;
        lastSequence = sequence;
    }
};

HidDevice::HidDevice(HidDeviceOptions options) : m_impl(std::make_unique<Impl>()) {
    m_impl->options = std::move(options);
}

HidDevice::~HidDevice() {
    close();
}

Status HidDevice::open() {
    Impl& m = *m_impl;
    if (m.device)
        return {};
    m.path = m.options.path;
    if (m.path.empty()) {
        auto devices = enumerateHidDevices(m.options.vendorId, m.options.productId);
        if (!devices)
            return devices.failure();
        if (devices->empty())
            return fail(ErrorCode::NotFound, "no hysteroscope with USB ID " + hexId(m.options.vendorId) + ":" +
                                                 hexId(m.options.productId) + " is connected");
        m.path = devices->front().path;
    } else if (hid_init() != 0) {
        return fail(ErrorCode::BackendFailure, "hidapi: cannot initialise: " + lastError(nullptr));
    }
    m.device = hid_open_path(m.path.c_str());
    if (!m.device)
        return fail(ErrorCode::BackendFailure, m.path + ": cannot open: " + lastError(nullptr) +
                                                   " (permissions: see docs/haptics-protocol.md, \"Linux\")");
    const auto failOpen = [this](Error error) -> Status {
        hid_close(m_impl->device);
        m_impl->device = nullptr;
        return fail(std::move(error));
    };
    auto limitsBytes = m.getFeature(hid::kLimitsReportId);
    if (!limitsBytes)
        return failOpen(limitsBytes.error());
    auto limits = hid::decodeLimitsReport(limitsBytes->data(), limitsBytes->size());
    if (!limits)
        return failOpen(Error{limits.error().code, m.path + ": " + limits.error().detail});
    auto calibrationBytes = m.getFeature(hid::kCalibrationReportId);
    if (!calibrationBytes)
        return failOpen(calibrationBytes.error());
    auto calibration = hid::decodeCalibrationReport(calibrationBytes->data(), calibrationBytes->size());
    if (!calibration)
        return failOpen(Error{calibration.error().code, m.path + ": " + calibration.error().detail});
    m.limits = *limits;
    m.calibration = *calibration;
    m.lost = false;
    m.haveSequence = false;
    m.stats = {};
    return {};
}

void HidDevice::close() {
    Impl& m = *m_impl;
    if (!m.device)
        return;
    if (!m.lost) {
        const auto off = hid::encodeOutputReport(ForceCommand{}, m.limits, m.lastSequence);
        (void)hid_write(m.device, off.data(), off.size()); // best effort: the device may be gone already
    }
    hid_close(m.device);
    m.device = nullptr;
    hid_exit();
}

ReadStatus HidDevice::read(sim::DeviceSample& out) {
    Impl& m = *m_impl;
    if (m.lost)
        return ReadStatus::Disconnected;
    if (!m.device)
        return ReadStatus::Error;
    bool got = false;
    std::uint8_t buffer[64];
    for (std::size_t i = 0; i < m.options.maxReportsPerRead; ++i) {
        const int n = hid_read_timeout(m.device, buffer, sizeof buffer, 0);
        if (n < 0) {
            // hidraw fails reads once the device node is gone (ENODEV, or a poll error): unplugged.
            m.lost = true;
            return ReadStatus::Disconnected;
        }
        if (n == 0)
            break;
        auto decoded = hid::decodeInputReport(buffer, static_cast<std::size_t>(n), m.calibration,
                                              m.limits.resectoscope ? hid::kProtocolVersion2 : hid::kProtocolVersion1);
        if (!decoded) {
            ++m.stats.refused;
            m.stats.lastRefusal = decoded.error().detail;
            continue;
        }
        ++m.stats.reports;
        if (got)
            ++m.stats.superseded;
        m.countSequence(decoded->sequence);
        out = decoded->sample;
        got = true;
    }
    return got ? ReadStatus::Sample : ReadStatus::NoNewData;
}

Status HidDevice::writeForce(const ForceCommand& command) {
    Impl& m = *m_impl;
    if (!m.device)
        return fail(ErrorCode::IoError, "hid device: not open");
    if (m.lost)
        return fail(ErrorCode::IoError, m.path + ": the device was disconnected");
    const auto report = hid::encodeOutputReport(command, m.limits, m.lastSequence);
    if (hid_write(m.device, report.data(), report.size()) < 0) {
        m.lost = true;
        return fail(ErrorCode::IoError, m.path + ": output report not sent (disconnected?): " + lastError(m.device));
    }
    ++m.stats.writes;
    return {};
}

DeviceLimits HidDevice::limits() const {
    return m_impl->limits;
}

std::string HidDevice::name() const {
    return "hid:" + hexId(m_impl->options.vendorId) + ":" + hexId(m_impl->options.productId);
}

const hid::Calibration& HidDevice::calibration() const {
    return m_impl->calibration;
}

Status HidDevice::writeCalibration(const hid::Calibration& calibration) {
    Impl& m = *m_impl;
    HS_TRY(hid::checkCalibration(calibration));
    if (!m.device || m.lost)
        return fail(ErrorCode::IoError, "hid device: not open");
    const auto report = hid::encodeCalibrationReport(calibration);
    if (hid_send_feature_report(m.device, report.data(), report.size()) < 0)
        return fail(ErrorCode::BackendFailure, m.path + ": calibration not sent: " + lastError(m.device));
    m.calibration = calibration;
    return {};
}

const HidDeviceStats& HidDevice::stats() const {
    return m_impl->stats;
}

} // namespace hs::haptics
