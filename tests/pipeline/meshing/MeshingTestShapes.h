#pragma once
// Analytic test shapes for the meshing tests.

#include "hs/core/RegionModel.h"
#include "hs/core/SurfaceMesh.h"

#include <cmath>
#include <map>
#include <utility>

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

} // namespace hs::test
