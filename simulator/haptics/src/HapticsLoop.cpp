// The 1 kHz haptics thread (HapticsLoop.h).
#include "hs/haptics/HapticsLoop.h"

#include "hs/haptics/Clock.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <string>

#include <pthread.h>
#include <sched.h>
#include <time.h>

namespace hs::haptics {

namespace {

constexpr std::uint64_t kStatsEveryTicks = 250;

timespec toTimespec(std::int64_t ns) {
    timespec ts{};
    ts.tv_sec = static_cast<time_t>(ns / 1000000000);
    ts.tv_nsec = static_cast<long>(ns % 1000000000);
    return ts;
}

/// Sleeps until the absolute CLOCK_MONOTONIC time `deadlineNs` (resumes after signals).
void sleepUntil(std::int64_t deadlineNs) {
    const timespec ts = toTimespec(deadlineNs);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
    }
}

ForceCommand scaled(const ForceCommand& c, double gain) {
    ForceCommand s = c;
    s.insertionForceN *= gain;
    s.pitchTorqueNmm *= gain;
    s.yawTorqueNmm *= gain;
    s.rollTorqueNmm *= gain;
    s.tipForceN *= gain;
    s.enabled = c.enabled && gain > 0.0;
    return s;
}

Status outside(const std::string& field, const std::string& range) {
    return fail(ErrorCode::InvalidInput, "haptics loop: " + field + " must be " + range);
}

} // namespace

void DurationHistogram::add(double us) {
    const double clampedUs = std::isfinite(us) ? std::max(0.0, us) : static_cast<double>(kBins);
    const std::size_t bin = std::min(static_cast<std::size_t>(clampedUs), kBins);
    ++m_counts[bin];
    ++m_count;
    m_max = std::max(m_max, clampedUs);
}

double DurationHistogram::quantile(double q) const {
    if (m_count == 0)
        return 0.0;
    const auto rank = static_cast<std::uint64_t>(std::ceil(std::clamp(q, 0.0, 1.0) * static_cast<double>(m_count)));
    std::uint64_t seen = 0;
    for (std::size_t bin = 0; bin < m_counts.size(); ++bin) {
        seen += m_counts[bin];
        if (seen >= std::max<std::uint64_t>(rank, 1))
            return bin == kBins ? m_max : static_cast<double>(bin);
    }
    return m_max;
}

DurationHistogram DurationHistogram::since(const DurationHistogram& earlier) const {
    DurationHistogram window;
    for (std::size_t bin = 0; bin < m_counts.size(); ++bin) {
        const std::uint64_t added = m_counts[bin] - std::min(m_counts[bin], earlier.m_counts[bin]);
        window.m_counts[bin] = added;
        window.m_count += added;
        if (added > 0)
            window.m_max = bin == kBins ? m_max : static_cast<double>(bin);
    }
    return window;
}

void DurationHistogram::merge(const DurationHistogram& other) {
    for (std::size_t bin = 0; bin < m_counts.size(); ++bin)
        m_counts[bin] += other.m_counts[bin];
    m_count += other.m_count;
    m_max = std::max(m_max, other.m_max);
}

Status checkHapticsLoopOptions(const HapticsLoopOptions& o) {
    if (!(o.periodS >= 0.0002 && o.periodS <= 0.01))
        return outside("periodS", "0.0002-0.01 s");
    if (!(o.frameTimeoutS >= 2 * o.periodS && o.frameTimeoutS <= 1.0))
        return outside("frameTimeoutS", "2 periods to 1 s");
    if (!(o.deviceTimeoutS >= 2 * o.periodS && o.deviceTimeoutS <= 1.0))
        return outside("deviceTimeoutS", "2 periods to 1 s");
    if (o.rampDownTicks < 1 || o.rampDownTicks > 10)
        return outside("rampDownTicks", "1-10");
    if (!(o.rampUpS >= 0.0 && o.rampUpS <= 10.0))
        return outside("rampUpS", "0-10 s");
    if (o.realtimePriority < 1 || o.realtimePriority > 99)
        return outside("realtimePriority", "1-99");
    if (o.queueCapacity < 16 || o.queueCapacity > (1u << 24))
        return outside("queueCapacity", "16-16777216 samples");
    if (o.recordTicks > 10000000)
        return outside("recordTicks", "at most 10000000");
    return {};
}

HapticsLoop::HapticsLoop(HapticDevice& device, HapticsLoopOptions options)
    : m_device(device), m_options(std::move(options)), m_contact(m_options.contact),
      m_queue(std::max<std::size_t>(m_options.queueCapacity, 16)) {}

HapticsLoop::~HapticsLoop() {
    stop();
}

void HapticsLoop::onDeviceLost(std::function<void()> callback) {
    m_onDeviceLost = std::move(callback);
}

Status HapticsLoop::start() {
    HS_TRY(checkHapticsLoopOptions(m_options));
    if (m_thread.joinable())
        return fail(ErrorCode::Internal, "haptics loop: already started");
    m_limits = m_device.limits();
    m_tick = m_options.firstTick;
    m_records.clear();
    m_records.reserve(m_options.recordTicks);
    m_stop.store(false);
    m_running.store(true, std::memory_order_release);
    m_thread = std::thread([this] { run(); });
    return {};
}

void HapticsLoop::stop() {
    m_stop.store(true, std::memory_order_release);
    if (m_thread.joinable())
        m_thread.join();
    m_running.store(false, std::memory_order_release);
}

void HapticsLoop::publish(std::shared_ptr<const sim::HapticFrame> frame) {
    std::atomic_store(&m_frame, std::move(frame));
    m_framePublishedNs.store(monotonicNs(), std::memory_order_release);
}

bool HapticsLoop::popSample(sim::DeviceSample& out, std::int64_t* takenNs) {
    TimedSample t;
    if (!m_queue.pop(t))
        return false;
    out = t.sample;
    if (takenNs)
        *takenNs = t.takenNs;
    return true;
}

bool HapticsLoop::takeNewest(std::size_t count, sim::DeviceSample* out, std::size_t& skipped, std::int64_t& newestNs) {
    skipped = 0;
    const std::size_t waiting = m_queue.size();
    if (count == 0 || waiting < count)
        return false;
    TimedSample t;
    for (std::size_t i = 0; i + count < waiting; ++i)
        if (m_queue.pop(t))
            ++skipped;
    for (std::size_t i = 0; i < count; ++i) {
        if (!m_queue.pop(t))
            return false; // cannot happen with one consumer: the producer only adds
        out[i] = t.sample;
        newestNs = t.takenNs;
    }
    return true;
}

HapticsStats HapticsLoop::stats() const {
    std::lock_guard<std::mutex> lock(m_statsMutex);
    return m_shared;
}

void HapticsLoop::publishStats() {
    std::unique_lock<std::mutex> lock(m_statsMutex, std::try_to_lock);
    if (lock.owns_lock())
        m_shared = m_local;
}

void HapticsLoop::run() {
    const auto periodNs = static_cast<std::int64_t>(std::llround(m_options.periodS * 1e9));
    if (m_options.realtime) {
        sched_param param{};
        param.sched_priority = m_options.realtimePriority;
        // Without CAP_SYS_NICE (or an rtprio limit) this fails: the loop then runs as an ordinary thread.
        m_local.realtime = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0;
    }
    std::int64_t deadline = monotonicNs();
    std::int64_t previousStart = 0;
    while (!m_stop.load(std::memory_order_acquire) && !m_deviceLost.load(std::memory_order_acquire)) {
        sleepUntil(deadline);
        const std::int64_t start = monotonicNs();
        m_local.latenessUs.add(static_cast<double>(start - deadline) * 1e-3);
        tick(start, previousStart);
        previousStart = start;
        if (m_local.ticks % kStatsEveryTicks == 0)
            publishStats();
        deadline += periodNs;
        // A tick that overran a whole period: skip the deadlines already past rather than burst to catch up.
        const std::int64_t now = monotonicNs();
        while (deadline + periodNs <= now) {
            deadline += periodNs;
            ++m_local.missedTicks;
        }
    }
    if (!m_deviceLost.load())
        (void)m_device.writeForce(ForceCommand{}); // leave the device without force
    {
        std::lock_guard<std::mutex> lock(m_statsMutex);
        m_shared = m_local;
    }
    m_running.store(false, std::memory_order_release);
}

void HapticsLoop::tick(std::int64_t now, std::int64_t previousStart) {
    const double periodUs = m_options.periodS * 1e6;
    if (previousStart != 0) {
        const double period = static_cast<double>(now - previousStart) * 1e-3;
        m_local.periodUs.add(period);
        m_local.jitterUs.add(std::abs(period - periodUs));
    }

    sim::DeviceSample sample;
    const ReadStatus status = m_device.read(sample);
    if (status == ReadStatus::Disconnected) {
        (void)m_device.writeForce(ForceCommand{}); // best effort: it is gone
        m_deviceLost.store(true, std::memory_order_release);
        m_local.deviceLost = true;
        if (m_onDeviceLost)
            m_onDeviceLost();
        return;
    }
    if (status == ReadStatus::Sample) {
        m_held = sample;
        m_haveSample = true;
        m_lastSampleNs = now;
    }
    m_held.tick = m_tick;
    if (!m_queue.push(TimedSample{m_held, now}))
        ++m_local.samplesDropped;

    const auto frame = std::atomic_load(&m_frame);
    const auto frameTimeoutNs = static_cast<std::int64_t>(m_options.frameTimeoutS * 1e9);
    const auto deviceTimeoutNs = static_cast<std::int64_t>(m_options.deviceTimeoutS * 1e9);
    const bool frameStale = !frame || now - m_framePublishedNs.load(std::memory_order_acquire) > frameTimeoutNs;
    const bool deviceStale = !m_haveSample || now - m_lastSampleNs > deviceTimeoutNs;

    ForceCommand command;
    if (frame && m_haveSample) {
        const double dt = m_previousUpdateNs ? static_cast<double>(now - m_previousUpdateNs) * 1e-9 : 0.0;
        command = m_contact.update(*frame, m_held, dt);
        m_previousUpdateNs = now;
    }

    // The watchdog: down to zero within rampDownTicks ticks of a stall, back up slowly once it clears.
    if (frameStale || deviceStale) {
        ++m_trippedTicks;
        const double down = 1.0 - static_cast<double>(m_trippedTicks) / m_options.rampDownTicks;
        m_gain = std::min(m_gain, std::max(0.0, down));
        ++m_local.watchdogTicks;
        m_local.frameStaleTicks += frameStale ? 1 : 0;
        m_local.deviceStaleTicks += deviceStale ? 1 : 0;
    } else {
        m_trippedTicks = 0;
        m_gain = m_options.rampUpS > 0.0 ? std::min(1.0, m_gain + m_options.periodS / m_options.rampUpS) : 1.0;
    }
    const ForceCommand written = clampForce(scaled(command, m_gain), m_limits);
    if (!m_device.writeForce(written))
        ++m_local.writeErrors;

    if (written.enabled) {
        m_local.maxForceN = std::max(m_local.maxForceN, std::abs(written.insertionForceN));
        m_local.maxTorqueNmm = std::max({m_local.maxTorqueNmm, std::abs(written.pitchTorqueNmm),
                                         std::abs(written.yawTorqueNmm), std::abs(written.rollTorqueNmm)});
        m_local.maxLoadFraction = std::max(m_local.maxLoadFraction, loadFraction(written, m_limits));
    }
    if (m_records.size() < m_options.recordTicks)
        m_records.push_back({m_tick, now, status, frameStale, deviceStale, m_gain, written});
    const std::int64_t end = monotonicNs();
    m_local.workUs.add(static_cast<double>(end - now) * 1e-3);
    ++m_local.ticks;
    ++m_tick;
}

} // namespace hs::haptics
