// Gutter filling around the charts of the baked maps.
#include "BakeSteps.h"

#include <algorithm>

namespace hs::texture::detail {

/// Fills the gutters: `rings` passes of averaging covered 8-neighbours into empty texels (so mipmaps and bilinear
/// filtering at chart borders fetch chart colours), then a constant for what is still empty.
void fillGutters(std::vector<ImageU8*> images, std::vector<std::uint8_t> covered, int size, int rings,
                 const std::vector<std::array<std::uint8_t, 4>>& fallback) {
    std::vector<std::uint8_t> next = covered;
    for (int ring = 0; ring < rings; ++ring) {
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * size + x;
                if (covered[i])
                    continue;
                std::array<std::array<int, 4>, 4> sum{};
                int count = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int xx = x + dx, yy = y + dy;
                        if (xx < 0 || yy < 0 || xx >= size || yy >= size ||
                            !covered[static_cast<std::size_t>(yy) * size + xx])
                            continue;
                        ++count;
                        for (std::size_t m = 0; m < images.size(); ++m)
                            for (int c = 0; c < images[m]->channels(); ++c)
                                sum[m][static_cast<std::size_t>(c)] += images[m]->at(xx, yy, c);
                    }
                if (count == 0)
                    continue;
                for (std::size_t m = 0; m < images.size(); ++m)
                    for (int c = 0; c < images[m]->channels(); ++c)
                        images[m]->at(x, y, c) =
                            static_cast<std::uint8_t>((sum[m][static_cast<std::size_t>(c)] + count / 2) / count);
                next[i] = 1;
            }
        covered = next;
    }
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            if (!covered[static_cast<std::size_t>(y) * size + x])
                for (std::size_t m = 0; m < images.size(); ++m)
                    for (int c = 0; c < images[m]->channels(); ++c)
                        images[m]->at(x, y, c) = fallback[m][static_cast<std::size_t>(c)];
}

} // namespace hs::texture::detail
