#include "hs/core/Timings.h"

#include <ctime>

namespace hs {

std::string utcNow() {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return text;
}

double StageTimings::totalSeconds() const {
    double total = 0.0;
    for (const auto& s : steps)
        total += s.seconds;
    return total;
}

StepTiming& StageTimings::step(const std::string& name) {
    for (auto& s : steps)
        if (s.name == name)
            return s;
    steps.push_back(StepTiming{name, 0.0, {}});
    return steps.back();
}

} // namespace hs
