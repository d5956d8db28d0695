// The camera head's automatic exposure: the circle's statistics and the exposure loop.
#include "hs/simrender/Exposure.h"

#include <algorithm>
#include <cmath>

namespace hs::simrender {

namespace {

/// Over a peak limit by less than this factor, the camera steps down by kCeilingMarginStops only (see update()).
constexpr double kMildOver = 2.0;
/// How far below an exposure that went over a peak limit the camera's ceiling is put.
constexpr double kCeilingMarginStops = 0.05;
/// How fast the ceiling rises while nothing goes over (the camera tries a little more light now and then).
constexpr double kCeilingRiseStopsPerS = 1.0;
/// The ceiling is dropped once the peaks have stayed under this share of their limit for kCeilingHoldS.
constexpr double kCeilingForgetBelow = 0.25;
constexpr double kCeilingHoldS = 0.3;

} // namespace

CircleStats circleStats(const std::uint8_t* pixels, int width, int height, int channels, double centreX, double centreY,
                        double radiusPx, int stride) {
    CircleStats s;
    if (!pixels || width <= 0 || height <= 0 || channels < 3 || !(radiusPx > 0.0))
        return s;
    stride = std::max(1, stride);
    const double r2 = radiusPx * radiusPx;
    double luma = 0.0;
    std::size_t clipped = 0, highlight = 0;
    constexpr int kClipped = 250;   // 0.98 of 255: at full scale, or so near it that the texture is gone
    constexpr int kHighlight = 235; // 0.92 of 255
    for (int y = 0; y < height; y += stride) {
        const double dy = y + 0.5 - centreY;
        if (dy * dy > r2)
            continue;
        const std::uint8_t* row =
            pixels + static_cast<std::size_t>(y) * static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
        for (int x = 0; x < width; x += stride) {
            const double dx = x + 0.5 - centreX;
            if (dx * dx + dy * dy > r2)
                continue;
            const std::uint8_t* p = row + static_cast<std::size_t>(x) * static_cast<std::size_t>(channels);
            luma += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            if (p[0] >= kClipped || p[1] >= kClipped || p[2] >= kClipped)
                ++clipped;
            if (p[0] >= kHighlight && p[1] >= kHighlight && p[2] >= kHighlight)
                ++highlight;
            ++s.pixels;
        }
    }
    if (s.pixels == 0)
        return s;
    const double n = static_cast<double>(s.pixels);
    s.meanLuminance = luma / (255.0 * n);
    s.clippedFraction = static_cast<double>(clipped) / n;
    s.highlightFraction = static_cast<double>(highlight) / n;
    return s;
}

AutoExposure::AutoExposure(const AutoExposureSettings& settings, double exposure)
    : m_settings(settings), m_exposure(std::clamp(exposure, settings.minExposure, settings.maxExposure)) {}

double AutoExposure::update(const CircleStats& stats, double elapsedS) {
    if (stats.pixels == 0 || !std::isfinite(elapsedS) || elapsedS < 0.0 || !std::isfinite(stats.meanLuminance))
        return m_exposure;
    // In stops: the correction is the error in stops, a share 1 - exp(-dt / tau) of it each frame. (Where the
    // displayed values rise more slowly than the exposure, as under a display gamma or the tone curve's shoulder,
    // the loop reaches its target in more frames, never past it.)
    const double mean = std::max(stats.meanLuminance, 1.0 / 255.0);
    double errorStops = std::log2(m_settings.targetLuminance / mean);
    // Peak limiting: more of the circle at full scale (or near white) than its limit stops down, whatever the mean
    // says, and puts a ceiling just under the exposure that went over. Far over (glare) it stops down four times as
    // fast, by a stop for every doubling of the share over the limit; a little over, by the ceiling's margin. The mean
    // then opens up no further than the ceiling, which rises slowly while nothing goes over, and is dropped once the
    // peaks have stayed low for a while (the scope has left the wall). A near wall whose white share rises steeply
    // with the exposure kept a loop without the ceiling hunting: half a stop down over the limit, the mean's pace up
    // past it (between 3.4 and 6.1 every 0.3 s halfway down the default canal). (Not on the first frame, which moves
    // the whole way by its mean: one glaring frame at switch-on would throw it far off.)
    double tau = std::max(1e-3, m_settings.timeConstantS);
    const double over =
        std::max(stats.clippedFraction / m_settings.clippedLimit, stats.highlightFraction / m_settings.nearWhiteLimit);
    bool mildlyOver = false;
    if (!m_first && over > 1.0) {
        m_ceiling = std::min(m_ceiling, m_exposure * std::exp2(-kCeilingMarginStops));
        m_calmS = 0.0;
        if (over >= kMildOver) {
            errorStops = std::min(errorStops, -std::log2(over));
            tau *= 0.25;
        } else {
            mildlyOver = true;
        }
    } else if (!m_first) {
        m_calmS = over < kCeilingForgetBelow ? m_calmS + elapsedS : 0.0;
        m_ceiling = m_calmS >= kCeilingHoldS
                        ? m_settings.maxExposure
                        : std::min(m_settings.maxExposure, m_ceiling * std::exp2(kCeilingRiseStopsPerS * elapsedS));
    }
    const double share = m_first ? 1.0 : 1.0 - std::exp(-elapsedS / tau);
    m_first = false;
    // A little over a limit: at least the ceiling's margin down at once, more at the mean's pace if it wants more.
    const double stepStops = mildlyOver ? std::min(errorStops * share, -kCeilingMarginStops) : errorStops * share;
    const double before = m_exposure;
    const double wanted = m_exposure * std::exp2(stepStops);
    const double next = wanted > before ? std::min(wanted, std::max(before, m_ceiling)) : wanted;
    m_exposure = std::clamp(next, m_settings.minExposure, m_settings.maxExposure);
    // Settled: moving by less than a twentieth of a stop, no peak over its limit, and not held by a ceiling that
    // nothing near the limit keeps (it is about to be dropped).
    const bool heldIdle = next < wanted && over < kCeilingForgetBelow;
    m_settled = std::abs(std::log2(m_exposure / before)) < 0.05 && over <= 1.0 && !heldIdle;
    return m_exposure;
}

} // namespace hs::simrender
