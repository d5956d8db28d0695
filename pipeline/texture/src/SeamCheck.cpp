// The seam check of a baked albedo: colour steps across chart seams against steps inside charts.
#include "BakeSteps.h"

#include "MeshAdjacency.h"

#include "hs/texture/Bake.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace hs::texture::detail {

/// Bilinear sample of the first three channels at (u, v) (v upwards).
void sampleBilinear(const ImageU8& img, double u, double v, double* out) {
    const double fx = u * img.width() - 0.5, fy = (1.0 - v) * img.height() - 0.5;
    const int x0 = std::clamp(static_cast<int>(std::floor(fx)), 0, img.width() - 1);
    const int y0 = std::clamp(static_cast<int>(std::floor(fy)), 0, img.height() - 1);
    const int x1 = std::min(x0 + 1, img.width() - 1), y1 = std::min(y0 + 1, img.height() - 1);
    const double ax = std::clamp(fx - x0, 0.0, 1.0), ay = std::clamp(fy - y0, 0.0, 1.0);
    for (int c = 0; c < 3; ++c)
        out[c] = (img.at(x0, y0, c) * (1 - ax) + img.at(x1, y0, c) * ax) * (1 - ay) +
                 (img.at(x0, y1, c) * (1 - ax) + img.at(x1, y1, c) * ax) * ay;
}

/// Mean squared albedo step across chart seams (both sides sampled at the same surface points) over the mean squared
/// step between horizontally neighbouring texels of one chart.
double chartSeamRatio(const SurfaceMesh& mesh, const Atlas& atlas, const ImageU8& albedo, const TexelMap& map) {
    const auto adj = detail::faceNeighbours(mesh);
    double seam = 0.0;
    std::int64_t seamCount = 0;
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
        for (std::size_t k = 0; k < 3; ++k) {
            const std::int32_t g = adj[f][k];
            if (g < 0 || static_cast<std::size_t>(g) < f ||
                atlas.chartOfFace[f] == atlas.chartOfFace[static_cast<std::size_t>(g)])
                continue;
            const std::int32_t va = mesh.triangles[f][k], vb = mesh.triangles[f][(k + 1) % 3];
            const auto uvOf = [&](std::size_t face, std::int32_t vertex) {
                for (std::size_t c = 0; c < 3; ++c)
                    if (mesh.triangles[face][c] == vertex)
                        return atlas.uvVertices[static_cast<std::size_t>(atlas.uvTriangles[face][c])];
                return UvVertex{};
            };
            const UvVertex a1 = uvOf(f, va), b1 = uvOf(f, vb);
            const UvVertex a2 = uvOf(static_cast<std::size_t>(g), va), b2 = uvOf(static_cast<std::size_t>(g), vb);
            for (double t : {0.25, 0.5, 0.75}) {
                double c1[3], c2[3];
                sampleBilinear(albedo, a1.u + (b1.u - a1.u) * t, a1.v + (b1.v - a1.v) * t, c1);
                sampleBilinear(albedo, a2.u + (b2.u - a2.u) * t, a2.v + (b2.v - a2.v) * t, c2);
                seam += (c1[0] - c2[0]) * (c1[0] - c2[0]) + (c1[1] - c2[1]) * (c1[1] - c2[1]) +
                        (c1[2] - c2[2]) * (c1[2] - c2[2]);
                ++seamCount;
            }
        }
    double inside = 0.0;
    std::int64_t insideCount = 0;
    for (int y = 0; y < map.size; ++y)
        for (int x = 0; x + 1 < map.size; ++x) {
            const std::size_t i = map.index(x, y);
            if (!map.exact[i] || !map.exact[i + 1] ||
                atlas.chartOfFace[static_cast<std::size_t>(map.face[i])] !=
                    atlas.chartOfFace[static_cast<std::size_t>(map.face[i + 1])])
                continue;
            double s = 0.0;
            for (int c = 0; c < 3; ++c) {
                const double d = static_cast<double>(albedo.at(x, y, c)) - albedo.at(x + 1, y, c);
                s += d * d;
            }
            inside += s;
            ++insideCount;
        }
    if (seamCount == 0 || insideCount == 0 || inside <= 0.0)
        return 0.0;
    return (seam / static_cast<double>(seamCount)) / (inside / static_cast<double>(insideCount));
}

} // namespace hs::texture::detail

namespace hs::texture {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Bilinear sample of the normal map at (u, v) (v upwards), as a tangent-space vector.
Vec3 sampleNormal(const ImageU8& img, double u, double v) {
    double rgb[3];
    detail::sampleBilinear(img, u, v, rgb);
    return Vec3(rgb[0] / 255.0 * 2.0 - 1.0, rgb[1] / 255.0 * 2.0 - 1.0, rgb[2] / 255.0 * 2.0 - 1.0);
}

} // namespace

NormalSeamStats normalSeamAngles(const TexturedSurface& drawn, const ImageU8& normal) {
    NormalSeamStats stats;
    const SurfaceMesh& mesh = drawn.mesh;
    const auto chartLabel = mesh.faceLabels.find("chart");
    if (chartLabel == mesh.faceLabels.end() || chartLabel->second.size() != mesh.triangles.size() ||
        drawn.uv.size() != mesh.points.size() || drawn.normals.size() != mesh.points.size() || normal.channels() < 3 ||
        normal.width() <= 0)
        return stats;
    const std::vector<std::int32_t>& chart = chartLabel->second;
    // The surface before its split along the seams: points welded where the split left copies at one place.
    std::map<std::array<double, 3>, std::int32_t> weld;
    std::vector<std::int32_t> welded(mesh.points.size());
    for (std::size_t i = 0; i < mesh.points.size(); ++i) {
        const Vec3& p = mesh.points[i];
        welded[i] = weld.try_emplace({p.x, p.y, p.z}, static_cast<std::int32_t>(weld.size())).first->second;
    }
    std::map<std::pair<std::int32_t, std::int32_t>, std::vector<std::pair<std::int32_t, int>>> edges;
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const std::int32_t a = welded[static_cast<std::size_t>(mesh.triangles[f][static_cast<std::size_t>(k)])];
            const std::int32_t b =
                welded[static_cast<std::size_t>(mesh.triangles[f][static_cast<std::size_t>((k + 1) % 3)])];
            edges[{std::min(a, b), std::max(a, b)}].emplace_back(static_cast<std::int32_t>(f), k);
        }
    // The tangent a renderer builds for a face (dP/du from its UVs).
    const auto tangentOf = [&](std::size_t f) {
        const auto& t = mesh.triangles[f];
        const Vec3 e1 = mesh.points[static_cast<std::size_t>(t[1])] - mesh.points[static_cast<std::size_t>(t[0])];
        const Vec3 e2 = mesh.points[static_cast<std::size_t>(t[2])] - mesh.points[static_cast<std::size_t>(t[0])];
        const auto& q0 = drawn.uv[static_cast<std::size_t>(t[0])];
        const auto& q1 = drawn.uv[static_cast<std::size_t>(t[1])];
        const auto& q2 = drawn.uv[static_cast<std::size_t>(t[2])];
        const double du1 = q1[0] - q0[0], dv1 = q1[1] - q0[1], du2 = q2[0] - q0[0], dv2 = q2[1] - q0[1];
        const double det = du1 * dv2 - du2 * dv1;
        return det == 0.0 ? Vec3() : (e1 * dv2 - e2 * dv1) / det;
    };
    const auto angleDeg = [](const Vec3& a, const Vec3& b) {
        return std::acos(std::clamp(dot(a, b), -1.0, 1.0)) * 180.0 / kPi;
    };
    const double texel = 1.0 / normal.width();
    std::vector<double> across, inside;
    for (const auto& [key, sides] : edges) {
        if (sides.size() != 2 ||
            chart[static_cast<std::size_t>(sides[0].first)] == chart[static_cast<std::size_t>(sides[1].first)])
            continue;
        // Each side's copies of the edge's two ends (in the welded order) and of the face's third corner.
        std::array<std::array<std::size_t, 3>, 2> corners{};
        std::array<Vec3, 2> tangent;
        for (std::size_t s = 0; s < 2; ++s) {
            const auto f = static_cast<std::size_t>(sides[s].first);
            const auto k = static_cast<std::size_t>(sides[s].second);
            auto a = static_cast<std::size_t>(mesh.triangles[f][k]);
            auto b = static_cast<std::size_t>(mesh.triangles[f][(k + 1) % 3]);
            if (welded[a] != key.first)
                std::swap(a, b);
            corners[s] = {a, b, static_cast<std::size_t>(mesh.triangles[f][(k + 2) % 3])};
            tangent[s] = tangentOf(f);
        }
        for (double t : {0.25, 0.5, 0.75}) {
            std::array<Vec3, 2> atSeam, inward;
            bool ok = true;
            for (std::size_t s = 0; s < 2 && ok; ++s) {
                const auto [a, b, c] = corners[s];
                const Vec3 n = normalized(drawn.normals[a] * (1.0 - t) + drawn.normals[b] * t);
                const Vec3 tt = normalized(tangent[s] - n * dot(tangent[s], n));
                const double u = drawn.uv[a][0] * (1.0 - t) + drawn.uv[b][0] * t;
                const double v = drawn.uv[a][1] * (1.0 - t) + drawn.uv[b][1] * t;
                // One texel into the face, towards its third corner: the same relief a texel away, in one chart.
                const double du = drawn.uv[c][0] - u, dv = drawn.uv[c][1] - v;
                const double reach = std::sqrt(du * du + dv * dv);
                ok = norm(n) > 0.0 && norm(tt) > 0.0 && reach > 0.0;
                if (!ok)
                    break;
                const double step = std::min(1.0, texel / reach);
                const Vec3 b3 = cross(n, tt);
                const auto rebuild = [&](double uu, double vv) {
                    const Vec3 ts = sampleNormal(normal, uu, vv);
                    return normalized(tt * ts.x + b3 * ts.y + n * ts.z);
                };
                atSeam[s] = rebuild(u, v);
                inward[s] = rebuild(u + du * step, v + dv * step);
            }
            if (!ok)
                continue;
            across.push_back(angleDeg(atSeam[0], atSeam[1]));
            inside.push_back(0.5 * (angleDeg(atSeam[0], inward[0]) + angleDeg(atSeam[1], inward[1])));
        }
    }
    if (across.empty())
        return stats;
    double acrossSq = 0.0, insideSq = 0.0;
    for (std::size_t i = 0; i < across.size(); ++i) {
        acrossSq += across[i] * across[i];
        insideSq += inside[i] * inside[i];
    }
    std::sort(across.begin(), across.end());
    std::sort(inside.begin(), inside.end());
    const auto at = [](const std::vector<double>& sorted, double q) {
        return sorted[static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1))];
    };
    stats.samples = static_cast<std::int64_t>(across.size());
    stats.medianDeg = at(across, 0.5);
    stats.p95Deg = at(across, 0.95);
    stats.maxDeg = across.back();
    stats.insideP95Deg = at(inside, 0.95);
    stats.ratio = insideSq > 0.0 ? acrossSq / insideSq : 0.0;
    return stats;
}

} // namespace hs::texture
