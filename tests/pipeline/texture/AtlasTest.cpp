#include "hs/texture/Atlas.h"

#include "TextureTestMeshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace hs;
using namespace hs::texture;

namespace {

double uvArea(const Atlas& atlas, std::size_t f) {
    const auto& t = atlas.uvTriangles[f];
    const UvVertex& a = atlas.uvVertices[static_cast<std::size_t>(t[0])];
    const UvVertex& b = atlas.uvVertices[static_cast<std::size_t>(t[1])];
    const UvVertex& c = atlas.uvVertices[static_cast<std::size_t>(t[2])];
    return 0.5 * ((b.u - a.u) * (c.v - a.v) - (c.u - a.u) * (b.v - a.v));
}

/// Texels whose centre lies strictly inside more than one UV triangle.
int overlappingTexels(const Atlas& atlas, int res) {
    std::vector<std::uint8_t> hits(static_cast<std::size_t>(res) * res, 0);
    int overlaps = 0;
    for (std::size_t f = 0; f < atlas.uvTriangles.size(); ++f) {
        std::array<double, 3> x, y;
        for (std::size_t k = 0; k < 3; ++k) {
            const UvVertex& q = atlas.uvVertices[static_cast<std::size_t>(atlas.uvTriangles[f][k])];
            x[k] = q.u * res;
            y[k] = q.v * res;
        }
        const double a2 = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
        const int x0 = std::max(0, int(std::floor(*std::min_element(x.begin(), x.end()))));
        const int x1 = std::min(res - 1, int(std::floor(*std::max_element(x.begin(), x.end()))));
        const int y0 = std::max(0, int(std::floor(*std::min_element(y.begin(), y.end()))));
        const int y1 = std::min(res - 1, int(std::floor(*std::max_element(y.begin(), y.end()))));
        for (int py = y0; py <= y1; ++py)
            for (int px = x0; px <= x1; ++px) {
                const double cx = px + 0.5, cy = py + 0.5;
                const double l0 = ((x[1] - cx) * (y[2] - cy) - (x[2] - cx) * (y[1] - cy)) / a2;
                const double l1 = ((x[2] - cx) * (y[0] - cy) - (x[0] - cx) * (y[2] - cy)) / a2;
                const double l2 = 1 - l0 - l1;
                if (l0 <= 1e-6 || l1 <= 1e-6 || l2 <= 1e-6)
                    continue;
                auto& h = hits[static_cast<std::size_t>(py) * res + px];
                if (h++)
                    ++overlaps;
            }
    }
    return overlaps;
}

void expectValidAtlas(const SurfaceMesh& mesh, const Atlas& atlas) {
    ASSERT_EQ(atlas.uvTriangles.size(), mesh.triangles.size());
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        EXPECT_GT(uvArea(atlas, f), 0.0) << "face " << f;
        EXPECT_GE(atlas.chartOfFace[f], 0);
        for (std::size_t k = 0; k < 3; ++k)
            EXPECT_EQ(atlas.uvVertices[static_cast<std::size_t>(atlas.uvTriangles[f][k])].vertex, mesh.triangles[f][k]);
    }
    for (const UvVertex& q : atlas.uvVertices) {
        EXPECT_GE(q.u, 0.0);
        EXPECT_LE(q.u, 1.0);
        EXPECT_GE(q.v, 0.0);
        EXPECT_LE(q.v, 1.0);
    }
    EXPECT_EQ(overlappingTexels(atlas, atlas.size), 0);
}

} // namespace

TEST(TextureAtlas, CoversEveryTriangleOfAnOrganWithPositiveAreaAndNoOverlap) {
    const SurfaceMesh organ = test::makeLabelledOrgan(24);
    AtlasParams p;
    p.size = 1024;
    const auto atlas = buildAtlas(organ, p);
    ASSERT_TRUE(atlas.ok()) << atlas.error().message();
    expectValidAtlas(organ, *atlas);
    EXPECT_GT(atlas->stats.charts, 5);
    EXPECT_GE(atlas->stats.l2Stretch, 0.99);
    EXPECT_LT(atlas->stats.l2Stretch, 1.15);
    EXPECT_GT(atlas->stats.fill, 0.3);
}

TEST(TextureAtlas, CoversTheBoundaryOfATetMesh) {
    const TetMesh cube = test::makeTetCube(6);
    const SurfaceMesh boundary = extractBoundary(cube);
    const auto atlas = buildAtlas(boundary, AtlasParams{512, 0, 40.0, 8});
    ASSERT_TRUE(atlas.ok()) << atlas.error().message();
    expectValidAtlas(boundary, *atlas);
    EXPECT_EQ(atlas->stats.charts, 6); // one per cube face
    EXPECT_NEAR(atlas->stats.l2Stretch, 1.0, 1e-6);
}

TEST(TextureAtlas, RejectsSizesOutOfRangeAndEmptySurfaces) {
    const SurfaceMesh organ = test::makeLabelledOrgan(4);
    AtlasParams p;
    p.size = 100000;
    const auto big = buildAtlas(organ, p);
    ASSERT_FALSE(big.ok());
    EXPECT_EQ(big.error().code, ErrorCode::LimitExceeded);
    EXPECT_NE(big.error().detail.find("64..8192"), std::string::npos);
    EXPECT_FALSE(buildAtlas(SurfaceMesh{}, AtlasParams{}).ok());
}
