#pragma once
// Improvement of an extracted tet mesh (no longer Delaunay): vertex smoothing, flips and boundary flips that raise
// the smallest dihedral angle, after Klingner and Shewchuk, "Aggressive Tetrahedral Mesh Improvement" (2007).

#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/TetMesh.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace hs::meshing::detail {

/// How a vertex may move.
enum class VertexFreedom : std::uint8_t {
    Free = 0,    ///< inside its region: anywhere (treated as Fixed when it lies on the mesh boundary)
    Surface = 1, ///< on an input surface or interface: along it, re-projected by the callback
    Feature = 2, ///< on a feature edge: along it, re-projected by the callback
    Fixed = 3,   ///< corner, or no known constraint
};

struct MeshImproveParams {
    double targetDihedralDeg = 17.0;   ///< degrees; tets with a smaller smallest dihedral angle are worked on
    int passes = 8;                    ///< passes over the sorted worklist of bad tets
    int maxRing = 8;                   ///< largest number of tets around an edge that edge removal handles
    double coplanarDeg = 12.0;         ///< degrees; boundary faces are re-triangulated only when their normals
                                       ///< differ by less (keeps the surface and its features)
    int smoothingSteps = 6;            ///< ascent steps per vertex smoothing
    bool contractVertices = true;      ///< last resort: remove an inner vertex by contracting it onto a neighbour
    int radiusRatioSweeps = 0;         ///< afterwards, sweeps of smoothing inner vertices for the mean radius ratio
    double radiusRatioBelow = 0.85;    ///< those sweeps move vertices whose star has a tet of a smaller radius ratio
    bool radiusRatioOnSurfaces = true; ///< those sweeps also move surface and feature vertices along them
};

struct MeshImproveCallbacks {
    /// Moves a trial position of a Surface or Feature vertex onto its surface or feature edge.
    std::function<Vec3(std::uint32_t vertex, const Vec3& candidate)> project;
    /// Surface vertex: unit normal of its surface there; Feature vertex: unit direction of its feature edge.
    std::function<Vec3(std::uint32_t vertex)> constraintAxis;
    /// Called after a vertex was moved for good (lets the caller update its projection hints).
    std::function<void(std::uint32_t vertex, const Vec3& position)> moved;
};

struct MeshImproveStats {
    std::size_t badBefore = 0; ///< tets below the target before
    std::size_t badAfter = 0;
    double minDihedralBefore = 0.0; ///< degrees
    double minDihedralAfter = 0.0;
    std::size_t edgeRemovals = 0;     ///< interior edges removed (3-2, 4-4, n-m flips)
    std::size_t faceFlips = 0;        ///< 2-3 flips
    std::size_t boundaryFlips = 0;    ///< boundary edges removed (2-2 flips of the surface, peeling)
    std::size_t smoothedVertices = 0; ///< accepted vertex moves
    std::size_t contractions = 0;     ///< inner vertices removed by contracting them onto a neighbour
    std::size_t radiusRatioMoves = 0; ///< vertex moves of the radius-ratio sweeps
    int passes = 0;
};

/// Centre of the sphere through a, b, c, d (their centroid when they are coplanar).
Vec3 circumcentre(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
/// 3 * inradius / circumradius of tet (a, b, c, d): 1 when regular, 0 when flat or inverted.
double radiusRatio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Smallest dihedral angle of tet (a, b, c, d) in degrees; negative when it is inverted or flat.
double minDihedralDeg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Improves the tets of `tets` (positively oriented, one region id each in `regions`) whose smallest dihedral angle
/// is below params.targetDihedralDeg, in a sorted worklist, sequentially (deterministic): removal of their edges
/// (3-2, 4-4 and n-to-2(n-2) flips inside a region; at the boundary only between nearly coplanar boundary faces),
/// 2-3 flips of their faces, smoothing of their vertices (nonsmooth ascent of the star's worst angle) and, last,
/// contraction of an inner vertex onto a neighbour. An
/// operation is kept only when the worst angle of the tets it changes improves and nothing inverts. Faces between
/// regions (interfaces) and the outer boundary keep their vertices on their surfaces; corners stay fixed.
/// `points` are moved in place; `tets` and `regions` are replaced. Fails with Cancelled on request.
Result<MeshImproveStats> improveMesh(std::vector<Vec3>& points, std::vector<Tet>& tets,
                                     std::vector<std::int32_t>& regions, const std::vector<VertexFreedom>& freedom,
                                     const MeshImproveParams& params, const MeshImproveCallbacks& callbacks,
                                     Progress& progress);

} // namespace hs::meshing::detail
