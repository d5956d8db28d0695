#pragma once
/// A uniform hash grid of points for radius and nearest-neighbour queries (deterministic: ties go to the lower id).

#include "hs/core/Vec3.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace hs::texture::detail {

class SpatialGrid {
public:
    explicit SpatialGrid(double cellSize) : m_cell(cellSize) {}

    void insert(std::int32_t id, const Vec3& p) { m_cells[key(cellOf(p.x), cellOf(p.y), cellOf(p.z))].push_back(id); }

    /// Calls fn(id) for every id in the cells overlapping the ball of `radius` around p (a superset of the ball).
    template <class Fn>
    void forEachNear(const Vec3& p, double radius, Fn&& fn) const {
        const std::int64_t x0 = cellOf(p.x - radius), x1 = cellOf(p.x + radius);
        const std::int64_t y0 = cellOf(p.y - radius), y1 = cellOf(p.y + radius);
        const std::int64_t z0 = cellOf(p.z - radius), z1 = cellOf(p.z + radius);
        for (std::int64_t z = z0; z <= z1; ++z)
            for (std::int64_t y = y0; y <= y1; ++y)
                for (std::int64_t x = x0; x <= x1; ++x) {
                    const auto it = m_cells.find(key(x, y, z));
                    if (it == m_cells.end())
                        continue;
                    for (std::int32_t id : it->second)
                        fn(id);
                }
    }

    /// The nearest of `points` (indexed by the inserted ids) within `radius`, -1 if none.
    std::int32_t nearest(const Vec3& p, double radius, const std::vector<Vec3>& points) const {
        std::int32_t best = -1;
        double bestD = radius * radius;
        forEachNear(p, radius, [&](std::int32_t id) {
            const double d = norm2(points[static_cast<std::size_t>(id)] - p);
            if (d < bestD || (d == bestD && best >= 0 && id < best)) {
                bestD = d;
                best = id;
            }
        });
        return best;
    }

private:
    std::int64_t cellOf(double v) const { return static_cast<std::int64_t>(std::floor(v / m_cell)); }
    static std::int64_t key(std::int64_t x, std::int64_t y, std::int64_t z) {
        return ((x & 0x1FFFFF) << 42) | ((y & 0x1FFFFF) << 21) | (z & 0x1FFFFF);
    }
    double m_cell;
    std::unordered_map<std::int64_t, std::vector<std::int32_t>> m_cells;
};

} // namespace hs::texture::detail
