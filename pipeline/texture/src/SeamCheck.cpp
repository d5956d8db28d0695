// The seam check of a baked albedo: colour steps across chart seams against steps inside charts.
#include "BakeSteps.h"

#include "MeshAdjacency.h"

#include <algorithm>
#include <cmath>

namespace hs::texture::detail {

namespace {

/// Bilinear albedo at (u, v).
void sampleAlbedo(const ImageU8& img, double u, double v, double* out) {
    const double fx = u * img.width() - 0.5, fy = (1.0 - v) * img.height() - 0.5;
    const int x0 = std::clamp(static_cast<int>(std::floor(fx)), 0, img.width() - 1);
    const int y0 = std::clamp(static_cast<int>(std::floor(fy)), 0, img.height() - 1);
    const int x1 = std::min(x0 + 1, img.width() - 1), y1 = std::min(y0 + 1, img.height() - 1);
    const double ax = std::clamp(fx - x0, 0.0, 1.0), ay = std::clamp(fy - y0, 0.0, 1.0);
    for (int c = 0; c < 3; ++c)
        out[c] = (img.at(x0, y0, c) * (1 - ax) + img.at(x1, y0, c) * ax) * (1 - ay) +
                 (img.at(x0, y1, c) * (1 - ax) + img.at(x1, y1, c) * ax) * ay;
}

} // namespace

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
                sampleAlbedo(albedo, a1.u + (b1.u - a1.u) * t, a1.v + (b1.v - a1.v) * t, c1);
                sampleAlbedo(albedo, a2.u + (b2.u - a2.u) * t, a2.v + (b2.v - a2.v) * t, c2);
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
