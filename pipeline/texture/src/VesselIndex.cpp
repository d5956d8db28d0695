// Vessel segments bucketed for per-texel lookups, and their look.
#include "BakeSteps.h"

#include "hs/core/Optics.h"

#include <algorithm>
#include <cmath>

namespace hs::texture::detail {

VesselIndex indexVessels(const VesselNetwork& net, double texelMm) {
    VesselIndex index;
    index.segments = &net.segments;
    double maxR = 0.0, maxLen = 0.0;
    for (const auto& s : net.segments) {
        maxR = std::max({maxR, s.radiusA, s.radiusB});
        maxLen = std::max(maxLen, distance(s.a, s.b));
    }
    index.reach = vesselShadowReachMm(maxR) + 2.0 * texelMm;
    index.query = 0.5 * maxLen + index.reach;
    std::vector<Vec3> midpoints(net.segments.size());
    for (std::size_t i = 0; i < net.segments.size(); ++i)
        midpoints[i] = (net.segments[i].a + net.segments[i].b) * 0.5;
    index.grid = PointGrid::of(midpoints, std::max(0.5, index.query));
    return index;
}

VesselSample sampleVessels(const VesselIndex& index, const Vec3& p, double texelMm, double cellHalf) {
    VesselSample out;
    if (!index.segments || index.segments->empty())
        return out;
    const auto& segs = *index.segments;
    index.grid.forEachNear(p, cellHalf, [&](std::int32_t id) {
        const VesselSegment& s = segs[static_cast<std::size_t>(id)];
        const Vec3 ab = s.b - s.a;
        const double len2 = norm2(ab);
        const double t = len2 > 0 ? std::clamp(dot(p - s.a, ab) / len2, 0.0, 1.0) : 0.0;
        const double d = distance(p, s.a + ab * t);
        const double r = s.radiusA + (s.radiusB - s.radiusA) * t;
        if (d > vesselShadowReachMm(r) + texelMm)
            return;
        // Averaged over the texel (a box's variance added to the spread's): a vessel thinner than a texel shows
        // fainter over its texel rather than by chance where a texel's centre falls.
        const std::array<double, 3> shadow = vesselShadow(r, d, texelMm / std::sqrt(12.0));
        for (std::size_t k = 0; k < 3; ++k)
            out.shadow[k] = std::max(out.shadow[k], static_cast<float>(shadow[k] * s.contrast));
    });
    return out;
}

} // namespace hs::texture::detail

namespace hs::texture {

namespace {

/// The mucosa's reduced scattering, 1/mm: soft tissues' mu_s' is about 1-2 per mm over the visible, rising towards the
/// blue ([Jacques2013], its power law in the wavelength).
constexpr std::array<double, 3> kMucosaScatteringPerMm{1.0, 1.4, 1.8};
/// The mucosa's blood volume share (its own absorption is its blood's): a few per cent, as in the soft tissues
/// [Jacques2013] reviews.
constexpr double kMucosaBloodShare = 0.02;

double effectiveAttenuationPerMm(std::size_t k) {
    const double mua = kMucosaBloodShare * kWholeBloodAbsorptionPerMm[k];
    return std::sqrt(3.0 * mua * (mua + kMucosaScatteringPerMm[k]));
}

} // namespace

double vesselDepthMm(double radiusMm) {
    return std::max(0.0, radiusMm) + kVesselCoverMm;
}

double vesselSpreadMm(double radiusMm) {
    return kVesselCoverMm + 0.5 * std::max(0.0, radiusMm);
}

double vesselShadowReachMm(double radiusMm) {
    return std::max(0.0, radiusMm) + 3.5 * vesselSpreadMm(radiusMm);
}

std::array<double, 3> vesselShadow(double radiusMm, double distanceMm, double extraSpreadMm) {
    std::array<double, 3> out{};
    if (!(radiusMm > 0.0) || !std::isfinite(distanceMm) || !std::isfinite(extraSpreadMm))
        return out;
    const double z = vesselDepthMm(radiusMm);
    // The vessel's cross-section seen from above, spread sideways by the diffuse light over about the depth at which
    // its upper half takes the light (its cover and half its radius): a band of its width blurred by a Gaussian of that
    // deviation (erf's closed form), and by `extraSpreadMm` in quadrature.
    const double spread = vesselSpreadMm(radiusMm);
    const double d = std::fabs(distanceMm), s = std::sqrt(2.0 * (spread * spread + extraSpreadMm * extraSpreadMm));
    const double band = 0.5 * (std::erf((radiusMm - d) / s) + std::erf((radiusMm + d) / s));
    const double chord = 0.5 * 3.141592653589793 * radiusMm; // a cylinder's mean chord seen from above
    for (std::size_t k = 0; k < 3; ++k) {
        const double absorbed = 1.0 - std::exp(-kWholeBloodAbsorptionPerMm[k] * chord);
        out[k] = std::clamp(band * absorbed * std::exp(-2.0 * effectiveAttenuationPerMm(k) * z), 0.0, 1.0);
    }
    return out;
}

} // namespace hs::texture
