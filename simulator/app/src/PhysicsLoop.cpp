// The physics thread: fixed steps paced by the clock (or by a device that runs at its own rate), every sample
// recorded, a frame published after each step.
#include "hs/simapp/PhysicsLoop.h"

#include <chrono>

namespace hs::simapp {

Result<bool> Stepper::step() {
    const std::size_t count = m_world.ticksPerStep();
    m_buffer.resize(count);
    if (!m_source.next(m_nextTick, count, m_buffer.data()))
        return false;
    HS_TRY(m_world.step(m_buffer.data(), count));
    if (m_record)
        m_record->insert(m_record->end(), m_buffer.begin(), m_buffer.end());
    m_nextTick += count;
    ++m_steps;
    return true;
}

Result<std::uint64_t> runSteps(sim::World& world, SampleSource& source, std::vector<sim::DeviceSample>* record,
                               const std::function<bool()>& shouldStop) {
    Stepper stepper(world, source, record);
    while (!shouldStop || !shouldStop()) {
        auto stepped = stepper.step();
        if (!stepped)
            return stepped.failure();
        if (!*stepped)
            break;
    }
    return stepper.steps();
}

PhysicsLoop::PhysicsLoop(sim::World& world, SampleSource& source) : m_world(world), m_source(source) {}

PhysicsLoop::~PhysicsLoop() {
    stop();
}

void PhysicsLoop::start() {
    if (m_thread.joinable())
        return;
    m_stop = false;
    m_finished = false;
    m_running = true;
    m_thread = std::thread([this] { run(); });
}

void PhysicsLoop::stop() {
    m_stop = true;
    if (m_thread.joinable())
        m_thread.join();
    m_running = false;
}

std::optional<Error> PhysicsLoop::error() const {
    const std::lock_guard lock(m_mutex);
    return m_error;
}

std::optional<Frame> PhysicsLoop::takeFrame() {
    const std::lock_guard lock(m_mutex);
    std::optional<Frame> frame;
    frame.swap(m_frame);
    return frame;
}

void PhysicsLoop::run() {
    using Clock = std::chrono::steady_clock;
    const auto stepDuration =
        std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(m_world.options().stepS));
    Stepper stepper(m_world, m_source, &m_samples);
    auto due = Clock::now();
    auto rateStart = due;
    int rateSteps = 0;
    while (!m_stop) {
        auto stepped = stepper.step();
        if (!stepped || !*stepped) {
            if (!stepped) {
                const std::lock_guard lock(m_mutex);
                m_error = stepped.error();
            }
            m_finished = true;
            break;
        }
        if (m_afterStep)
            m_afterStep(m_world);
        Frame frame{m_world.snapshot(), simrender::progressOf(m_world.options().exercise, m_world.metrics())};
        {
            const std::lock_guard lock(m_mutex);
            m_frame = std::move(frame);
        }
        ++rateSteps;
        const auto now = Clock::now();
        if (now - rateStart >= std::chrono::seconds(1)) {
            m_stepsPerSecond = rateSteps / std::chrono::duration<double>(now - rateStart).count();
            rateStart = now;
            rateSteps = 0;
        }
        if (m_source.paced())
            continue;
        // Real time: one step per stepS of wall time. A world that falls behind catches up at most a little
        // (no burst of steps after a stall).
        due += stepDuration;
        if (due < now - 10 * stepDuration)
            due = now;
        std::this_thread::sleep_until(due);
    }
    m_running = false;
}

} // namespace hs::simapp
