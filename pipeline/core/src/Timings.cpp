#include "hs/core/Timings.h"

namespace hs {

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
