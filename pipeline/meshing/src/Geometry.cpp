#include "hs/meshing/Geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hs::meshing {
namespace {

constexpr double kRadToDeg = 57.295779513082320876798;

bool planeBoxOverlap(const Vec3& normal, const Vec3& vert, const Vec3& maxBox) {
    Vec3 vmin, vmax;
    for (int q = 0; q < 3; ++q) {
        const double v = vert[q];
        if (normal[q] > 0.0) {
            vmin[q] = -maxBox[q] - v;
            vmax[q] = maxBox[q] - v;
        } else {
            vmin[q] = maxBox[q] - v;
            vmax[q] = -maxBox[q] - v;
        }
    }
    if (dot(normal, vmin) > 0.0)
        return false;
    return dot(normal, vmax) >= 0.0;
}

/// Separation along axis = e x edge, for the three triangle vertices projected; true when separated.
bool separatedOnAxis(const Vec3& axis, const Vec3& v0, const Vec3& v1, const Vec3& v2, const Vec3& half) {
    const double p0 = dot(axis, v0), p1 = dot(axis, v1), p2 = dot(axis, v2);
    const double lo = std::min({p0, p1, p2});
    const double hi = std::max({p0, p1, p2});
    const double radius = half.x * std::fabs(axis.x) + half.y * std::fabs(axis.y) + half.z * std::fabs(axis.z);
    return lo > radius || hi < -radius;
}

} // namespace

bool triangleBoxOverlap(const Vec3& boxCenter, const Vec3& half, const Vec3& a, const Vec3& b, const Vec3& c) {
    // Move the box to the origin.
    const Vec3 v0 = a - boxCenter, v1 = b - boxCenter, v2 = c - boxCenter;
    const Vec3 e0 = v1 - v0, e1 = v2 - v1, e2 = v0 - v2;
    // 9 axes: cross products of the box axes with the triangle edges.
    const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const Vec3& edge : {e0, e1, e2})
        for (const Vec3& axis : axes)
            if (separatedOnAxis(cross(axis, edge), v0, v1, v2, half))
                return false;
    // 3 axes: the box face normals (the triangle's bounding box against the box).
    for (int q = 0; q < 3; ++q) {
        const double lo = std::min({v0[q], v1[q], v2[q]});
        const double hi = std::max({v0[q], v1[q], v2[q]});
        if (lo > half[q] || hi < -half[q])
            return false;
    }
    // 1 axis: the triangle normal.
    return planeBoxOverlap(cross(e0, e1), v0, half);
}

TetShape tetShape(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
    TetShape s;
    const Vec3 a = p1 - p0, b = p2 - p0, c = p3 - p0;
    const double det = dot(a, cross(b, c));
    s.volume = det / 6.0;
    // Edge lengths.
    const Vec3 edges[6] = {a, b, c, p2 - p1, p3 - p1, p3 - p2};
    double lmin2 = std::numeric_limits<double>::infinity(), lmax2 = 0.0;
    for (const Vec3& e : edges) {
        lmin2 = std::min(lmin2, norm2(e));
        lmax2 = std::max(lmax2, norm2(e));
    }
    s.edgeRatio = lmin2 > 0.0 ? std::sqrt(lmax2 / lmin2) : std::numeric_limits<double>::infinity();
    // Face area vectors, outward for a positive tet (faces opposite p0..p3).
    const Vec3 n0 = cross(p2 - p1, p3 - p1); // opposite p0
    const Vec3 n1 = cross(c, b);             // opposite p1: (p0, p3, p2)
    const Vec3 n2 = cross(a, c);             // opposite p2: (p0, p1, p3)
    const Vec3 n3 = cross(b, a);             // opposite p3: (p0, p2, p1)
    const Vec3 normals[4] = {n0, n1, n2, n3};
    double area2Sum = 0.0; // sum of 2 * face areas
    for (const Vec3& n : normals)
        area2Sum += norm(n);
    const double absDet = std::fabs(det);
    if (absDet <= 0.0 || area2Sum <= 0.0) {
        s.radiusRatio = 0.0;
        s.minDihedral = 0.0;
        s.maxDihedral = 180.0;
        return s;
    }
    // inradius = 3V / A = |det| / (sum of 2*areas); circumradius = |a^2 (b x c) + b^2 (c x a) + c^2 (a x b)| / 2|det|.
    const double inradius = absDet / area2Sum;
    const Vec3 circ = cross(b, c) * norm2(a) + cross(c, a) * norm2(b) + cross(a, b) * norm2(c);
    const double circumradius = norm(circ) / (2.0 * absDet);
    s.radiusRatio = 3.0 * inradius / circumradius;
    // Dihedral angle at the edge shared by faces i and j: pi - angle between their outward normals.
    const double sign = det > 0.0 ? 1.0 : -1.0;
    s.minDihedral = 180.0;
    s.maxDihedral = 0.0;
    for (int i = 0; i < 4; ++i) {
        for (int j = i + 1; j < 4; ++j) {
            const Vec3 ni = normalized(normals[i] * sign), nj = normalized(normals[j] * sign);
            const double cosine = std::clamp(-dot(ni, nj), -1.0, 1.0);
            const double angle = std::acos(cosine) * kRadToDeg;
            s.minDihedral = std::min(s.minDihedral, angle);
            s.maxDihedral = std::max(s.maxDihedral, angle);
        }
    }
    return s;
}

} // namespace hs::meshing
