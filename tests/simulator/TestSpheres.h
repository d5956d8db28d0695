#pragma once
// Latitude-longitude spheres for the view's tests (EndoscopicViewTest, ViewDecimationTest).

#include "hs/core/SurfaceMesh.h"

#include <cmath>
#include <cstdint>

namespace hs::simrender::test {

/// A sphere of radius 20 mm: one point at each pole and `rings` latitude rings of `segments` points, outward
/// triangles. With `seam`, each ring has one point more whose place is its first point's: the seam cut open as a
/// texture's seam is (the points along it duplicated); without, the sphere is closed.
inline SurfaceMesh latitudeSphere(int rings, int segments, bool seam) {
    constexpr double kPi = 3.14159265358979323846;
    const double radius = 20.0;
    const int perRing = seam ? segments + 1 : segments;
    SurfaceMesh mesh;
    mesh.points.push_back({0, 0, radius});
    for (int r = 1; r <= rings; ++r) {
        const double theta = kPi * r / (rings + 1);
        for (int s = 0; s < perRing; ++s) {
            const double phi = 2.0 * kPi * s / segments;
            mesh.points.push_back({radius * std::sin(theta) * std::cos(phi), radius * std::sin(theta) * std::sin(phi),
                                   radius * std::cos(theta)});
        }
    }
    mesh.points.push_back({0, 0, -radius});
    const auto at = [&](int r, int s) { return static_cast<std::int32_t>(1 + (r - 1) * perRing + s % perRing); };
    const auto south = static_cast<std::int32_t>(mesh.points.size() - 1);
    for (int s = 0; s < segments; ++s) {
        mesh.triangles.push_back({0, at(1, s), at(1, s + 1)});
        for (int r = 1; r < rings; ++r) {
            mesh.triangles.push_back({at(r, s), at(r + 1, s), at(r + 1, s + 1)});
            mesh.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r, s + 1)});
        }
        mesh.triangles.push_back({at(rings, s), south, at(rings, s + 1)});
    }
    return mesh;
}

} // namespace hs::simrender::test
