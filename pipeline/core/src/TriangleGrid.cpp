#include "hs/core/TriangleGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace hs {

namespace {

/// floor(x) clamped to 0..last, for any double: NaN and values beyond int64's range (a file's 1e300 coordinates,
/// whose areas overflow to infinity and cell sizes to NaN) are clamped before the cast, which would be undefined.
std::int64_t clampedCell(double x, std::int64_t last) {
    if (!(x > 0.0))
        return 0;
    if (x >= static_cast<double>(last))
        return last;
    return static_cast<std::int64_t>(std::floor(x));
}

} // namespace

TriangleGrid::TriangleGrid(const SurfaceMesh& mesh, double cellSize, bool insideTests) : m_mesh(&mesh) {
    const Bounds b = bounds(mesh);
    const Vec3 size = b.size();
    if (!(cellSize > 0.0)) {
        const double area = std::max(surfaceArea(mesh), 1e-30);
        cellSize = std::sqrt(4.0 * area / std::max<double>(1.0, double(mesh.triangles.size())));
    }
    // Keep the grid below ~ 8 cells per triangle (and 2^24 cells) whatever the cell size asked.
    const double maxCells = std::min(16777216.0, 8.0 * double(mesh.triangles.size()) + 64.0);
    while ((size.x / cellSize + 1) * (size.y / cellSize + 1) * (size.z / cellSize + 1) > maxCells)
        cellSize *= 1.25;
    m_cell = cellSize;
    m_origin = b.min;
    for (int q = 0; q < 3; ++q) {
        // Finite, the loop above bounds the cells; otherwise (infinite extent or cell size) one cell on that axis.
        const double cells = size[q] / cellSize;
        m_dims[q] = std::isfinite(cells) ? 1 + clampedCell(cells, std::int64_t{1} << 24) : 1;
    }
    const auto cellCount = static_cast<std::size_t>(m_dims[0] * m_dims[1] * m_dims[2]);

    auto cellRange = [&](const Triangle& t, std::int64_t lo[3], std::int64_t hi[3]) {
        for (int q = 0; q < 3; ++q) {
            double mn = 1e300, mx = -1e300;
            for (auto v : t) {
                mn = std::min(mn, mesh.points[static_cast<std::size_t>(v)][q]);
                mx = std::max(mx, mesh.points[static_cast<std::size_t>(v)][q]);
            }
            lo[q] = clampedCell((mn - m_origin[q]) / m_cell, m_dims[q] - 1);
            hi[q] = clampedCell((mx - m_origin[q]) / m_cell, m_dims[q] - 1);
        }
    };
    std::vector<std::uint32_t> counts(cellCount + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
        for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
            std::int64_t lo[3], hi[3];
            cellRange(mesh.triangles[f], lo, hi);
            for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
                for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
                    for (std::int64_t i = lo[0]; i <= hi[0]; ++i) {
                        const auto cell = static_cast<std::size_t>((k * m_dims[1] + j) * m_dims[0] + i);
                        if (pass == 0)
                            ++counts[cell + 1];
                        else
                            m_items[counts[cell]++] = static_cast<std::int32_t>(f);
                    }
        }
        if (pass == 0) {
            for (std::size_t c = 0; c < cellCount; ++c)
                counts[c + 1] += counts[c];
            m_start = counts;
            m_items.resize(counts[cellCount]);
        }
    }

    if (!insideTests)
        return;
    // Pseudo-normals: face normals, angle-weighted vertex normals, edge normals.
    const std::size_t nf = mesh.triangles.size();
    m_faceNormals.resize(nf);
    m_vertexNormals.assign(mesh.points.size(), Vec3{});
    m_edgeNormals.resize(nf);
    std::unordered_map<std::uint64_t, Vec3> edgeSum;
    edgeSum.reserve(nf * 2);
    for (std::size_t f = 0; f < nf; ++f) {
        const Triangle& t = mesh.triangles[f];
        const Vec3 n = faceNormal(mesh, f);
        m_faceNormals[f] = n;
        for (int k = 0; k < 3; ++k) {
            const auto v = static_cast<std::size_t>(t[static_cast<std::size_t>(k)]);
            const Vec3& p = mesh.points[v];
            const Vec3 e1 =
                normalized(mesh.points[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)])] - p);
            const Vec3 e2 =
                normalized(mesh.points[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 2) % 3)])] - p);
            const double angle = std::acos(std::clamp(dot(e1, e2), -1.0, 1.0));
            m_vertexNormals[v] += n * angle;
            edgeSum[edgeKey(t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)])] += n;
        }
    }
    for (std::size_t f = 0; f < nf; ++f) {
        const Triangle& t = mesh.triangles[f];
        for (int k = 0; k < 3; ++k)
            m_edgeNormals[f][static_cast<std::size_t>(k)] =
                edgeSum[edgeKey(t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)])];
    }
}

double TriangleGrid::boxDistance2(const Vec3& p) const {
    double outside2 = 0.0;
    for (int q = 0; q < 3; ++q) {
        const double lo = m_origin[q], hi = m_origin[q] + double(m_dims[q]) * m_cell;
        const double d = p[q] < lo ? lo - p[q] : (p[q] > hi ? p[q] - hi : 0.0);
        outside2 += d * d;
    }
    return outside2;
}

double TriangleGrid::distance(const Vec3& p, double cutoff) const {
    const SurfaceHit hit = closestWithin(p, cutoff * cutoff);
    return std::sqrt(hit.triangle >= 0 ? hit.closest.distance2 : cutoff * cutoff);
}

SurfaceHit TriangleGrid::closest(const Vec3& p) const {
    return closestWithin(p, std::numeric_limits<double>::infinity());
}

SurfaceHit TriangleGrid::closestWithin(const Vec3& p, double maxDistance2) const {
    SurfaceHit best;
    best.closest.distance2 = std::numeric_limits<double>::infinity();
    const SurfaceMesh& mesh = *m_mesh;
    // Distance from p to the grid box (p may lie outside it).
    const double outside2 = boxDistance2(p);
    if (!(outside2 < maxDistance2))
        return best;
    std::int64_t c[3];
    for (int q = 0; q < 3; ++q)
        c[q] = clampedCell((p[q] - m_origin[q]) / m_cell, m_dims[q] - 1);
    const std::int64_t maxRing = std::max({m_dims[0], m_dims[1], m_dims[2]});
    for (std::int64_t ring = 0; ring <= maxRing; ++ring) {
        // Every point in ring r+1 or further is at least r * cell away from p's cell boundary.
        if (ring > 0) {
            const double reach = double(ring - 1) * m_cell;
            const double lowerBound = reach * reach + outside2;
            if ((best.closest.distance2 < lowerBound && best.triangle >= 0) || !(lowerBound < maxDistance2))
                break;
        }
        for (std::int64_t k = c[2] - ring; k <= c[2] + ring; ++k) {
            if (k < 0 || k >= m_dims[2])
                continue;
            for (std::int64_t j = c[1] - ring; j <= c[1] + ring; ++j) {
                if (j < 0 || j >= m_dims[1])
                    continue;
                const bool jkShell = (k == c[2] - ring || k == c[2] + ring || j == c[1] - ring || j == c[1] + ring);
                for (std::int64_t i = c[0] - ring; i <= c[0] + ring;
                     i += (jkShell ? 1 : 2 * std::max<std::int64_t>(ring, 1))) {
                    if (i < 0 || i >= m_dims[0])
                        continue;
                    const auto cell = static_cast<std::size_t>((k * m_dims[1] + j) * m_dims[0] + i);
                    for (std::uint32_t it = m_start[cell]; it < m_start[cell + 1]; ++it) {
                        const std::int32_t f = m_items[it];
                        const Triangle& t = mesh.triangles[static_cast<std::size_t>(f)];
                        const ClosestPoint cp = closestPointOnTriangle(p, mesh.points[static_cast<std::size_t>(t[0])],
                                                                       mesh.points[static_cast<std::size_t>(t[1])],
                                                                       mesh.points[static_cast<std::size_t>(t[2])]);
                        if (cp.distance2 < best.closest.distance2 ||
                            (cp.distance2 == best.closest.distance2 && f < best.triangle)) {
                            best.closest = cp;
                            best.triangle = f;
                        }
                    }
                    if (ring == 0)
                        break;
                }
            }
        }
    }
    if (!(best.closest.distance2 < maxDistance2))
        return SurfaceHit{};
    return best;
}

bool TriangleGrid::insideFromHit(const Vec3& p, const SurfaceHit& hit) const {
    if (hit.triangle < 0)
        return false;
    const auto f = static_cast<std::size_t>(hit.triangle);
    const Triangle& t = m_mesh->triangles[f];
    Vec3 n;
    switch (hit.closest.feature) {
    case TriangleFeature::Face:
        n = m_faceNormals[f];
        break;
    case TriangleFeature::EdgeAB:
        n = m_edgeNormals[f][0];
        break;
    case TriangleFeature::EdgeBC:
        n = m_edgeNormals[f][1];
        break;
    case TriangleFeature::EdgeCA:
        n = m_edgeNormals[f][2];
        break;
    case TriangleFeature::VertexA:
        n = m_vertexNormals[static_cast<std::size_t>(t[0])];
        break;
    case TriangleFeature::VertexB:
        n = m_vertexNormals[static_cast<std::size_t>(t[1])];
        break;
    case TriangleFeature::VertexC:
        n = m_vertexNormals[static_cast<std::size_t>(t[2])];
        break;
    }
    return dot(p - hit.closest.point, n) < 0.0;
}

bool TriangleGrid::inside(const Vec3& p) const {
    return insideFromHit(p, closest(p));
}

} // namespace hs
