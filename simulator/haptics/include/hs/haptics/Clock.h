#pragma once
/// The haptics loop's clock: CLOCK_MONOTONIC in nanoseconds (the clock its absolute deadlines use). Devices that
/// record timestamps (ScriptedDevice, the tests' hidapi fake) use the same one, so their times compare.

#include <cstdint>

#include <time.h>

namespace hs::haptics {

inline std::int64_t monotonicNs() {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<std::int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

} // namespace hs::haptics
