#include "hs/core/LabelTransfer.h"

#include "hs/core/TriangleGeometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace hs {
namespace {

/// Triangles of a surface hashed into cubic cells by their bounding boxes.
class TriangleGrid {
public:
    TriangleGrid(const SurfaceMesh& mesh, double cell) : m_mesh(mesh), m_cell(cell) {
        for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
            Bounds b;
            for (auto v : mesh.triangles[f])
                b.add(mesh.points[static_cast<std::size_t>(v)]);
            const auto lo = cellOf(b.min), hi = cellOf(b.max);
            for (auto i = lo[0]; i <= hi[0]; ++i)
                for (auto j = lo[1]; j <= hi[1]; ++j)
                    for (auto k = lo[2]; k <= hi[2]; ++k)
                        m_cells[key(i, j, k)].push_back(f);
        }
    }

    /// Nearest face to p within `maxDistance`, or -1.
    std::int64_t nearest(const Vec3& p, double maxDistance) const {
        const auto c = cellOf(p);
        const auto rings = static_cast<std::int64_t>(std::ceil(maxDistance / m_cell)) + 1;
        double best = maxDistance * maxDistance;
        std::int64_t bestFace = -1;
        for (std::int64_t r = 0; r <= rings; ++r) {
            // Everything in ring r is at least (r - 1) cells away: stop once that exceeds the best distance.
            const double ringDistance = static_cast<double>(std::max<std::int64_t>(r - 1, 0)) * m_cell;
            if (bestFace >= 0 && ringDistance * ringDistance > best)
                break;
            for (auto i = c[0] - r; i <= c[0] + r; ++i)
                for (auto j = c[1] - r; j <= c[1] + r; ++j)
                    for (auto k = c[2] - r; k <= c[2] + r; ++k) {
                        if (std::max({std::abs(i - c[0]), std::abs(j - c[1]), std::abs(k - c[2])}) != r)
                            continue; // only the shell of ring r
                        const auto it = m_cells.find(key(i, j, k));
                        if (it == m_cells.end())
                            continue;
                        for (auto f : it->second) {
                            const auto& t = m_mesh.triangles[f];
                            const auto cp = closestPointOnTriangle(p, m_mesh.points[static_cast<std::size_t>(t[0])],
                                                                   m_mesh.points[static_cast<std::size_t>(t[1])],
                                                                   m_mesh.points[static_cast<std::size_t>(t[2])]);
                            const auto face = static_cast<std::int64_t>(f);
                            if (cp.distance2 < best || (cp.distance2 == best && face < bestFace)) {
                                best = cp.distance2;
                                bestFace = face;
                            }
                        }
                    }
        }
        return bestFace;
    }

private:
    std::array<std::int64_t, 3> cellOf(const Vec3& p) const {
        return {static_cast<std::int64_t>(std::floor(p.x / m_cell)),
                static_cast<std::int64_t>(std::floor(p.y / m_cell)),
                static_cast<std::int64_t>(std::floor(p.z / m_cell))};
    }
    static std::uint64_t key(std::int64_t i, std::int64_t j, std::int64_t k) {
        return (static_cast<std::uint64_t>(i & 0x1FFFFF) << 42) | (static_cast<std::uint64_t>(j & 0x1FFFFF) << 21) |
               static_cast<std::uint64_t>(k & 0x1FFFFF);
    }

    const SurfaceMesh& m_mesh;
    double m_cell;
    std::unordered_map<std::uint64_t, std::vector<std::size_t>> m_cells;
};

double meanEdgeLength(const SurfaceMesh& mesh) {
    double sum = 0.0;
    for (const auto& t : mesh.triangles)
        for (int e = 0; e < 3; ++e)
            sum += distance(mesh.points[static_cast<std::size_t>(t[static_cast<std::size_t>(e)])],
                            mesh.points[static_cast<std::size_t>(t[static_cast<std::size_t>((e + 1) % 3)])]);
    return mesh.triangles.empty() ? 1.0 : sum / (3.0 * static_cast<double>(mesh.triangles.size()));
}

} // namespace

Status transferFaceLabels(const SurfaceMesh& from, SurfaceMesh& to, const std::vector<std::string>& names,
                          double maxDistanceMm, std::int32_t fallback) {
    HS_TRY(validate(from));
    HS_TRY(validate(to));
    if (!(maxDistanceMm > 0.0) || !std::isfinite(maxDistanceMm))
        return fail(ErrorCode::InvalidInput, "label transfer distance must be a finite positive length in mm");
    std::vector<const std::vector<std::int32_t>*> sources;
    for (const auto& name : names) {
        const auto it = from.faceLabels.find(name);
        if (it == from.faceLabels.end() || it->second.size() != from.triangles.size())
            return fail(ErrorCode::InvalidInput, "the source surface has no face label '" + name + "'");
        sources.push_back(&it->second);
    }
    const TriangleGrid grid(from, std::max(meanEdgeLength(from), 1e-6));
    std::vector<std::vector<std::int32_t>> values(names.size(),
                                                  std::vector<std::int32_t>(to.triangles.size(), fallback));
    for (std::size_t f = 0; f < to.triangles.size(); ++f) {
        const auto& t = to.triangles[f];
        const Vec3 centroid = (to.points[static_cast<std::size_t>(t[0])] + to.points[static_cast<std::size_t>(t[1])] +
                               to.points[static_cast<std::size_t>(t[2])]) /
                              3.0;
        const auto source = grid.nearest(centroid, maxDistanceMm);
        if (source < 0)
            continue;
        for (std::size_t n = 0; n < names.size(); ++n)
            values[n][f] = (*sources[n])[static_cast<std::size_t>(source)];
    }
    for (std::size_t n = 0; n < names.size(); ++n)
        to.faceLabels[names[n]] = std::move(values[n]);
    return {};
}

} // namespace hs
