#pragma once
/// A uniform grid over the triangles of one surface, for closest-point queries (projection, distances, inside tests,
/// Hausdorff distances, label transfer). Searches are exact: the closest triangle, ties to the lowest index.

#include "hs/core/SurfaceMesh.h"
#include "hs/core/TriangleGeometry.h"

#include <array>
#include <cstdint>
#include <vector>

namespace hs {

struct SurfaceHit {
    std::int32_t triangle = -1;
    ClosestPoint closest;
};

class TriangleGrid {
public:
    /// cellSize <= 0 picks about 4 triangles per occupied cell. `insideTests`: also the pseudo-normals that
    /// inside() and insideFromHit() need.
    explicit TriangleGrid(const SurfaceMesh& mesh, double cellSize = 0.0, bool insideTests = true);

    /// The closest triangle to p (exact: rings are searched until no cell can hold a closer point).
    SurfaceHit closest(const Vec3& p) const;
    /// The closest triangle to p if it lies closer than sqrt(maxDistance2), else no hit (triangle -1). Cells that
    /// cannot hold a closer point are not searched, so a far-away grid costs one box test.
    SurfaceHit closestWithin(const Vec3& p, double maxDistance2) const;
    /// Unsigned distance from p to the surface, capped at `cutoff` (sqrt(cutoff^2) when nothing is closer).
    double distance(const Vec3& p, double cutoff) const;
    /// Squared distance from p to the grid's box (0 inside): a lower bound of every distance to the surface.
    double boxDistance2(const Vec3& p) const;
    /// Signed distance-side test (needs insideTests) with angle-weighted pseudo-normals (Baerentzen & Aanaes 2005):
    /// true when p lies inside the outward-oriented closed surface.
    bool inside(const Vec3& p) const;
    /// Sign test of p against an already known closest point on `triangle`.
    bool insideFromHit(const Vec3& p, const SurfaceHit& hit) const;

    const SurfaceMesh& mesh() const { return *m_mesh; }

private:
    const SurfaceMesh* m_mesh;
    Vec3 m_origin;
    double m_cell = 1.0;
    std::int64_t m_dims[3] = {1, 1, 1};
    std::vector<std::uint32_t> m_start; // CSR: cell -> range in m_items
    std::vector<std::int32_t> m_items;
    // Pseudo-normals.
    std::vector<Vec3> m_faceNormals;
    std::vector<Vec3> m_vertexNormals;              // angle-weighted
    std::vector<std::array<Vec3, 3>> m_edgeNormals; // per face edge (ab, bc, ca): sum of the two face normals
};

} // namespace hs
