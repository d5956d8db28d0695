#include "hs/core/SurfaceMesh.h"

#include <gtest/gtest.h>

#include <limits>

namespace {

/// Unit cube [0,1]^3, 12 outward triangles.
hs::SurfaceMesh cube() {
    hs::SurfaceMesh m;
    m.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    m.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                   {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    return m;
}

} // namespace

TEST(SurfaceMesh, CubeIsWatertightWithUnitVolume) {
    const auto m = cube();
    ASSERT_TRUE(hs::validate(m).ok());
    const auto topo = hs::analyzeTopology(m);
    EXPECT_TRUE(topo.isWatertight());
    EXPECT_EQ(topo.components, 1u);
    EXPECT_NEAR(hs::enclosedVolume(m), 1.0, 1e-12);
    EXPECT_NEAR(hs::surfaceArea(m), 6.0, 1e-12);
    EXPECT_NEAR(hs::bounds(m).diagonal(), std::sqrt(3.0), 1e-12);
}

TEST(SurfaceMesh, RemovedFaceLeavesThreeBoundaryEdges) {
    auto m = cube();
    m.triangles.pop_back();
    const auto topo = hs::analyzeTopology(m);
    EXPECT_EQ(topo.boundaryEdges, 3u);
    EXPECT_FALSE(topo.isClosed());
}

TEST(SurfaceMesh, FlippedFaceIsInconsistent) {
    auto m = cube();
    std::swap(m.triangles[0][1], m.triangles[0][2]);
    const auto topo = hs::analyzeTopology(m);
    EXPECT_EQ(topo.inconsistentEdges, 3u);
    EXPECT_FALSE(topo.isWatertight());
}

TEST(SurfaceMesh, TwoCubesSharingAVertexAreNonManifoldThere) {
    auto m = cube();
    const auto second = cube();
    const auto offset = static_cast<std::int32_t>(m.points.size());
    for (auto p : second.points)
        m.points.push_back(p + hs::Vec3(1, 1, 1));
    for (auto t : second.triangles)
        m.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    // Weld the second cube's (0,0,0) corner (index offset) onto the first cube's (1,1,1) corner (index 6).
    for (auto& t : m.triangles)
        for (auto& v : t)
            if (v == offset)
                v = 6;
    const auto topo = hs::analyzeTopology(m);
    EXPECT_EQ(topo.nonManifoldVertices, 1u);
    EXPECT_EQ(topo.components, 2u);
    EXPECT_EQ(topo.unreferencedVertices, 1u);
}

TEST(SurfaceMesh, ValidateNamesTheBadIndexAndTheBadCoordinate) {
    auto m = cube();
    m.triangles[3][1] = 99;
    auto s = hs::validate(m);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().detail.find("triangle 3"), std::string::npos);
    m = cube();
    m.points[2].y = std::nan("");
    s = hs::validate(m);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().detail.find("vertex 2"), std::string::npos);
    m = cube();
    m.faceLabels["region"] = {1, 2};
    EXPECT_FALSE(hs::validate(m).ok());
}

TEST(SurfaceMesh, ValidateRefusesFiniteCoordinatesBeyondTheLimitNamingTheRange) {
    // 1e300 is finite, but its square is not: areas and grid cells computed from it would be inf or NaN.
    for (const double bad : {1e300, -1e300, 2.0 * hs::kMaxCoordinate, std::numeric_limits<double>::max()}) {
        auto m = cube();
        m.points[5].z = bad;
        const auto s = hs::validate(m);
        ASSERT_FALSE(s.ok()) << bad;
        EXPECT_EQ(s.error().code, hs::ErrorCode::InvalidInput);
        EXPECT_NE(s.error().detail.find("vertex 5"), std::string::npos) << s.error().detail;
        EXPECT_NE(s.error().detail.find("allowed -1e+09..1e+09"), std::string::npos) << s.error().detail;
    }
    auto m = cube();
    m.points[5].z = -hs::kMaxCoordinate; // the limit itself is allowed
    EXPECT_TRUE(hs::validate(m).ok());
}
