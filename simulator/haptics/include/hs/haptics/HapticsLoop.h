#pragma once
/// The 1 kHz haptics thread (docs/simulator.md, "Haptics"). Each tick, at an absolute deadline: read the device,
/// hand the sample to the physics through a lock-free queue (ticks numbered from firstTick, consecutive), compute the
/// force with the local contact model against the newest published HapticFrame, clamp it to the device's limits and
/// write it. It never waits on the physics: frames are swapped in through an atomic shared_ptr.
///
/// Watchdog: when no new frame has come for frameTimeoutS (the physics stalled) or no new sample for deviceTimeoutS
/// (the device stalled or sends garbage), the force ramps to zero within rampDownTicks ticks, and back up over
/// rampUpS once both recover. When the device is disconnected the loop writes zero (best effort), sets deviceLost(),
/// calls the callback once and ends its thread; the app pauses the trial.

#include "hs/core/Result.h"
#include "hs/haptics/ContactModel.h"
#include "hs/haptics/HapticDevice.h"
#include "hs/haptics/SpscQueue.h"
#include "hs/sim/Device.h"
#include "hs/sim/HapticFrame.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace hs::haptics {

struct HapticsLoopOptions {
    double periodS = 0.001;           ///< s, the tick (1 kHz: sim::kDeviceRateHz)
    double frameTimeoutS = 0.050;     ///< s, no new HapticFrame for longer: the physics stalled
    double deviceTimeoutS = 0.010;    ///< s, no new device sample for longer: the device stalled
    int rampDownTicks = 2;            ///< ticks from full force to zero once the watchdog trips (1-10)
    double rampUpS = 0.100;           ///< s, from zero to full force at the start and after a trip
    bool realtime = true;             ///< ask for SCHED_FIFO (silently stays SCHED_OTHER without the privilege)
    int realtimePriority = 80;        ///< 1-99 with SCHED_FIFO
    std::size_t queueCapacity = 8192; ///< device samples waiting for the physics (8 s at 1 kHz)
    std::uint64_t firstTick = 0;      ///< the first tick's number (a resumed trial continues its numbering)
    std::size_t recordTicks = 0;      ///< keep a record of the first N ticks (tests); 0: none
    ContactParams contact;
};
/// InvalidInput naming the field and its range.
[[nodiscard]] Status checkHapticsLoopOptions(const HapticsLoopOptions& options);

/// One tick, as recorded with HapticsLoopOptions::recordTicks.
struct TickRecord {
    std::uint64_t tick = 0;
    std::int64_t timeNs = 0; ///< monotonicNs() at the tick's start
    ReadStatus read = ReadStatus::NoNewData;
    bool frameStale = false;
    bool deviceStale = false;
    double gain = 0.0;    ///< the watchdog's force scale, 0..1
    ForceCommand written; ///< clamped, as written
};

/// A histogram of durations in microseconds (1 us bins up to 20 ms, then one overflow bin).
class DurationHistogram {
public:
    static constexpr std::size_t kBins = 20001;
    DurationHistogram() : m_counts(kBins + 1, 0) {}
    void add(double us);
    std::uint64_t count() const { return m_count; }
    double max() const { return m_max; }
    /// The q quantile (0..1), us, to the bin (1 us); 0 when empty.
    double quantile(double q) const;
    /// What was added to this histogram after `earlier`, an earlier copy of it (a window of a run); its max is the
    /// window's highest bin (exact in the overflow bin only when that holds the whole run's max).
    DurationHistogram since(const DurationHistogram& earlier) const;
    /// Adds `other`'s durations (the windows of a run put together).
    void merge(const DurationHistogram& other);

private:
    std::vector<std::uint64_t> m_counts;
    std::uint64_t m_count = 0;
    double m_max = 0.0;
};

struct HapticsStats {
    std::uint64_t ticks = 0;
    DurationHistogram periodUs;      ///< between consecutive tick starts
    DurationHistogram jitterUs;      ///< |period - periodS|
    DurationHistogram latenessUs;    ///< tick start after its deadline
    DurationHistogram workUs;        ///< read + force + write
    std::uint64_t missedTicks = 0;   ///< deadlines skipped because a tick overran a whole period
    std::uint64_t watchdogTicks = 0; ///< ticks with the watchdog active (force ramping down or zero)
    std::uint64_t frameStaleTicks = 0;
    std::uint64_t deviceStaleTicks = 0;
    std::uint64_t samplesDropped = 0; ///< the physics' queue was full
    std::uint64_t writeErrors = 0;
    double maxForceN = 0.0;       ///< largest |insertion force| written
    double maxTorqueNmm = 0.0;    ///< largest |torque| written
    double maxLoadFraction = 0.0; ///< largest written value as a fraction of its limit (<= 1)
    bool realtime = false;        ///< SCHED_FIFO was granted
    bool deviceLost = false;
};

class HapticsLoop {
public:
    /// `device` must outlive the loop and be open before start().
    explicit HapticsLoop(HapticDevice& device, HapticsLoopOptions options = {});
    ~HapticsLoop();
    HapticsLoop(const HapticsLoop&) = delete;
    HapticsLoop& operator=(const HapticsLoop&) = delete;

    /// Called once from the haptics thread when the device is lost; set before start().
    void onDeviceLost(std::function<void()> callback);
    /// Starts the thread. InvalidInput for bad options; Internal when already started.
    [[nodiscard]] Status start();
    /// Writes zero force and joins the thread. Idempotent.
    void stop();
    bool running() const { return m_running.load(std::memory_order_acquire); }

    /// Physics thread: the newest surface to render forces against (frames are immutable once published).
    void publish(std::shared_ptr<const sim::HapticFrame> frame);
    /// Physics thread (the one consumer): the next device sample in tick order, and when the loop took it
    /// (monotonicNs); false when none is waiting.
    bool popSample(sim::DeviceSample& out, std::int64_t* takenNs = nullptr);
    std::size_t pendingSamples() const { return m_queue.size(); }
    /// Physics thread: the newest `count` samples once at least `count` wait (false, nothing taken, before), the
    /// older ones dropped: a physics step slower than the device time it covers consumes the newest device state
    /// instead of falling further behind. `skipped` counts the dropped samples, `newestNs` is when the loop took the
    /// last one. The caller renumbers the ticks (the world's own sequence) and records exactly what it consumed.
    bool takeNewest(std::size_t count, sim::DeviceSample* out, std::size_t& skipped, std::int64_t& newestNs);

    bool deviceLost() const { return m_deviceLost.load(std::memory_order_acquire); }
    /// Any thread: the statistics (refreshed every 100 ticks while running; complete after stop()).
    HapticsStats stats() const;
    /// After stop(): the recorded ticks (HapticsLoopOptions::recordTicks).
    const std::vector<TickRecord>& tickRecords() const { return m_records; }

private:
    void run();
    void tick(std::int64_t now, std::int64_t previousStart);
    void publishStats();

    HapticDevice& m_device;
    const HapticsLoopOptions m_options;
    DeviceLimits m_limits;
    ContactModel m_contact;
    struct TimedSample {
        sim::DeviceSample sample;
        std::int64_t takenNs = 0;
    };
    SpscQueue<TimedSample> m_queue;
    std::thread m_thread;
    std::atomic<bool> m_running{false};
    std::atomic<bool> m_stop{false};
    std::atomic<bool> m_deviceLost{false};
    std::function<void()> m_onDeviceLost;
    std::shared_ptr<const sim::HapticFrame> m_frame; ///< only through std::atomic_load/atomic_store
    std::atomic<std::int64_t> m_framePublishedNs{0};

    // The haptics thread's own state.
    std::uint64_t m_tick = 0;
    sim::DeviceSample m_held;
    bool m_haveSample = false;
    std::int64_t m_lastSampleNs = 0;
    std::int64_t m_previousUpdateNs = 0;
    double m_gain = 0.0;
    int m_trippedTicks = 0;
    HapticsStats m_local;
    std::vector<TickRecord> m_records;

    mutable std::mutex m_statsMutex; ///< guards m_shared; the haptics thread only try_locks it
    HapticsStats m_shared;
};

} // namespace hs::haptics
