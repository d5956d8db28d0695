#pragma once
/// Where the physics gets its device samples: the one seam between input devices and the world. The physics thread
/// asks a SampleSource for the ticksPerStep() samples of each step, in tick order. Sources: the keyboard and mouse
/// (KeyboardSource), a script (ScriptSource), a recorded trial (TrialSource); the haptics module's 1 kHz loop plugs
/// in as another source whose next() waits for the loop's samples and whose paced() is true (docs/simulator.md,
/// "Running the simulator").

#include "hs/haptics/HapticDevice.h"
#include "hs/haptics/HapticsLoop.h"
#include "hs/sim/Device.h"
#include "hs/sim/HapticFrame.h"
#include "hs/sim/Script.h"
#include "hs/sim/Trial.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

namespace hs::simapp {

class SampleSource {
public:
    virtual ~SampleSource() = default;
    /// Writes `count` samples for ticks firstTick, firstTick + 1, ... into `out` (tick fields set). May block
    /// until a device has produced them. False when the source has ended (nothing written).
    virtual bool next(std::uint64_t firstTick, std::size_t count, sim::DeviceSample* out) = 0;
    /// True when next() waits for a device running at its own rate (the physics thread then does not pace itself
    /// by the clock).
    virtual bool paced() const { return false; }
    /// When the newest sample of the last next() was taken from the device (monotonicNs; 0: not a device).
    virtual std::int64_t newestSampleNs() const { return 0; }
    /// Device samples dropped so far because the physics fell behind (the world took the newest instead).
    virtual std::uint64_t skippedSamples() const { return 0; }
};

/// A script's samples; ends after its last key frame (the last step is filled with the last key frame's sample), or
/// before tick `tickLimit` when that comes first (the step that reaches it is the last).
class ScriptSource final : public SampleSource {
public:
    explicit ScriptSource(sim::Script script, std::uint64_t tickLimit = UINT64_MAX)
        : m_script(std::move(script)), m_tickLimit(tickLimit) {}
    bool next(std::uint64_t firstTick, std::size_t count, sim::DeviceSample* out) override;

private:
    sim::Script m_script;
    std::uint64_t m_tickLimit;
};

/// A recorded trial's samples; ends with them.
class TrialSource final : public SampleSource {
public:
    explicit TrialSource(const sim::Trial& trial) : m_trial(trial) {}
    bool next(std::uint64_t firstTick, std::size_t count, sim::DeviceSample* out) override;

private:
    const sim::Trial& m_trial;
};

/// The scope driven by keys and the mouse. The GUI thread says which motions are held and adds mouse and wheel
/// increments; next() (on the physics thread) integrates them tick by tick, so the samples are what a device at
/// 1 kHz would have reported. Never ends.
class KeyboardSource final : public SampleSource {
public:
    enum class Axis { Insertion, Pitch, Yaw, Roll, CameraRoll, WorkingElement };
    /// Speeds while a key is held: insertion mm/s, the angles degrees/s.
    static constexpr double kInsertionMmPerS = 15.0;
    static constexpr double kPivotDegPerS = 20.0;
    static constexpr double kRollDegPerS = 90.0;
    /// mm/s, the loop moved along the sheath by the working element.
    static constexpr double kWorkingElementMmPerS = 10.0;
    /// The fastest a nudge is spent: mm/s of insertion, degrees/s of the angles.
    static constexpr double kMaxNudgeMmPerS = 100.0;
    static constexpr double kMaxNudgeDegPerS = 360.0;
    /// How long a mark press is held, ticks.
    static constexpr std::uint32_t kMarkTicks = 100;

    explicit KeyboardSource(const sim::DeviceSample& start = startSample());
    /// Outside the external os, the shaft on the canal's axis, inflow open, outflow half open.
    static sim::DeviceSample startSample();

    /// -1, 0 or +1: the motion of `axis` while a key is held.
    void setHeld(Axis axis, int direction);
    /// Adds `amount` (mm or degrees) to `axis` over the next ticks, at most kMaxNudge*PerS (mouse drags, wheel).
    void nudge(Axis axis, double amount);
    void toggleInflow();
    void toggleOutflow();
    /// Holds the mark button for kMarkTicks.
    void mark();
    /// Holds `button` (a pedal: sim::kButtonCut, kButtonCoagulate) down or lets it up.
    void setButtonHeld(std::uint32_t button, bool held);
    /// Presses `button` once (held for kMarkTicks: sim::kButtonPumpUp, kButtonPumpDown).
    void press(std::uint32_t button);
    /// The instrument in use (sim::Instrument); the loop drawn in on a change.
    void setInstrument(std::uint32_t instrument);
    /// The newest sample produced (for the GUI's status).
    sim::DeviceSample current() const;

    bool next(std::uint64_t firstTick, std::size_t count, sim::DeviceSample* out) override;

private:
    mutable std::mutex m_mutex;
    sim::DeviceSample m_sample;
    int m_held[6] = {0, 0, 0, 0, 0, 0};
    double m_nudge[6] = {0, 0, 0, 0, 0, 0};
    std::uint32_t m_markTicksLeft = 0;
    std::uint32_t m_pedals = 0;  ///< buttons held down
    std::uint32_t m_pressed = 0; ///< the button pressed once, held for m_pressTicksLeft
    std::uint32_t m_pressTicksLeft = 0;
};

/// A haptic device through the 1 kHz haptics loop (hs::haptics::HapticsLoop): next() waits for the loop's samples,
/// so the device paces the physics; publish() hands the loop the world's newest surface after every step. When the
/// device is lost the loop writes zero force and next() ends the source: the trial stops there (the window says so
/// and offers the report).
class HapticsSource final : public SampleSource {
public:
    /// Opens `device` and starts the loop. The errors of HapticDevice::open and HapticsLoop::start.
    [[nodiscard]] static Result<std::unique_ptr<HapticsSource>> start(std::unique_ptr<haptics::HapticDevice> device,
                                                                      haptics::HapticsLoopOptions options = {});
    ~HapticsSource() override;
    bool next(std::uint64_t firstTick, std::size_t count, sim::DeviceSample* out) override;
    bool paced() const override { return true; }
    std::int64_t newestSampleNs() const override { return m_newestNs.load(); }
    std::uint64_t skippedSamples() const override { return m_skipped.load(); }
    /// Physics thread, after each step.
    void publish(std::shared_ptr<const sim::HapticFrame> frame);
    /// Ends next()'s wait (the window is closing).
    void cancel() { m_cancelled.store(true); }
    bool deviceLost() const;
    haptics::HapticsStats stats() const;
    std::string deviceName() const;
    /// What the device renders and reports (read at open; `resectoscope` false: the diagnostic scope only).
    haptics::DeviceLimits deviceLimits() const;

private:
    HapticsSource() = default;
    std::unique_ptr<haptics::HapticDevice> m_device;
    std::unique_ptr<haptics::HapticsLoop> m_loop;
    std::atomic<bool> m_cancelled{false};
    std::atomic<std::uint64_t> m_skipped{0};
    std::atomic<std::int64_t> m_newestNs{0};
};

} // namespace hs::simapp
