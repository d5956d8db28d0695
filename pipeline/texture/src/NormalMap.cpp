// The tangent-space normal map from the shading's relief.
#include "BakeSteps.h"

#include "hs/core/Parallel.h"

#include <algorithm>
#include <cmath>

namespace hs::texture::detail {

/// Tangent-space normals from height differences inside each chart (x along +u, y along +v).
ImageU8 normalMap(const TexelMap& map, const Shading& shading, const Atlas& atlas, double texelMm, double strength,
                  int threads) {
    const int n = map.size;
    ImageU8 out = ImageU8::create(n, n, 3, 0).value();
    parallelChunks(
        static_cast<std::size_t>(n), evenChunk(static_cast<std::size_t>(n), threads), threads,
        [&](std::size_t, std::size_t y0Chunk, std::size_t y1Chunk) {
            const int y0 = static_cast<int>(y0Chunk), y1 = static_cast<int>(y1Chunk);
            for (int y = y0; y < y1; ++y)
                for (int x = 0; x < n; ++x) {
                    const std::size_t i = map.index(x, y);
                    if (!shading.covered[i])
                        continue;
                    const std::int32_t chart = atlas.chartOfFace[static_cast<std::size_t>(map.face[i])];
                    const auto h = [&](int xx, int yy, float& value) {
                        if (xx < 0 || yy < 0 || xx >= n || yy >= n)
                            return false;
                        const std::size_t j = map.index(xx, yy);
                        if (!shading.covered[j] || atlas.chartOfFace[static_cast<std::size_t>(map.face[j])] != chart)
                            return false;
                        value = shading.height[j];
                        return true;
                    };
                    const auto slope = [&](int dx, int dy) {
                        float a = 0, b = 0;
                        const float c = shading.height[i];
                        const bool hasA = h(x + dx, y + dy, a), hasB = h(x - dx, y - dy, b);
                        if (hasA && hasB)
                            return (a - b) / (2.0 * texelMm);
                        if (hasA)
                            return (a - c) / texelMm;
                        if (hasB)
                            return (c - b) / texelMm;
                        return 0.0;
                    };
                    const double du = slope(1, 0) * strength, dv = slope(0, -1) * strength; // v grows upwards
                    const Vec3 nn = normalized(Vec3(-du, -dv, 1.0));
                    out.at(x, y, 0) = static_cast<std::uint8_t>(std::lround((nn.x * 0.5 + 0.5) * 255.0));
                    out.at(x, y, 1) = static_cast<std::uint8_t>(std::lround((nn.y * 0.5 + 0.5) * 255.0));
                    out.at(x, y, 2) = static_cast<std::uint8_t>(std::lround((nn.z * 0.5 + 0.5) * 255.0));
                }
        });
    return out;
}

} // namespace hs::texture::detail
