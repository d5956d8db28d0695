#include "hs/core/Rng.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include <cmath>
#include <vector>

using hs::Rng;

TEST(Rng, GivesTheSameSequenceForTheSameSeed) {
    Rng a(42), b(42);
    for (int i = 0; i < 1000; ++i)
        ASSERT_EQ(a.next(), b.next());
}

TEST(Rng, MatchesTheReferenceXoshiroOutput) {
    // Pinned values: if these change, every scene generated from a seed changes. Computed once by this
    // implementation of SplitMix64 seeding + xoshiro256** (Blackman & Vigna), checked against an independent
    // implementation of the published algorithm.
    Rng rng(1);
    EXPECT_EQ(rng.next(), 0xb3f2af6d0fc710c5ull);
    EXPECT_EQ(rng.next(), 0x853b559647364ceaull);
    EXPECT_EQ(rng.next(), 0x92f89756082a4514ull);
}

TEST(Rng, UniformStaysInTheUnitInterval) {
    Rng rng(7);
    double sum = 0.0;
    for (int i = 0; i < 100000; ++i) {
        const double u = rng.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        sum += u;
    }
    EXPECT_NEAR(sum / 100000.0, 0.5, 0.005);
}

TEST(Rng, BelowIsUnbiasedOverSmallRanges) {
    Rng rng(3);
    std::vector<int> counts(6, 0);
    for (int i = 0; i < 60000; ++i)
        ++counts[static_cast<std::size_t>(rng.below(6))];
    for (int c : counts)
        EXPECT_NEAR(c, 10000, 400);
}

TEST(Rng, BetweenIncludesBothEnds) {
    Rng rng(5);
    bool sawLo = false, sawHi = false;
    for (int i = 0; i < 1000; ++i) {
        const auto v = rng.between(-2, 2);
        ASSERT_GE(v, -2);
        ASSERT_LE(v, 2);
        sawLo |= v == -2;
        sawHi |= v == 2;
    }
    EXPECT_TRUE(sawLo && sawHi);
}

TEST(Rng, NormalHasUnitVarianceAndZeroMean) {
    Rng rng(11);
    double sum = 0.0, sum2 = 0.0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double x = rng.normal();
        sum += x;
        sum2 += x * x;
    }
    const double mean = sum / n;
    EXPECT_NEAR(mean, 0.0, 0.01);
    EXPECT_NEAR(sum2 / n - mean * mean, 1.0, 0.02);
}

TEST(Rng, TruncatedNormalKeepsTheNormalsDrawsInsideItsInterval) {
    Rng a(11), b(11);
    for (int i = 0; i < 2000; ++i) {
        const double v = a.truncatedNormal(2.0, 1.5, 0.5, 4.0);
        ASSERT_GE(v, 0.5);
        ASSERT_LE(v, 4.0);
        double w = b.normal(2.0, 1.5); // the same draws, those outside redrawn
        while (w < 0.5 || w > 4.0)
            w = b.normal(2.0, 1.5);
        ASSERT_EQ(v, w);
    }
    EXPECT_THROW(a.truncatedNormal(0.0, 1.0, 1.0, -1.0), std::invalid_argument);
    EXPECT_THROW(a.truncatedNormal(0.0, 0.0, -1.0, 1.0), std::invalid_argument);
    EXPECT_THROW(a.truncatedNormal(0.0, 1.0, 50.0, 51.0), std::invalid_argument); // no draw ever lands there
}

TEST(Rng, DerivedGeneratorsAreIndependentAndReproducible) {
    Rng base(9);
    EXPECT_EQ(base.derive(0).next(), Rng(9).derive(0).next());
    EXPECT_NE(base.derive(0).next(), base.derive(1).next());
    EXPECT_NE(Rng::deriveSeed(9, 0), Rng::deriveSeed(9, 1));
}

TEST(PortableLog, AgreesWithTheLibraryLogarithm) {
    Rng rng(13);
    for (int i = 0; i < 10000; ++i) {
        const double x = std::ldexp(rng.uniform(0.5, 1.0), static_cast<int>(rng.between(-60, 60)));
        EXPECT_NEAR(hs::portableLog(x), std::log(x), 4e-16 * std::fmax(1.0, std::fabs(std::log(x))));
    }
    EXPECT_EQ(hs::portableLog(1.0), 0.0);
    EXPECT_TRUE(std::isnan(hs::portableLog(-1.0)));
    EXPECT_TRUE(std::isinf(hs::portableLog(0.0)));
}
