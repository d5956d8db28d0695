#pragma once
/// Per-step timings and counts of a stage (kept for every pipeline step, printed with --verbose).

#include <chrono>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace hs {

/// Now, in UTC, as ISO 8601 to the second ("2026-12-03T08:20:00Z"): the one clock text of batch records and trials.
std::string utcNow();

struct StepTiming {
    std::string name;                                         ///< "voxelize", "relax", ...
    double seconds = 0.0;                                     ///< wall-clock time, s
    std::vector<std::pair<std::string, std::int64_t>> counts; ///< e.g. {"particles", 51234}
};

struct StageTimings {
    std::vector<StepTiming> steps;
    double totalSeconds() const;
    /// Adds a step (or adds time and counts to an existing one of the same name).
    StepTiming& step(const std::string& name);
};

/// Measures the lifetime of a scope into `timings.step(name)`.
class ScopedStepTimer {
public:
    ScopedStepTimer(StageTimings& timings, std::string name)
        : m_timings(timings), m_name(std::move(name)), m_start(std::chrono::steady_clock::now()) {}
    ~ScopedStepTimer() {
        const auto dt = std::chrono::steady_clock::now() - m_start;
        m_timings.step(m_name).seconds += std::chrono::duration<double>(dt).count();
    }
    ScopedStepTimer(const ScopedStepTimer&) = delete;
    ScopedStepTimer& operator=(const ScopedStepTimer&) = delete;

private:
    StageTimings& m_timings;
    std::string m_name;
    std::chrono::steady_clock::time_point m_start;
};

} // namespace hs
