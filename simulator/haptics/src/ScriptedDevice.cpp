#include "hs/haptics/ScriptedDevice.h"

#include "hs/haptics/Clock.h"

#include <algorithm>

namespace hs::haptics {

ScriptedDevice::ScriptedDevice(sim::Script script, ScriptedDeviceOptions options)
    : m_script(std::move(script)), m_options(std::move(options)) {}

ScriptedDevice::ScriptedDevice(std::vector<sim::DeviceSample> samples, ScriptedDeviceOptions options)
    : m_samples(std::move(samples)), m_useSamples(true), m_options(std::move(options)) {}

Status ScriptedDevice::open() {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_open = true;
    return {};
}

void ScriptedDevice::close() {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_open = false;
}

std::uint64_t ScriptedDevice::length() const {
    return m_useSamples ? m_samples.size() : m_script.tickCount();
}

sim::DeviceSample ScriptedDevice::sampleAt(std::uint64_t index) const {
    sim::DeviceSample s = m_useSamples ? m_samples[static_cast<std::size_t>(index)] : m_script.sampleAt(index);
    s.tick = 0;
    return s;
}

ReadStatus ScriptedDevice::read(sim::DeviceSample& out) {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_open)
        return ReadStatus::Error;
    const std::uint64_t index = m_reads++;
    if (index >= m_options.disconnectAt)
        return ReadStatus::Disconnected;
    if (index >= m_options.silentFrom && index - m_options.silentFrom < m_options.silentReads)
        return ReadStatus::NoNewData;
    const std::uint64_t n = length();
    if (n == 0)
        return ReadStatus::NoNewData;
    if (m_played >= n) {
        if (!m_options.loop)
            return ReadStatus::NoNewData;
        m_played = 0;
    }
    out = sampleAt(m_played++);
    return ReadStatus::Sample;
}

Status ScriptedDevice::writeForce(const ForceCommand& command) {
    const std::int64_t now = monotonicNs();
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_open)
        return fail(ErrorCode::IoError, m_options.name + ": not open");
    if (m_reads > m_options.disconnectAt)
        return fail(ErrorCode::IoError, m_options.name + ": disconnected");
    if (m_written.size() < m_options.maxRecorded)
        m_written.push_back({m_reads, now, clampForce(command, m_options.limits)});
    return {};
}

bool ScriptedDevice::finished() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return !m_options.loop && m_played >= length();
}

std::uint64_t ScriptedDevice::reads() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_reads;
}

std::vector<WrittenForce> ScriptedDevice::written() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_written;
}

ManualDevice::ManualDevice(std::string name, DeviceLimits limits) : m_name(std::move(name)), m_limits(limits) {}

Status ManualDevice::open() {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_open = true;
    return {};
}

void ManualDevice::close() {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_open = false;
}

ReadStatus ManualDevice::read(sim::DeviceSample& out) {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_connected)
        return ReadStatus::Disconnected;
    if (!m_open)
        return ReadStatus::Error;
    out = m_sample;
    return ReadStatus::Sample;
}

Status ManualDevice::writeForce(const ForceCommand& command) {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_connected || !m_open)
        return fail(ErrorCode::IoError, m_name + ": not connected");
    m_lastForce = clampForce(command, m_limits);
    return {};
}

void ManualDevice::setSample(const sim::DeviceSample& sample) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_sample = sim::clamped(sample);
    m_sample.tick = 0;
}

sim::DeviceSample ManualDevice::sample() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_sample;
}

void ManualDevice::setConnected(bool connected) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_connected = connected;
}

ForceCommand ManualDevice::lastForce() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_lastForce;
}

} // namespace hs::haptics
