#include "hs/texture/Bake.h"
#include "hs/texture/ImageFiles.h"

#include "TestSupport.h"
#include "TextureTestMeshes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

using namespace hs;
using namespace hs::texture;

namespace {

std::string fileBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

BakeParams smallBake(std::uint64_t seed = 3) {
    BakeParams p;
    p.size = 512;
    p.baseTextureSize = 128;
    p.seed = seed;
    p.labels.myomaValues = {1};
    p.labels.polypValues = {2};
    return p;
}

bool coveredAt(const ImageU8& coverage, double u, double v) {
    const int x = std::clamp(static_cast<int>(u * coverage.width()), 0, coverage.width() - 1);
    const int y = std::clamp(static_cast<int>((1.0 - v) * coverage.height()), 0, coverage.height() - 1);
    return coverage.at(x, y) != 0;
}

} // namespace

TEST(TextureBake, LeavesNoPartOfTheTetMeshBoundaryUnmapped) {
    const SurfaceMesh surface = extractBoundary(test::makeTetCube(8));
    const auto bake = bakeAppearance(surface, smallBake());
    ASSERT_TRUE(bake.ok()) << bake.error().message();
    const Atlas& atlas = bake->atlas;
    for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
        const auto& t = atlas.uvTriangles[f];
        double cu = 0, cv = 0;
        for (std::int32_t i : t) {
            cu += atlas.uvVertices[static_cast<std::size_t>(i)].u / 3;
            cv += atlas.uvVertices[static_cast<std::size_t>(i)].v / 3;
        }
        ASSERT_TRUE(coveredAt(bake->coverage, cu, cv)) << "face " << f;
        for (std::int32_t i : t) { // corners, pulled slightly inwards
            const UvVertex& q = atlas.uvVertices[static_cast<std::size_t>(i)];
            ASSERT_TRUE(coveredAt(bake->coverage, q.u + 0.1 * (cu - q.u), q.v + 0.1 * (cv - q.v))) << "face " << f;
        }
    }
    EXPECT_GT(bake->stats.facesPerClass[1], 0); // region 1 of the cube reaches its top face
    EXPECT_GT(bake->stats.vesselSegments, 0);
}

TEST(TextureBake, SameSeedGivesByteIdenticalFilesWhateverTheThreadCount) {
    const SurfaceMesh organ = test::makeLabelledOrgan(14);
    BakeParams p = smallBake(9);
    p.threads = 1;
    const auto a = bakeAppearance(organ, p);
    p.threads = 2;
    const auto b = bakeAppearance(organ, p);
    ASSERT_TRUE(a.ok() && b.ok());
    test::TempDir dir;
    ASSERT_TRUE(writeBakeOutputs(organ, *a, dir.file("a")).ok());
    ASSERT_TRUE(writeBakeOutputs(organ, *b, dir.file("b")).ok());
    for (const char* name : {"albedo.png", "normal.png", "roughness.png", "surface.vtp", "surface.obj"}) {
        const std::string bytes = fileBytes(dir.path() / "a" / name);
        EXPECT_FALSE(bytes.empty()) << name;
        EXPECT_EQ(bytes, fileBytes(dir.path() / "b" / name)) << name;
    }
}

TEST(TextureBake, MyomaIsPalerThanEndometriumAndSeamsDoNotShow) {
    const SurfaceMesh organ = test::makeLabelledOrgan(16);
    const auto bake = bakeAppearance(organ, smallBake());
    ASSERT_TRUE(bake.ok());
    std::array<double, kAppearanceCount> green{}, count{};
    for (std::size_t f = 0; f < organ.triangles.size(); ++f) {
        double cu = 0, cv = 0;
        for (std::int32_t i : bake->atlas.uvTriangles[f]) {
            cu += bake->atlas.uvVertices[static_cast<std::size_t>(i)].u / 3;
            cv += bake->atlas.uvVertices[static_cast<std::size_t>(i)].v / 3;
        }
        const int x = static_cast<int>(cu * bake->albedo.width()),
                  y = static_cast<int>((1 - cv) * bake->albedo.height());
        const auto c = static_cast<std::size_t>(bake->faceAppearance[f]);
        green[c] += bake->albedo.at(x, y, 1);
        count[c] += 1;
    }
    ASSERT_GT(count[0], 0);
    ASSERT_GT(count[1], 0);
    ASSERT_GT(count[2], 0);
    EXPECT_GT(green[1] / count[1], green[0] / count[0] + 20);
    EXPECT_LT(bake->stats.chartSeamRatio, 1.0);
    EXPECT_LT(bake->atlas.stats.l2Stretch, 1.15);
}

TEST(TextureBake, SurfaceWithoutLabelsIsAllEndometrium) {
    SurfaceMesh organ = test::makeLabelledOrgan(6);
    organ.faceLabels.clear();
    const auto classes = classifyFaces(organ, AppearanceLabels{});
    EXPECT_TRUE(std::all_of(classes.begin(), classes.end(), [](Appearance a) { return a == Appearance::Endometrium; }));
}

TEST(TextureBake, RejectsUnreadableExemplarNamingTheFile) {
    test::TempDir dir;
    {
        std::ofstream garbage(dir.file("mucosa.jpg"), std::ios::binary);
        garbage << "garbage";
    }
    BakeParams p = smallBake();
    p.exemplarFiles[0] = dir.file("mucosa.jpg");
    const auto bake = bakeAppearance(test::makeLabelledOrgan(4), p);
    ASSERT_FALSE(bake.ok());
    EXPECT_EQ(bake.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(bake.error().detail.find("mucosa.jpg"), std::string::npos) << bake.error().detail;
    p.exemplarFiles[0].clear();
    p.size = 100000;
    const auto huge = bakeAppearance(test::makeLabelledOrgan(4), p);
    ASSERT_FALSE(huge.ok());
    EXPECT_EQ(huge.error().code, ErrorCode::LimitExceeded);
}

TEST(TextureVessels, FollowMurraysLawAndAreLargerOverMyomas) {
    const SurfaceMesh organ = test::makeLabelledOrgan(16);
    AppearanceLabels labels;
    labels.myomaValues = {1};
    labels.polypValues = {2};
    VesselParams params;
    const auto net = growVessels(organ, classifyFaces(organ, labels), params);
    ASSERT_TRUE(net.ok());
    std::array<double, kAppearanceCount> maxR{};
    for (const auto& s : net->segments) {
        EXPECT_GE(s.radiusA, s.radiusB - 1e-12); // radii never grow towards the leaves
        auto& m = maxR[static_cast<std::size_t>(s.appearance)];
        m = std::max(m, s.radiusA);
    }
    EXPECT_GT(net->roots[0], 0);
    EXPECT_EQ(net->roots[2], 1); // one central vessel per polyp
    EXPECT_GT(maxR[1], maxR[0]);
    EXPECT_GT(net->nodes[0], 100);
}
