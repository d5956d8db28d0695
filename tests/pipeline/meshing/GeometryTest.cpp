#include "MeshingTestShapes.h"
#include "hs/core/TriangleGrid.h"

#include "hs/core/Rng.h"
#include "hs/meshing/Geometry.h"
#include "hs/meshing/QualityReport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace hs;
using namespace hs::meshing;

TEST(TriangleBoxOverlap, DetectsTrianglesThroughTouchingAndBesideTheBox) {
    const Vec3 c{0, 0, 0}, h{0.5, 0.5, 0.5};
    EXPECT_TRUE(triangleBoxOverlap(c, h, {-2, -2, 0}, {2, -2, 0}, {0, 2, 0}));       // cuts through
    EXPECT_TRUE(triangleBoxOverlap(c, h, {0.5, -1, -1}, {0.5, 1, -1}, {0.5, 0, 2})); // lies on a face
    EXPECT_FALSE(triangleBoxOverlap(c, h, {0.6, -1, -1}, {0.6, 1, -1}, {0.6, 0, 2}));
    // Bounding boxes overlap, but the triangle passes beside the corner (only the edge-cross axes separate).
    EXPECT_FALSE(triangleBoxOverlap(c, h, {1.4, 0, -1}, {0, 1.4, -1}, {0.7, 0.7, 2}));
    EXPECT_TRUE(triangleBoxOverlap(c, h, {0.9, 0, -1}, {0, 0.9, -1}, {0.45, 0.45, 2}));
}

TEST(ClosestPointOnTriangle, ProjectsOntoFaceEdgeAndVertex) {
    const Vec3 a{0, 0, 0}, b{2, 0, 0}, c{0, 2, 0};
    auto face = closestPointOnTriangle({0.5, 0.5, 3}, a, b, c);
    EXPECT_EQ(face.feature, TriangleFeature::Face);
    EXPECT_NEAR(std::sqrt(face.distance2), 3.0, 1e-12);
    auto edge = closestPointOnTriangle({1, -1, 0}, a, b, c);
    EXPECT_EQ(edge.feature, TriangleFeature::EdgeAB);
    EXPECT_NEAR(std::sqrt(edge.distance2), 1.0, 1e-12);
    auto vertex = closestPointOnTriangle({3, -1, 0}, a, b, c);
    EXPECT_EQ(vertex.feature, TriangleFeature::VertexB);
    EXPECT_NEAR(std::sqrt(vertex.distance2), std::sqrt(2.0), 1e-12);
}

TEST(TetShape, MatchesHandComputedValuesOfKnownTetrahedra) {
    // Regular tetrahedron: radius ratio 1, all dihedral angles acos(1/3) = 70.5288 degrees.
    const TetShape regular = tetShape({1, 1, 1}, {-1, 1, -1}, {1, -1, -1}, {-1, -1, 1});
    EXPECT_NEAR(regular.radiusRatio, 1.0, 1e-12);
    EXPECT_NEAR(regular.minDihedral, 70.528779, 1e-5);
    EXPECT_NEAR(regular.maxDihedral, 70.528779, 1e-5);
    EXPECT_NEAR(regular.edgeRatio, 1.0, 1e-12);
    EXPECT_GT(regular.volume, 0.0);
    // Corner tetrahedron: V = 1/6, inradius 0.5 / (1.5 + sqrt(3)/2), circumradius sqrt(3)/2;
    // dihedral angles 90 (three) and acos(1/sqrt(3)) = 54.7356 (three); edge ratio sqrt(2).
    const TetShape corner = tetShape({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
    const double rin = 0.5 / (1.5 + std::sqrt(3.0) / 2.0);
    EXPECT_NEAR(corner.radiusRatio, 3.0 * rin / (std::sqrt(3.0) / 2.0), 1e-12);
    EXPECT_NEAR(corner.minDihedral, 54.735610, 1e-5);
    EXPECT_NEAR(corner.maxDihedral, 90.0, 1e-9);
    EXPECT_NEAR(corner.edgeRatio, std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(corner.volume, 1.0 / 6.0, 1e-15);
    // Body-centred cubic tetrahedron: radius ratio 3 * (sqrt(2)/8) / (sqrt(5)/4) = 0.9487, angles 60 and 90.
    const TetShape bcc = tetShape({0, 0, 0}, {1, 0, 0}, {0.5, 0.5, 0.5}, {0.5, -0.5, 0.5});
    EXPECT_NEAR(bcc.radiusRatio, 3.0 * (std::sqrt(2.0) / 8.0) / (std::sqrt(5.0) / 4.0), 1e-12);
    EXPECT_NEAR(bcc.minDihedral, 60.0, 1e-9);
    EXPECT_NEAR(bcc.maxDihedral, 90.0, 1e-9);
    // A flat sliver: four points on a circle.
    const TetShape flat = tetShape({1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 1e-9});
    EXPECT_LT(flat.radiusRatio, 1e-6);
    EXPECT_LT(flat.minDihedral, 1e-3);
}

TEST(QualityReport, CountsSliversInvertedTetsAndHistogramBuckets) {
    TetMesh mesh;
    mesh.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1e-6}};
    mesh.tets = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 1, 2, 4}};
    const QualityReport q = measureQuality(mesh);
    EXPECT_EQ(q.tetCount, 3u);
    EXPECT_EQ(q.invertedCount, 1u); // the second tet is the first one mirrored
    EXPECT_EQ(q.sliverCount, 1u);   // the flat one
    EXPECT_EQ(q.radiusRatioHistogram[7] + q.radiusRatioHistogram[0], 3u);
    EXPECT_NEAR(q.maxDihedralDeg, 180.0, 1e-3);
    EXPECT_FALSE(q.hasReference);
}

TEST(QualityReport, CountsNonManifoldEdgesAndVerticesOfTheOuterBoundary) {
    TetMesh mesh;
    mesh.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 2}, {0, 1, 2}, {1, 0, 2}, {0, -1, -1}};
    mesh.tets = {{0, 1, 2, 3}};
    QualityReport q = measureQuality(mesh);
    EXPECT_EQ(q.boundaryNonManifoldEdges, 0u);
    EXPECT_EQ(q.boundaryNonManifoldVertices, 0u);
    // A second tet touching the first only at point 3: one vertex with two fans.
    mesh.tets = {{0, 1, 2, 3}, {3, 4, 5, 6}};
    q = measureQuality(mesh);
    EXPECT_EQ(q.boundaryNonManifoldEdges, 0u);
    EXPECT_EQ(q.boundaryNonManifoldVertices, 1u);
    // A second tet sharing only the edge 0-1: four boundary faces at that edge.
    mesh.tets = {{0, 1, 2, 3}, {0, 1, 7, 6}};
    q = measureQuality(mesh);
    EXPECT_EQ(q.boundaryNonManifoldEdges, 1u);
}

TEST(TriangleGrid, BoundedSearchFindsTheClosestTriangleOrNothingWithinTheBound) {
    // A small sphere far from most query points, as a pathology's grid is from most samples of a merged body.
    const SurfaceMesh sphere = test::icosphere(3.0, 3, {20.0, 0.0, 0.0});
    const TriangleGrid grid(sphere);
    Rng rng(7);
    for (int i = 0; i < 300; ++i) {
        const Vec3 p{rng.uniform(-40.0, 40.0), rng.uniform(-40.0, 40.0), rng.uniform(-40.0, 40.0)};
        double brute = 1e300;
        for (const Triangle& t : sphere.triangles)
            brute = std::min(brute,
                             closestPointOnTriangle(p, sphere.points[std::size_t(t[0])],
                                                    sphere.points[std::size_t(t[1])], sphere.points[std::size_t(t[2])])
                                 .distance2);
        EXPECT_EQ(grid.closest(p).closest.distance2, brute);
        const SurfaceHit within = grid.closestWithin(p, brute * 1.01 + 1e-12);
        ASSERT_GE(within.triangle, 0);
        EXPECT_EQ(within.closest.distance2, brute);
        EXPECT_LT(grid.closestWithin(p, brute * 0.99).triangle, 0);
        EXPECT_LE(grid.boxDistance2(p), brute);
    }
}

TEST(TriangleGrid, CoordinatesNearTheLimitsOfDoubleGiveOneCellNotUndefinedCasts) {
    // Found by fuzzing scene packages (UBSan): 1e300 mm coordinates, finite so a reader takes them, overflow the area
    // to infinity and the cell size to NaN, and the cell indices were cast from NaN. Every index is now clamped
    // before its cast (the sanitizer build checks there is no undefined cast); the grid is one cell and answers.
    const SurfaceMesh sphere = test::icosphere(1e300, 2, {0.0, 0.0, 0.0});
    const TriangleGrid grid(sphere);
    for (const Vec3& p : {Vec3{0, 0, 0}, Vec3{2e300, 0, 0}, Vec3{-1e300, 1e299, 5},
                          Vec3{std::numeric_limits<double>::quiet_NaN(), 0, 0}}) {
        const SurfaceHit hit = grid.closest(p);
        EXPECT_GE(hit.triangle, -1);
        EXPECT_LT(hit.triangle, static_cast<std::int32_t>(sphere.triangles.size()));
    }
    // A grid of ordinary size is unchanged: the clamped index is floor's wherever floor fits.
    const SurfaceMesh small = test::icosphere(3.0, 2, {1e6, 0.0, 0.0});
    const TriangleGrid smallGrid(small);
    EXPECT_NEAR(std::sqrt(smallGrid.closest({1e6 + 10.0, 0.0, 0.0}).closest.distance2), 7.0, 0.2);
}

TEST(QualityReport, MeasuresHausdorffAndVolumeAgainstTheReference) {
    // A unit cube split into 6 tets (Kuhn triangulation) against the cube surface.
    TetMesh mesh;
    for (int i = 0; i < 8; ++i)
        mesh.points.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
    mesh.tets = {{0, 1, 3, 7}, {0, 1, 7, 5}, {0, 2, 7, 3}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 7, 6}};
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
        if (signedVolume(mesh, t) < 0)
            std::swap(mesh.tets[t][2], mesh.tets[t][3]);
    const RegionModel ref = RegionModel::fromSurfaces({test::box({0, 0, 0}, {1, 1, 1})});
    const QualityReport q = measureQuality(mesh, &ref);
    ASSERT_TRUE(q.hasReference);
    EXPECT_NEAR(q.hausdorffDistance, 0.0, 1e-12);
    EXPECT_NEAR(q.volumeError, 0.0, 1e-12);
    ASSERT_EQ(q.regions.size(), 1u);
    EXPECT_NEAR(q.regions[0].inputVolume, 1.0, 1e-12);
    EXPECT_NEAR(q.boundingBoxDiagonal, std::sqrt(3.0), 1e-12);
}

TEST(QualityReport, ListsEveryTetsShapeAndTheWorstFirst) {
    // A regular tet and a flattened one: the flat one is the worst, and the histogram agrees with the shapes.
    TetMesh mesh;
    mesh.points = {{0, 0, 0},
                   {1, 0, 0},
                   {0.5, std::sqrt(3.0) / 2.0, 0},
                   {0.5, std::sqrt(3.0) / 6.0, std::sqrt(2.0 / 3.0)},
                   {0.5, std::sqrt(3.0) / 6.0, 0.05}};
    mesh.tets = {{0, 1, 2, 3}, {0, 1, 2, 4}};
    for (int threads : {1, 2}) {
        const std::vector<TetShape> shapes = tetShapes(mesh, threads);
        ASSERT_EQ(shapes.size(), 2u);
        EXPECT_NEAR(shapes[0].radiusRatio, 1.0, 1e-9);
        EXPECT_LT(shapes[1].radiusRatio, 0.5);
        const std::vector<double> ratios{shapes[0].radiusRatio, shapes[1].radiusRatio};
        EXPECT_EQ(worstTets(ratios, 5), (std::vector<std::size_t>{1, 0}));
        EXPECT_EQ(worstTets(ratios, 1), (std::vector<std::size_t>{1}));
    }
    const QualityReport report = measureQuality(mesh);
    EXPECT_EQ(report.radiusRatioHistogram[9], 1u);
}
