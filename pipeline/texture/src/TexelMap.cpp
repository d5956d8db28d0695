// Rasterization of the atlas: which face, and where in it, each texel shows.
#include "BakeSteps.h"

#include "hs/core/Parallel.h"

#include <algorithm>
#include <cmath>

namespace hs::texture::detail {

TexelMap rasterize(const SurfaceMesh& mesh, const Atlas& atlas, int threads) {
    TexelMap map;
    map.size = atlas.size;
    const auto n = static_cast<std::size_t>(atlas.size) * atlas.size;
    map.face.assign(n, -1);
    map.bary.assign(n, {0.0f, 0.0f});
    map.exact.assign(n, 0);
    const double s = atlas.size;
    parallelChunks(
        static_cast<std::size_t>(atlas.size), evenChunk(static_cast<std::size_t>(atlas.size), threads), threads,
        [&](std::size_t, std::size_t rowBeginChunk, std::size_t rowEndChunk) {
            const int rowBegin = static_cast<int>(rowBeginChunk), rowEnd = static_cast<int>(rowEndChunk);
            for (int pass = 0; pass < 2; ++pass) { // 0: centres inside; 1: touched texels not yet taken
                for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
                    const auto& uvt = atlas.uvTriangles[f];
                    std::array<double, 3> X, Y;
                    for (std::size_t k = 0; k < 3; ++k) {
                        const UvVertex& q = atlas.uvVertices[static_cast<std::size_t>(uvt[k])];
                        X[k] = q.u * s;
                        Y[k] = (1.0 - q.v) * s;
                    }
                    const double area2 = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
                    if (area2 == 0.0)
                        continue;
                    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({X[0], X[1], X[2]}))) - 2);
                    const int x1 =
                        std::min(atlas.size - 1, static_cast<int>(std::floor(std::max({X[0], X[1], X[2]}))) + 2);
                    const int y0 = std::max(rowBegin, static_cast<int>(std::floor(std::min({Y[0], Y[1], Y[2]}))) - 2);
                    const int y1 = std::min(rowEnd - 1, static_cast<int>(std::floor(std::max({Y[0], Y[1], Y[2]}))) + 2);
                    // Edge k is opposite corner k. The second pass takes the texels up to a texel outside the chart
                    // (1 to 1.41 texels along the edge's normal) and extends the face over them, unclamped: a
                    // bilinear sample on the chart's border reads texels up to a texel away, and the normal map's
                    // differences across the border need the relief to go on there, not to stop at the edge.
                    std::array<double, 3> margin;
                    for (std::size_t k = 0; k < 3; ++k) {
                        const double ex = X[(k + 2) % 3] - X[(k + 1) % 3], ey = Y[(k + 2) % 3] - Y[(k + 1) % 3];
                        margin[k] = pass == 0 ? 0.0 : (std::fabs(ex) + std::fabs(ey)) / std::fabs(area2);
                    }
                    for (int y = y0; y <= y1; ++y)
                        for (int x = x0; x <= x1; ++x) {
                            const double px = x + 0.5, py = y + 0.5;
                            std::array<double, 3> l;
                            l[0] = ((X[1] - px) * (Y[2] - py) - (X[2] - px) * (Y[1] - py)) / area2;
                            l[1] = ((X[2] - px) * (Y[0] - py) - (X[0] - px) * (Y[2] - py)) / area2;
                            l[2] = 1.0 - l[0] - l[1];
                            if (l[0] < -margin[0] || l[1] < -margin[1] || l[2] < -margin[2])
                                continue;
                            const std::size_t i = map.index(x, y);
                            if (map.face[i] >= 0)
                                continue;
                            map.face[i] = static_cast<std::int32_t>(f);
                            map.bary[i] = {static_cast<float>(l[1]), static_cast<float>(l[2])};
                            map.exact[i] = pass == 0 ? 1 : 0;
                        }
                }
            }
        });
    return map;
}

} // namespace hs::texture::detail
