// The scope passage check on synthetic bodies built here: a thick-walled tube (the canal) with a closed chamber on
// top (the cavity), meshed as a lattice of cubes split into six tets each, so the free widths are known exactly.
#include "hs/scene/ScopePassage.h"

#include "hs/scene/Scene.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

using namespace hs;
using namespace hs::scene;

namespace {

constexpr double kCellMm = 0.5;
constexpr double kOuterRadiusMm = 6.0;
constexpr double kCanalTopMm = 20.0; ///< the internal os
constexpr double kChamberCentreMm = 24.0;
constexpr double kChamberRadiusMm = 4.0;
constexpr double kTopMm = 32.0;

/// Tets filling the lattice cells of edge kCellMm in [lo, hi] whose centre is tissue. Each cube is split into the
/// six tets around its main diagonal (Freudenthal), which conform across cubes.
TetMesh latticeBody(const Vec3& lo, const Vec3& hi, const std::function<bool(const Vec3&)>& tissue) {
    const int nx = int(std::lround((hi.x - lo.x) / kCellMm)), ny = int(std::lround((hi.y - lo.y) / kCellMm)),
              nz = int(std::lround((hi.z - lo.z) / kCellMm));
    std::vector<std::int32_t> node(std::size_t((nx + 1) * (ny + 1) * (nz + 1)), -1);
    TetMesh mesh;
    auto nodeAt = [&](int i, int j, int k) {
        auto& id = node[std::size_t((k * (ny + 1) + j) * (nx + 1) + i)];
        if (id < 0) {
            id = std::int32_t(mesh.points.size());
            mesh.points.push_back(lo + Vec3(i, j, k) * kCellMm);
        }
        return id;
    };
    static const std::array<std::array<int, 4>, 6> kKuhn{
        {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}}};
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                if (!tissue(lo + Vec3(i + 0.5, j + 0.5, k + 0.5) * kCellMm))
                    continue;
                for (const auto& corners : kKuhn) {
                    Tet t;
                    for (int c = 0; c < 4; ++c)
                        t[std::size_t(c)] =
                            nodeAt(i + (corners[std::size_t(c)] & 1), j + ((corners[std::size_t(c)] >> 1) & 1),
                                   k + ((corners[std::size_t(c)] >> 2) & 1));
                    mesh.tets.push_back(t);
                    if (signedVolume(mesh, mesh.tets.size() - 1) < 0.0)
                        std::swap(mesh.tets.back()[2], mesh.tets.back()[3]);
                }
            }
    mesh.regions.assign(mesh.tets.size(), 0);
    return mesh;
}

TetMesh latticeBody(const std::function<bool(const Vec3&)>& tissue) {
    return latticeBody(Vec3(-kOuterRadiusMm, -kOuterRadiusMm, 0.0), Vec3(kOuterRadiusMm, kOuterRadiusMm, kTopMm),
                       tissue);
}

/// A cylinder of radius 6 with a square canal of half-side canalHalfMm(z) from z = 0 to 20 and a spherical chamber
/// of radius 4 at z = 24: the canal's free width is 2 * canalHalfMm exactly (lattice-aligned).
TetMesh tubeWithChamber(const std::function<double(double)>& canalHalfMm) {
    return latticeBody([&](const Vec3& p) {
        if (p.x * p.x + p.y * p.y > kOuterRadiusMm * kOuterRadiusMm)
            return false;
        if (p.z < kCanalTopMm + 1.0 && std::fabs(p.x) < canalHalfMm(p.z) && std::fabs(p.y) < canalHalfMm(p.z))
            return false;
        return distance(p, Vec3(0, 0, kChamberCentreMm)) > kChamberRadiusMm;
    });
}

ScopeLandmarks tubeLandmarks() {
    return {Vec3(0, 0, 0), Vec3(0, 0, kCanalTopMm), Vec3(0, 0, kChamberCentreMm + 2.0)};
}

ScopePassage check(const TetMesh& mesh, double diameterMm) {
    ScopePassageParams params;
    params.scopeDiameterMm = diameterMm;
    auto r = checkScopePassage(mesh, tubeLandmarks(), params);
    EXPECT_TRUE(r.ok()) << r.error().message();
    return r.ok() ? *r : ScopePassage{};
}

} // namespace

TEST(ScopePassage, PassesAThinScopeThroughAFiveMillimetreCanal) {
    const auto passage = check(tubeWithChamber([](double) { return 2.5; }), 2.9);
    EXPECT_TRUE(passage.open);
    EXPECT_TRUE(passage.ballPasses);
    EXPECT_TRUE(passage.straightPasses);
    EXPECT_NEAR(passage.narrowest.freeWidthMm, 5.0, 0.1);
    ASSERT_FALSE(passage.route.empty());
    EXPECT_LT(passage.route.front().positionMm.z, 0.0);
    EXPECT_EQ(passage.route.front().part, PassagePart::Outside);
    EXPECT_EQ(passage.route.back().part, PassagePart::Cavity);
    EXPECT_LE(distance(passage.route.back().positionMm, tubeLandmarks().fundusMm), 5.0);
}

TEST(ScopePassage, StopsAScopeWiderThanATwoMillimetreCanal) {
    const auto passage = check(tubeWithChamber([](double) { return 1.0; }), 2.9);
    EXPECT_TRUE(passage.open);
    EXPECT_FALSE(passage.ballPasses);
    EXPECT_FALSE(passage.straightPasses);
    EXPECT_NEAR(passage.narrowest.freeWidthMm, 2.0, 0.1);
    // The canal is equally narrow everywhere: the first narrowest point from the start is at its entrance.
    EXPECT_GT(passage.narrowest.positionMm.z, -passage.voxelSizeMm);
    EXPECT_LT(passage.narrowest.positionMm.z, kCanalTopMm);
}

TEST(ScopePassage, ReportsAPinchedNeckAsTheNarrowestPointAtItsHeight) {
    // 5 mm wide, pinched to 2 mm in the one cell layer 12.0-12.5 mm (centre 12.25).
    const auto mesh = tubeWithChamber([](double z) { return z > 12.0 && z < 12.5 ? 1.0 : 2.5; });
    const auto passage = check(mesh, 2.9);
    EXPECT_TRUE(passage.open);
    EXPECT_FALSE(passage.ballPasses);
    EXPECT_NEAR(passage.narrowest.freeWidthMm, 2.0, 0.1);
    EXPECT_NEAR(passage.narrowest.positionMm.z, 12.25, passage.voxelSizeMm);
    EXPECT_EQ(passage.narrowest.part, PassagePart::Canal);
    EXPECT_EQ(passage.narrowestCanal.positionMm, passage.narrowest.positionMm);
    EXPECT_TRUE(passage.canalOpen);
    EXPECT_FALSE(passage.canalPasses);
    // A 1.8 mm scope goes through the neck.
    EXPECT_TRUE(check(mesh, 1.8).ballPasses);
}

TEST(ScopePassage, ReportsAClosedCanalWhereTissueClosesIt) {
    const auto mesh = tubeWithChamber([](double z) { return z > 8.0 && z < 9.0 ? 0.0 : 2.5; });
    const auto passage = check(mesh, 2.9);
    EXPECT_FALSE(passage.open);
    EXPECT_FALSE(passage.ballPasses);
    EXPECT_EQ(passage.narrowest.freeWidthMm, 0.0);
    // The route ends below the 1 mm closure (its lower face at z = 8).
    EXPECT_NEAR(passage.narrowest.positionMm.z, 8.0, passage.voxelSizeMm);
    EXPECT_EQ(passage.route.back().positionMm, passage.narrowest.positionMm);
    EXPECT_NEAR(passage.closedGapMm, 1.0, passage.voxelSizeMm);
    EXPECT_FALSE(passage.canalOpen);
    EXPECT_EQ(passage.canalClosedGapMm, passage.closedGapMm);
}

TEST(ScopePassage, ReportsASolidBodyAsClosed) {
    const auto passage = check(tubeWithChamber([](double) { return 0.0; }), 2.9);
    EXPECT_FALSE(passage.open);
    EXPECT_EQ(passage.narrowest.freeWidthMm, 0.0);
}

TEST(ScopePassage, FindsTheInternalOsNarrowerThanTheCanal) {
    // A 5 mm canal that narrows to 3 mm in its last millimetre, at the internal os.
    const auto mesh = tubeWithChamber([](double z) { return z > 19.0 ? 1.5 : 2.5; });
    const auto passage = check(mesh, 2.9);
    EXPECT_TRUE(passage.ballPasses);
    EXPECT_NEAR(passage.narrowest.freeWidthMm, 3.0, 0.1);
    EXPECT_EQ(passage.narrowest.part, PassagePart::InternalOs);
}

TEST(ScopePassage, FailsTheStraightStretchAtABendTheBallGetsThrough) {
    // An L-shaped canal 4 mm square: up from the external os at x = -8 to z = 16, then along +x to a chamber at
    // x = 8. A 2.9 mm ball follows it; 10 mm of straight scope cannot turn the corner.
    const auto mesh = latticeBody(Vec3(-12, -4, 0), Vec3(12, 4, 24), [](const Vec3& p) {
        const bool across = std::fabs(p.y) < 2.0;
        const bool up = across && p.x > -10.0 && p.x < -6.0 && p.z < 16.0;
        const bool along = across && p.x > -10.0 && p.x < 10.0 && p.z > 12.0 && p.z < 16.0;
        const bool chamber = across && p.x > 6.0 && p.x < 10.0 && p.z > 12.0 && p.z < 20.0;
        return !(up || along || chamber);
    });
    ScopePassageParams params;
    params.scopeDiameterMm = 2.9;
    auto r = checkScopePassage(mesh, {Vec3(-8, 0, 0), Vec3(-8, 0, 12), Vec3(8, 0, 18)}, params);
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_TRUE(r->ballPasses);
    EXPECT_NEAR(r->narrowest.freeWidthMm, 4.0, 0.1);
    EXPECT_FALSE(r->straightPasses);
    EXPECT_LT(r->straightWidthMm, 2.9);
    // Without a straight stretch only the ball counts.
    params.straightLengthMm = 0.0;
    auto ball = checkScopePassage(mesh, {Vec3(-8, 0, 0), Vec3(-8, 0, 12), Vec3(8, 0, 18)}, params);
    ASSERT_TRUE(ball.ok());
    EXPECT_TRUE(ball->straightPasses);
}

TEST(ScopePassage, TellsANarrowCavityFromANarrowCanal) {
    // A 5 mm canal into a chamber that a 2 mm slot at z = 24 narrows (a pathology in the cavity, say).
    const auto mesh = latticeBody([](const Vec3& p) {
        if (p.x * p.x + p.y * p.y > kOuterRadiusMm * kOuterRadiusMm)
            return false;
        if (p.z < kCanalTopMm + 1.0 && std::fabs(p.x) < 2.5 && std::fabs(p.y) < 2.5)
            return false;
        if (p.z > 24.0 && p.z < 25.0 && (std::fabs(p.x) > 1.0 || std::fabs(p.y) > 1.0))
            return true;
        return distance(p, Vec3(0, 0, kChamberCentreMm)) > kChamberRadiusMm;
    });
    ScopePassageParams params;
    params.fundusReachMm = 1.0; // the fundus beyond the slot
    auto r = checkScopePassage(mesh, tubeLandmarks(), params);
    ASSERT_TRUE(r.ok()) << r.error().message();
    EXPECT_FALSE(r->ballPasses);
    EXPECT_NEAR(r->narrowest.freeWidthMm, 2.0, 0.1);
    EXPECT_EQ(r->narrowest.part, PassagePart::Cavity);
    EXPECT_TRUE(r->canalPasses);
    EXPECT_GT(r->narrowestCanal.freeWidthMm, 4.0); // the canal's square meeting the chamber's sphere
}

TEST(ScopePassage, GivesTheSameReportEveryRun) {
    const auto mesh = tubeWithChamber([](double z) { return z > 12.0 && z < 12.5 ? 1.0 : 2.5; });
    const auto a = check(mesh, 2.9);
    const auto b = check(mesh, 2.9);
    ASSERT_EQ(a.route.size(), b.route.size());
    for (std::size_t i = 0; i < a.route.size(); ++i) {
        EXPECT_EQ(a.route[i].positionMm, b.route[i].positionMm);
        EXPECT_EQ(a.route[i].freeWidthMm, b.route[i].freeWidthMm);
    }
    EXPECT_EQ(a.narrowest.positionMm, b.narrowest.positionMm);
    EXPECT_EQ(a.straightWidthMm, b.straightWidthMm);
}

TEST(ScopePassage, RefusesAnEmptyOrInvalidMesh) {
    auto empty = checkScopePassage(TetMesh{}, tubeLandmarks());
    ASSERT_FALSE(empty.ok());
    EXPECT_EQ(empty.error().code, ErrorCode::InvalidInput);

    TetMesh broken;
    broken.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    broken.tets = {Tet{0, 1, 2, 7}};
    auto invalid = checkScopePassage(broken, tubeLandmarks());
    ASSERT_FALSE(invalid.ok());
    EXPECT_EQ(invalid.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(invalid.error().detail.find("invalid tet mesh"), std::string::npos);

    TetMesh flat;
    flat.points = {Vec3(0, 0, 0), Vec3(30, 0, 0), Vec3(0, 30, 0), Vec3(30, 30, 0)};
    flat.tets = {Tet{0, 1, 2, 3}};
    auto thin = checkScopePassage(flat, {Vec3(1, 1, 0), Vec3(20, 20, 0), Vec3(25, 25, 0)});
    ASSERT_FALSE(thin.ok());
    EXPECT_EQ(thin.error().code, ErrorCode::InvalidInput);
}

TEST(ScopePassage, RefusesParametersOutOfRangeNamingThem) {
    const auto mesh = tubeWithChamber([](double) { return 2.5; });
    const std::vector<std::pair<std::function<void(ScopePassageParams&)>, std::string>> cases{
        {[](ScopePassageParams& p) { p.scopeDiameterMm = 0.5; }, "scopeDiameterMm"},
        {[](ScopePassageParams& p) { p.scopeDiameterMm = 11.0; }, "scopeDiameterMm"},
        {[](ScopePassageParams& p) { p.scopeDiameterMm = std::nan(""); }, "scopeDiameterMm"},
        {[](ScopePassageParams& p) { p.voxelFraction = 0.01; }, "voxelFraction"},
        {[](ScopePassageParams& p) { p.straightLengthMm = -1.0; }, "straightLengthMm"},
        {[](ScopePassageParams& p) { p.startOffsetMm = 0.0; }, "startOffsetMm"},
        {[](ScopePassageParams& p) { p.fundusReachMm = 100.0; }, "fundusReachMm"},
        {[](ScopePassageParams& p) { p.maxVoxels = 0; }, "maxVoxels"},
    };
    for (const auto& [edit, name] : cases) {
        ScopePassageParams params;
        edit(params);
        auto r = checkScopePassage(mesh, tubeLandmarks(), params);
        ASSERT_FALSE(r.ok()) << name;
        EXPECT_EQ(r.error().code, ErrorCode::InvalidInput) << name;
        EXPECT_NE(r.error().detail.find(name), std::string::npos) << r.error().detail;
        EXPECT_NE(r.error().detail.find(".."), std::string::npos) << r.error().detail;
    }
}

TEST(ScopePassage, RefusesAGridAboveTheVoxelLimit) {
    ScopePassageParams params;
    params.maxVoxels = 1000;
    auto r = checkScopePassage(tubeWithChamber([](double) { return 2.5; }), tubeLandmarks(), params);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::LimitExceeded);
    EXPECT_NE(r.error().detail.find("maxVoxels 1000"), std::string::npos) << r.error().detail;
}

TEST(ScopePassage, RefusesLandmarksThatAreNotFiniteCoincideOrLieOutside) {
    const auto mesh = tubeWithChamber([](double) { return 2.5; });
    ScopeLandmarks nan = tubeLandmarks();
    nan.fundusMm.x = std::nan("");
    ScopeLandmarks same = tubeLandmarks();
    same.internalOsMm = same.externalOsMm;
    ScopeLandmarks outside = tubeLandmarks();
    outside.externalOsMm = Vec3(0, 0, -100);
    for (const auto& l : {nan, same, outside}) {
        auto r = checkScopePassage(mesh, l);
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().code, ErrorCode::InvalidInput);
    }
}

TEST(ScopePassage, StopsWhenCancelled) {
    Progress progress;
    progress.requestCancel();
    auto r = checkScopePassage(tubeWithChamber([](double) { return 2.5; }), tubeLandmarks(), {}, progress);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::Cancelled);
}

TEST(ScopeLandmarks, FindsBothOsAndTheFundusFromLabelledFaces) {
    const auto body = tubeWithChamber([](double) { return 2.5; });
    const SurfaceMesh surface = extractBoundary(body);
    std::vector<std::int32_t> canal, ostia;
    for (std::size_t f = 0; f < surface.faceCount(); ++f) {
        const auto& t = surface.triangles[f];
        const Vec3 c = (surface.points[std::size_t(t[0])] + surface.points[std::size_t(t[1])] +
                        surface.points[std::size_t(t[2])]) /
                       3.0;
        const bool lumen = std::fabs(c.x) <= 2.5 && std::fabs(c.y) <= 2.5;
        if (lumen && c.z > 0.0 && c.z < kCanalTopMm)
            canal.push_back(std::int32_t(f));
        // Two "ostia" on either side of the chamber's top.
        if (distance(c, Vec3(0, 0, kChamberCentreMm)) < kChamberRadiusMm + 1.0 && c.z > kChamberCentreMm + 1.0 &&
            std::fabs(c.x) > 2.0)
            ostia.push_back(std::int32_t(f));
    }
    ASSERT_FALSE(canal.empty());
    ASSERT_FALSE(ostia.empty());
    auto l = findScopeLandmarks(surface, canal, ostia);
    ASSERT_TRUE(l.ok()) << l.error().message();
    EXPECT_NEAR(distance(l->externalOsMm, Vec3(0, 0, 0)), 0.0, 1.0);
    EXPECT_NEAR(distance(l->internalOsMm, Vec3(0, 0, kCanalTopMm)), 0.0, 1.5);
    EXPECT_NEAR(l->fundusMm.x, 0.0, 0.5);
    EXPECT_GT(l->fundusMm.z, kChamberCentreMm);
    EXPECT_EQ(l->ostiaFound, 2);
    auto passage = checkScopePassage(body, *l);
    ASSERT_TRUE(passage.ok()) << passage.error().message();
    EXPECT_TRUE(passage->ballPasses);
}

TEST(ScopeLandmarks, TakesASingleOstiumForTheFundusAndSaysSo) {
    const auto body = tubeWithChamber([](double) { return 2.5; });
    const SurfaceMesh surface = extractBoundary(body);
    std::vector<std::int32_t> canal, ostium;
    for (std::size_t f = 0; f < surface.faceCount(); ++f) {
        const auto& t = surface.triangles[f];
        const Vec3 c = (surface.points[std::size_t(t[0])] + surface.points[std::size_t(t[1])] +
                        surface.points[std::size_t(t[2])]) /
                       3.0;
        if (std::fabs(c.x) <= 2.5 && std::fabs(c.y) <= 2.5 && c.z > 0.0 && c.z < kCanalTopMm)
            canal.push_back(std::int32_t(f));
        if (distance(c, Vec3(3.0, 0, kChamberCentreMm + 2.0)) < 1.5)
            ostium.push_back(std::int32_t(f));
    }
    ASSERT_FALSE(ostium.empty());
    auto l = findScopeLandmarks(surface, canal, ostium);
    ASSERT_TRUE(l.ok()) << l.error().message();
    EXPECT_EQ(l->ostiaFound, 1);
    EXPECT_LT(distance(l->fundusMm, Vec3(3.0, 0, kChamberCentreMm + 2.0)), 1.5);
}

TEST(ScopeLandmarks, RefusesMissingOrOutOfRangeFaces) {
    const SurfaceMesh surface = extractBoundary(tubeWithChamber([](double) { return 2.5; }));
    auto noCanal = findScopeLandmarks(surface, {}, {0});
    ASSERT_FALSE(noCanal.ok());
    EXPECT_NE(noCanal.error().detail.find("cervical-canal"), std::string::npos);
    auto noOstia = findScopeLandmarks(surface, {0, 1, 2}, {});
    ASSERT_FALSE(noOstia.ok());
    EXPECT_NE(noOstia.error().detail.find("ostium"), std::string::npos);
    auto outOfRange = findScopeLandmarks(surface, {0, std::int32_t(surface.faceCount())}, {0});
    ASSERT_FALSE(outOfRange.ok());
    EXPECT_EQ(outOfRange.error().code, ErrorCode::InvalidInput);
    Scene scene;
    auto noLabels = findScopeLandmarks(scene);
    ASSERT_FALSE(noLabels.ok());
    EXPECT_NE(noLabels.error().detail.find("cervical-canal"), std::string::npos);
}
