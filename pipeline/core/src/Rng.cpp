#include "hs/core/Rng.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace hs {
namespace {

std::uint64_t splitMix64(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

std::uint64_t rotl(std::uint64_t x, int k) {
    return (x << k) | (x >> (64 - k));
}

} // namespace

Rng::Rng(std::uint64_t seed) : m_seed(seed) {
    std::uint64_t state = seed;
    for (auto& word : m_s)
        word = splitMix64(state);
}

std::uint64_t Rng::next() {
    const std::uint64_t result = rotl(m_s[1] * 5, 7) * 9;
    const std::uint64_t t = m_s[1] << 17;
    m_s[2] ^= m_s[0];
    m_s[3] ^= m_s[1];
    m_s[1] ^= m_s[2];
    m_s[0] ^= m_s[3];
    m_s[2] ^= t;
    m_s[3] = rotl(m_s[3], 45);
    return result;
}

double Rng::uniform() {
    return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

double Rng::uniform(double lo, double hi) {
    return lo + (hi - lo) * uniform();
}

std::uint64_t Rng::below(std::uint64_t n) {
    // Rejection of the lowest (2^64 mod n) values removes the modulo bias (as OpenBSD's arc4random_uniform).
    const std::uint64_t threshold = (0 - n) % n;
    for (;;) {
        const std::uint64_t r = next();
        if (r >= threshold)
            return r % n;
    }
}

std::int64_t Rng::between(std::int64_t lo, std::int64_t hi) {
    if (hi <= lo)
        return lo;
    const auto span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo) + 1;
    if (span == 0) // the full 64-bit range
        return static_cast<std::int64_t>(next());
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(lo) + below(span));
}

double Rng::truncatedNormal(double mean, double sd, double lo, double hi) {
    if (!(sd > 0.0) || !(lo <= hi))
        throw std::invalid_argument("Rng::truncatedNormal: needs sd > 0 and lo <= hi");
    for (int draw = 0; draw < 1000000; ++draw) {
        const double v = normal(mean, sd);
        if (v >= lo && v <= hi)
            return v;
    }
    throw std::invalid_argument("Rng::truncatedNormal: [lo, hi] holds almost none of the normal's mass");
}

double Rng::normal() {
    if (m_hasSpare) {
        m_hasSpare = false;
        return m_spare;
    }
    double u = 0.0, v = 0.0, s = 0.0;
    do {
        u = 2.0 * uniform() - 1.0;
        v = 2.0 * uniform() - 1.0;
        s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    const double factor = std::sqrt(-2.0 * portableLog(s) / s);
    m_spare = v * factor;
    m_hasSpare = true;
    return u * factor;
}

Rng Rng::derive(std::uint64_t index) const {
    return Rng(deriveSeed(m_seed, index));
}

std::uint64_t Rng::deriveSeed(std::uint64_t seed, std::uint64_t index) {
    std::uint64_t state = seed ^ (0xD1B54A32D192ED03ull * (index + 1));
    splitMix64(state);
    return splitMix64(state);
}

double portableLog(double x) {
    if (std::isnan(x) || x < 0.0)
        return std::numeric_limits<double>::quiet_NaN();
    if (x == 0.0)
        return -std::numeric_limits<double>::infinity();
    if (std::isinf(x))
        return x;
    // x = m * 2^e with m in [sqrt(1/2), sqrt(2)); log x = e ln2 + 2 atanh(s), s = (m - 1) / (m + 1), |s| < 0.1716.
    int e = 0;
    double m = std::frexp(x, &e); // exact: m in [0.5, 1)
    if (m < 0.70710678118654752440) {
        m *= 2.0;
        --e;
    }
    const double s = (m - 1.0) / (m + 1.0);
    const double s2 = s * s;
    // atanh series to s^23: the next term is below 2.5e-18 relative.
    double sum = 1.0 / 23.0;
    for (int k = 21; k >= 3; k -= 2)
        sum = 1.0 / k + s2 * sum;
    const double series = 2.0 * s + 2.0 * s * s2 * sum;
    constexpr double kLn2Hi = 6.93147180369123816490e-01; // ln 2 split so that e * kLn2Hi is exact
    constexpr double kLn2Lo = 1.90821492927058770002e-10;
    const double de = static_cast<double>(e);
    return de * kLn2Hi + (series + de * kLn2Lo);
}

} // namespace hs
