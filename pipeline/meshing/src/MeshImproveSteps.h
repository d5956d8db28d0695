#pragma once
/// The mesh improver behind improveMesh (MeshImprove.h), shared by its sources: its driver and bookkeeping
/// (MeshImprove.cpp), edge removal, flips and vertex contraction (MeshImproveTopology.cpp) and vertex smoothing
/// (MeshImproveSmooth.cpp).

#include "MeshImprove.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace hs::meshing::detail {

/// Degrees per radian.
constexpr double kRadToDeg = 57.295779513082320876798;
/// An operation must raise the worst angle of the tets it changes by at least this (degrees): no cycling.
constexpr double kMinGainDeg = 1e-3;

/// Index of a tet in the improver's tet list (dead tets keep theirs).
using TetId = std::uint32_t;
/// No tet (across a boundary face, or none found).
constexpr TetId kNoTet = std::numeric_limits<TetId>::max();

/// Faces of a positive tet, oriented so that (face, opposite vertex) is an even permutation of the tet.
constexpr int kFace[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

/// Tets around an edge (a, b): tet i is (a, b, vertices[i], vertices[i + 1]) positively oriented (indices modulo
/// the ring size when closed). An open ring starts and ends at boundary faces.
struct EdgeRing {
    std::vector<std::int32_t> vertices;
    std::vector<TetId> tets;
    bool closed = false;
    std::int32_t region = 0;
};

/// The mesh being improved (its tets with region, quality and liveness, the tets around each vertex) and the
/// operations on it. Its members are defined by concern: MeshImprove.cpp (bookkeeping, the worklist driver),
/// MeshImproveTopology.cpp (edge removal, flips, contraction), MeshImproveSmooth.cpp (smoothing).
class Improver {
public:
    /// Takes over `tets` (positive) with their `regions`; `points` are moved in place by the operations.
    Improver(std::vector<Vec3>& points, const std::vector<Tet>& tets, const std::vector<std::int32_t>& regions,
             const std::vector<VertexFreedom>& freedom, const MeshImproveParams& params,
             const MeshImproveCallbacks& callbacks);

    /// The worklist passes over the bad tets, then the radius-ratio sweeps; fails with Cancelled on request.
    Result<MeshImproveStats> run(Progress& progress);

    /// The live tets and their regions.
    void output(std::vector<Tet>& tets, std::vector<std::int32_t>& regions) const;

private:
    // ---- mesh bookkeeping (MeshImprove.cpp) ----

    double quality(const Tet& t) const { return minDihedralDeg(point(t[0]), point(t[1]), point(t[2]), point(t[3])); }
    const Vec3& point(std::int32_t v) const { return m_points[static_cast<std::size_t>(v)]; }

    TetId addTet(const Tet& t, std::int32_t region);

    void killTet(TetId id);

    static bool contains(const Tet& t, std::int32_t v) { return std::find(t.begin(), t.end(), v) != t.end(); }

    bool edgeExists(std::int32_t a, std::int32_t b) const;

    /// The tet across face k of tet t (kNoTet at the boundary).
    TetId neighbourAcross(TetId t, int k) const;

    /// Whether v lies on a face without a neighbour of the same region (outer boundary or interface): the faces of
    /// its star through v, as the pairs of their other two vertices, must each come twice, from the same region.
    bool onBoundary(std::int32_t v);

    VertexFreedom freedomOf(std::int32_t v);

    double worstQuality() const;

    /// Bad tets by quality (worst first), then by their sorted vertices: a deterministic order.
    std::vector<std::pair<double, Tet>> worklist() const;

    TetId findTet(const Tet& sortedKey) const;

    // ---- operations ----

    /// Tries, in this order, until one succeeds: removal of each edge, 2-3 flip of each face, smoothing of the
    /// vertices (several may move), contraction of an inner vertex. Flips first: they are cheap and local, and
    /// Delaunay slivers are mostly fixed by a 3-2 or 4-4 flip.
    bool improveTet(TetId t);

    // ---- edge removal, flips, contraction (MeshImproveTopology.cpp) ----

    /// The ring of tets around edge (a, b); false when it is not a simple ring of one region or too long.
    bool edgeRing(std::int32_t a, std::int32_t b, EdgeRing& ring) const;

    /// Outward normal of face (a, b, c) of a tet whose fourth vertex is `inner`.
    Vec3 outwardNormal(std::int32_t a, std::int32_t b, std::int32_t c, std::int32_t inner) const;

    /// Removes edge (a, b): the polygon of its ring is re-triangulated for the best worst tet by dynamic programming
    /// (Klincsek; Shewchuk's edge removal), tets (a, triangle) and (b, reversed triangle). At the boundary the ring
    /// is open and the removal flips the two boundary faces at (a, b) when they are nearly coplanar (with one tet
    /// in the ring: the tet is peeled).
    bool removeEdge(std::int32_t a, std::int32_t b);

    /// The triangulation of polygon r (closed by the chord from its last to its first vertex) whose tets
    /// (a, triangle) and (b, reversed triangle) have the best worst angle, by dynamic programming over sub-polygons
    /// r_i..r_j (Klincsek 1980). Returns that angle (180 for a polygon of two vertices: no tets).
    double bestTriangulation(std::int32_t a, std::int32_t b, const std::vector<std::int32_t>& r,
                             std::vector<std::array<std::size_t, 3>>& triangles) const;

    /// An open ring may be re-triangulated when its two end faces are true boundary faces (no tet of another
    /// region behind them: interfaces stay as they are) and nearly coplanar, so the surface barely moves.
    bool boundaryRemovalAllowed(std::int32_t a, std::int32_t b, const EdgeRing& ring);

    /// 2-3 flip of face k of tet t with the tet behind it (same region): the three tets around the new edge.
    bool flip23(TetId t, int k);

    /// Removes inner vertex v by contracting it onto the neighbour w whose cone over v's link (the tets of v not
    /// containing w, with v replaced by w) has the best worst tet. The link, the boundary of the cavity, does not
    /// change, so when every new tet is positive they fill the cavity exactly.
    bool contractVertex(std::int32_t v);

    // ---- smoothing (MeshImproveSmooth.cpp) ----

    /// The points of tet t with vertex v moved to x.
    std::array<Vec3, 4> pointsWith(TetId t, std::int32_t v, const Vec3& x) const;
    /// Smallest dihedral angle (degrees) of tet t with vertex v moved to x.
    double qualityWith(TetId t, std::int32_t v, const Vec3& x) const;

    double starWorst(const std::vector<TetId>& star, std::int32_t v, const Vec3& x) const;

    Vec3 constrained(std::int32_t v, VertexFreedom f, const Vec3& x) const;

    /// Moves v to raise the worst smallest dihedral angle of its star: nonsmooth steepest ascent over the active
    /// tets (Freitag & Ollivier-Gooch; Klingner & Shewchuk), finite-difference gradients, halving line search.
    /// Surface and feature vertices move in their tangent space and are projected back.
    bool smoothVertex(std::int32_t v);

    /// The steepest direction raising every tet of the star within kActiveBandDeg of its worst (the point of the
    /// convex hull of their gradients closest to the origin), in the vertex's tangent space (a plane for Surface
    /// vertices with normal `axis`, the line `axis` for Feature vertices). Central differences of step h (mm).
    Vec3 ascentDirection(const std::vector<TetId>& star, std::int32_t v, const Vec3& x, double h, VertexFreedom f,
                         const Vec3& axis) const;

    // ---- mean quality ----

    double radiusRatioWith(TetId t, std::int32_t v, const Vec3& x) const;

    /// One sweep in vertex order over the vertices that may move (inner ones freely, surface and feature ones along
    /// their constraint) and whose star has a tet of radius ratio below params.radiusRatioBelow: each is moved
    /// towards its optimal-Delaunay point (the volume-weighted mean of its star's circumcentres, Chen & Xu 2004;
    /// Alliez et al. 2005), all or half the way, or to the centroid of its neighbours, whichever raises the sum of
    /// the star's radius ratios most while keeping its smallest dihedral angle at least min(before, target). The
    /// worst-angle passes above fix the slivers; this raises the many fair tets of the boundary layer, which dominate
    /// the mean on thin bodies. Returns the number of moved vertices.
    std::size_t smoothRadiusRatioSweep();

    std::vector<Vec3>& m_points;
    const std::vector<VertexFreedom>& m_freedom;
    const MeshImproveParams& m_params;
    const MeshImproveCallbacks& m_cb;
    std::vector<Tet> m_tets;
    std::vector<std::int32_t> m_region;
    std::vector<std::uint8_t> m_alive;
    std::vector<double> m_quality;
    std::vector<std::vector<TetId>> m_vertexTets;
    std::vector<std::int8_t> m_boundary; ///< per vertex: -1 unknown, 0 inside, 1 on a boundary or interface face
    std::vector<std::array<std::int32_t, 3>> m_faceScratch; ///< onBoundary: faces through the vertex
    MeshImproveStats m_stats;
};

} // namespace hs::meshing::detail
