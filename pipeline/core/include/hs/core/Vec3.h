#pragma once
/// A small 3-D vector of doubles (millimetres wherever it is a position).

#include <cmath>
#include <vector>

namespace hs {

struct Vec3 {
    double x = 0.0, y = 0.0, z = 0.0;

    constexpr Vec3() = default;
    constexpr Vec3(double xv, double yv, double zv) : x(xv), y(yv), z(zv) {}

    constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
    Vec3& operator+=(const Vec3& o) {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
    Vec3& operator-=(const Vec3& o) {
        x -= o.x;
        y -= o.y;
        z -= o.z;
        return *this;
    }
    Vec3& operator*=(double s) {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    constexpr bool operator==(const Vec3& o) const { return x == o.x && y == o.y && z == o.z; }
    constexpr bool operator!=(const Vec3& o) const { return !(*this == o); }
};

constexpr Vec3 operator*(double s, const Vec3& v) {
    return v * s;
}
constexpr double dot(const Vec3& a, const Vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(const Vec3& v) {
    return std::sqrt(dot(v, v));
}
constexpr double norm2(const Vec3& v) {
    return dot(v, v);
}
inline double distance(const Vec3& a, const Vec3& b) {
    return norm(a - b);
}
/// v / |v|, or the zero vector for a zero-length v.
inline Vec3 normalized(const Vec3& v) {
    const double n = norm(v);
    return n > 0.0 ? v / n : Vec3{};
}
inline bool isFinite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
/// `v` turned by `angleRad` about the unit `axis` (Rodrigues' formula).
inline Vec3 rotatedAbout(const Vec3& v, const Vec3& axis, double angleRad) {
    const double c = std::cos(angleRad);
    const double s = std::sin(angleRad);
    return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1.0 - c));
}
/// A unit vector perpendicular to the unit `axis`, as close to `hint` as possible (another direction when the hint
/// lies along the axis).
inline Vec3 perpendicularTo(const Vec3& axis, const Vec3& hint) {
    Vec3 p = hint - axis * dot(hint, axis);
    if (norm(p) < 1e-6)
        p = Vec3{1.0, 0.0, 0.0} - axis * axis.x;
    if (norm(p) < 1e-6)
        p = Vec3{0.0, 0.0, 1.0} - axis * axis.z;
    return normalized(p);
}

/// Axis-aligned box; empty (min > max) until a point is added.
struct Bounds {
    Vec3 min{1e300, 1e300, 1e300};
    Vec3 max{-1e300, -1e300, -1e300};

    bool empty() const { return min.x > max.x; }
    void add(const Vec3& p) {
        min = {std::fmin(min.x, p.x), std::fmin(min.y, p.y), std::fmin(min.z, p.z)};
        max = {std::fmax(max.x, p.x), std::fmax(max.y, p.y), std::fmax(max.z, p.z)};
    }
    Vec3 size() const { return empty() ? Vec3{} : max - min; }
    Vec3 center() const { return (min + max) * 0.5; }
    double diagonal() const { return norm(size()); }
};

/// The mean of `points` (the zero vector for none): the one home of this helper.
inline Vec3 centroid(const std::vector<Vec3>& points) {
    Vec3 c;
    for (const Vec3& p : points)
        c += p;
    return points.empty() ? c : c / static_cast<double>(points.size());
}

} // namespace hs
