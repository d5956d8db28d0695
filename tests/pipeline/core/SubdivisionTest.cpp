// Loop subdivision, per-corner data through it, the surface shape measure and tet embedding.
#include "hs/core/Subdivision.h"
#include "hs/core/TetEmbedding.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace hs;

namespace {

/// Regular octahedron of radius 1, outward faces; face label "side" = +1 upper half, -1 lower half.
SurfaceMesh octahedron() {
    SurfaceMesh m;
    m.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    m.faceLabels["side"] = {1, 1, 1, 1, -1, -1, -1, -1};
    m.vertexLabels["id"] = {0, 1, 2, 3, 4, 5};
    return m;
}

/// n^3 unit cubes, each cut into 6 positively oriented tets around its main diagonal (Kuhn).
TetMesh cubeGrid(int n) {
    TetMesh m;
    const auto id = [n](int i, int j, int k) { return static_cast<std::int32_t>((k * (n + 1) + j) * (n + 1) + i); };
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i)
                m.points.push_back({double(i), double(j), double(k)});
    const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                for (const auto& path : paths) {
                    int c[3] = {i, j, k};
                    Tet t{};
                    t[0] = id(c[0], c[1], c[2]);
                    for (int s = 0; s < 3; ++s) {
                        ++c[path[s]];
                        t[static_cast<std::size_t>(s + 1)] = id(c[0], c[1], c[2]);
                    }
                    m.tets.push_back(t);
                    if (signedVolume(m, m.tets.size() - 1) < 0.0)
                        std::swap(m.tets.back()[2], m.tets.back()[3]);
                }
    return m;
}

double radiusSpread(const SurfaceMesh& m) {
    double lo = 1e9, hi = 0.0;
    for (const Vec3& p : m.points) {
        lo = std::min(lo, norm(p));
        hi = std::max(hi, norm(p));
    }
    return hi - lo;
}

} // namespace

TEST(LoopSubdivision, QuadruplesFacesKeepsLabelsByParentAndStaysWatertight) {
    const SurfaceMesh base = octahedron();
    const SurfaceMesh once = loopSubdivide(base);
    EXPECT_EQ(once.triangles.size(), 32u);
    EXPECT_EQ(once.points.size(), 6u + 12u); // old points, then one per edge
    EXPECT_TRUE(analyzeTopology(once).isWatertight());
    EXPECT_TRUE(once.vertexLabels.empty());
    for (std::size_t f = 0; f < once.triangles.size(); ++f)
        EXPECT_EQ(once.faceLabels.at("side")[f], base.faceLabels.at("side")[f / 4]);
    // Children sit on their parent: child 4f touches parent f's corner a, the centre child none of them.
    for (std::size_t f = 0; f < base.triangles.size(); ++f) {
        EXPECT_EQ(once.triangles[4 * f][0], base.triangles[f][0]);
        EXPECT_EQ(once.triangles[4 * f + 1][1], base.triangles[f][1]);
        EXPECT_EQ(once.triangles[4 * f + 2][2], base.triangles[f][2]);
        for (auto v : once.triangles[4 * f + 3])
            EXPECT_GE(v, 6);
    }
    const SurfaceMesh thrice = loopSubdivide(base, 3);
    EXPECT_EQ(thrice.triangles.size(), 8u * 64u);
    EXPECT_TRUE(analyzeTopology(thrice).isWatertight());
    EXPECT_GT(enclosedVolume(thrice), 0.0);
}

TEST(LoopSubdivision, SmoothsTowardsARoundLimitWithTheOctahedronsSymmetry) {
    // The octahedron's limit surface is round-ish: the spread of the point radii shrinks and the normals of
    // neighbouring faces turn less and less at each level (an octahedron's faces meet at 70.5 degrees).
    SurfaceMesh m = octahedron();
    double spread = radiusSpread(m);
    double deviation = measureSurfaceShape(m).maxNormalDeviationDeg;
    EXPECT_NEAR(deviation, 180.0 - 109.47, 0.01);
    for (int level = 1; level <= 3; ++level) {
        m = loopSubdivide(m);
        const double s = radiusSpread(m);
        const double d = measureSurfaceShape(m).maxNormalDeviationDeg;
        EXPECT_LT(d, deviation * 0.75) << "level " << level;
        spread = s;
        deviation = d;
    }
    EXPECT_LT(deviation, 15.0);
    // Symmetric under x -> -x: the point set maps onto itself.
    for (const Vec3& p : m.points) {
        bool found = false;
        for (const Vec3& q : m.points)
            found = found || distance(q, Vec3{-p.x, p.y, p.z}) < 1e-12;
        EXPECT_TRUE(found);
    }
    EXPECT_GT(spread, 0.0);
}

TEST(LoopSubdivision, OpenEdgesAreCreasesAndStayOnTheirCurve) {
    // A flat open fan: the boundary is a crease, so boundary points stay in the plane and on the boundary polygon's
    // smoothed curve; interior points stay in the plane too.
    SurfaceMesh m;
    m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}};
    const SurfaceMesh s = loopSubdivide(m, 2);
    EXPECT_EQ(analyzeTopology(s).boundaryEdges, 4u * 4u);
    for (const Vec3& p : s.points)
        EXPECT_EQ(p.z, 0.0);
    EXPECT_EQ(s.points[0], (Vec3{0, 0, 0})); // the centre is symmetric: it stays
}

TEST(LoopSubdivision, CornerValuesFollowTheChildrenLinearly) {
    std::vector<std::array<CornerUv, 3>> corners{{CornerUv{0, 0}, CornerUv{1, 0}, CornerUv{0, 1}}};
    const auto once = subdivideCorners(corners);
    ASSERT_EQ(once.size(), 4u);
    EXPECT_EQ(once[0][1], (CornerUv{0.5, 0}));
    EXPECT_EQ(once[3][0], (CornerUv{0.5, 0}));
    EXPECT_EQ(once[3][1], (CornerUv{0.5, 0.5}));
    EXPECT_EQ(once[3][2], (CornerUv{0, 0.5}));
    EXPECT_EQ(once[2][2], (CornerUv{0, 1}));
}

TEST(SurfaceShape, MeasuresAnglesEdgesAndNormalTurnsOnMaskedFaces) {
    const SurfaceMesh m = octahedron();
    const SurfaceShape all = measureSurfaceShape(m);
    EXPECT_EQ(all.faces, 8u);
    EXPECT_NEAR(all.minAngleDeg, 60.0, 1e-9);
    EXPECT_NEAR(all.meanEdgeMm, std::sqrt(2.0), 1e-12);
    std::vector<std::int32_t> upper{1, 1, 1, 1, 0, 0, 0, 0};
    EXPECT_EQ(measureSurfaceShape(m, upper).faces, 4u);
    SurfaceMesh spike = m;
    spike.points[4] = {0, 0, 10}; // a spike on the top vertex: thin triangles, sharp turns
    const SurfaceShape s = measureSurfaceShape(spike, upper);
    EXPECT_LT(s.minAngleDeg, 10.0);
    EXPECT_GT(s.maxNormalDeviationDeg, all.maxNormalDeviationDeg);
}

TEST(SurfaceShape, TellsRidgesFromValleys) {
    // An octahedron with outward faces is convex everywhere: all its edges are ridges (the normals of neighbouring
    // faces 70.5 degrees apart). Its top pushed in below the equator makes the upper edges valleys (a notch); the
    // spike (the top pulled far out) makes them sharper ridges.
    const SurfaceMesh m = octahedron();
    const SurfaceShape convex = measureSurfaceShape(m);
    EXPECT_NEAR(convex.maxRidgeDeg, 180.0 - 109.471221, 1e-4);
    EXPECT_EQ(convex.maxValleyDeg, 0.0);
    SurfaceMesh dent = m;
    dent.points[4] = {0, 0, -0.5};
    const std::vector<std::int32_t> upper{1, 1, 1, 1, 0, 0, 0, 0};
    const SurfaceShape notch = measureSurfaceShape(dent, upper);
    EXPECT_GT(notch.maxValleyDeg, 0.0);
    EXPECT_LT(notch.maxRidgeDeg, notch.maxValleyDeg);
    SurfaceMesh spike = m;
    spike.points[4] = {0, 0, 10};
    EXPECT_GT(measureSurfaceShape(spike, upper).maxRidgeDeg, 85.0); // its sides nearly upright, 90 degrees apart
}

TEST(TetEmbedding, PointsInsideGetTheirTetAndPointsOutsideTheNearestWithBoundedWeights) {
    const TetMesh grid = cubeGrid(2);
    ASSERT_TRUE(validate(grid).ok());
    ASSERT_EQ(invertedTetCount(grid), 0u);
    std::vector<Vec3> points{{0.3, 0.4, 0.5}, {1.5, 1.2, 1.9}, {1.0, 1.0, 1.0}, {2.1, 1.0, 1.0}, {-0.05, 0.5, 0.5}};
    const auto e = embedPoints(grid, points);
    ASSERT_EQ(e.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        ASSERT_GE(e[i].tet, 0);
        double sum = 0.0;
        for (double w : e[i].weights)
            sum += w;
        EXPECT_NEAR(sum, 1.0, 1e-12);
        EXPECT_LT(distance(embeddedPoint(grid, e[i]), points[i]), 1e-12);
    }
    for (std::size_t i = 0; i < 3; ++i) // inside: no negative weight
        for (double w : e[i].weights)
            EXPECT_GE(w, -1e-12) << "point " << i;
    // Outside by 0.1 and 0.05 mm: a boundary tet, extrapolated a little.
    for (std::size_t i = 3; i < 5; ++i) {
        double lowest = 0.0;
        for (double w : e[i].weights)
            lowest = std::min(lowest, w);
        EXPECT_LT(lowest, 0.0);
        EXPECT_GT(lowest, -0.25);
    }
    // The embedded point follows the mesh: move the mesh affinely, the embedded point moves the same way.
    TetMesh moved = grid;
    for (Vec3& p : moved.points)
        p = Vec3{2.0 * p.x + 0.5 * p.y, p.y - 0.3 * p.z, 1.5 * p.z} + Vec3{10, 0, -4};
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3& p = points[i];
        const Vec3 expected = Vec3{2.0 * p.x + 0.5 * p.y, p.y - 0.3 * p.z, 1.5 * p.z} + Vec3{10, 0, -4};
        EXPECT_LT(distance(embeddedPoint(moved, e[i]), expected), 1e-12);
    }
}

TEST(TetEmbedding, IsTheSameWithAnyThreadCount) {
    const TetMesh grid = cubeGrid(3);
    std::vector<Vec3> points;
    for (int i = 0; i < 500; ++i)
        points.push_back({std::fmod(i * 0.37, 3.2) - 0.1, std::fmod(i * 0.61, 3.0), std::fmod(i * 0.83, 3.1)});
    const auto one = embedPoints(grid, points, 1);
    const auto four = embedPoints(grid, points, 4);
    ASSERT_EQ(one.size(), four.size());
    for (std::size_t i = 0; i < one.size(); ++i) {
        EXPECT_EQ(one[i].tet, four[i].tet);
        EXPECT_EQ(one[i].weights, four[i].weights);
    }
    EXPECT_TRUE(embedPoints(TetMesh{}, points).front().tet == -1);
}
