#pragma once
/// Closest points on triangles and rays through them: the one home of these tests for the pipeline (the mesher's
/// projection, the organ checks, the pathologies) and the simulator (contact, visibility, haptics).

#include "hs/core/Vec3.h"

namespace hs {

/// Which part of a triangle a closest point lies on (needed to pick the right pseudo-normal for inside tests).
enum class TriangleFeature { Face, EdgeAB, EdgeBC, EdgeCA, VertexA, VertexB, VertexC };

struct ClosestPoint {
    Vec3 point;           ///< closest point on the triangle, mm
    double distance2 = 0; ///< squared distance to the query point, mm^2
    TriangleFeature feature = TriangleFeature::Face;
    double wa = 1.0, wb = 0.0, wc = 0.0; ///< its barycentric coordinates (weights of a, b, c)
};

/// Closest point of triangle (a, b, c) to p (Ericson, "Real-Time Collision Detection", 5.1.5), with its feature.
ClosestPoint closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Ray-triangle intersection (Moller & Trumbore, "Fast, minimum storage ray-triangle intersection", 1997): true on a
/// hit with t > tMin along `dir`; `u` and `v` are the hit's barycentric coordinates of b and c.
bool rayTriangle(const Vec3& origin, const Vec3& dir, const Vec3& a, const Vec3& b, const Vec3& c, double tMin,
                 double& t, double& u, double& v);

} // namespace hs
