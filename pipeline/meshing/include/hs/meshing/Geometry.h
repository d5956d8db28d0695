#pragma once
/// Geometric primitives of the mesher: exact triangle-box overlap and closest points on triangles.

#include "hs/core/TriangleGeometry.h"
#include "hs/core/Vec3.h"

#include <array>

namespace hs::meshing {

/// True when triangle (a, b, c) and the axis-aligned box (centre, half extents) share at least one point: the
/// separating-axis test of Akenine-Möller ("Fast 3D triangle-box overlap testing", JGT 2001), 13 axes.
bool triangleBoxOverlap(const Vec3& boxCenter, const Vec3& boxHalfSize, const Vec3& a, const Vec3& b, const Vec3& c);

// Closest points on triangles live in core (hs/core/TriangleGeometry.h), shared with the anatomy checks.
using hs::ClosestPoint;
using hs::closestPointOnTriangle;
using hs::TriangleFeature;

/// Quality measures of one tetrahedron. Angles in degrees.
struct TetShape {
    double volume = 0.0;      ///< signed, mm^3 (positive when dot(p1-p0, (p2-p0) x (p3-p0)) > 0)
    double radiusRatio = 0.0; ///< 3 * inradius / circumradius: 1 for the regular tetrahedron, 0 when flat
    double minDihedral = 0.0; ///< smallest of the six dihedral angles (70.53 for the regular tetrahedron)
    double maxDihedral = 0.0; ///< largest of the six
    double edgeRatio = 0.0;   ///< longest / shortest edge (>= 1; infinite for a zero-length edge)
};

TetShape tetShape(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3);

} // namespace hs::meshing
