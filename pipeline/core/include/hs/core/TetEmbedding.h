#pragma once
/// Points bound to a tetrahedral mesh by barycentric coordinates, so that they follow it when it deforms: a point p
/// embedded in tet (q0, q1, q2, q3) with weights w is sum_k w_k q_k, before and after the q move. The visual surface
/// of a scene is so bound to its tets (the simulator's mapping; SOFA's BarycentricMapping does the same).

#include "hs/core/TetMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace hs {

struct TetEmbedding {
    std::int32_t tet = -1;           ///< index into TetMesh::tets
    std::array<double, 4> weights{}; ///< barycentric, sum 1; all >= 0 inside the tet, some < 0 outside it
};

/// Barycentric coordinates of p in tet `tet` (zero weights for a flat tet).
std::array<double, 4> barycentricIn(const TetMesh& mesh, std::size_t tet, const Vec3& p);
/// The same for the tet (q0, q1, q2, q3), either orientation (all zero for a flat one).
std::array<double, 4> barycentric(const Vec3& q0, const Vec3& q1, const Vec3& q2, const Vec3& q3, const Vec3& p);

/// The point an embedding stands for in `mesh` (with the mesh's current points).
Vec3 embeddedPoint(const TetMesh& mesh, const TetEmbedding& e);

/// Embeds each point in the tet that contains it or, for a point outside the mesh (a visual surface runs just
/// inside and just outside the tets' boundary), in a boundary tet near it, with extrapolated weights. The search
/// starts at the tet of the nearest boundary face and walks towards the point (through the face opposite the most
/// negative weight) until a tet contains it or the walk reaches the boundary, and also tries every tet at that
/// face's corners; the tet kept is the one whose smallest weight is largest (the least extrapolated). Deterministic;
/// `threads` only splits the work. An empty mesh embeds nothing (every tet -1).
std::vector<TetEmbedding> embedPoints(const TetMesh& mesh, const std::vector<Vec3>& points, int threads = 1);

} // namespace hs
