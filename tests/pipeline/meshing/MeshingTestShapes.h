#pragma once
// Analytic test shapes for the meshing tests and bench_meshing (bench/meshing uses the thin plate and the hollow
// shell below, so that the bench and the tests mesh the same shapes).

#include "hs/core/RegionModel.h"
#include "hs/core/SurfaceMesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace hs::test {

/// Icosphere of `radius` around `center`, `levels` subdivisions (level 3: 642 vertices), outward oriented.
inline SurfaceMesh icosphere(double radius, int levels, const Vec3& center = {}) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    SurfaceMesh m;
    m.points = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    m.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                   {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                   {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (auto& p : m.points)
        p = normalized(p);
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<int, int>, int> mid;
        auto midpoint = [&](int a, int b) {
            const auto key = std::make_pair(std::min(a, b), std::max(a, b));
            auto it = mid.find(key);
            if (it != mid.end())
                return it->second;
            m.points.push_back(normalized(m.points[std::size_t(a)] + m.points[std::size_t(b)]));
            const int idx = int(m.points.size()) - 1;
            mid[key] = idx;
            return idx;
        };
        std::vector<Triangle> next;
        for (const auto& tri : m.triangles) {
            const int a = midpoint(tri[0], tri[1]), b = midpoint(tri[1], tri[2]), c = midpoint(tri[2], tri[0]);
            next.push_back({tri[0], a, c});
            next.push_back({tri[1], b, a});
            next.push_back({tri[2], c, b});
            next.push_back({a, b, c});
        }
        m.triangles = next;
    }
    for (auto& p : m.points)
        p = center + p * radius;
    return m;
}

/// Axis-aligned box [lo, hi], 12 outward triangles.
inline SurfaceMesh box(const Vec3& lo, const Vec3& hi) {
    SurfaceMesh m;
    for (int i = 0; i < 8; ++i)
        m.points.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
    m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                   {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    return m;
}

namespace detail {

/// Triangles between two closed rings of vertex indices, each ordered by increasing angle from the +x axis
/// (`inner` may be a single vertex, the centre), facing +z when `up`: a zipper that always advances on the ring
/// whose next vertex has the smaller angle.
inline void zipRings(const std::vector<std::int32_t>& inner, const std::vector<double>& innerAngle,
                     const std::vector<std::int32_t>& outer, const std::vector<double>& outerAngle, bool up,
                     std::vector<Triangle>& out) {
    const std::size_t n = inner.size(), m = outer.size();
    auto push = [&](std::int32_t a, std::int32_t b, std::int32_t c) {
        out.push_back(up ? Triangle{a, b, c} : Triangle{a, c, b});
    };
    const double twoPi = 2.0 * 3.14159265358979323846;
    std::size_t i = 0, j = 0;
    while (i < n || j < m) {
        const double nextInner = i < n ? innerAngle[(i + 1) % n] + (i + 1 >= n ? twoPi : 0.0) : 1e300;
        const double nextOuter = j < m ? outerAngle[(j + 1) % m] + (j + 1 >= m ? twoPi : 0.0) : 1e300;
        if (n > 1 && nextInner <= nextOuter) {
            push(inner[i % n], outer[j % m], inner[(i + 1) % n]);
            ++i;
        } else {
            push(inner[i % n], outer[j % m], outer[(j + 1) % m]);
            ++j;
            if (n == 1 && j == m)
                i = n;
        }
    }
}

} // namespace detail

/// Thin plate: a flat disc (cylinder) of `diameter` and `thickness` (mm) around the origin, axis z, with a sharp
/// rim (two circular feature edges of 90 degrees). Triangles of about `edge` mm: concentric rings on the two faces,
/// a band of rings on the rim. Outward oriented.
inline SurfaceMesh thinDisc(double diameter = 40.0, double thickness = 3.0, double edge = 0.6) {
    const double pi = 3.14159265358979323846, radius = 0.5 * diameter;
    const int rings = std::max(1, int(std::lround(radius / edge)));
    const int rimCount = std::max(6, int(std::lround(2.0 * pi * radius / edge)));
    const int bands = std::max(1, int(std::lround(thickness / edge)));
    SurfaceMesh m;
    auto ring = [&](double r, int count, double z, double phase, std::vector<std::int32_t>& ids,
                    std::vector<double>& angles) {
        for (int k = 0; k < count; ++k) {
            const double a = phase + 2.0 * pi * k / count;
            ids.push_back(std::int32_t(m.points.size()));
            angles.push_back(a);
            m.points.push_back({r * std::cos(a), r * std::sin(a), z});
        }
    };
    // The rim: bands + 1 rings of rimCount vertices from the bottom face to the top face.
    std::vector<std::vector<std::int32_t>> rim(std::size_t(bands) + 1);
    std::vector<double> rimAngle;
    for (int b = 0; b <= bands; ++b) {
        std::vector<double> angles;
        ring(radius, rimCount, -0.5 * thickness + thickness * b / bands, 0.0, rim[std::size_t(b)], angles);
        rimAngle = angles;
    }
    for (int b = 0; b < bands; ++b)
        for (int k = 0; k < rimCount; ++k) {
            const auto& lo = rim[std::size_t(b)];
            const auto& hi = rim[std::size_t(b) + 1];
            const std::int32_t a = lo[std::size_t(k)], bq = lo[std::size_t((k + 1) % rimCount)],
                               c = hi[std::size_t((k + 1) % rimCount)], d = hi[std::size_t(k)];
            m.triangles.push_back({a, bq, c});
            m.triangles.push_back({a, c, d});
        }
    // The faces: rings inward from the rim to the centre vertex, every other ring turned by half a step.
    for (int side = 0; side < 2; ++side) {
        const bool up = side == 1;
        const double z = up ? 0.5 * thickness : -0.5 * thickness;
        std::vector<std::int32_t> outer = up ? rim.back() : rim.front();
        std::vector<double> outerAngle = rimAngle;
        for (int k = rings - 1; k >= 0; --k) {
            std::vector<std::int32_t> ids;
            std::vector<double> angles;
            if (k == 0) {
                ids.push_back(std::int32_t(m.points.size()));
                angles.push_back(0.0);
                m.points.push_back({0.0, 0.0, z});
            } else {
                const double r = radius * k / rings;
                const int count = std::max(6, int(std::lround(2.0 * pi * r / edge)));
                ring(r, count, z, (rings - k) % 2 == 1 ? pi / count : 0.0, ids, angles);
            }
            detail::zipRings(ids, angles, outer, outerAngle, up, m.triangles);
            outer = std::move(ids);
            outerAngle = std::move(angles);
        }
    }
    return m;
}

/// Hollow body: a closed ellipsoidal shell, one surface of two components as a hollow organ comes to the mesher
/// (the uterus wall is one surface bounding both the outside and the cavity): the outer ellipsoid with semi-axes
/// `outer` (outward) and an inner one with each semi-axis `wall` mm shorter (inward, so it bounds the cavity).
/// Icosphere triangulations with `levels` subdivisions (5: 20480 triangles each).
inline SurfaceMesh hollowEllipsoid(const Vec3& outer = {30.0, 22.0, 18.0}, double wall = 4.0, int levels = 5) {
    SurfaceMesh shell = icosphere(1.0, levels);
    SurfaceMesh cavity = shell;
    for (auto& p : shell.points)
        p = {p.x * outer.x, p.y * outer.y, p.z * outer.z};
    for (auto& p : cavity.points)
        p = {p.x * (outer.x - wall), p.y * (outer.y - wall), p.z * (outer.z - wall)};
    const auto offset = static_cast<std::int32_t>(shell.points.size());
    shell.points.insert(shell.points.end(), cavity.points.begin(), cavity.points.end());
    for (const Triangle& t : cavity.triangles)
        shell.triangles.push_back({t[0] + offset, t[2] + offset, t[1] + offset});
    return shell;
}

} // namespace hs::test
