#include "hs/texture/Bake.h"
#include "hs/texture/ImageFiles.h"
#include "hs/texture/Vessels.h"

#include "TestSupport.h"
#include "TextureTestMeshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
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

/// A cervical canal and the start of the cavity as one open tube along +z, seen from inside: the canal (face label
/// "tissue" 3) from the external os at z = 0 to the internal os at z = kCanalMm, the cavity (2) above it; +y
/// anterior. Angle theta runs from +y (anterior) towards +x.
struct CanalTube {
    static constexpr double kRadiusMm = 2.5, kCanalMm = 24.0, kCavityMm = 10.0, kRingMm = 0.5;
    static constexpr int kAround = 32;
    SurfaceMesh mesh;
    int rings = 0;

    CanalTube() {
        rings = static_cast<int>(std::lround((kCanalMm + kCavityMm) / kRingMm)) + 1;
        for (int i = 0; i < rings; ++i)
            for (int j = 0; j < kAround; ++j) {
                const double theta = 2.0 * M_PI * j / kAround;
                mesh.points.push_back({kRadiusMm * std::sin(theta), kRadiusMm * std::cos(theta), i * kRingMm});
            }
        std::vector<std::int32_t> tissue;
        for (int i = 0; i + 1 < rings; ++i)
            for (int j = 0; j < kAround; ++j) {
                const std::int32_t p00 = at(i, j), p01 = at(i, j + 1), p10 = at(i + 1, j), p11 = at(i + 1, j + 1);
                mesh.triangles.push_back({p00, p11, p01}); // normals into the lumen
                mesh.triangles.push_back({p00, p10, p11});
                const std::int32_t t = (i + 0.5) * kRingMm < kCanalMm ? 3 : 2;
                tissue.push_back(t);
                tissue.push_back(t);
            }
        mesh.faceLabels["tissue"] = tissue;
    }
    std::int32_t at(int i, int j) const { return i * kAround + (j % kAround + kAround) % kAround; }

    CanalFrame frame() const {
        CanalFrame f;
        f.externalOsMm = {0.0, 0.0, 0.0};
        f.internalOsMm = {0.0, 0.0, kCanalMm};
        f.anterior = {0.0, 1.0, 0.0};
        f.radiusMm = kRadiusMm;
        return f;
    }

    /// The albedo's luma (0..1) at height z and angle theta (radians from anterior) on the tube.
    double lumaAt(const BakeResult& bake, double z, double theta) const {
        const double fi = z / kRingMm, fj = theta / (2.0 * M_PI) * kAround;
        const int i = std::clamp(static_cast<int>(std::floor(fi)), 0, rings - 2);
        const int j = static_cast<int>(std::floor(fj));
        const double t = fi - i, u = fj - j;
        const std::size_t quad = static_cast<std::size_t>(i * kAround + (j % kAround + kAround) % kAround);
        // Face 2q is (p00, p11, p01), u >= t; face 2q+1 is (p00, p10, p11).
        const std::size_t f = u >= t ? 2 * quad : 2 * quad + 1;
        const std::array<double, 3> w =
            u >= t ? std::array<double, 3>{1.0 - u, t, u - t} : std::array<double, 3>{1.0 - t, t - u, u};
        double uu = 0.0, vv = 0.0;
        for (std::size_t k = 0; k < 3; ++k) {
            const UvVertex& q = bake.atlas.uvVertices[static_cast<std::size_t>(bake.atlas.uvTriangles[f][k])];
            uu += w[k] * q.u;
            vv += w[k] * q.v;
        }
        const int x = std::clamp(static_cast<int>(uu * bake.albedo.width()), 0, bake.albedo.width() - 1);
        const int y = std::clamp(static_cast<int>((1.0 - vv) * bake.albedo.height()), 0, bake.albedo.height() - 1);
        return (0.2126 * bake.albedo.at(x, y, 0) + 0.7152 * bake.albedo.at(x, y, 1) +
                0.0722 * bake.albedo.at(x, y, 2)) /
               255.0;
    }
};

BakeParams canalBake() {
    BakeParams p = smallBake(5);
    p.size = 1024;
    p.vessels = false; // the vessels would cross the folds the test reads
    p.labels.canalValues = {3};
    return p;
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

// Vessels lie beneath the mucosa (docs/texture.md, "Vessels beneath the surface"): blood absorbs green and blue far
// more than red, and green and blue reach only a few tenths of a millimetre into the mucosa, so a capillary just under
// the surface takes green and blue (it shows red) while a deeper, wider vessel takes a little of each, over a band
// wider than itself.
TEST(TextureVessels, ShowThroughTheMucosaRedWhenFineAndDullAndSoftWhenDeep) {
    const auto capillary = vesselShadow(0.02, 0.0);
    const auto deep = vesselShadow(0.3, 0.0);
    std::printf("capillary (0.02 mm): red %.3f, green %.3f, blue %.3f; vessel of 0.3 mm: red %.3f, green %.3f, blue "
                "%.3f\n",
                capillary[0], capillary[1], capillary[2], deep[0], deep[1], deep[2]);
    EXPECT_GT(capillary[1], 10.0 * capillary[0]); // green and blue taken, red kept: the capillary shows red
    EXPECT_GT(capillary[2], 10.0 * capillary[0]);
    EXPECT_GT(capillary[1], 0.1);
    EXPECT_LT(deep[1] / deep[0], 0.5 * capillary[1] / capillary[0]); // depth filters green out: duller
    EXPECT_GT(deep[0], capillary[0]);                                // and it takes more red
    // Softer: the shadow's edge (from 90 % to 10 % of its peak) widens with the depth at which the vessel lies.
    const auto edge = [](double r) {
        const double peak = vesselShadow(r, 0.0)[1];
        double d = 0.0, inner = 0.0;
        for (; vesselShadow(r, d)[1] > 0.1 * peak; d += 1e-4)
            if (vesselShadow(r, d)[1] > 0.9 * peak)
                inner = d;
        return d - inner;
    };
    const double fine = edge(0.02), wide = edge(0.3);
    std::printf("the shadow's edge, 90 to 10 %% of its peak: %.3f mm (radius 0.02 mm), %.3f mm (0.3 mm)\n", fine, wide);
    EXPECT_GT(fine, 0.03); // even a capillary's is softer than a painted line (a texel, 0.05-0.1 mm, at 1024²)
    EXPECT_GT(wide, 3.0 * fine);
    // Nothing beyond its reach; a texel's sampling keeps the shadow's integral.
    for (const double r : {0.02, 0.1, 0.3})
        for (std::size_t k = 0; k < 3; ++k)
            EXPECT_LT(vesselShadow(r, vesselShadowReachMm(r))[k], 1e-3 * vesselShadow(r, 0.0)[k] + 1e-12);
    std::printf("at its reach the 0.3 mm vessel's green shadow is %.2e of its peak\n",
                vesselShadow(0.3, vesselShadowReachMm(0.3))[1] / vesselShadow(0.3, 0.0)[1]);
    double sharp = 0.0, sampled = 0.0;
    for (double d = -2.0; d <= 2.0; d += 1e-3) {
        sharp += vesselShadow(0.05, d)[1] * 1e-3;
        sampled += vesselShadow(0.05, d, 0.1)[1] * 1e-3;
    }
    std::printf("the 0.05 mm vessel's green shadow integrated: %.6f mm sharp, %.6f mm over a 0.1 mm spread\n", sharp,
                sampled);
    EXPECT_NEAR(sampled, sharp, 1e-3 * sharp);
    EXPECT_EQ(vesselShadow(0.0, 0.0), (std::array<double, 3>{}));
    EXPECT_EQ(vesselShadow(0.1, std::nan("")), (std::array<double, 3>{}));
}

// The vessels change the albedo only: the mucosa's surface over them, its normal map, is the same without them.
TEST(TextureBake, VesselsDarkenTheAlbedoAndLeaveTheReliefAsItIs) {
    const SurfaceMesh organ = test::makeLabelledOrgan(16);
    BakeParams with = smallBake();
    BakeParams without = with;
    without.vessels = false;
    const auto a = bakeAppearance(organ, with);
    const auto b = bakeAppearance(organ, without);
    ASSERT_TRUE(a.ok() && b.ok());
    std::printf("%zu vessel segments on the test organ\n", a->vessels.segments.size());
    ASSERT_GT(a->vessels.segments.size(), 100u);
    EXPECT_EQ(a->normal.data(), b->normal.data());
    std::size_t darker = 0, lighter = 0;
    for (std::size_t i = 0; i < a->albedo.data().size(); ++i) {
        darker += a->albedo.data()[i] < b->albedo.data()[i];
        lighter += a->albedo.data()[i] > b->albedo.data()[i];
    }
    std::printf("albedo channels darker with the vessels: %zu, lighter: %zu\n", darker, lighter);
    EXPECT_GT(darker, 1000u);
    EXPECT_EQ(lighter, 0u);
}

TEST(TextureBake, TheCanalHasItsOwnLookOnlyWhereTheLabelSaysSo) {
    const CanalTube tube;
    const auto canal = classifyFaces(tube.mesh, canalBake().labels);
    const auto plain = classifyFaces(tube.mesh, smallBake().labels); // no canal values: all endometrium
    for (std::size_t f = 0; f < canal.size(); ++f) {
        const bool isCanal = tube.mesh.faceLabels.at("tissue")[f] == 3;
        ASSERT_EQ(canal[f], isCanal ? Appearance::CervicalCanal : Appearance::Endometrium) << "face " << f;
        ASSERT_EQ(plain[f], Appearance::Endometrium) << "face " << f;
    }
    // A pathology's label wins over the canal's (a polyp hanging into the canal keeps its look).
    SurfaceMesh withPolyp = tube.mesh;
    withPolyp.faceLabels["region"] = std::vector<std::int32_t>(withPolyp.triangles.size(), 0);
    withPolyp.faceLabels["region"][10] = 2;
    EXPECT_EQ(classifyFaces(withPolyp, canalBake().labels)[10], Appearance::Polyp);
}

TEST(TextureBake, TheCanalShowsThePlicaePalmataeAndTheInternalOsItsRing) {
    // docs/texture.md, "The cervical canal": an anterior and a posterior longitudinal ridge with oblique folds
    // branching upwards from each, the posterior ones between the anterior ones (Gray 1918); smooth lateral walls; a
    // paler ring at the internal os (Mhaskar). The folds' crests are paler than their clefts, so the albedo shows them
    // on the light detail too (no normal map there).
    const CanalTube tube;
    BakeParams p = canalBake();
    p.canal = tube.frame();
    const auto bake = bakeAppearance(tube.mesh, p);
    ASSERT_TRUE(bake.ok()) << bake.error().message();
    BakeParams flat = canalBake(); // the same canal look without the frame: no folds, no ring
    const auto plain = bakeAppearance(tube.mesh, flat);
    ASSERT_TRUE(plain.ok());

    constexpr double kSpacingMm = 2.6, kRise = 0.8; // the folds as Shading.cpp draws them
    // Along a line beside each ridge (1-1.5 mm of arc off it), the crests' places against the clefts' places (half a
    // fold further), over the lower two thirds of the canal, on both sides of both ridges.
    const auto contrast = [&](const BakeResult& b, bool anteriorWall, double phaseShift, double offMm = 0.0) {
        double crests = 0.0, clefts = 0.0;
        int n = 0;
        for (double arcMm : {offMm + 1.0, offMm + 1.25, offMm + 1.5})
            for (double side : {-1.0, 1.0})
                for (int k = 1; k <= 6; ++k) {
                    const double theta = (anteriorWall ? 0.0 : M_PI) + side * arcMm / CanalTube::kRadiusMm;
                    const double crestZ = (k + phaseShift) * kSpacingMm + kRise * arcMm;
                    crests += tube.lumaAt(b, crestZ, theta);
                    clefts += tube.lumaAt(b, crestZ + 0.5 * kSpacingMm, theta);
                    ++n;
                }
        return (crests - clefts) / n;
    };
    const double anterior = contrast(*bake, true, 0.0);
    const double posteriorBetween = contrast(*bake, false, 0.5); // the posterior crests lie half a fold up
    const double posteriorOpposite = contrast(*bake, false, 0.0);
    const double none = contrast(*plain, true, 0.0);
    // The lateral walls, a quarter turn from the ridges (1.57 rad, beyond the folds' 1.35): where the folds would
    // continue, nothing.
    const double lateral = contrast(*bake, true, 0.0, 0.5 * M_PI * CanalTube::kRadiusMm - 1.25);
    // The ring: the luma around the internal os against the canal 4 mm below it and the cavity 5 mm above it.
    const auto ringLuma = [&](const BakeResult& b, double z) {
        double sum = 0.0;
        for (int j = 0; j < 16; ++j)
            sum += tube.lumaAt(b, z, 2.0 * M_PI * (j + 0.5) / 16);
        return sum / 16;
    };
    const double os = ringLuma(*bake, CanalTube::kCanalMm), below = ringLuma(*bake, CanalTube::kCanalMm - 4.0),
                 above = ringLuma(*bake, CanalTube::kCanalMm + 5.0);
    const double osPlain = ringLuma(*plain, CanalTube::kCanalMm);
    std::printf("crest - cleft luma: anterior %.4f, posterior between %.4f, posterior opposite %.4f, no frame %.4f, "
                "lateral wall %.4f\n"
                "ring luma %.3f (no frame %.3f), canal below %.3f, cavity above %.3f\n",
                anterior, posteriorBetween, posteriorOpposite, none, lateral, os, osPlain, below, above);
    // Crests paler than clefts, by more than the mucosa's own texture gives at the same places without the folds.
    EXPECT_GT(anterior, 0.03);
    EXPECT_GT(posteriorBetween, 0.03);
    EXPECT_LT(posteriorOpposite, 0.0); // opposite the anterior crests, the posterior wall has its clefts
    EXPECT_LT(std::abs(none), 0.5 * anterior);
    EXPECT_LT(std::abs(lateral), 0.5 * anterior); // folds on the front and back walls, smooth lateral walls
    EXPECT_GT(os, below + 0.03);
    EXPECT_GT(os, above + 0.03);
    EXPECT_GT(os, osPlain + 0.03);

    // A frame that cannot be a canal is refused by name.
    p.canal->internalOsMm = p.canal->externalOsMm;
    const auto bad = bakeAppearance(tube.mesh, p);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().detail.find("canal"), std::string::npos) << bad.error().detail;
}
