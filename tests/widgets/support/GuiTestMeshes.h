#pragma once
/// Small meshes and image checks shared by the widget and GUI tests. Meshes are generated, not random.

#include "hs/core/SurfaceMesh.h"
#include "hs/core/TetMesh.h"

#include <QColor>
#include <QImage>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <utility>

namespace hs::test {

/// A UV sphere of `radius` mm at the origin, outward-oriented, `rings` x `segments` quads (poles as fans).
inline SurfaceMesh makeSphere(double radius = 10.0, int rings = 24, int segments = 48) {
    constexpr double kPi = 3.14159265358979323846;
    SurfaceMesh mesh;
    mesh.points.push_back({0.0, 0.0, radius});
    for (int r = 1; r < rings; ++r) {
        const double theta = kPi * r / rings;
        for (int s = 0; s < segments; ++s) {
            const double phi = 2.0 * kPi * s / segments;
            mesh.points.push_back({radius * std::sin(theta) * std::cos(phi), radius * std::sin(theta) * std::sin(phi),
                                   radius * std::cos(theta)});
        }
    }
    mesh.points.push_back({0.0, 0.0, -radius});
    const auto south = static_cast<std::int32_t>(mesh.points.size() - 1);
    auto ringPoint = [segments](int ring, int s) {
        return static_cast<std::int32_t>(1 + (ring - 1) * segments + (s % segments));
    };
    for (int s = 0; s < segments; ++s)
        mesh.triangles.push_back({0, ringPoint(1, s), ringPoint(1, s + 1)});
    for (int r = 1; r + 1 < rings; ++r) {
        for (int s = 0; s < segments; ++s) {
            mesh.triangles.push_back({ringPoint(r, s), ringPoint(r + 1, s), ringPoint(r + 1, s + 1)});
            mesh.triangles.push_back({ringPoint(r, s), ringPoint(r + 1, s + 1), ringPoint(r, s + 1)});
        }
    }
    for (int s = 0; s < segments; ++s)
        mesh.triangles.push_back({ringPoint(rings - 1, s), south, ringPoint(rings - 1, s + 1)});
    // Region label: northern half 0, southern half 1.
    std::vector<std::int32_t> regions;
    for (const Triangle& t : mesh.triangles)
        regions.push_back(mesh.points[static_cast<std::size_t>(t[0])].z +
                                      mesh.points[static_cast<std::size_t>(t[1])].z +
                                      mesh.points[static_cast<std::size_t>(t[2])].z >=
                                  0.0
                              ? 0
                              : 1);
    mesh.faceLabels["region"] = regions;
    return mesh;
}

/// A cube of side `size` mm centred at the origin, cut into n^3 cells of 6 tetrahedra each (Kuhn subdivision);
/// tets with x > 0 are region 1, the others region 0.
inline TetMesh makeTetCube(int n = 4, double size = 20.0) {
    TetMesh mesh;
    const double h = size / n;
    auto index = [n](int i, int j, int k) { return static_cast<std::int32_t>((k * (n + 1) + j) * (n + 1) + i); };
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i)
                mesh.points.push_back({-size / 2 + i * h, -size / 2 + j * h, -size / 2 + k * h});
    // The six paths from corner 000 to 111 along the axes, one tetrahedron each.
    constexpr std::array<std::array<int, 3>, 6> kAxisOrders{
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    for (int k = 0; k < n; ++k) {
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                for (const auto& order : kAxisOrders) {
                    std::array<int, 3> c{i, j, k};
                    Tet tet{};
                    tet[0] = index(c[0], c[1], c[2]);
                    for (int step = 0; step < 3; ++step) {
                        ++c[static_cast<std::size_t>(order[static_cast<std::size_t>(step)])];
                        tet[static_cast<std::size_t>(step + 1)] = index(c[0], c[1], c[2]);
                    }
                    mesh.tets.push_back(tet);
                    if (signedVolume(mesh, mesh.tets.size() - 1) < 0.0)
                        std::swap(mesh.tets.back()[2], mesh.tets.back()[3]);
                    mesh.regions.push_back(2 * i + 1 > n ? 1 : 0);
                }
            }
        }
    }
    return mesh;
}

/// Sum of absolute channel differences.
inline int colourDistance(QRgb a, QRgb b) {
    return std::abs(qRed(a) - qRed(b)) + std::abs(qGreen(a) - qGreen(b)) + std::abs(qBlue(a) - qBlue(b));
}

/// Pixels of `image` farther than `tolerance` from `background`.
inline int pixelsDifferentFrom(const QImage& image, QRgb background, int tolerance = 24) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (colourDistance(image.pixel(x, y), background) > tolerance)
                ++count;
    return count;
}

/// Pixels that differ between two images of the same size.
inline int pixelsDifferentBetween(const QImage& a, const QImage& b, int tolerance = 24) {
    if (a.size() != b.size())
        return a.width() * a.height();
    int count = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            if (colourDistance(a.pixel(x, y), b.pixel(x, y)) > tolerance)
                ++count;
    return count;
}

} // namespace hs::test
