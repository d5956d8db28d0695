#pragma once
/// Loop subdivision of a triangle surface (Loop 1987, "Smooth subdivision surfaces based on triangles"): each level
/// splits every triangle into four at its edge midpoints and moves old and new points by Loop's masks, so the
/// surface converges to a smooth (C2 almost everywhere) limit while every triangle keeps its parent's shape.

#include "hs/core/SurfaceMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace hs {

/// Texture coordinates of one triangle corner.
using CornerUv = std::array<double, 2>;

/// One level of Loop subdivision. The children of face f are faces 4f .. 4f+3, with m_ab, m_bc, m_ca the new points
/// on the edges of f = (a, b, c):
///     4f = (a, m_ab, m_ca), 4f+1 = (m_ab, b, m_bc), 4f+2 = (m_ca, m_bc, c), 4f+3 = (m_ab, m_bc, m_ca),
/// so after L levels face i descends from face i >> 2L. Points 0..n-1 are the old points (moved), the edge points
/// follow in the order their edges first appear (faces in order, edges ab, bc, ca). Every face label is inherited;
/// vertex labels are dropped (an edge point has no value of its own). Edges with one face or more than two are
/// creases (the curve rule: 1/2 1/2 and 1/8 3/4 1/8); a point with other than two crease edges stays where it is.
SurfaceMesh loopSubdivide(const SurfaceMesh& mesh);
/// `levels` levels of loopSubdivide (0: a copy without vertex labels).
SurfaceMesh loopSubdivide(const SurfaceMesh& mesh, int levels);

/// Taubin's lambda|mu smoothing (Taubin 1995, "A signal processing approach to fair surface design"): each
/// iteration moves every selected point by lambda times the umbrella vector (mean of its neighbours minus itself),
/// then by mu (< -lambda) times the new one, which removes fins and spikes (high frequencies) without shrinking the
/// surface like plain Laplacian smoothing. Points of the faces where `faceMask` is nonzero move (all when empty); a
/// point never moves farther than `maxDisplacement` from where it started. Deterministic (sums in edge order).
struct TaubinParams {
    int iterations = 10;
    double lambda = 0.5;
    double mu = -0.53;
    double maxDisplacement = 1e300; ///< mm
    /// A move that would turn a face around the point over, or give it an angle below this (or below the one it
    /// had, if smaller), is not made: the fairing never makes needles or fold-overs.
    double minAngleDeg = 15.0;
};
SurfaceMesh taubinSmooth(const SurfaceMesh& mesh, const std::vector<std::int32_t>& faceMask,
                         const TaubinParams& params);

/// Per-corner data through one level of loopSubdivide: each child corner gets its parent corner's value or the
/// mean of two (linear along the parent face, so the children of a textured face keep the same texture).
std::vector<std::array<CornerUv, 3>> subdivideCorners(const std::vector<std::array<CornerUv, 3>>& corners);

/// The shape of a surface's triangles and of its normal field, over the faces where `mask` is nonzero (all faces
/// when the mask is empty). Edges are matched by their end points' positions, so a surface split along UV seams
/// has its seam edges measured too.
struct SurfaceShape {
    std::size_t faces = 0;
    double minAngleDeg = 0.0;           ///< smallest triangle angle
    double maxNormalDeviationDeg = 0.0; ///< largest angle between the normals of two faces sharing an edge
    double p99NormalDeviationDeg = 0.0; ///< 99th percentile of that angle over the edges
    double sharpEdgeFraction = 0.0;     ///< fraction of the edges whose faces turn by more than 30 degrees
    /// The largest turn across an edge where the surface is convex on the side its normals face (a ridge: a fin or a
    /// spike stands up as one), and where it is concave (a valley: a crease, a fold into a notch). Meaningful when
    /// the faces are consistently oriented.
    double maxRidgeDeg = 0.0;
    double maxValleyDeg = 0.0;
    double meanEdgeMm = 0.0;
    double maxEdgeMm = 0.0;
};
SurfaceShape measureSurfaceShape(const SurfaceMesh& mesh, const std::vector<std::int32_t>& mask = {});

} // namespace hs
