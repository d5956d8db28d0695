// Device samples from a script, a recorded trial or the keyboard and mouse.
#include "hs/simapp/SampleSource.h"

#include <chrono>
#include <thread>

#include <algorithm>

namespace hs::simapp {

bool ScriptSource::next(std::uint64_t firstTick, std::size_t count, sim::DeviceSample* out) {
    if (firstTick >= m_script.tickCount() || firstTick >= m_tickLimit)
        return false;
    for (std::size_t i = 0; i < count; ++i) {
        out[i] = m_script.sampleAt(firstTick + i);
        out[i].tick = firstTick + i;
    }
    return true;
}

bool TrialSource::next(std::uint64_t firstTick, std::size_t count, sim::DeviceSample* out) {
    if (firstTick + count > m_trial.samples.size())
        return false;
    std::copy_n(m_trial.samples.begin() + static_cast<std::ptrdiff_t>(firstTick), count, out);
    return true;
}

KeyboardSource::KeyboardSource(const sim::DeviceSample& start) : m_sample(start) {}

sim::DeviceSample KeyboardSource::startSample() {
    sim::DeviceSample s;
    s.insertionMm = -5.0;
    s.inflow = 1.0;
    s.outflow = 0.5;
    return s;
}

void KeyboardSource::setHeld(Axis axis, int direction) {
    const std::lock_guard lock(m_mutex);
    m_held[static_cast<int>(axis)] = std::clamp(direction, -1, 1);
}

void KeyboardSource::nudge(Axis axis, double amount) {
    const std::lock_guard lock(m_mutex);
    m_nudge[static_cast<int>(axis)] += amount;
}

void KeyboardSource::toggleInflow() {
    const std::lock_guard lock(m_mutex);
    m_sample.inflow = m_sample.inflow > 0.5 ? 0.0 : 1.0;
}

void KeyboardSource::toggleOutflow() {
    const std::lock_guard lock(m_mutex);
    m_sample.outflow = m_sample.outflow > 0.25 ? 0.0 : 0.5;
}

void KeyboardSource::mark() {
    const std::lock_guard lock(m_mutex);
    m_markTicksLeft = kMarkTicks;
}

void KeyboardSource::setButtonHeld(std::uint32_t button, bool held) {
    const std::lock_guard lock(m_mutex);
    m_pedals = held ? (m_pedals | button) : (m_pedals & ~button);
}

void KeyboardSource::press(std::uint32_t button) {
    const std::lock_guard lock(m_mutex);
    m_pressed = button;
    m_pressTicksLeft = kMarkTicks;
}

void KeyboardSource::setInstrument(std::uint32_t instrument) {
    const std::lock_guard lock(m_mutex);
    if (instrument != m_sample.instrument)
        m_sample.workingElementMm = 0.0;
    m_sample.instrument = instrument;
}

sim::DeviceSample KeyboardSource::current() const {
    const std::lock_guard lock(m_mutex);
    return m_sample;
}

bool KeyboardSource::next(std::uint64_t firstTick, std::size_t count, sim::DeviceSample* out) {
    const std::lock_guard lock(m_mutex);
    const double dt = 1.0 / sim::kDeviceRateHz;
    const double speeds[6] = {kInsertionMmPerS, kPivotDegPerS, kPivotDegPerS,
                              kRollDegPerS,     kRollDegPerS,  kWorkingElementMmPerS};
    double* fields[6] = {&m_sample.insertionMm, &m_sample.pitchDeg,      &m_sample.yawDeg,
                         &m_sample.rollDeg,     &m_sample.cameraRollDeg, &m_sample.workingElementMm};
    // Mouse and wheel increments are spent at most this fast, so the scope never jumps between two ticks.
    const double nudgeRates[6] = {kMaxNudgeMmPerS,  kMaxNudgeDegPerS, kMaxNudgeDegPerS,
                                  kMaxNudgeDegPerS, kMaxNudgeDegPerS, kMaxNudgeMmPerS};
    for (std::size_t i = 0; i < count; ++i) {
        for (int a = 0; a < 6; ++a) {
            const double step = std::clamp(m_nudge[a], -nudgeRates[a] * dt, nudgeRates[a] * dt);
            *fields[a] += m_held[a] * speeds[a] * dt + step;
            m_nudge[a] -= step;
        }
        // Rolls wrap around; insertion and pivot angles stop at the device's range.
        for (double* roll : {&m_sample.rollDeg, &m_sample.cameraRollDeg}) {
            if (*roll > sim::kMaxRollDeg)
                *roll -= 360.0;
            else if (*roll < -sim::kMaxRollDeg)
                *roll += 360.0;
        }
        m_sample.buttons = (m_markTicksLeft > 0 ? sim::kButtonMark : 0u) | (m_pressTicksLeft > 0 ? m_pressed : 0u);
        // The pedals work an instrument only (a diagnostic scope alone has nothing to energise or close).
        if (m_sample.instrument != sim::kInstrumentNone)
            m_sample.buttons |= m_pedals;
        m_markTicksLeft = m_markTicksLeft > 0 ? m_markTicksLeft - 1 : 0;
        m_pressTicksLeft = m_pressTicksLeft > 0 ? m_pressTicksLeft - 1 : 0;
        m_sample = sim::clamped(m_sample);
        m_sample.tick = firstTick + i;
        out[i] = m_sample;
    }
    return true;
}

Result<std::unique_ptr<HapticsSource>> HapticsSource::start(std::unique_ptr<haptics::HapticDevice> device,
                                                            haptics::HapticsLoopOptions options) {
    std::unique_ptr<HapticsSource> source(new HapticsSource());
    HS_TRY(device->open());
    source->m_device = std::move(device);
    source->m_loop = std::make_unique<haptics::HapticsLoop>(*source->m_device, options);
    if (Status started = source->m_loop->start(); !started.ok()) {
        source->m_device->close();
        return started.failure();
    }
    return source;
}

HapticsSource::~HapticsSource() {
    if (m_loop)
        m_loop->stop();
    if (m_device)
        m_device->close();
}

bool HapticsSource::next(std::uint64_t firstTick, std::size_t count, sim::DeviceSample* out) {
    // Wait for the step's samples (the device's pace); when the physics has fallen behind, take the newest ones and
    // drop the rest, so the world follows the device's present, not its past. The world numbers the ticks it
    // consumed (they are what the trial records, and what a replay steps through).
    std::size_t skipped = 0;
    std::int64_t newestNs = 0;
    while (!m_loop->takeNewest(count, out, skipped, newestNs)) {
        if (m_cancelled.load() || m_loop->deviceLost() || !m_loop->running())
            return false;
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    for (std::size_t i = 0; i < count; ++i) {
        out[i] = sim::clamped(out[i]);
        out[i].tick = firstTick + i;
    }
    m_skipped.fetch_add(skipped);
    m_newestNs.store(newestNs);
    return true;
}

void HapticsSource::publish(std::shared_ptr<const sim::HapticFrame> frame) {
    m_loop->publish(std::move(frame));
}

bool HapticsSource::deviceLost() const {
    return m_loop->deviceLost();
}

haptics::HapticsStats HapticsSource::stats() const {
    return m_loop->stats();
}

haptics::DeviceLimits HapticsSource::deviceLimits() const {
    return m_device->limits();
}

std::string HapticsSource::deviceName() const {
    return m_device->name();
}

} // namespace hs::simapp
