#pragma once
/// Closest points on triangles (used by the mesher's projection and the organ checks).

#include "hs/core/Vec3.h"

namespace hs {

/// Which part of a triangle a closest point lies on (needed to pick the right pseudo-normal for inside tests).
enum class TriangleFeature { Face, EdgeAB, EdgeBC, EdgeCA, VertexA, VertexB, VertexC };

struct ClosestPoint {
    Vec3 point;           ///< closest point on the triangle, mm
    double distance2 = 0; ///< squared distance to the query point, mm^2
    TriangleFeature feature = TriangleFeature::Face;
};

/// Closest point of triangle (a, b, c) to p (Ericson, "Real-Time Collision Detection", 5.1.5), with its feature.
ClosestPoint closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

} // namespace hs
