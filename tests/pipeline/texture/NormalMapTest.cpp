// The normal map against a relief known in closed form: what a renderer rebuilds from the map must be the relief's
// own normal, on every chart, whatever the chart's tilt against the faces.
#include "hs/texture/Atlas.h"
#include "hs/texture/Bake.h"

#include "BakeSteps.h"
#include "TextureTestMeshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace hs;
using namespace hs::texture;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// A relief h(p) = amplitude sin(k . p), mm.
struct Waves {
    Vec3 k;
    double amplitudeMm = 0.0;
    double height(const Vec3& p) const { return amplitudeMm * std::sin(dot(k, p)); }
    Vec3 gradient(const Vec3& p) const { return k * (amplitudeMm * std::cos(dot(k, p))); }
};

struct Frame {
    Vec3 t, b, n;
};

/// The frame a renderer builds for a face (VTK's vtkPolyDataTangents and its normal-mapping shader): the tangent
/// dP/du from the face's texture coordinates, made orthogonal to the normal, and the bitangent N x T.
Frame rendererFrame(const SurfaceMesh& mesh, const Atlas& atlas, std::size_t f) {
    const auto& tri = mesh.triangles[f];
    Vec3 p[3];
    double u[3], v[3];
    for (std::size_t k = 0; k < 3; ++k) {
        p[k] = mesh.points[static_cast<std::size_t>(tri[k])];
        const UvVertex& q = atlas.uvVertices[static_cast<std::size_t>(atlas.uvTriangles[f][k])];
        u[k] = q.u;
        v[k] = q.v; // the texture's t: the renderer samples the map with its origin at the bottom left
    }
    const Vec3 a = p[2] - p[1], b = p[0] - p[1];
    const double du1 = u[2] - u[1], dv1 = v[2] - v[1], du2 = u[0] - u[1], dv2 = v[0] - v[1];
    const Vec3 tangent = (a * dv2 - b * dv1) / (du1 * dv2 - du2 * dv1);
    Frame frame;
    frame.n = normalized(cross(p[1] - p[0], p[2] - p[0]));
    frame.t = normalized(tangent - frame.n * dot(tangent, frame.n));
    frame.b = cross(frame.n, frame.t);
    return frame;
}

double angleDeg(const Vec3& a, const Vec3& b) {
    return std::acos(std::clamp(dot(normalized(a), normalized(b)), -1.0, 1.0)) * 180.0 / kPi;
}

double quantile(std::vector<double> values, double q) {
    std::sort(values.begin(), values.end());
    return values[static_cast<std::size_t>(q * static_cast<double>(values.size() - 1))];
}

} // namespace

// Charts are planar projections: a face up to the atlas's 40 degrees off its chart's plane is foreshortened there.
// The map stored the height's differences per texel over the texel's nominal size, so it overstated the slope along
// the tilt by up to 1 / cos(40) and the neighbouring chart, seen head on, did not: a relief with a direction (the
// canal's folds) changed its slope at every seam and the charts showed as patches.
TEST(TextureNormalMap, TheRendererRebuildsTheReliefsOwnNormalOnEveryChart) {
    const SurfaceMesh organ = test::subdivideMidpoint(test::makeLabelledOrgan(12, 30.0));
    AtlasParams params;
    params.size = 1024;
    const auto atlas = buildAtlas(organ, params);
    ASSERT_TRUE(atlas.ok());
    const double texelMm = 1.0 / atlas->stats.texelsPerMm;
    const detail::TexelMap map = detail::rasterize(organ, *atlas, 1);

    // Waves 6 mm long (about 45 texels), not along any axis; slope up to 0.42.
    Waves waves;
    waves.k = normalized(Vec3(1.0, 0.6, 0.3)) * (2.0 * kPi / 6.0);
    waves.amplitudeMm = 0.4;
    const std::size_t texels = static_cast<std::size_t>(map.size) * static_cast<std::size_t>(map.size);
    detail::Shading shading;
    shading.height.assign(texels, 0.0f);
    shading.covered.assign(texels, 0);
    std::vector<Vec3> where(texels);
    for (std::size_t i = 0; i < texels; ++i) {
        if (map.face[i] < 0)
            continue;
        const auto& tri = organ.triangles[static_cast<std::size_t>(map.face[i])];
        const double w1 = map.bary[i][0], w2 = map.bary[i][1];
        where[i] = organ.points[static_cast<std::size_t>(tri[0])] * (1.0 - w1 - w2) +
                   organ.points[static_cast<std::size_t>(tri[1])] * w1 +
                   organ.points[static_cast<std::size_t>(tri[2])] * w2;
        shading.height[i] = static_cast<float>(waves.height(where[i]));
        shading.covered[i] = 1;
    }
    ImageU8 normal = detail::normalMap(organ, map, shading, *atlas, texelMm, 1.0, 1);
    // As the bake leaves it: the gutters filled from the charts' borders.
    detail::fillGutters({&normal}, shading.covered, map.size, atlas->stats.padding + 1, {{128, 128, 255, 0}});

    // Texels whose four neighbours lie on the same chart (the central differences the map takes).
    std::vector<double> errors, tilted, headOn;
    std::vector<Frame> frames(organ.triangles.size());
    for (std::size_t f = 0; f < organ.triangles.size(); ++f)
        frames[f] = rendererFrame(organ, *atlas, f);
    const auto chartAt = [&](int x, int y) {
        const std::size_t j = map.index(x, y);
        return map.exact[j] ? atlas->chartOfFace[static_cast<std::size_t>(map.face[j])] : -1;
    };
    for (int y = 1; y + 1 < map.size; ++y)
        for (int x = 1; x + 1 < map.size; ++x) {
            const std::int32_t chart = chartAt(x, y);
            if (chart < 0 || chartAt(x - 1, y) != chart || chartAt(x + 1, y) != chart || chartAt(x, y - 1) != chart ||
                chartAt(x, y + 1) != chart)
                continue;
            const std::size_t i = map.index(x, y);
            const Frame& fr = frames[static_cast<std::size_t>(map.face[i])];
            const Vec3 ts((normal.at(x, y, 0) / 255.0) * 2.0 - 1.0, (normal.at(x, y, 1) / 255.0) * 2.0 - 1.0,
                          (normal.at(x, y, 2) / 255.0) * 2.0 - 1.0);
            const Vec3 rebuilt = fr.t * ts.x + fr.b * ts.y + fr.n * ts.z;
            const Vec3 g = waves.gradient(where[i]);
            const Vec3 truth = fr.n - (g - fr.n * dot(g, fr.n));
            const double error = angleDeg(rebuilt, truth);
            errors.push_back(error);
            // The face's tilt against its chart's plane shows as the texel's foreshortening: the longest surface
            // step of one texel along the image's axes over the texel's nominal size.
            const Vec3 px = where[map.index(x + 1, y)] - where[map.index(x - 1, y)];
            const Vec3 py = where[map.index(x, y + 1)] - where[map.index(x, y - 1)];
            const double stretch = 0.5 * std::max(norm(px), norm(py)) / texelMm;
            (stretch > 1.1 ? tilted : headOn).push_back(error);
        }
    ASSERT_GT(errors.size(), 100000u);
    ASSERT_GT(tilted.size(), 200u) << "the atlas has no faces tilted against their chart: the test shows nothing";
    const double all50 = quantile(errors, 0.5), all99 = quantile(errors, 0.99);
    const double tilted99 = quantile(tilted, 0.99), headOn99 = quantile(headOn, 0.99);
    std::printf("normal map against the relief's own normal, degrees (%zu texels; %zu foreshortened > 1.1x):\n"
                "  median %.2f, p99 %.2f; foreshortened p99 %.2f, head-on p99 %.2f\n",
                errors.size(), tilted.size(), all50, all99, tilted99, headOn99);
    // Across the charts' seams the two sides must rebuild one normal: a bilinear sample on a chart's border reads
    // texels up to one outside it, which the rasterizer now covers with the face extended (it clamped them onto the
    // edge, flattening the relief's last half texel, and left the rest to the gutter's averages).
    const NormalSeamStats seams = normalSeamAngles(makeTexturedSurface(organ, *atlas), normal);
    std::printf("across the seams (%lld samples): median %.2f, p95 %.2f, max %.2f; a texel inside: p95 %.2f\n",
                static_cast<long long>(seams.samples), seams.medianDeg, seams.p95Deg, seams.maxDeg, seams.insideP95Deg);
    // One 8-bit step of the stored normal turns it by up to 0.45 degrees, and central differences over 45-texel waves
    // err by far less: 1 degree is two such steps. The map before this check: p99 1.74 overall and 5.87 on the
    // foreshortened texels (median 0.26).
    EXPECT_LT(all99, 1.0);
    EXPECT_LT(tilted99, 1.0);
    // Half the seam samples within a degree (clamped border texels: median 1.76, p95 6.06). The tail is the bumps'
    // creases (faces 45-60 degrees apart), where the faceted relief has no one normal.
    ASSERT_GT(seams.samples, 1000);
    EXPECT_LT(seams.medianDeg, 1.0);
}

// The canal's folds are drawn from the canal's frame. Measured around the wall by the local distance from the axis,
// the folds followed the coarse canal's facets (a facet is nearer the axis at its middle than at its ends): their
// slope turned at every facet's edge, and the normal map showed the facets as patches. Around an octagonal canal, the
// fold height's slope changes across an edge no more than a smooth relief's does over the same step.
TEST(TextureNormalMap, TheCanalsFoldsDoNotTurnAtTheCanalsFacets) {
    CanalFrame frame;
    frame.externalOsMm = {0.0, 0.0, 0.0};
    frame.internalOsMm = {0.0, 0.0, 30.0};
    frame.anterior = {0.0, 1.0, 0.0};
    constexpr double kCornerMm = 2.5; // the octagon's corners' distance from the axis
    frame.radiusMm = kCornerMm;
    frame.wallRadiusMm = kCornerMm * std::cos(kPi / 8.0); // the facets' middles
    const detail::CanalAxes axes = detail::canalAxes(frame);
    constexpr int kSides = 8, kSteps = 400; // per facet
    const double sMm = 12.0;                // halfway up, where the folds stand at full height
    std::vector<double> height;
    std::vector<bool> edgeAfter; // a facet's edge lies between sample i and i + 1 ... i + 2
    for (int side = 0; side < kSides; ++side) {
        const double a0 = 2.0 * kPi * side / kSides + kPi / kSides, a1 = a0 + 2.0 * kPi / kSides;
        const Vec3 c0(kCornerMm * std::sin(a0), kCornerMm * std::cos(a0), sMm);
        const Vec3 c1(kCornerMm * std::sin(a1), kCornerMm * std::cos(a1), sMm);
        for (int i = 0; i < kSteps; ++i) {
            const double t = (i + 0.5) / kSteps;
            height.push_back(detail::canalRelief(axes, c0 * (1.0 - t) + c1 * t).foldHeightMm);
            edgeAfter.push_back(i + 1 == kSteps);
        }
    }
    const double stepMm = 2.0 * kCornerMm * std::sin(kPi / kSides) / kSteps;
    double atEdges = 0.0, inside = 0.0;
    const std::size_t n = height.size();
    for (std::size_t i = 0; i < n; ++i) {
        const double h0 = height[i], h1 = height[(i + 1) % n], h2 = height[(i + 2) % n];
        const double turn = std::fabs((h2 - h1) - (h1 - h0)) / stepMm; // the slope's change over one step
        if (edgeAfter[i] || edgeAfter[(i + 1) % n])
            atEdges = std::max(atEdges, turn);
        else
            inside = std::max(inside, turn);
    }
    std::printf("the folds' slope changes by up to %.5f across the facets' edges, %.5f between neighbouring samples "
                "inside them (step %.4f mm)\n",
                atEdges, inside, stepMm);
    ASSERT_GT(inside, 0.0) << "no folds on the octagon: the test shows nothing";
    EXPECT_LT(atEdges, 2.0 * inside);
}
