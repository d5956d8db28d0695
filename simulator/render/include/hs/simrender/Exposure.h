#pragma once
/// The endoscope camera head's automatic exposure: what a hysteroscopy camera does with the picture inside the
/// optic's circle. It measures the circle's mean luminance and clipped share each frame and moves its exposure, in
/// stops, towards the target with a time constant of a few hundred milliseconds (docs/simulator.md, "Endoscopic
/// view"). Plain C++: the view reads its frames back and feeds them here; the benchmark measures with the same code.

#include <cstddef>
#include <cstdint>

namespace hs::simrender {

/// What a frame shows inside the optic's circle.
struct CircleStats {
    std::size_t pixels = 0;         ///< inside the circle
    double meanLuminance = 0.0;     ///< 0..1, Rec. 709 luma of the displayed (gamma-encoded) values
    double clippedFraction = 0.0;   ///< share of the pixels with a channel at 98 % of full scale or more (250)
    double highlightFraction = 0.0; ///< share of the pixels near white (every channel >= 0.92 of full scale)
};

/// The statistics of an RGBA (or RGB: `channels` 3) 8-bit image, rows from the bottom (OpenGL's order; the circle is
/// symmetric, so the order does not matter), over the circle of `radiusPx` about (`centreX`, `centreY`) in pixels.
/// Every `stride`-th pixel in each direction (1: all).
CircleStats circleStats(const std::uint8_t* pixels, int width, int height, int channels, double centreX, double centreY,
                        double radiusPx, int stride = 1);

struct AutoExposureSettings {
    double targetLuminance = 0.45; ///< 0..1, the mean luma the camera keeps in the circle (about mid-grey)
    double timeConstantS = 0.15;   ///< s, how fast the exposure follows (a camera head adapts in a few hundred ms)
    /// The range the camera head covers (shutter and gain together: 1/60 to 1/10,000 s is about 170x, and gain some
    /// 8x more), as factors on the lamp's light.
    double minExposure = 1.0 / 16.0;
    double maxExposure = 1024.0;
    /// Above this clipped share the camera stops down further, whatever the mean says.
    double clippedLimit = 0.02;
    /// ... and above this near-white share (a wall so close that it shows white and loses its texture).
    double nearWhiteLimit = 0.05;
};

class AutoExposure {
public:
    explicit AutoExposure(const AutoExposureSettings& settings = {}, double exposure = 1.0);
    /// Moves the exposure after a frame shot with exposure() showed `stats`, `elapsedS` after the previous one (the
    /// first frame after reset() moves the whole way). Returns the new exposure. A frame with no pixel in the circle
    /// or a non-finite or negative time changes nothing.
    double update(const CircleStats& stats, double elapsedS);
    double exposure() const { return m_exposure; }
    /// Whether the last update moved the exposure by less than a twentieth of a stop with no peak over its limit and
    /// no ceiling about to be dropped holding it (a still picture has settled).
    bool settled() const { return m_settled; }
    /// The next update moves the whole way (a new scene, a camera switched on).
    void reset() {
        m_first = true;
        m_ceiling = m_settings.maxExposure;
        m_calmS = 0.0;
    }
    const AutoExposureSettings& settings() const { return m_settings; }

private:
    AutoExposureSettings m_settings;
    double m_exposure = 1.0;
    bool m_first = true;
    bool m_settled = false;
    double m_ceiling = 1e300; ///< the exposure the mean may open up to (peak limiting; see update())
    double m_calmS = 0.0;     ///< s, since the peaks were last near their limit
};

} // namespace hs::simrender
