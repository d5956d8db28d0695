// The endoscopic view's lighter surface (hs/simrender/ViewDecimation.h) on a latitude-longitude sphere whose seam is
// cut open as a texture's seam is (the points along it duplicated), and the recognition of software GL renderers.

#include "hs/simrender/ViewDecimation.h"
#include "TestSpheres.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace hs::simrender {
namespace {

SurfaceMesh seamedSphere(int rings = 24, int segments = 48) {
    return test::latitudeSphere(rings, segments, true);
}

using Edge = std::pair<std::size_t, std::size_t>;

/// Edges with one incident triangle, as pairs of the visual surface's point indices.
std::set<Edge> borderEdges(const std::vector<Triangle>& triangles, const std::vector<std::size_t>& source = {}) {
    std::map<Edge, int> uses;
    for (const Triangle& t : triangles)
        for (int k = 0; k < 3; ++k) {
            std::size_t a = static_cast<std::size_t>(t[static_cast<std::size_t>(k)]);
            std::size_t b = static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)]);
            if (!source.empty()) {
                a = source[a];
                b = source[b];
            }
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    std::set<Edge> border;
    for (const auto& [edge, count] : uses)
        if (count == 1)
            border.insert(edge);
    return border;
}

/// Six times the signed volume enclosed, from the visual surface's points.
double volume(const std::vector<Triangle>& triangles, const std::vector<Vec3>& points,
              const std::vector<std::size_t>& source) {
    double sum = 0.0;
    for (const Triangle& t : triangles) {
        const Vec3& a = points[source[static_cast<std::size_t>(t[0])]];
        const Vec3& b = points[source[static_cast<std::size_t>(t[1])]];
        const Vec3& c = points[source[static_cast<std::size_t>(t[2])]];
        sum += dot(a, cross(b, c));
    }
    return sum / 6.0;
}

TEST(ViewDecimation, HalvesTheTrianglesOverPointsOfTheSurface) {
    const SurfaceMesh sphere = seamedSphere();
    const DecimatedSurface light = decimateForView(sphere, {});
    EXPECT_LE(light.triangles.size(), sphere.triangles.size() * 6 / 10);
    EXPECT_GE(light.triangles.size(), sphere.triangles.size() * 4 / 10);
    EXPECT_EQ(light.innerTriangles, light.triangles.size());
    // Every drawn point is one of the surface's, once; every triangle is over drawn points and not degenerate.
    std::set<std::size_t> distinct(light.sourcePoints.begin(), light.sourcePoints.end());
    EXPECT_EQ(distinct.size(), light.sourcePoints.size());
    for (std::size_t p : light.sourcePoints)
        EXPECT_LT(p, sphere.points.size());
    for (const Triangle& t : light.triangles) {
        for (std::int32_t i : t)
            ASSERT_LT(static_cast<std::size_t>(i), light.sourcePoints.size());
        EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
    }
}

TEST(ViewDecimation, KeepsTheSeamAndCoversTheSameSurface) {
    const SurfaceMesh sphere = seamedSphere();
    std::vector<std::size_t> identity(sphere.points.size());
    for (std::size_t i = 0; i < identity.size(); ++i)
        identity[i] = i;
    const DecimatedSurface light = decimateForView(sphere, {});
    // The seam's edges, and only they, are still borders: no crack along the seam, no hole opened.
    EXPECT_EQ(borderEdges(light.triangles, light.sourcePoints), borderEdges(sphere.triangles));
    // The same side out and nearly the same volume: the triangles still cover the sphere.
    const double before = volume(sphere.triangles, sphere.points, identity);
    const double after = volume(light.triangles, sphere.points, light.sourcePoints);
    EXPECT_GT(after, 0.0);
    EXPECT_NEAR(after / before, 1.0, 0.03);
}

TEST(ViewDecimation, KeepsInnerAndOuterFacesApartAndJoined) {
    const SurfaceMesh sphere = seamedSphere();
    // The southern half stands for the organ's outer surface.
    std::vector<bool> outer(sphere.triangles.size());
    for (std::size_t f = 0; f < sphere.triangles.size(); ++f) {
        double z = 0.0;
        for (std::int32_t p : sphere.triangles[f])
            z += sphere.points[static_cast<std::size_t>(p)].z;
        outer[f] = z < 0.0;
    }
    const DecimatedSurface light = decimateForView(sphere, outer);
    ASSERT_GT(light.innerTriangles, 0u);
    ASSERT_LT(light.innerTriangles, light.triangles.size());
    const auto side = [&](std::size_t begin, std::size_t end) {
        return std::vector<Triangle>(light.triangles.begin() + static_cast<std::ptrdiff_t>(begin),
                                     light.triangles.begin() + static_cast<std::ptrdiff_t>(end));
    };
    const std::vector<Triangle> inner = side(0, light.innerTriangles);
    const std::vector<Triangle> outside = side(light.innerTriangles, light.triangles.size());
    // Each side is drawn over points of its own faces.
    std::set<std::size_t> innerPoints, outerPoints;
    for (std::size_t f = 0; f < sphere.triangles.size(); ++f)
        for (std::int32_t p : sphere.triangles[f])
            (outer[f] ? outerPoints : innerPoints).insert(static_cast<std::size_t>(p));
    for (const Triangle& t : inner)
        for (std::int32_t p : t)
            EXPECT_EQ(innerPoints.count(light.sourcePoints[static_cast<std::size_t>(p)]), 1u);
    for (const Triangle& t : outside)
        for (std::int32_t p : t)
            EXPECT_EQ(outerPoints.count(light.sourcePoints[static_cast<std::size_t>(p)]), 1u);
    // Where the halves meet, both keep the same points: together they have only the seam as border.
    EXPECT_EQ(borderEdges(light.triangles, light.sourcePoints), borderEdges(sphere.triangles));
    std::set<Edge> innerBorder = borderEdges(inner, light.sourcePoints);
    std::set<Edge> outerBorder = borderEdges(outside, light.sourcePoints);
    std::size_t shared = 0;
    for (const Edge& e : innerBorder)
        shared += outerBorder.count(e);
    EXPECT_GT(shared, 0u);
}

TEST(ViewDecimation, IsDeterministicAndKeepsEverythingWithoutReduction) {
    const SurfaceMesh sphere = seamedSphere(10, 20);
    const DecimatedSurface first = decimateForView(sphere, {});
    const DecimatedSurface second = decimateForView(sphere, {});
    EXPECT_EQ(first.sourcePoints, second.sourcePoints);
    EXPECT_EQ(first.triangles, second.triangles);
    ViewDecimationParams none;
    none.targetReduction = 0.0;
    const DecimatedSurface all = decimateForView(sphere, {}, none);
    EXPECT_EQ(all.triangles.size(), sphere.triangles.size());
    EXPECT_EQ(all.sourcePoints.size(), sphere.points.size());
    // The same triangles in the same order, their points numbered in the order of first use.
    EXPECT_EQ(all.triangles.front(), (Triangle{0, 1, 2}));
    for (std::size_t f = 0; f < sphere.triangles.size(); ++f)
        for (std::size_t k = 0; k < 3; ++k)
            ASSERT_EQ(all.sourcePoints[static_cast<std::size_t>(all.triangles[f][k])],
                      static_cast<std::size_t>(sphere.triangles[f][k]));
}

TEST(SoftwareRenderer, IsRecognisedByItsRendererString) {
    EXPECT_TRUE(isSoftwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
    EXPECT_TRUE(isSoftwareRenderer("softpipe"));
    EXPECT_TRUE(isSoftwareRenderer("Mesa X11 swrast"));
    EXPECT_TRUE(isSoftwareRenderer("Google SwiftShader"));
    EXPECT_TRUE(isSoftwareRenderer("Microsoft Basic Render Driver"));
    EXPECT_FALSE(isSoftwareRenderer("NVIDIA GeForce RTX 3060/PCIe/SSE2"));
    EXPECT_FALSE(isSoftwareRenderer("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"));
    EXPECT_FALSE(isSoftwareRenderer("AMD Radeon RX 6600 (navi23, LLVM 15.0.6, DRM 3.49, 6.1.0-13-amd64)"));
    EXPECT_FALSE(isSoftwareRenderer(""));
}

} // namespace
} // namespace hs::simrender
