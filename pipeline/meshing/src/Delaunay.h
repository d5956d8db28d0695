#pragma once
// Delaunay tetrahedralization of the particles and the local sliver repair that needs the triangulation (CGAL).
// The only file of hs_meshing that includes CGAL is Delaunay.cpp.

#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/TetMesh.h"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace hs::meshing::detail {

struct SliverRepairParams {
    double minDihedralDeg = 15.0; ///< tets below this are repaired
    double step = 1.0;            ///< mm, typical trial displacement of a vertex
    int rounds = 4;               ///< passes over the remaining bad tets
    int attempts = 8;             ///< trial positions per vertex
    std::uint64_t seed = 1;
};

struct SliverRepairCallbacks {
    /// Whether a tet with this centroid belongs to the mesh (only those are repaired and scored).
    std::function<bool(const Vec3& centroid)> kept;
    /// Whether a tet with these four point kinds can be kept without the (costly) centroid test.
    std::function<bool(const std::array<std::uint32_t, 4>& vertices)> surelyKept;
    /// Moves a trial position of `vertex` onto its constraint (surface, voxel); false when it may not go there.
    std::function<bool(std::uint32_t vertex, Vec3& candidate)> constrain;
};

struct DelaunayOutput {
    std::vector<Tet> tets;                               ///< finite cells, positively oriented
    std::vector<std::array<std::int64_t, 4>> neighbours; ///< across the face opposite vertex k; -1: hull
    std::size_t repairedTets = 0;                        ///< bad tets removed by vertex moves
    std::size_t movedVertices = 0;
};

/// Delaunay tetrahedralization of `points`; then, when `callbacks.constrain` is set, moves vertices of kept tets
/// whose smallest dihedral angle is below params.minDihedralDeg to seeded trial positions that raise the smallest
/// dihedral angle around them (a deterministic variant of sliver perturbation, Tournois et al. 2009). `points` is
/// updated with the moves. The triangulation is unique (symbolic perturbation), so the output depends only on the
/// input points and the seed.
Result<DelaunayOutput> delaunayTetrahedra(std::vector<Vec3>& points, const SliverRepairParams& params,
                                          const SliverRepairCallbacks& callbacks, Progress& progress);

} // namespace hs::meshing::detail
