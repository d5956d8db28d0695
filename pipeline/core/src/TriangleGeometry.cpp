#include "hs/core/TriangleGeometry.h"

#include <cmath>

namespace hs {

ClosestPoint closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    auto result = [&](const Vec3& q, TriangleFeature f, double wb = 0.0, double wc = 0.0) {
        return ClosestPoint{q, norm2(p - q), f, 1.0 - wb - wc, wb, wc};
    };
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0)
        return result(a, TriangleFeature::VertexA);
    const Vec3 bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3)
        return result(b, TriangleFeature::VertexB, 1.0);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        const double v = d1 / (d1 - d3);
        return result(a + ab * v, TriangleFeature::EdgeAB, v);
    }
    const Vec3 cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6)
        return result(c, TriangleFeature::VertexC, 0.0, 1.0);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        const double w = d2 / (d2 - d6);
        return result(a + ac * w, TriangleFeature::EdgeCA, 0.0, w);
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return result(b + (c - b) * w, TriangleFeature::EdgeBC, 1.0 - w, w);
    }
    const double sum = va + vb + vc;
    if (!(sum > 0.0)) // degenerate triangle: fall back to the nearest vertex
        return result(a, TriangleFeature::VertexA);
    const double denom = 1.0 / sum;
    const double v = vb * denom, w = vc * denom;
    return result(a + ab * v + ac * w, TriangleFeature::Face, v, w);
}

bool rayTriangle(const Vec3& origin, const Vec3& dir, const Vec3& a, const Vec3& b, const Vec3& c, double tMin,
                 double& t, double& u, double& v) {
    const Vec3 e1 = b - a, e2 = c - a;
    const Vec3 p = cross(dir, e2);
    const double det = dot(e1, p);
    if (std::fabs(det) < 1e-14)
        return false;
    const double inv = 1.0 / det;
    const Vec3 s = origin - a;
    u = dot(s, p) * inv;
    if (u < 0.0 || u > 1.0)
        return false;
    const Vec3 q = cross(s, e1);
    v = dot(dir, q) * inv;
    if (v < 0.0 || u + v > 1.0)
        return false;
    t = dot(e2, q) * inv;
    return t > tMin;
}

} // namespace hs
