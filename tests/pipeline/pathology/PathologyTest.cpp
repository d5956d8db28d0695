// The pathology stage's bars: FIGO type and size measured from the geometry, impossible requests, timings.
#include "OrganOstia.h"
#include "SampleOrgans.h"
#include "TestSupport.h"

#include "hs/merge/Merge.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

namespace hs::pathology {
namespace {

using clinical::FigoType;
using clinical::GrowthModel;
using clinical::LasmarScore;
using clinical::SurfacePlacement;
using clinical::UterineLocation;
using test::myoma;
using test::polyp;

/// Creases (degrees between the normals of two faces sharing an edge) of the organ's endometrium within `reach` of
/// `centre`, where a pocket opened in the cavity meets the wall: the 99th percentile and how many exceed 30 degrees.
struct Creases {
    double p99Deg = 0.0;
    int over30 = 0;
};
Creases cavityCreases(const SurfaceMesh& organ, const Vec3& centre, double reach) {
    const auto& tissue = organ.faceLabels.at("tissue");
    std::map<std::pair<std::int32_t, std::int32_t>, std::size_t> firstFace;
    std::vector<double> angles;
    for (std::size_t f = 0; f < organ.triangles.size(); ++f) {
        if (static_cast<clinical::SurfaceTissue>(tissue[f]) != clinical::SurfaceTissue::Endometrium)
            continue;
        const Triangle& tri = organ.triangles[f];
        for (int k = 0; k < 3; ++k) {
            const std::int32_t a = tri[static_cast<std::size_t>(k)], b = tri[static_cast<std::size_t>((k + 1) % 3)];
            const auto key = std::minmax(a, b);
            const auto it = firstFace.find(key);
            if (it == firstFace.end()) {
                firstFace.emplace(key, f);
                continue;
            }
            const Vec3 mid =
                (organ.points[static_cast<std::size_t>(a)] + organ.points[static_cast<std::size_t>(b)]) * 0.5;
            if (distance(mid, centre) > reach)
                continue;
            const double c = std::clamp(dot(faceNormal(organ, f), faceNormal(organ, it->second)), -1.0, 1.0);
            angles.push_back(std::acos(c) * 180.0 / 3.14159265358979323846);
        }
    }
    Creases out;
    if (angles.empty())
        return out;
    std::sort(angles.begin(), angles.end());
    out.p99Deg = angles[angles.size() * 99 / 100];
    out.over30 = static_cast<int>(angles.end() - std::upper_bound(angles.begin(), angles.end(), 30.0));
    return out;
}

double secondsOf(const std::chrono::steady_clock::time_point& start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Case {
    GrowthModel model;
    FigoType figo;
};

std::string caseName(const testing::TestParamInfo<Case>& info) {
    std::string figo = info.param.figo.toString();
    for (char& c : figo)
        if (c == '-')
            c = '_';
    return std::string(toString(info.param.model)) + "_figo" + figo;
}

class FigoBar : public testing::TestWithParam<Case> {};

// The default run uses 3 organs (bench_pathology sweeps 20); a 20 mm myoma at the posterior wall.
TEST_P(FigoBar, MeasuredTypeAndSizeMatchAndTheMergedBodyIsValid) {
    const Case c = GetParam();
    int figoMatches = 0, organs = 3;
    for (int seed = 1; seed <= organs; ++seed) {
        PathologyParams params;
        params.seed = static_cast<std::uint64_t>(seed);
        params.pathologies.push_back(myoma("m", c.model, c.figo, 20.0));
        auto grown = growPathologies(test::testOrgan(static_cast<std::uint64_t>(seed)), params);
        ASSERT_TRUE(grown.ok()) << grown.error().detail;
        const Descriptors& d = grown->pathologies[0].descriptors;
        figoMatches += d.figo == c.figo ? 1 : 0;
        EXPECT_NEAR(d.sizeMm, 20.0, 2.0) << "seed " << seed;
        auto body = merge::mergeBody(*grown);
        ASSERT_TRUE(body.ok()) << "seed " << seed << ": " << body.error().detail;
        for (const auto& s : body->body.surfaces)
            EXPECT_TRUE(analyzeTopology(s.surface).isWatertight()) << s.name;
    }
    EXPECT_EQ(figoMatches, organs);
}

INSTANTIATE_TEST_SUITE_P(Pathology, FigoBar,
                         testing::Values(Case{GrowthModel::Skeleton, {0, -1}}, Case{GrowthModel::Skeleton, {1, -1}},
                                         Case{GrowthModel::Skeleton, {2, -1}}, Case{GrowthModel::Skeleton, {3, -1}},
                                         Case{GrowthModel::Skeleton, {4, -1}}, Case{GrowthModel::Skeleton, {5, -1}},
                                         Case{GrowthModel::Skeleton, {6, -1}}, Case{GrowthModel::Skeleton, {7, -1}},
                                         Case{GrowthModel::Skeleton, {2, 5}}, Case{GrowthModel::Particles, {0, -1}},
                                         Case{GrowthModel::Particles, {1, -1}}, Case{GrowthModel::Particles, {2, -1}},
                                         Case{GrowthModel::Particles, {3, -1}}, Case{GrowthModel::Particles, {4, -1}},
                                         Case{GrowthModel::Particles, {5, -1}}, Case{GrowthModel::Particles, {6, -1}},
                                         Case{GrowthModel::Particles, {7, -1}}, Case{GrowthModel::Particles, {2, 5}}),
                         caseName);

struct PolypCase {
    GrowthModel model;
    bool pedunculated;
    UterineLocation where;
};

std::string polypName(const testing::TestParamInfo<PolypCase>& info) {
    std::string where(toString(info.param.where));
    for (char& c : where)
        if (c == '-')
            c = '_';
    return std::string(toString(info.param.model)) + (info.param.pedunculated ? "_pedunculated_" : "_sessile_") + where;
}

class PolypBar : public testing::TestWithParam<PolypCase> {};

// 12 mm polyps (pedunculated: on an 8 mm stalk) in 3 organs: grown, a stalk measured exactly when one was asked
// for, the size (of the head) within 10 %, merged into a valid body.
TEST_P(PolypBar, GrowsWithItsStalkAndSizeAndMergesIntoAValidBody) {
    const PolypCase c = GetParam();
    double stalkSum = 0.0;
    for (int seed = 1; seed <= 3; ++seed) {
        PathologyParams params;
        params.seed = static_cast<std::uint64_t>(seed);
        params.pathologies.push_back(polyp("p", c.model, 12.0, c.pedunculated, c.pedunculated ? 8.0 : 0.0, c.where));
        auto grown = growPathologies(test::testOrgan(static_cast<std::uint64_t>(seed)), params);
        ASSERT_TRUE(grown.ok()) << "seed " << seed << ": " << grown.error().detail;
        const Descriptors& d = grown->pathologies[0].descriptors;
        EXPECT_EQ(d.pedunculated, c.pedunculated) << "seed " << seed;
        if (c.pedunculated) {
            EXPECT_NEAR(d.stalkLengthMm, 8.0, 1.5) << "seed " << seed;
            stalkSum += d.stalkLengthMm;
        }
        EXPECT_NEAR(d.sizeMm, 12.0, 1.2) << "seed " << seed;
        EXPECT_GT(d.cavityFraction, 0.5) << "seed " << seed;
        auto body = merge::mergeBody(*grown);
        EXPECT_TRUE(body.ok()) << "seed " << seed << ": " << (body.ok() ? "" : body.error().detail);
    }
    if (c.pedunculated) { // 8 mm asked; the particle model's measured 9.4 mm on average when scaled about the foot
        EXPECT_NEAR(stalkSum / 3.0, 8.0, 0.8);
    }
}

INSTANTIATE_TEST_SUITE_P(Pathology, PolypBar,
                         testing::Values(PolypCase{GrowthModel::Skeleton, false, UterineLocation::Fundal},
                                         PolypCase{GrowthModel::Skeleton, true, UterineLocation::Fundal},
                                         PolypCase{GrowthModel::Skeleton, false, UterineLocation::Posterior},
                                         PolypCase{GrowthModel::Skeleton, true, UterineLocation::Posterior},
                                         PolypCase{GrowthModel::Particles, false, UterineLocation::Fundal},
                                         PolypCase{GrowthModel::Particles, true, UterineLocation::Fundal},
                                         PolypCase{GrowthModel::Particles, false, UterineLocation::Posterior},
                                         PolypCase{GrowthModel::Particles, true, UterineLocation::Posterior}),
                         polypName);

// The former default case: a 25 mm FIGO 2 posterior myoma and a pedunculated fundal polyp (10 mm, stalk 8 mm) in the
// same cavity. The polyp's pushes once stretched the myoma to 31 mm, and the myoma's the polyp to 20 mm (measured
// sessile, its head in the anterior wall).
TEST(Pathology, PlacesAPosteriorMyomaBesideAPedunculatedFundalPolyp) {
    for (GrowthModel model : {GrowthModel::Skeleton, GrowthModel::CellularAutomaton}) {
        PathologyParams params;
        params.pathologies.push_back(myoma("m", model, {2, -1}, 25.0, UterineLocation::Posterior));
        params.pathologies.push_back(polyp("p", GrowthModel::Skeleton, 10.0, true, 8.0, UterineLocation::Fundal));
        auto grown = growPathologies(test::testOrgan(1), params);
        ASSERT_TRUE(grown.ok()) << grown.error().detail;
        const Descriptors& m = grown->pathologies[0].descriptors;
        const Descriptors& p = grown->pathologies[1].descriptors;
        EXPECT_EQ(m.figo, (FigoType{2, -1})) << toString(model);
        EXPECT_NEAR(m.sizeMm, 25.0, 2.5) << toString(model);
        EXPECT_TRUE(p.pedunculated) << toString(model);
        EXPECT_NEAR(p.sizeMm, 10.0, 1.0) << toString(model);
        auto body = merge::mergeBody(*grown);
        EXPECT_TRUE(body.ok()) << (body.ok() ? "" : body.error().detail);
    }
}

// The pushes that open the cavity around a head on a stalk left a box-like pocket with square corners where it met the
// wall; the walls now collapse onto the head (keeping the clearance), so the pocket is rounded: fewer sharp creases.
TEST(Pathology, OpensARoundedPocketAroundAHeadOnAStalk) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        PathologyParams params;
        params.seed = seed;
        params.pathologies.push_back(myoma("m", GrowthModel::Skeleton, {0, -1}, 20.0));
        auto grown = growPathologies(test::testOrgan(seed), params);
        ASSERT_TRUE(grown.ok()) << grown.error().detail;
        Vec3 head; // the vertex mean: near the head's centre, pulled a little towards the stalk
        for (const Vec3& q : grown->pathologies[0].surface.points)
            head += q;
        head = head / static_cast<double>(grown->pathologies[0].surface.points.size());
        const Creases c = cavityCreases(grown->organ, head, 25.0);
        std::printf("organ %d: pocket creases p99 %.1f deg, %d over 30 deg\n", static_cast<int>(seed), c.p99Deg,
                    c.over30);
        // Measured: 28-33 deg and 26-37 edges; without the rounding 44-53 deg and 64-88 edges.
        EXPECT_LT(c.p99Deg, 38.0) << "organ " << seed;
        EXPECT_LT(c.over30, 45) << "organ " << seed;
    }
}

// A clinical location names a wall: organ 6's posterior wall is about 17 mm thick at the nominal seat, too thick for a
// 20 mm hybrid to span, so the seat slides to a thinner part of the same wall. A point placement stays where it is.
TEST(Pathology, SlidesAHybridsSeatToWhereTheWallIsThinEnoughButKeepsAPointPlacement) {
    const SurfaceMesh organ = test::testOrgan(6);
    PathologyParams params;
    params.pathologies.push_back(myoma("m", GrowthModel::Skeleton, {2, -1}, 20.0));
    auto nominal = growPathologies(organ, params);
    ASSERT_TRUE(nominal.ok()) << nominal.error().detail;
    const Vec3 seat = nominal->pathologies[0].anchor;

    params.pathologies[0].figo = {2, 5};
    auto hybrid = growPathologies(organ, params);
    ASSERT_TRUE(hybrid.ok()) << hybrid.error().detail;
    EXPECT_EQ(hybrid->pathologies[0].descriptors.figo, (FigoType{2, 5}));
    const double slid = distance(hybrid->pathologies[0].anchor, seat);
    EXPECT_GT(slid, 1.0);
    EXPECT_LT(slid, 0.4 * 50.0);
    ASSERT_EQ(hybrid->warnings.size(), 1u); // the slide is reported
    EXPECT_NE(hybrid->warnings[0].find("too thick for a 20 mm FIGO 2-5 myoma to span; seated"), std::string::npos)
        << hybrid->warnings[0];

    params.pathologies[0].placement = SurfacePlacement{seat, {0.0, 0.0, 1.0}};
    auto clicked = growPathologies(organ, params);
    ASSERT_TRUE(clicked.ok()) << clicked.error().detail;
    EXPECT_LT(distance(clicked->pathologies[0].anchor, seat), 0.5);
}

TEST(Pathology, SameSeedGivesTheSameShape) {
    PathologyParams params;
    params.pathologies.push_back(myoma("m", GrowthModel::CellularAutomaton, {2, -1}, 20.0));
    const SurfaceMesh organ = test::testOrgan(1);
    auto a = growPathologies(organ, params);
    auto b = growPathologies(organ, params);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a->pathologies[0].surface.points, b->pathologies[0].surface.points);
}

// The time is printed, not asserted (tests run in parallel on noisy machines); the 2-second bar is a benchmark's:
// `bench_pathology 20 30` prints the mean grow time of a 30 mm myoma per model.
TEST(Pathology, GrowsOneThreeCentimetreMyomaWithAnyModel) {
    const SurfaceMesh organ = test::testOrgan(1);
    for (GrowthModel model : {GrowthModel::CellularAutomaton, GrowthModel::Skeleton, GrowthModel::Particles}) {
        PathologyParams params;
        params.pathologies.push_back(myoma("m", model, {2, -1}, 30.0));
        const auto start = std::chrono::steady_clock::now();
        auto grown = growPathologies(organ, params);
        const double seconds = secondsOf(start);
        ASSERT_TRUE(grown.ok()) << grown.error().detail;
        std::printf("30 mm myoma, %s: %.2f s, %.1f mm\n", std::string(toString(model)).c_str(), seconds,
                    grown->pathologies[0].descriptors.sizeMm);
        EXPECT_NEAR(grown->pathologies[0].descriptors.sizeMm, 30.0, 6.0) << toString(model);
    }
}

TEST(Pathology, PlacesAndMergesFivePathologiesWithinTenSeconds) {
    PathologyParams params;
    params.pathologies.push_back(myoma("a", GrowthModel::Skeleton, {2, -1}, 15.0, UterineLocation::Posterior));
    params.pathologies.push_back(myoma("b", GrowthModel::Particles, {4, -1}, 12.0, UterineLocation::Anterior));
    params.pathologies.push_back(myoma("c", GrowthModel::Skeleton, {6, -1}, 15.0, UterineLocation::RightLateral));
    params.pathologies.push_back(myoma("d", GrowthModel::Skeleton, {5, -1}, 12.0, UterineLocation::LeftLateral));
    params.pathologies.push_back(polyp("e", GrowthModel::Skeleton, 8.0, false, 0.0, UterineLocation::Fundal));
    const auto start = std::chrono::steady_clock::now();
    auto grown = growPathologies(test::testOrgan(2), params);
    ASSERT_TRUE(grown.ok()) << grown.error().detail;
    auto body = merge::mergeBody(*grown);
    const double seconds = secondsOf(start);
    ASSERT_TRUE(body.ok()) << body.error().detail;
    EXPECT_EQ(body->body.surfaces.size(), 6u);
    std::printf("five pathologies grown and merged: %.2f s\n", seconds);
    if (test::kTimeBarsApply) {
        EXPECT_LE(seconds, 10.0);
    }
}

// ---- Impossible requests: an error that says what is impossible. ----

TEST(Pathology, RefusesASixCentimetreMyomaInAFourCentimetreUterus) {
    anatomy::UterusShapeParams small;
    small.lengthMm = 55.0;
    small.widthMm = 40.0;
    small.apDepthMm = 30.0;
    small.cavityLengthMm = 22.0;
    small.cavityWidthMm = 22.0;
    small.cervixLengthMm = 25.0;
    auto organ = anatomy::generateUterus(small);
    ASSERT_TRUE(organ.ok()) << organ.error().detail;
    PathologyParams params;
    params.pathologies.push_back(myoma("big", GrowthModel::Skeleton, {4, -1}, 60.0));
    auto grown = growPathologies(organ->mesh, params);
    ASSERT_FALSE(grown.ok());
    EXPECT_EQ(grown.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(grown.error().detail.find("cannot grow in this uterus"), std::string::npos) << grown.error().detail;
}

TEST(Pathology, RefusesAPolypOutsideTheCavity) {
    const SurfaceMesh organ = test::testOrgan(1);
    // The serosa at the fundus: the highest point of the organ.
    Vec3 top = organ.points.front();
    for (const Vec3& p : organ.points)
        if (p.z > top.z)
            top = p;
    PathologyRequest r = polyp("p", GrowthModel::Skeleton, 10.0, false, 0.0);
    r.placement = SurfacePlacement{top, {0.0, 0.0, 1.0}};
    PathologyParams params;
    params.pathologies.push_back(r);
    auto grown = growPathologies(organ, params);
    ASSERT_FALSE(grown.ok());
    EXPECT_NE(grown.error().detail.find("outside the cavity"), std::string::npos) << grown.error().detail;
}

TEST(Pathology, RefusesFigoNine) {
    PathologyParams params;
    params.pathologies.push_back(myoma("m", GrowthModel::Skeleton, {9, -1}, 20.0));
    auto grown = growPathologies(test::testOrgan(1), params);
    ASSERT_FALSE(grown.ok());
    EXPECT_NE(grown.error().detail.find("FIGO type 9 does not exist"), std::string::npos) << grown.error().detail;
}

double nearestPoint(const SurfaceMesh& mesh, const Vec3& p) {
    double best = 1e300;
    for (const Vec3& q : mesh.points)
        best = std::min(best, distance(p, q));
    return best;
}

// A cornual location names the cornu's walls, not the ostium: a polyp asked for there grows beside the right tubal
// ostium, keeping it free, and says so: its nearest point lies more than 4 mm from the ostium's centre (at its
// nominal seat, aimed at the cornu, 2.5-2.6 mm for a sessile and 0.5-0.7 mm for a pedunculated one; now 7.3 mm at
// the least). A point placement on the ostium (a case that means it) stays there.
TEST(Pathology, SeatsACornualPolypBesideTheOstiumButKeepsAPointOnIt) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const SurfaceMesh organ = test::testOrgan(seed);
        const auto found = test::rightOstiumCentre(organ);
        ASSERT_TRUE(found.ok()) << found.error().detail;
        const Vec3 ostium = *found;
        for (const bool stalked : {false, true}) {
            PathologyParams params;
            params.seed = seed;
            params.pathologies.push_back(
                polyp("p", GrowthModel::Skeleton, 10.0, stalked, 5.0, UterineLocation::CornualRight));
            auto grown = growPathologies(organ, params);
            ASSERT_TRUE(grown.ok()) << grown.error().detail;
            const double gap = nearestPoint(grown->pathologies[0].surface, ostium);
            std::printf("organ %d, %s polyp: %.1f mm from the right ostium's centre\n", static_cast<int>(seed),
                        stalked ? "pedunculated" : "sessile", gap);
            EXPECT_GT(gap, 4.0) << "organ " << seed << (stalked ? " pedunculated" : " sessile");
            const bool said = std::any_of(grown->warnings.begin(), grown->warnings.end(), [](const std::string& w) {
                return w.find("polyp 'p': at its nominal seat it would cover or hide the right tubal ostium") !=
                       std::string::npos;
            });
            EXPECT_TRUE(said) << "organ " << seed;
        }
        PathologyParams onIt;
        onIt.seed = seed;
        onIt.pathologies.push_back(polyp("p", GrowthModel::Skeleton, 10.0, false, 5.0));
        onIt.pathologies[0].placement = SurfacePlacement{ostium, {0.0, 0.0, 1.0}};
        auto clicked = growPathologies(organ, onIt);
        ASSERT_TRUE(clicked.ok()) << clicked.error().detail;
        EXPECT_LT(distance(clicked->pathologies[0].anchor, ostium), 3.0) << "organ " << seed;
    }
}

TEST(Pathology, MovesASecondPathologyAtTheSameLocationAlongItsWall) {
    // A clinical location names a wall: two myomas asked for on the posterior wall both grow there, apart.
    PathologyParams params;
    params.pathologies.push_back(myoma("a", GrowthModel::Skeleton, {4, -1}, 20.0));
    params.pathologies.push_back(myoma("b", GrowthModel::Skeleton, {3, -1}, 15.0));
    auto grown = growPathologies(test::testOrgan(1), params);
    ASSERT_TRUE(grown.ok()) << grown.error().detail;
    ASSERT_EQ(grown->pathologies.size(), 2u);
    const auto& a = grown->pathologies[0];
    const auto& b = grown->pathologies[1];
    EXPECT_GT(distance(a.anchor, b.anchor), 5.0);
    EXPECT_GT(dot(a.intoWall, b.intoWall), std::cos(45.0 * 3.14159265358979 / 180.0) - 1e-9); // the same wall
    EXPECT_NEAR(a.descriptors.sizeMm, 20.0, 2.0);
    EXPECT_NEAR(b.descriptors.sizeMm, 15.0, 1.5);
    const bool said = std::any_of(grown->warnings.begin(), grown->warnings.end(), [](const std::string& w) {
        return w.find("myoma 'b': at its nominal seat it overlaps myoma 'a'") != std::string::npos;
    });
    EXPECT_TRUE(said);
}

TEST(Pathology, RefusesOverlappingPathologiesPlacedByPoint) {
    // A point placement (a click) stays where it was put: on top of the other myoma's seat, the case is refused.
    PathologyParams first;
    first.pathologies.push_back(myoma("a", GrowthModel::Skeleton, {4, -1}, 20.0));
    const SurfaceMesh organ = test::testOrgan(1);
    auto alone = growPathologies(organ, first);
    ASSERT_TRUE(alone.ok()) << alone.error().detail;
    PathologyParams params = first;
    params.pathologies.push_back(myoma("b", GrowthModel::Skeleton, {3, -1}, 15.0));
    params.pathologies[1].placement = SurfacePlacement{alone->pathologies[0].anchor, -alone->pathologies[0].intoWall};
    auto grown = growPathologies(organ, params);
    ASSERT_FALSE(grown.ok());
    EXPECT_NE(grown.error().detail.find("overlap"), std::string::npos) << grown.error().detail;
}

TEST(Pathology, RefusesCellularAutomatonPolyps) {
    PathologyParams params;
    params.pathologies.push_back(polyp("p", GrowthModel::CellularAutomaton, 10.0, false, 0.0));
    auto grown = growPathologies(test::testOrgan(1), params);
    ASSERT_FALSE(grown.ok());
    EXPECT_NE(grown.error().detail.find("myomas only"), std::string::npos);
}

TEST(Pathology, LasmarScoreFollowsTheTable) {
    Descriptors d;
    d.sizeMm = 30.0;
    d.topography = 2;
    d.baseExtension = 0.5;
    d.intramuralFraction = 0.6;
    d.lateralWall = true;
    const LasmarScore s = lasmarScore(d);
    EXPECT_EQ(s.size, 1);
    EXPECT_EQ(s.extension, 1);
    EXPECT_EQ(s.penetration, 2);
    EXPECT_EQ(s.total(), 1 + 2 + 1 + 2 + 1);
}

TEST(Pathology, MeasuresAHeadThatRestsOnAWallFromItsStalksRoot) {
    // A 10 mm head on a 6 mm stalk whose head also lies against a wall: the base (wall points near it) is mostly
    // where the head rests. From the base's centre no stalk is seen and the polyp measures as one 16 mm body; from
    // the root it grows from (WallContact::root), as the pathology stage and generate pass it, it is a 10 mm head.
    const SurfaceMesh organ = test::testOrgan(1);
    Vec3 centre;
    for (const Vec3& p : organ.points)
        centre += p;
    const Vec3 root = centre / static_cast<double>(organ.points.size());
    const Vec3 axis{0.0, 0.0, 1.0}, side{1.0, 0.0, 0.0}, other{0.0, 1.0, 0.0};
    const double stalkMm = 6.0, headRadiusMm = 5.0;
    const Vec3 head = root + axis * (stalkMm + headRadiusMm);
    WallContact c;
    constexpr double kPi = 3.14159265358979323846;
    for (int i = 0; i <= 24; ++i) // the stalk: a cylinder of radius 1 mm
        for (int k = 0; k < 12; ++k) {
            const double a = 2.0 * kPi * k / 12.0;
            c.points.push_back(root + axis * (stalkMm * i / 24.0) + (side * std::cos(a) + other * std::sin(a)));
        }
    for (int i = 1; i < 24; ++i) // the head: a sphere
        for (int k = 0; k < 24; ++k) {
            const double t = kPi * i / 24.0, a = 2.0 * kPi * k / 24.0;
            c.points.push_back(head + (axis * std::cos(t) + (side * std::cos(a) + other * std::sin(a)) * std::sin(t)) *
                                          headRadiusMm);
        }
    c.centre = head;
    c.sizeMm = stalkMm + 2.0 * headRadiusMm;
    c.volumeMm3 = 4.0 / 3.0 * kPi * 125.0;
    c.fractions.tissue = 0.05;
    c.fractions.cavity = 0.95;
    for (int k = 0; k < 8; ++k) { // where the stalk meets the wall
        const double a = 2.0 * kPi * k / 8.0;
        c.base.push_back(root + (side * std::cos(a) + other * std::sin(a)) * 1.2);
    }
    for (int i = -4; i <= 4; ++i) // where the head rests on a wall beside it
        for (int k = -4; k <= 4; ++k)
            c.base.push_back(head + side * (headRadiusMm + 0.5) + axis * (0.5 * i) + other * (0.5 * k));

    auto fromCentre = describeContact(organ, c, clinical::PathologyKind::Polyp, 1.0);
    ASSERT_TRUE(fromCentre.ok()) << fromCentre.error().detail;
    EXPECT_FALSE(fromCentre->pedunculated);
    EXPECT_NEAR(fromCentre->sizeMm, 16.0, 1e-9);

    c.root = root;
    auto fromRoot = describeContact(organ, c, clinical::PathologyKind::Polyp, 1.0);
    ASSERT_TRUE(fromRoot.ok()) << fromRoot.error().detail;
    EXPECT_TRUE(fromRoot->pedunculated);
    EXPECT_NEAR(fromRoot->sizeMm, 10.0, 0.5);
    EXPECT_NEAR(fromRoot->stalkLengthMm, stalkMm, 1.0);
    EXPECT_LT(fromRoot->baseWidthMm, 3.0); // the stalk's foot, not the wall under the head
}

} // namespace
} // namespace hs::pathology

namespace hs::pathology {

TEST(Pathology, SeatsAClickOnTheWallAndRefusesTheCervixAPolypOnTheSerosaAndAMiss) {
    const SurfaceMesh organ = test::testOrgan(3);
    const auto& tissue = organ.faceLabels.at(clinical::kSurfaceTissueLabel);
    const auto faceOf = [&](clinical::SurfaceTissue t) {
        return static_cast<std::size_t>(std::find(tissue.begin(), tissue.end(), clinical::labelValue(t)) -
                                        tissue.begin());
    };
    const auto centre = [&](std::size_t f) {
        const Triangle& t = organ.triangles[f];
        return (organ.points[static_cast<std::size_t>(t[0])] + organ.points[static_cast<std::size_t>(t[1])] +
                organ.points[static_cast<std::size_t>(t[2])]) /
               3.0;
    };
    const std::size_t wall = faceOf(clinical::SurfaceTissue::Endometrium);
    auto seat = seatAt(organ, centre(wall), clinical::PathologyKind::Polyp);
    ASSERT_TRUE(seat.ok()) << seat.error().message();
    EXPECT_EQ(seat->pointMm, centre(wall));
    EXPECT_NEAR(norm(seat->normal), 1.0, 1e-9);

    const std::size_t serosa = faceOf(clinical::SurfaceTissue::Serosa);
    EXPECT_TRUE(seatAt(organ, centre(serosa), clinical::PathologyKind::Myoma).ok());
    auto polypOutside = seatAt(organ, centre(serosa), clinical::PathologyKind::Polyp);
    ASSERT_FALSE(polypOutside.ok());
    EXPECT_NE(polypOutside.error().detail.find("serosa"), std::string::npos);

    const std::size_t canal = faceOf(clinical::SurfaceTissue::CervicalCanal);
    auto cervix = seatAt(organ, centre(canal), clinical::PathologyKind::Myoma);
    ASSERT_FALSE(cervix.ok());
    EXPECT_EQ(cervix.error().code, ErrorCode::Unsupported);
    // A click beside the organ seats nothing.
    EXPECT_FALSE(seatAt(organ, centre(serosa) + faceNormal(organ, serosa) * 3.0, clinical::PathologyKind::Myoma).ok());
}

} // namespace hs::pathology

namespace hs::pathology {

TEST(Pathology, ShowsEachModelsGrowthAsItHappensWithoutChangingIt) {
    const SurfaceMesh organ = test::testOrgan(3);
    PathologyParams params;
    params.pathologies = {
        test::myoma("ca", clinical::GrowthModel::CellularAutomaton, {4, -1}, 15.0),
        test::myoma("particles", clinical::GrowthModel::Particles, {4, -1}, 15.0, clinical::UterineLocation::Anterior),
        test::polyp("skeleton", clinical::GrowthModel::Skeleton, 8.0, false, 0.0)};
    std::vector<GrowthFrame> frames;
    auto watched = growPathologies(organ, params, Progress::none(), [&](const GrowthFrame& f) { frames.push_back(f); });
    ASSERT_TRUE(watched.ok()) << watched.error().message();
    auto unwatched = growPathologies(organ, params);
    ASSERT_TRUE(unwatched.ok());
    for (std::size_t i = 0; i < params.pathologies.size(); ++i)
        EXPECT_EQ(watched->pathologies[i].surface.points, unwatched->pathologies[i].surface.points) << i;

    for (std::size_t i = 0; i < params.pathologies.size(); ++i) {
        std::vector<const GrowthFrame*> mine;
        for (const GrowthFrame& f : frames)
            if (f.pathology == i)
                mine.push_back(&f);
        ASSERT_GE(mine.size(), 3u) << i;
        EXPECT_EQ(mine.front()->model, params.pathologies[i].model);
        EXPECT_TRUE(mine.back()->last) << i;
        // It grows: more points at the end than at the start, around where it was seated.
        EXPECT_GT(mine.back()->points.size(), mine.front()->points.size()) << i;
        Vec3 centre{};
        for (const Vec3& p : mine.back()->points)
            centre += p / static_cast<double>(mine.back()->points.size());
        EXPECT_LT(distance(centre, bounds(watched->pathologies[i].surface).center()), 10.0) << i;
    }
}

} // namespace hs::pathology
