#pragma once
/// Devices without hardware. ScriptedDevice plays a Script (Script.h) or a trial's samples, one per read (the haptics
/// loop reads once per tick), and records every force written (tests, batch runs, the benchmark); it can also stall
/// or be unplugged on cue. ManualDevice holds a state another thread sets (the app's keyboard and mouse).

#include "hs/haptics/HapticDevice.h"
#include "hs/sim/Script.h"

#include <cstdint>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

namespace hs::haptics {

struct ScriptedDeviceOptions {
    DeviceLimits limits{5.0, 300.0}; ///< what the device pretends to render (a typical desktop device's range)
    std::string name = "scripted";   ///< "scripted:FILE" in trials
    bool loop = false;               ///< start over after the last sample (benchmarks); otherwise hold it
    std::uint64_t silentFrom = std::numeric_limits<std::uint64_t>::max();   ///< from this read on, NoNewData ...
    std::uint64_t silentReads = 0;                                          ///< ... for this many reads (a stall)
    std::uint64_t disconnectAt = std::numeric_limits<std::uint64_t>::max(); ///< from this read on, Disconnected
    std::size_t maxRecorded = 1000000; ///< forces recorded at most (the newest are dropped beyond)
};

/// One force the device was given.
struct WrittenForce {
    std::uint64_t read = 0;  ///< reads before the write (the haptics loop's tick count)
    std::int64_t timeNs = 0; ///< monotonicNs() at the write
    ForceCommand command;    ///< as rendered: clamped to the limits
};

class ScriptedDevice final : public HapticDevice {
public:
    ScriptedDevice(sim::Script script, ScriptedDeviceOptions options = {});
    /// A recorded trial's samples (their ticks are ignored).
    ScriptedDevice(std::vector<sim::DeviceSample> samples, ScriptedDeviceOptions options = {});

    Status open() override;
    void close() override;
    ReadStatus read(sim::DeviceSample& out) override;
    Status writeForce(const ForceCommand& command) override;
    DeviceLimits limits() const override { return m_options.limits; }
    std::string name() const override { return m_options.name; }

    /// Every sample played (not looping).
    bool finished() const;
    std::uint64_t reads() const;
    /// The forces written so far (thread-safe).
    std::vector<WrittenForce> written() const;

private:
    sim::DeviceSample sampleAt(std::uint64_t index) const;
    std::uint64_t length() const;

    sim::Script m_script;
    std::vector<sim::DeviceSample> m_samples;
    bool m_useSamples = false;
    ScriptedDeviceOptions m_options;
    mutable std::mutex m_mutex;
    bool m_open = false;
    std::uint64_t m_reads = 0;
    std::uint64_t m_played = 0;
    std::vector<WrittenForce> m_written;
};

/// A device whose state other threads set; thread-safe. Every read returns the current state (there is no "new"
/// data for a keyboard: its state is always current).
class ManualDevice final : public HapticDevice {
public:
    explicit ManualDevice(std::string name = "keyboard", DeviceLimits limits = {});

    Status open() override;
    void close() override;
    ReadStatus read(sim::DeviceSample& out) override;
    Status writeForce(const ForceCommand& command) override;
    DeviceLimits limits() const override { return m_limits; }
    std::string name() const override { return m_name; }

    /// Any thread: the state read from the next tick on (clamped into Device.h's ranges).
    void setSample(const sim::DeviceSample& sample);
    sim::DeviceSample sample() const;
    /// Any thread: false makes reads report Disconnected (tests; a virtual device that went away).
    void setConnected(bool connected);
    /// The newest force written (the app shows it as a gauge).
    ForceCommand lastForce() const;

private:
    const std::string m_name;
    const DeviceLimits m_limits;
    mutable std::mutex m_mutex;
    bool m_open = false;
    bool m_connected = true;
    sim::DeviceSample m_sample;
    ForceCommand m_lastForce;
};

} // namespace hs::haptics
