#include "hs/core/Progress.h"

#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

TEST(Progress, ForwardsReportsToTheCallback) {
    std::vector<std::pair<std::string, double>> seen;
    hs::Progress p([&](std::string_view key, double f) { seen.emplace_back(std::string(key), f); });
    p.report("a", 0.25);
    p.report("b", 2.0);
    ASSERT_EQ(seen.size(), 2u);
    EXPECT_EQ(seen[0].first, "a");
    EXPECT_DOUBLE_EQ(seen[1].second, 1.0); // clamped
}

TEST(Progress, SubRangesMapIntoTheParent) {
    double last = -1.0;
    hs::Progress p([&](std::string_view, double f) { last = f; });
    auto sub = p.sub(0.5, 0.75);
    sub.report("x", 0.5);
    EXPECT_DOUBLE_EQ(last, 0.625);
}

TEST(Progress, CancellingTheParentCancelsTheChild) {
    hs::Progress p;
    auto sub = p.sub(0.0, 1.0);
    EXPECT_FALSE(sub.cancelled());
    std::thread t([&] { p.requestCancel(); });
    t.join();
    EXPECT_TRUE(sub.cancelled());
}

TEST(Progress, TheNoneInstanceIsNeverCancelled) {
    hs::Progress::none().requestCancel();
    hs::Progress::none().report("ignored", 0.5);
    EXPECT_FALSE(hs::Progress::none().cancelled());
}
