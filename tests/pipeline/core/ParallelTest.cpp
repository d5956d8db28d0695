// The worker team: every chunk exactly once, the same sums as a serial loop, run after run, and a clean shutdown.
#include "hs/core/Parallel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace hs {
namespace {

TEST(WorkerTeam, CoversEveryChunkOnceRunAfterRun) {
    WorkerTeam team(2);
    EXPECT_EQ(team.size(), 2);
    const std::size_t n = 10007;
    std::vector<double> serial(n), parallel(n);
    for (std::size_t i = 0; i < n; ++i)
        serial[i] = std::sin(static_cast<double>(i)) * 3.0;
    for (int run = 0; run < 500; ++run) {
        std::vector<int> visits(n, 0);
        team.run(n, evenChunk(n, 8), [&](std::size_t, std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                parallel[i] = std::sin(static_cast<double>(i)) * 3.0;
                ++visits[i];
            }
        });
        for (std::size_t i = 0; i < n; ++i)
            ASSERT_EQ(visits[i], 1) << "run " << run << " item " << i;
        ASSERT_EQ(parallel, serial);
    }
}

TEST(WorkerTeam, OneThreadOrOneChunkRunsSerially) {
    WorkerTeam one(1);
    EXPECT_EQ(one.size(), 1);
    int calls = 0;
    one.run(100, 10, [&](std::size_t, std::size_t, std::size_t) { ++calls; });
    EXPECT_EQ(calls, 10);
    WorkerTeam two(2);
    calls = 0;
    two.run(5, 10, [&](std::size_t c, std::size_t b, std::size_t e) {
        EXPECT_EQ(c, 0u);
        EXPECT_EQ(b, 0u);
        EXPECT_EQ(e, 5u);
        ++calls;
    });
    EXPECT_EQ(calls, 1);
    two.run(0, 10, [&](std::size_t, std::size_t, std::size_t) { ++calls; });
    EXPECT_EQ(calls, 1);
}

} // namespace
} // namespace hs
