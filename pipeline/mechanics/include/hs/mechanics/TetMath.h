#pragma once
// Small 3x3 matrix helpers for the tissue's tets and the rotation of a deformation (its polar decomposition's R),
// shared by the solvers. Row-major std::array<double, 9>.

#include "hs/core/Vec3.h"

#include <array>
#include <cmath>

namespace hs::mechanics {

using Mat3 = std::array<double, 9>; // row-major

inline Vec3 column(const Mat3& m, int c) {
    return {m[static_cast<std::size_t>(c)], m[static_cast<std::size_t>(3 + c)], m[static_cast<std::size_t>(6 + c)]};
}

/// The shape matrix of points (columns p1 - p0, p2 - p0, p3 - p0).
inline Mat3 shapeMatrix(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
    const Vec3 a = p1 - p0, b = p2 - p0, c = p3 - p0;
    return {a.x, b.x, c.x, a.y, b.y, c.y, a.z, b.z, c.z};
}

inline Mat3 multiply(const Mat3& a, const Mat3& b) {
    Mat3 r{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            double s = 0.0;
            for (std::size_t k = 0; k < 3; ++k)
                s += a[3 * i + k] * b[3 * k + j];
            r[3 * i + j] = s;
        }
    return r;
}

/// a^T b.
inline Mat3 multiplyTransposed(const Mat3& a, const Mat3& b) {
    Mat3 r{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            double s = 0.0;
            for (std::size_t k = 0; k < 3; ++k)
                s += a[3 * k + i] * b[3 * k + j];
            r[3 * i + j] = s;
        }
    return r;
}

inline double determinant(const Mat3& m) {
    return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
}

inline bool invert(const Mat3& m, Mat3& out, double& det) {
    det = determinant(m);
    if (std::abs(det) < 1e-300)
        return false;
    const double i = 1.0 / det;
    out = {(m[4] * m[8] - m[5] * m[7]) * i, (m[2] * m[7] - m[1] * m[8]) * i, (m[1] * m[5] - m[2] * m[4]) * i,
           (m[5] * m[6] - m[3] * m[8]) * i, (m[0] * m[8] - m[2] * m[6]) * i, (m[2] * m[3] - m[0] * m[5]) * i,
           (m[3] * m[7] - m[4] * m[6]) * i, (m[1] * m[6] - m[0] * m[7]) * i, (m[0] * m[4] - m[1] * m[3]) * i};
    return true;
}

/// The rotation of `a` (its polar decomposition's R) by Muller et al.'s iteration ("A Robust Method to Extract the
/// Rotational Part of Deformations", MIG 2016), warm-started from the previous rotation `q` (w, x, y, z), which it
/// updates. Always a proper rotation, also for an inverted `a`.
inline Mat3 rotationOf(const Mat3& a, std::array<double, 4>& q, int iterations) {
    const auto toMatrix = [](const std::array<double, 4>& r) {
        const double w = r[0], x = r[1], y = r[2], z = r[3];
        return Mat3{1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                    2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                    2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
    };
    for (int it = 0; it < iterations; ++it) {
        const Mat3 r = toMatrix(q);
        const Vec3 r0 = column(r, 0), r1 = column(r, 1), r2 = column(r, 2);
        const Vec3 a0 = column(a, 0), a1 = column(a, 1), a2 = column(a, 2);
        const Vec3 omega = (cross(r0, a0) + cross(r1, a1) + cross(r2, a2)) *
                           (1.0 / (std::abs(dot(r0, a0) + dot(r1, a1) + dot(r2, a2)) + 1e-9));
        const double angle = norm(omega);
        if (angle < 1e-9)
            break;
        // The turn's quaternion; for the small turns of a warm start (1, omega / 2) normalized is accurate to
        // angle^3 and needs no trigonometry.
        std::array<double, 4> d{1.0, 0.5 * omega.x, 0.5 * omega.y, 0.5 * omega.z};
        if (angle > 0.3) {
            const Vec3 axis = omega / angle;
            const double s = std::sin(0.5 * angle);
            d = {std::cos(0.5 * angle), axis.x * s, axis.y * s, axis.z * s};
        }
        std::array<double, 4> n{d[0] * q[0] - d[1] * q[1] - d[2] * q[2] - d[3] * q[3],
                                d[0] * q[1] + d[1] * q[0] + d[2] * q[3] - d[3] * q[2],
                                d[0] * q[2] - d[1] * q[3] + d[2] * q[0] + d[3] * q[1],
                                d[0] * q[3] + d[1] * q[2] - d[2] * q[1] + d[3] * q[0]};
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] + n[3] * n[3]);
        for (double& v : n)
            v /= len;
        q = n;
    }
    return toMatrix(q);
}

} // namespace hs::mechanics
