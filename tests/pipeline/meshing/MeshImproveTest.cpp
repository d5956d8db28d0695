#include "MeshImprove.h"
#include "MeshingTestShapes.h"

#include "hs/core/Rng.h"
#include "hs/meshing/ParticleMesher.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

using namespace hs;
using namespace hs::meshing;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct SmallMesh {
    std::vector<Vec3> points;
    std::vector<Tet> tets;
    std::vector<std::int32_t> regions;
    std::vector<detail::VertexFreedom> freedom;
};

double worstAngle(const SmallMesh& m) {
    double worst = 180.0;
    for (const Tet& t : m.tets)
        worst = std::min(worst, detail::minDihedralDeg(m.points[std::size_t(t[0])], m.points[std::size_t(t[1])],
                                                       m.points[std::size_t(t[2])], m.points[std::size_t(t[3])]));
    return worst;
}

double volume(const SmallMesh& m) {
    double v = 0.0;
    for (const Tet& t : m.tets) {
        const Vec3 &a = m.points[std::size_t(t[0])], &b = m.points[std::size_t(t[1])], &c = m.points[std::size_t(t[2])],
                   &d = m.points[std::size_t(t[3])];
        v += dot(b - a, cross(c - a, d - a)) / 6.0;
    }
    return v;
}

/// Edge (a, b) = (0, 0, +-h) with three tets around it; the ring runs clockwise seen from a.
SmallMesh threeTetsAroundAnEdge(double h) {
    SmallMesh m;
    m.points = {{0, 0, h}, {0, 0, -h}};
    for (int i = 0; i < 3; ++i)
        m.points.push_back({std::cos(-2.0 * kPi * i / 3.0), std::sin(-2.0 * kPi * i / 3.0), 0.0});
    for (std::int32_t i = 0; i < 3; ++i)
        m.tets.push_back({0, 1, 2 + i, 2 + (i + 1) % 3});
    m.regions.assign(m.tets.size(), 0);
    m.freedom.assign(m.points.size(), detail::VertexFreedom::Fixed);
    return m;
}

/// A unit cube split into 12 tets around an inner vertex at `centre`.
SmallMesh cubeStar(const Vec3& centre) {
    const SurfaceMesh cube = test::box({0, 0, 0}, {1, 1, 1});
    SmallMesh m;
    m.points = cube.points;
    m.points.push_back(centre);
    const auto c = static_cast<std::int32_t>(m.points.size() - 1);
    for (const Triangle& t : cube.triangles)
        m.tets.push_back({c, t[0], t[1], t[2]}); // outward triangle seen from inside: positive
    m.regions.assign(m.tets.size(), 0);
    m.freedom.assign(m.points.size(), detail::VertexFreedom::Fixed);
    m.freedom.back() = detail::VertexFreedom::Free;
    return m;
}

/// With `smoothOnly`, the inner vertex may move but not go.
detail::MeshImproveStats improve(SmallMesh& m, double target, bool smoothOnly = false) {
    detail::MeshImproveParams params;
    params.targetDihedralDeg = target;
    params.contractVertices = !smoothOnly;
    auto stats = detail::improveMesh(m.points, m.tets, m.regions, m.freedom, params, {}, Progress::none());
    EXPECT_TRUE(stats.ok());
    return stats.ok() ? *stats : detail::MeshImproveStats{};
}

} // namespace

TEST(MeshImprove, RemovesAnEdgeWhenTwoTetsAreBetterThanThree) {
    SmallMesh m = threeTetsAroundAnEdge(2.0); // three needles (32.8 degrees) around a long edge
    const double before = worstAngle(m), v0 = volume(m);
    EXPECT_NEAR(before, 32.84, 0.01);
    const auto stats = improve(m, 40.0);
    EXPECT_EQ(stats.edgeRemovals, 1u);
    ASSERT_EQ(m.tets.size(), 2u);
    EXPECT_GT(worstAngle(m), 65.0);
    EXPECT_NEAR(volume(m), v0, 1e-12);
}

TEST(MeshImprove, FlipsTwoFlatTetsIntoThree) {
    // The two caps (a, r0, r1, r2) and (b, r2, r1, r0) around a short vertical axis: 21.8 degrees; the three tets
    // around the edge (a, b) have 43.6.
    SmallMesh m = threeTetsAroundAnEdge(0.2);
    m.tets = {{0, 2, 3, 4}, {1, 4, 3, 2}};
    m.regions.assign(2, 0);
    const double v0 = volume(m);
    EXPECT_NEAR(worstAngle(m), 21.8, 0.01);
    const auto stats = improve(m, 30.0);
    EXPECT_EQ(stats.faceFlips, 1u);
    ASSERT_EQ(m.tets.size(), 3u);
    EXPECT_GT(worstAngle(m), 43.0);
    EXPECT_NEAR(volume(m), v0, 1e-12);
}

TEST(MeshImprove, NeverFlipsAcrossARegionInterface) {
    SmallMesh m = threeTetsAroundAnEdge(0.2);
    m.tets = {{0, 2, 3, 4}, {1, 4, 3, 2}};
    m.regions = {0, 1};
    const auto stats = improve(m, 30.0);
    EXPECT_EQ(stats.faceFlips, 0u);
    EXPECT_EQ(m.tets.size(), 2u);
    EXPECT_EQ(m.regions, (std::vector<std::int32_t>{0, 1}));
}

TEST(MeshImprove, SmoothingNeverInvertsAndRaisesTheWorstAngle) {
    Rng rng(7);
    for (int trial = 0; trial < 50; ++trial) {
        // The inner vertex anywhere near a face, edge or corner of the cube: flat tets around it.
        const Vec3 centre(rng.uniform(0.03, 0.97), rng.uniform(0.03, 0.97), rng.uniform(0.03, 0.97));
        SmallMesh m = cubeStar(centre);
        const double before = worstAngle(m), v0 = volume(m);
        ASSERT_GT(before, 0.0);
        const auto stats = improve(m, 60.0, true);
        EXPECT_GE(stats.smoothedVertices, 1u) << "trial " << trial;
        ASSERT_EQ(m.tets.size(), 12u) << "a flip would leave flat tets on the cube faces";
        const double after = worstAngle(m);
        EXPECT_GT(after, 0.0) << "trial " << trial;
        EXPECT_GE(after, before) << "trial " << trial;
        EXPECT_NEAR(volume(m), v0, 1e-12);
        if (before < 20.0) {
            EXPECT_GT(after, before + 5.0) << "trial " << trial << " from " << before;
        }
    }
    // From a corner, the ascent reaches the centre's quality (the best star is the centred one).
    SmallMesh m = cubeStar({0.1, 0.15, 0.2});
    improve(m, 90.0, true);
    ASSERT_EQ(m.tets.size(), 12u);
    EXPECT_GT(worstAngle(m), 0.95 * worstAngle(cubeStar({0.5, 0.5, 0.5})));
}

TEST(MeshImprove, KeepsFixedVerticesAndTheBoundary) {
    SmallMesh m = cubeStar({0.5, 0.5, 0.05});
    const std::vector<Vec3> fixedPoints(m.points.begin(), m.points.end() - 1);
    improve(m, 60.0, true);
    EXPECT_TRUE(std::equal(fixedPoints.begin(), fixedPoints.end(), m.points.begin()));
}

TEST(MeshImprove, LeavesNoSliverInAParticleMeshOfASphere) {
    const RegionModel body = RegionModel::fromSurfaces({test::icosphere(10.0, 3)}, {"sphere"});
    MeshParams p;
    p.targetEdgeLength = 1.2;
    p.seed = 3;
    p.threads = 2;
    auto result = meshParticles(body, p);
    ASSERT_TRUE(result.ok()) << result.error().message();
    const QualityReport& q = result->quality;
    EXPECT_EQ(q.sliverCount, 0u);
    EXPECT_EQ(q.invertedCount, 0u);
    EXPECT_GE(q.minDihedralDeg, 15.0);
    EXPECT_GT(q.meanRadiusRatio, 0.88);
    EXPECT_LT(q.volumeError, 0.02);
    // Still a proper tet mesh: every face is shared by at most two tets, and the boundary is closed.
    std::map<std::array<std::int32_t, 3>, int> faces;
    for (const Tet& t : result->mesh.tets)
        for (int k = 0; k < 4; ++k) {
            std::array<std::int32_t, 3> f{};
            for (int i = 0, j = 0; i < 4; ++i)
                if (i != k)
                    f[std::size_t(j++)] = t[std::size_t(i)];
            std::sort(f.begin(), f.end());
            ++faces[f];
        }
    for (const auto& [f, count] : faces)
        ASSERT_LE(count, 2);
    const SurfaceMesh boundary = extractBoundary(result->mesh);
    std::map<std::pair<std::int32_t, std::int32_t>, int> edges;
    for (const Triangle& t : boundary.triangles)
        for (int k = 0; k < 3; ++k)
            ++edges[{std::min(t[std::size_t(k)], t[std::size_t((k + 1) % 3)]),
                     std::max(t[std::size_t(k)], t[std::size_t((k + 1) % 3)])}];
    for (const auto& [e, count] : edges)
        EXPECT_EQ(count, 2) << "boundary edge " << e.first << "-" << e.second;
}

TEST(MeshImprove, ContractsAnInnerVertexThatCannotMoveWell) {
    // A regular tet split at an inner vertex: the four parts have at most 35.3 degrees wherever the vertex goes,
    // the tet itself 70.5.
    SmallMesh m;
    m.points = {{1, 1, 1}, {-1, 1, -1}, {1, -1, -1}, {-1, -1, 1}, {0.1, 0.05, -0.02}};
    const Tet whole{0, 1, 2, 3};
    ASSERT_GT(detail::minDihedralDeg(m.points[0], m.points[1], m.points[2], m.points[3]), 0.0);
    for (int k = 0; k < 4; ++k) {
        Tet t = whole;
        t[std::size_t(k)] = 4;
        m.tets.push_back(t);
    }
    m.regions.assign(4, 0);
    m.freedom.assign(5, detail::VertexFreedom::Fixed);
    m.freedom[4] = detail::VertexFreedom::Free;
    const double v0 = volume(m);
    const auto stats = improve(m, 60.0);
    EXPECT_EQ(stats.contractions, 1u);
    ASSERT_EQ(m.tets.size(), 1u);
    EXPECT_NEAR(worstAngle(m), 70.53, 0.01);
    EXPECT_NEAR(volume(m), v0, 1e-12);
}
