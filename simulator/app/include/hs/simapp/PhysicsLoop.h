#pragma once
/// The simulator's physics thread: steps the World at its fixed rate with the samples of a SampleSource, records
/// every sample (the trial), and publishes a frame (snapshot and exercise progress) after each step for the render
/// thread, which takes the newest one at display rate. runSteps() is the same loop without a clock (headless).

#include "hs/core/Result.h"
#include "hs/sim/World.h"
#include "hs/simapp/SampleSource.h"
#include "hs/simrender/Hud.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace hs::simapp {

/// What the render thread draws.
struct Frame {
    sim::WorldSnapshot snapshot;
    simrender::ExerciseProgress progress;
};

/// Feeds a world from a source, step by step, recording every sample fed when `record` is not null.
class Stepper {
public:
    Stepper(sim::World& world, SampleSource& source, std::vector<sim::DeviceSample>* record = nullptr)
        : m_world(world), m_source(source), m_record(record) {}
    /// One step: the source's next ticksPerStep() samples through World::step. False when the source has ended;
    /// a failed step is an error.
    [[nodiscard]] Result<bool> step();
    std::uint64_t steps() const { return m_steps; }

private:
    sim::World& m_world;
    SampleSource& m_source;
    std::vector<sim::DeviceSample>* m_record;
    std::vector<sim::DeviceSample> m_buffer;
    std::uint64_t m_nextTick = 0;
    std::uint64_t m_steps = 0;
};

/// Steps until the source ends (as fast as possible) or `shouldStop` says so; returns the steps done.
[[nodiscard]] Result<std::uint64_t> runSteps(sim::World& world, SampleSource& source,
                                             std::vector<sim::DeviceSample>* record,
                                             const std::function<bool()>& shouldStop = {});

class PhysicsLoop {
public:
    /// Neither `world` nor `source` is owned; both outlive the loop.
    PhysicsLoop(sim::World& world, SampleSource& source);
    ~PhysicsLoop();
    PhysicsLoop(const PhysicsLoop&) = delete;
    PhysicsLoop& operator=(const PhysicsLoop&) = delete;

    /// Called on the physics thread after every step (set before start()): where the haptics loop gets the newest
    /// HapticFrame (`haptics.publish(world.hapticFrame())`).
    void setAfterStep(std::function<void(const sim::World&)> afterStep) { m_afterStep = std::move(afterStep); }

    void start();
    /// Stops and joins the thread; the world is then the caller's again.
    void stop();
    bool running() const { return m_running.load(); }
    /// The source ended or a step failed (then error() says why).
    bool finished() const { return m_finished.load(); }
    std::optional<Error> error() const;

    /// The newest frame since the last call, or nothing.
    std::optional<Frame> takeFrame();
    /// Every sample consumed so far (call after stop()).
    const std::vector<sim::DeviceSample>& samples() const { return m_samples; }
    /// Steps per second of wall time over the last second (the world's rate when it keeps up).
    double stepsPerSecond() const { return m_stepsPerSecond.load(); }

private:
    void run();

    sim::World& m_world;
    SampleSource& m_source;
    std::thread m_thread;
    std::atomic<bool> m_stop{false};
    std::atomic<bool> m_running{false};
    std::atomic<bool> m_finished{false};
    std::atomic<double> m_stepsPerSecond{0.0};
    mutable std::mutex m_mutex; ///< guards m_frame and m_error
    std::optional<Frame> m_frame;
    std::optional<Error> m_error;
    std::vector<sim::DeviceSample> m_samples;
    std::function<void(const sim::World&)> m_afterStep;
};

} // namespace hs::simapp
