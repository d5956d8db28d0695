// bench_haptics: how steady the 1 kHz haptics loop runs while a physics thread loads the machine.
//
// The physics is a parameter (Physics below). With --package DIR it is the simulator's World on that scene package:
// it pops ticksPerStep() device samples, steps the world and publishes world.hapticFrame(), as hysteroscene-sim
// does. Without, a stand-in publishes a frame of 48 contacts every 5 ms after burning ~4 ms of CPU.
//
//   bench_haptics [--seconds 10] [--package DIR [--throttle-hz 100] [--demo polypectomy|myomectomy]]
// --throttle-hz: the physics held to that rate; the table gains the lag between the device and the world.
// --demo: the device plays that exercise's demonstration (demonstrationScript) once, in real time, and the World
// cuts as it goes; the table gains the ticks while the cutting pedal was down (to the loop's statistics' 0.25 s
// publishing) and the physics steps taken then. --seconds defaults to the demonstration's length.
#include "hs/haptics/Clock.h"
#include "hs/haptics/HapticsLoop.h"
#include "hs/haptics/ScriptedDevice.h"
#include "hs/sim/Trial.h"
#include "hs/sim/World.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace hs;
using namespace hs::haptics;

constexpr double kPi = 3.14159265358979323846;

/// Runs on its own thread until `stop`; consumes the loop's samples and publishes frames. Returns frames published.
using Physics = std::function<std::uint64_t(HapticsLoop& loop, const std::atomic<bool>& stop)>;

sim::ScopeFrame pivotFrame() {
    sim::ScopeFrame f;
    f.axis = {0.0, 0.0, 1.0};
    f.anterior = {0.0, 1.0, 0.0};
    f.left = {-1.0, 0.0, 0.0};
    return f;
}

/// The stand-in physics: every 5 ms, ~4 ms of CPU, then a new frame of 48 contacts (the most the World hands over)
/// with a full compliance matrix, the wall breathing by +-0.5 mm in front of the scope.
std::uint64_t fakePhysics(HapticsLoop& loop, const std::atomic<bool>& stop) {
    constexpr std::size_t kContacts = 48;
    std::uint64_t step = 0;
    std::int64_t next = monotonicNs();
    volatile double sink = 0.0;
    while (!stop.load()) {
        sim::DeviceSample sample;
        while (loop.popSample(sample)) {
        }
        const std::int64_t burnUntil = monotonicNs() + 4000000;
        double x = 1.0;
        while (monotonicNs() < burnUntil)
            for (int i = 0; i < 1000; ++i)
                x = std::sqrt(x + 1.0);
        sink = sink + x;
        auto frame = std::make_shared<sim::HapticFrame>();
        frame->step = step;
        frame->timeS = static_cast<double>(step) * 0.005;
        frame->pivot = pivotFrame();
        frame->scopeDofs = {0.045, 0.0, 0.0};
        const double breathing = 0.5e-3 * std::sin(frame->timeS * 2.0 * kPi);
        for (std::size_t i = 0; i < kContacts; ++i) {
            sim::HapticContact c;
            const double angle = 2.0 * kPi * static_cast<double>(i) / kContacts;
            c.gapM = breathing + 0.2e-3 * static_cast<double>(i % 4);
            c.scopeGradient = {-1.0, -0.04 * std::cos(angle), -0.04 * std::sin(angle)};
            c.normal = {0.0, 0.0, -1.0};
            c.tip = i < 8;
            frame->contacts.push_back(c);
        }
        frame->compliance.assign(kContacts * kContacts, 0.0);
        for (std::size_t i = 0; i < kContacts; ++i)
            for (std::size_t j = 0; j < kContacts; ++j)
                frame->compliance[i * kContacts + j] = (i == j ? 3e-3 : 1e-3 / (1.0 + std::abs(double(i) - double(j))));
        loop.publish(std::move(frame));
        ++step;
        next += 5000000;
        const timespec ts{static_cast<time_t>(next / 1000000000), static_cast<long>(next % 1000000000)};
        clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr);
    }
    return step;
}

/// What the world's steps saw of the device: when each step ended against when the loop took the newest sample the
/// step consumed (ms), and the samples dropped because the physics had fallen behind.
struct LagLog {
    std::vector<double> lagMs;
    std::size_t skipped = 0;
};

/// The ticks of the haptics loop while the World cut (the cutting pedal down), put together from windows of the
/// loop's statistics, and the physics steps' wall times then.
struct CuttingLog {
    bool cutting = false;
    HapticsStats atStart; ///< the loop's statistics when the pedal went down
    DurationHistogram jitterUs, periodUs, latenessUs;
    std::uint64_t ticks = 0, missedTicks = 0;
    std::vector<double> stepMs;
    double seconds = 0.0;
    std::int64_t startedNs = 0;

    void observe(const HapticsLoop& loop, bool nowCutting) {
        if (nowCutting == cutting)
            return;
        const HapticsStats s = loop.stats();
        if (nowCutting) {
            atStart = s;
            startedNs = monotonicNs();
        } else {
            jitterUs.merge(s.jitterUs.since(atStart.jitterUs));
            periodUs.merge(s.periodUs.since(atStart.periodUs));
            latenessUs.merge(s.latenessUs.since(atStart.latenessUs));
            ticks += s.ticks - atStart.ticks;
            missedTicks += s.missedTicks - atStart.missedTicks;
            seconds += static_cast<double>(monotonicNs() - startedNs) * 1e-9;
        }
        cutting = nowCutting;
    }
};

/// The World on a scene package: the device's samples step it, the newest ones when it has fallen behind (as
/// hysteroscene-sim's HapticsSource takes them); every step publishes its haptic frame. `throttleHz` > 0 holds each
/// step to at least 1/throttleHz of wall time (a slow machine, or a heavy scene).
Physics worldPhysics(sim::World& world, std::uint64_t& steps, double throttleHz, LagLog& log, CuttingLog& cuts) {
    return
        [&world, &steps, throttleHz, &log, &cuts](HapticsLoop& loop, const std::atomic<bool>& stop) -> std::uint64_t {
            const std::size_t per = world.ticksPerStep();
            std::vector<sim::DeviceSample> samples(per);
            std::uint64_t tick = 0;
            loop.publish(world.hapticFrame());
            while (!stop.load()) {
                std::size_t skipped = 0;
                std::int64_t newestNs = 0;
                if (!loop.takeNewest(per, samples.data(), skipped, newestNs)) {
                    std::this_thread::sleep_for(std::chrono::microseconds(200));
                    continue;
                }
                const std::int64_t started = monotonicNs();
                for (std::size_t i = 0; i < per; ++i) {
                    samples[i] = sim::clamped(samples[i]);
                    samples[i].tick = tick + i;
                }
                if (!world.step(samples.data(), per).ok())
                    break;
                if (cuts.cutting)
                    cuts.stepMs.push_back(static_cast<double>(monotonicNs() - started) * 1e-6);
                cuts.observe(loop, world.state().loop.cutting);
                if (throttleHz > 0.0) {
                    // Sleep to 0.3 ms before, then spin: the throttle itself adds no lag.
                    const auto until = started + static_cast<std::int64_t>(1e9 / throttleHz);
                    if (until - monotonicNs() > 300000)
                        std::this_thread::sleep_for(std::chrono::nanoseconds(until - monotonicNs() - 300000));
                    while (monotonicNs() < until) {
                    }
                }
                log.lagMs.push_back(static_cast<double>(monotonicNs() - newestNs) * 1e-6);
                log.skipped += skipped;
                tick += per;
                ++steps;
                loop.publish(world.hapticFrame());
            }
            cuts.observe(loop, false);
            return steps;
        };
}

/// In along the axis, into the far wall 10 mm deep, sweeping pitch and yaw along it, and back: 4 s, repeated.
sim::Script pushScript() {
    sim::Script script;
    const auto key = [&](double t, double insertion, double pitch, double yaw) {
        sim::KeyFrame k;
        k.timeS = t;
        k.sample.insertionMm = insertion;
        k.sample.pitchDeg = pitch;
        k.sample.yawDeg = yaw;
        k.sample.inflow = 1.0;
        script.keyframes.push_back(k);
    };
    key(0.0, 30.0, 0.0, 0.0);
    key(1.0, 78.0, 0.0, 0.0);
    key(2.0, 78.0, 12.0, -8.0);
    key(3.0, 80.0, -10.0, 10.0);
    key(4.0, 30.0, 0.0, 0.0);
    return script;
}

struct BenchConfig {
    double seconds = 10.0;
    bool secondsGiven = false;
    std::string package;     ///< empty: the stand-in physics
    double throttleHz = 0.0; ///< with --package: each physics step takes at least 1/throttleHz s
    sim::Exercise demo = sim::Exercise::Exploration; ///< with --package: an operative exercise's demonstration
    DeviceLimits limits{5.0, 300.0};
};

/// `script` played once (a demonstration) or, without one, the push into the wall, repeated.
int runBench(const BenchConfig& config, const sim::Script* script, const Physics& physics, const char* physicsName) {
    ScriptedDeviceOptions deviceOptions;
    deviceOptions.limits = config.limits;
    deviceOptions.loop = script == nullptr;
    deviceOptions.maxRecorded = 0;
    ScriptedDevice device(script ? *script : pushScript(), deviceOptions);
    if (!device.open().ok())
        return 1;
    HapticsLoop loop(device);
    if (Status started = loop.start(); !started) {
        std::fprintf(stderr, "bench_haptics: %s\n", started.error().detail.c_str());
        return 1;
    }
    std::atomic<bool> stop{false};
    std::uint64_t frames = 0;
    std::thread physicsThread([&] { frames = physics(loop, stop); });
    std::this_thread::sleep_for(std::chrono::duration<double>(config.seconds));
    loop.stop();
    stop = true;
    physicsThread.join();

    const HapticsStats s = loop.stats();
    std::printf("bench_haptics: %.1f s, scripted device (%s), physics thread: %s\n", config.seconds,
                script ? "the exercise's demonstration, once" : "push into the wall, 4 s cycle", physicsName);
    std::printf("%-34s %s\n", "scheduling", s.realtime ? "SCHED_FIFO" : "SCHED_OTHER (no real-time privilege)");
    std::printf("%-34s %llu\n", "ticks", static_cast<unsigned long long>(s.ticks));
    std::printf("%-34s %.0f / %.0f / %.0f us\n", "tick period p50 / p99 / max", s.periodUs.quantile(0.5),
                s.periodUs.quantile(0.99), s.periodUs.max());
    std::printf("%-34s %.0f / %.0f us\n", "jitter |period - 1 ms| p99 / max", s.jitterUs.quantile(0.99),
                s.jitterUs.max());
    std::printf("%-34s %.0f / %.0f us\n", "wake-up lateness p99 / max", s.latenessUs.quantile(0.99),
                s.latenessUs.max());
    std::printf("%-34s %.0f / %.0f / %.0f us\n", "work per tick p50 / p99 / max", s.workUs.quantile(0.5),
                s.workUs.quantile(0.99), s.workUs.max());
    std::printf("%-34s %llu (%.3f %%)\n", "ticks missed", static_cast<unsigned long long>(s.missedTicks),
                100.0 * static_cast<double>(s.missedTicks) / static_cast<double>(std::max<std::uint64_t>(s.ticks, 1)));
    std::printf("%-34s %llu (frame %llu, device %llu)\n", "watchdog ticks",
                static_cast<unsigned long long>(s.watchdogTicks), static_cast<unsigned long long>(s.frameStaleTicks),
                static_cast<unsigned long long>(s.deviceStaleTicks));
    std::printf("%-34s %.3f / %.3f N\n", "max force / limit", s.maxForceN, config.limits.maxForceN);
    std::printf("%-34s %.1f / %.1f N*mm\n", "max torque / limit", s.maxTorqueNmm, config.limits.maxTorqueNmm);
    std::printf("%-34s %llu\n", "frames published", static_cast<unsigned long long>(frames));
    std::printf("%-34s %llu\n", "samples dropped (queue full)", static_cast<unsigned long long>(s.samplesDropped));
    return s.maxLoadFraction <= 1.0 ? 0 : 2;
}

} // namespace

int main(int argc, char** argv) {
    BenchConfig config;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--seconds") == 0 && i + 1 < argc) {
            config.seconds = std::atof(argv[++i]);
        } else if (std::strcmp(argv[i], "--throttle-hz") == 0 && i + 1 < argc) {
            config.throttleHz = std::atof(argv[++i]);
        } else if (std::strcmp(argv[i], "--package") == 0 && i + 1 < argc) {
            config.package = argv[++i];
        } else if (std::strcmp(argv[i], "--demo") == 0 && i + 1 < argc) {
            if (!sim::fromString(argv[++i], config.demo) || !sim::isOperative(config.demo)) {
                std::fprintf(stderr, "bench_haptics: --demo takes polypectomy or myomectomy\n");
                return 1;
            }
        } else {
            std::fprintf(stderr, "usage: bench_haptics [--seconds S] [--package DIR [--throttle-hz H] "
                                 "[--demo polypectomy|myomectomy]]\n");
            return 1;
        }
        if (std::strcmp(argv[i - 1], "--seconds") == 0)
            config.secondsGiven = true;
    }
    const bool demo = sim::isOperative(config.demo);
    if (demo && config.package.empty()) {
        std::fprintf(stderr, "bench_haptics: --demo needs --package\n");
        return 1;
    }
    if (!(config.seconds > 0.0 && config.seconds <= 3600.0)) {
        std::fprintf(stderr, "bench_haptics: --seconds must be in (0, 3600]\n");
        return 1;
    }
    if (config.package.empty())
        return runBench(config, nullptr, fakePhysics,
                        "stand-in (4900-triangle sphere, a frame every 5 ms after ~4 ms of CPU)");
    sim::WorldOptions worldOptions;
    worldOptions.exercise = config.demo;
    auto world = sim::World::load(config.package, worldOptions);
    if (!world) {
        std::fprintf(stderr, "bench_haptics: %s\n", world.error().detail.c_str());
        return 3;
    }
    sim::Script script;
    if (demo) {
        auto planned = sim::demonstrationScript(**world);
        if (!planned) {
            std::fprintf(stderr, "bench_haptics: %s\n", planned.error().detail.c_str());
            return 3;
        }
        script = std::move(*planned);
        config.limits.resectoscope = true;
        if (!config.secondsGiven)
            config.seconds = static_cast<double>(script.tickCount()) / sim::kDeviceRateHz + 1.0;
    }
    std::uint64_t steps = 0;
    LagLog log;
    CuttingLog cuts;
    const int code =
        runBench(config, demo ? &script : nullptr, worldPhysics(**world, steps, config.throttleHz, log, cuts),
                 config.throttleHz > 0.0 ? "the World on the package, throttled"
                                         : "the World on the package (paced by the device)");
    std::vector<double> lags = log.lagMs;
    std::sort(lags.begin(), lags.end());
    const auto quantile = [&lags](double q) {
        return lags.empty() ? 0.0
                            : lags[std::min(lags.size() - 1,
                                            static_cast<std::size_t>(q * static_cast<double>(lags.size() - 1)))];
    };
    const double stepMs = config.throttleHz > 0.0 ? 1e3 / config.throttleHz : 0.0;
    std::printf("%-34s %.2f / %.2f / %.2f ms", "lag device -> world p50/p99/max", quantile(0.5), quantile(0.99),
                quantile(1.0));
    if (stepMs > 0.0)
        std::printf(" (bar: one step + 1 ms = %.1f ms at p99)", stepMs + 1.0);
    std::printf("\n");
    std::printf("%-34s %zu\n", "samples skipped (physics behind)", log.skipped);
    std::printf("%-34s %llu (%.0f Hz)\n", "physics steps", static_cast<unsigned long long>(steps),
                static_cast<double>(steps) / config.seconds);
    if (demo) {
        const sim::TrialMetrics& m = (*world)->metrics();
        std::printf("while cutting (pedal down)         %.1f s wall, %llu ticks\n", cuts.seconds,
                    static_cast<unsigned long long>(cuts.ticks));
        std::printf("%-34s %.0f / %.0f / %.0f us\n", "  tick period p50 / p99 / max", cuts.periodUs.quantile(0.5),
                    cuts.periodUs.quantile(0.99), cuts.periodUs.max());
        std::printf("%-34s %.0f / %.0f us (bar: p99 < 300 us)\n", "  jitter |period - 1 ms| p99 / max",
                    cuts.jitterUs.quantile(0.99), cuts.jitterUs.max());
        std::printf("%-34s %.0f / %.0f us\n", "  wake-up lateness p99 / max", cuts.latenessUs.quantile(0.99),
                    cuts.latenessUs.max());
        std::printf("%-34s %llu\n", "  ticks missed", static_cast<unsigned long long>(cuts.missedTicks));
        std::vector<double> cutStepMs = cuts.stepMs;
        std::sort(cutStepMs.begin(), cutStepMs.end());
        const auto at = [&cutStepMs](double q) {
            return cutStepMs.empty()
                       ? 0.0
                       : cutStepMs[std::min(cutStepMs.size() - 1,
                                            static_cast<std::size_t>(q * static_cast<double>(cutStepMs.size())))];
        };
        std::printf("%-34s %zu, %.2f / %.2f / %.2f ms p50 / p99 / max\n", "  physics steps", cutStepMs.size(), at(0.5),
                    at(0.99), at(1.0));
        std::printf("%-34s %.1f s simulated: %.3f mL healthy, %llu cut events, %.1f s cutting\n", "the trial", m.timeS,
                    m.resection.healthyRemovedMl, static_cast<unsigned long long>(m.resection.cutEvents),
                    m.resection.cuttingTimeS);
        for (const sim::PathologyResection& p : m.resection.pathologies)
            std::printf("  %-32s %.1f %% of %.2f mL removed\n", (p.kind + " " + p.id).c_str(), p.removedPercent,
                        p.volumeMl);
    }
    return code;
}
