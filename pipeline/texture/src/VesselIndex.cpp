// Vessel segments bucketed for per-texel lookups, and their look.
#include "BakeSteps.h"

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
    index.reach = maxR + 2.0 * texelMm;
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
        const double drawn = std::max(r, 0.5 * texelMm); // at least one texel wide, fainter when thinner
        if (d > drawn + texelMm)
            return;
        const double edge = std::clamp((drawn - d) / texelMm + 0.5, 0.0, 1.0);
        const double cover = edge * std::min(1.0, r / (0.5 * texelMm)) * s.contrast;
        if (cover > out.cover) {
            out.cover = static_cast<float>(cover);
            out.radius = static_cast<float>(r);
        }
        if (d < r)
            out.height = std::max(out.height, static_cast<float>(0.5 * r * std::sqrt(1.0 - (d / r) * (d / r))));
    });
    return out;
}

/// Blood colour by calibre: capillaries bright red, larger (deeper) vessels darker and bluer.
void vesselColour(float radius, float* rgb) {
    const float t = std::clamp((radius - 0.03f) / 0.3f, 0.0f, 1.0f);
    rgb[0] = 0.70f + (0.42f - 0.70f) * t;
    rgb[1] = 0.10f + (0.05f - 0.10f) * t;
    rgb[2] = 0.13f + (0.16f - 0.13f) * t;
}

} // namespace hs::texture::detail
