#include "hs/core/TriangleGeometry.h"

namespace hs {

ClosestPoint closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    auto result = [&](const Vec3& q, TriangleFeature f) { return ClosestPoint{q, norm2(p - q), f}; };
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0)
        return result(a, TriangleFeature::VertexA);
    const Vec3 bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3)
        return result(b, TriangleFeature::VertexB);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        const double v = d1 / (d1 - d3);
        return result(a + ab * v, TriangleFeature::EdgeAB);
    }
    const Vec3 cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6)
        return result(c, TriangleFeature::VertexC);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        const double w = d2 / (d2 - d6);
        return result(a + ac * w, TriangleFeature::EdgeCA);
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return result(b + (c - b) * w, TriangleFeature::EdgeBC);
    }
    const double sum = va + vb + vc;
    if (!(sum > 0.0)) // degenerate triangle: fall back to the nearest vertex
        return result(a, TriangleFeature::VertexA);
    const double denom = 1.0 / sum;
    const double v = vb * denom, w = vc * denom;
    return result(a + ab * v + ac * w, TriangleFeature::Face);
}

} // namespace hs
