#pragma once
/// A uniform grid of points for radius, neighbour-cell and nearest-point queries: the one point grid of the pipeline
/// (particle relaxation, pathology cell growth, vessel growth and the vessel bake use it).
///
/// Cell (i, j, k) holds the points p with floor((p - origin) / cellSize) = (i, j, k). The grid stores the cells that
/// meet a box given up front (plus `pad` cells on each side) densely; a point beyond them goes to the nearest border
/// cell, and queries clamp their cell range the same way, so a query still finds it (every query returns a superset
/// of the points it asks for: callers filter by distance). Points can be added at any time: a whole set at once into
/// an empty grid is stored by counting sort (each cell's points contiguous, as a neighbour search per particle wants),
/// later points in a list per cell.
///
/// Deterministic: a query visits rows of cells in z, y order; in a row, the points inserted as a set (cell by cell in
/// x order, each cell's in insertion order), then those inserted one by one (the same way).

#include "hs/core/Vec3.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace hs {

class PointGrid {
public:
    /// Most cells a grid allocates; a finer request coarsens the cell by 1.25 until it fits (the same points are
    /// found, more of them per cell).
    static constexpr std::int64_t kMaxCells = std::int64_t(1) << 24;

    PointGrid() = default;
    /// Cells of edge `cellSize` (mm, > 0) with a corner at `origin`, covering `box` and `pad` more cells each side.
    PointGrid(const Bounds& box, double cellSize, const Vec3& origin = {}, int pad = 0) {
        reset(box, cellSize, origin, pad);
    }
    /// A grid of points[i] with the id i, over the points' own box.
    static PointGrid of(const std::vector<Vec3>& points, double cellSize) {
        Bounds box;
        for (const Vec3& p : points)
            box.add(p);
        PointGrid grid(box, cellSize);
        grid.insertAll(points);
        return grid;
    }

    /// Empties the grid and lays it out anew (keeps its memory).
    void reset(const Bounds& box, double cellSize, const Vec3& origin = {}, int pad = 0) {
        m_cell = cellSize > 0.0 && std::isfinite(cellSize) ? cellSize : 1.0;
        m_origin = origin;
        const Bounds b = box.empty() ? Bounds{origin, origin} : box;
        for (;;) {
            double cells = 1.0;
            for (int q = 0; q < 3; ++q) {
                m_lo[q] = floorCell(b.min[q], q) - pad;
                m_dims[q] = std::max<std::int64_t>(1, floorCell(b.max[q], q) + pad - m_lo[q] + 1);
                cells *= double(m_dims[q]);
            }
            if (cells <= double(kMaxCells))
                break;
            m_cell *= 1.25;
        }
        const auto count = static_cast<std::size_t>(m_dims[0] * m_dims[1] * m_dims[2]);
        m_start.assign(count + 1, 0);
        m_sorted.clear();
        m_head.assign(count, -1);
        m_tail.assign(count, -1);
        m_next.clear();
        m_ids.clear();
    }

    void insert(std::int32_t id, const Vec3& p) {
        const std::size_t c = cellOf(p);
        const auto item = static_cast<std::int32_t>(m_ids.size());
        m_ids.push_back(id);
        m_next.push_back(-1);
        if (m_tail[c] < 0)
            m_head[c] = item;
        else
            m_next[static_cast<std::size_t>(m_tail[c])] = item;
        m_tail[c] = item;
    }
    /// Inserts points[i] with the id i, in order.
    void insertAll(const std::vector<Vec3>& points) {
        if (size() != 0) {
            for (std::size_t i = 0; i < points.size(); ++i)
                insert(static_cast<std::int32_t>(i), points[i]);
            return;
        }
        std::vector<std::uint32_t> cells(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            cells[i] = static_cast<std::uint32_t>(cellOf(points[i]));
            ++m_start[cells[i] + 1];
        }
        for (std::size_t c = 0; c + 1 < m_start.size(); ++c)
            m_start[c + 1] += m_start[c];
        m_sorted.resize(points.size());
        std::vector<std::uint32_t> cursor(m_start.begin(), m_start.end() - 1);
        for (std::size_t i = 0; i < points.size(); ++i)
            m_sorted[cursor[cells[i]]++] = static_cast<std::int32_t>(i);
    }

    /// Calls fn(id) for every id in the cells overlapping the box of the ball of `radius` around p.
    template <class Fn>
    void forEachNear(const Vec3& p, double radius, Fn&& fn) const {
        visit(coord(p.x - radius, 0), coord(p.x + radius, 0), coord(p.y - radius, 1), coord(p.y + radius, 1),
              coord(p.z - radius, 2), coord(p.z + radius, 2), fn);
    }

    /// Calls fn(id) for every id in p's cell and the 26 around it: every point within one cell edge of p.
    template <class Fn>
    void forEachInCellsAround(const Vec3& p, Fn&& fn) const {
        const std::int64_t x = coord(p, 0), y = coord(p, 1), z = coord(p, 2);
        visit(std::max<std::int64_t>(x - 1, 0), std::min(x + 1, m_dims[0] - 1), std::max<std::int64_t>(y - 1, 0),
              std::min(y + 1, m_dims[1] - 1), std::max<std::int64_t>(z - 1, 0), std::min(z + 1, m_dims[2] - 1), fn);
    }

    /// The nearest of `points` (indexed by the inserted ids) within `radius`, -1 if none; ties go to the lower id.
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

    double cellSize() const { return m_cell; }
    std::size_t size() const { return m_sorted.size() + m_ids.size(); }

private:
    std::int64_t floorCell(double v, int q) const {
        const double c = std::floor((v - m_origin[q]) / m_cell);
        return std::isnan(c) ? 0 : static_cast<std::int64_t>(std::clamp(c, -1e15, 1e15));
    }
    /// The cell coordinate of v along axis q, clamped to the grid.
    std::int64_t coord(double v, int q) const {
        return std::clamp(floorCell(v, q) - m_lo[q], std::int64_t(0), m_dims[q] - 1);
    }
    std::int64_t coord(const Vec3& p, int q) const { return coord(p[q], q); }
    std::size_t cellOf(const Vec3& p) const { return cellIndex(coord(p, 0), coord(p, 1), coord(p, 2)); }
    std::size_t cellIndex(std::int64_t x, std::int64_t y, std::int64_t z) const {
        return static_cast<std::size_t>((z * m_dims[1] + y) * m_dims[0] + x);
    }
    template <class Fn>
    void visit(std::int64_t x0, std::int64_t x1, std::int64_t y0, std::int64_t y1, std::int64_t z0, std::int64_t z1,
               Fn& fn) const {
        for (std::int64_t z = z0; z <= z1; ++z)
            for (std::int64_t y = y0; y <= y1; ++y) {
                const std::size_t row = cellIndex(0, y, z);
                const std::uint32_t end = m_start[row + static_cast<std::size_t>(x1) + 1];
                for (std::uint32_t k = m_start[row + static_cast<std::size_t>(x0)]; k < end; ++k)
                    fn(m_sorted[k]);
                if (m_ids.empty())
                    continue;
                for (std::int64_t x = x0; x <= x1; ++x)
                    for (std::int32_t i = m_head[row + static_cast<std::size_t>(x)]; i >= 0;
                         i = m_next[static_cast<std::size_t>(i)])
                        fn(m_ids[static_cast<std::size_t>(i)]);
            }
    }

    Vec3 m_origin;
    double m_cell = 1.0;
    std::int64_t m_lo[3] = {0, 0, 0};
    std::int64_t m_dims[3] = {1, 1, 1};
    std::vector<std::uint32_t> m_start{0, 0};         // per cell + 1: the cell's range in m_sorted
    std::vector<std::int32_t> m_sorted;               // ids of a whole set inserted at once, by cell
    std::vector<std::int32_t> m_head{-1}, m_tail{-1}; // per cell: first and last item inserted one by one
    std::vector<std::int32_t> m_next;                 // per item: the next in its cell
    std::vector<std::int32_t> m_ids;                  // per item
};

} // namespace hs
