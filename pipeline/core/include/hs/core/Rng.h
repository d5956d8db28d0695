#pragma once
/// A seeded random generator whose numbers are the same on every platform and compiler.
///
/// std::uniform_*_distribution and std::normal_distribution are implementation-defined, so this class draws
/// everything itself from xoshiro256** (Blackman & Vigna 2018), seeded through SplitMix64. Floating-point
/// results use only IEEE-754 basic operations (and sqrt, which IEEE requires to be correctly rounded); the
/// logarithm for normal deviates is computed here, not by the C library, whose last bits vary.

#include <array>
#include <cstdint>

namespace hs {

class Rng {
public:
    explicit Rng(std::uint64_t seed = 1);

    /// 64 uniformly distributed bits.
    std::uint64_t next();
    /// Uniform double in [0, 1) with 53 random bits.
    double uniform();
    /// Uniform double in [lo, hi).
    double uniform(double lo, double hi);
    /// Uniform integer in [0, n) without modulo bias; n must be > 0.
    std::uint64_t below(std::uint64_t n);
    /// Uniform integer in [lo, hi] (inclusive).
    std::int64_t between(std::int64_t lo, std::int64_t hi);
    /// Standard normal deviate (Marsaglia polar method).
    double normal();
    double normal(double mean, double sd) { return mean + sd * normal(); }
    /// A normal deviate of `mean` and `sd` drawn again until it lies in [lo, hi]: the normal's density cut to the
    /// interval (rejection sampling; the one sampler of truncated normals). The interval must hold a fair share of the
    /// mass: std::invalid_argument for sd <= 0, lo > hi, or a million draws without one inside.
    double truncatedNormal(double mean, double sd, double lo, double hi);
    /// True with probability p.
    bool bernoulli(double p) { return uniform() < p; }

    /// A new independent generator for sub-task `index` (e.g. one per thread block or per variant), so that
    /// results do not depend on how work is split.
    Rng derive(std::uint64_t index) const;
    /// A derived seed for `index`, for seeds written into files (variants of a case).
    static std::uint64_t deriveSeed(std::uint64_t seed, std::uint64_t index);

private:
    std::array<std::uint64_t, 4> m_s{};
    std::uint64_t m_seed = 0;
    bool m_hasSpare = false;
    double m_spare = 0.0;
};

/// Natural logarithm from IEEE basic operations only (max error about 1 ulp), identical on every platform.
double portableLog(double x);

} // namespace hs
