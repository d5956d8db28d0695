// The pose of a rigid scope's camera: along the canal, an oblique optic tilted and rolled, and a region's view.
#include "hs/scene/ScopeView.h"
#include "hs/scene/Scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace hs;
using namespace hs::scene;

namespace {

constexpr double kPi = 3.14159265358979323846;

ScopeLandmarks canalAlongZ() {
    ScopeLandmarks l;
    l.externalOsMm = {0.0, 0.0, 0.0};
    l.internalOsMm = {0.0, 0.0, 30.0};
    l.fundusMm = {0.0, 0.0, 60.0};
    return l;
}

double degreesBetween(const Vec3& a, const Vec3& b) {
    return std::acos(std::clamp(dot(normalized(a), normalized(b)), -1.0, 1.0)) * 180.0 / kPi;
}

} // namespace

TEST(ScopeView, AStraightOpticLooksUpTheCanalFromTheTip) {
    auto view = scopeView(canalAlongZ(), 10.0, 0.0, 0.0);
    ASSERT_TRUE(view.ok()) << view.error().message();
    EXPECT_NEAR(view->eyeMm.z, 10.0, 1e-12);
    EXPECT_NEAR(degreesBetween(view->direction, {0, 0, 1}), 0.0, 1e-9);
    EXPECT_NEAR(dot(view->up, view->direction), 0.0, 1e-12);
    EXPECT_GT(view->up.y, 0.99); // anterior is up at roll 0
}

TEST(ScopeView, AThirtyDegreeOpticLooksOffTheShaftTowardsItsRoll) {
    auto anterior = scopeView(canalAlongZ(), 5.0, 30.0, 0.0);
    ASSERT_TRUE(anterior.ok());
    EXPECT_NEAR(degreesBetween(anterior->direction, anterior->shaft), 30.0, 1e-9);
    EXPECT_GT(anterior->direction.y, 0.0);
    auto posterior = scopeView(canalAlongZ(), 5.0, 30.0, 180.0);
    ASSERT_TRUE(posterior.ok());
    EXPECT_LT(posterior->direction.y, 0.0);
    EXPECT_NEAR(degreesBetween(posterior->direction, posterior->shaft), 30.0, 1e-9);
    auto lateral = scopeView(canalAlongZ(), 5.0, 30.0, 90.0);
    ASSERT_TRUE(lateral.ok());
    EXPECT_NEAR(std::abs(lateral->direction.x), std::sin(30.0 * kPi / 180.0), 1e-9);
}

TEST(ScopeView, RefusesCoincidentOsAndAnOpticBeyondNinetyDegrees) {
    ScopeLandmarks same = canalAlongZ();
    same.internalOsMm = same.externalOsMm;
    EXPECT_FALSE(scopeView(same, 0.0, 30.0, 0.0).ok());
    EXPECT_FALSE(scopeView(canalAlongZ(), 0.0, 120.0, 0.0).ok());
    EXPECT_FALSE(scopeView(canalAlongZ(), std::nan(""), 30.0, 0.0).ok());
}

TEST(ScopeView, SeesARegionFromTheCavityAtTheGivenDistance) {
    Scene scene;
    scene.tets.points = {{10, 0, 40}, {12, 0, 40}, {10, 2, 40}, {10, 0, 42}};
    scene.tets.tets = {{0, 1, 2, 3}};
    scene.tets.regions = {4};
    auto view = viewOfRegion(scene, canalAlongZ(), 4, 5.0);
    ASSERT_TRUE(view.ok()) << view.error().message();
    const Vec3 centre{10.5, 0.5, 40.5};
    EXPECT_NEAR(distance(view->eyeMm, centre), 5.0, 1e-9);
    EXPECT_NEAR(degreesBetween(view->direction, centre - view->eyeMm), 0.0, 1e-6);
    EXPECT_FALSE(viewOfRegion(scene, canalAlongZ(), 7, 5.0).ok());
}

namespace {

/// A visual surface of two ostium triangles, left (-x) and right (+x) of the canal's axis at the fundus' height, and,
/// when `blocked`, a wall triangle across the sight line from the cavity's middle to the left one.
Scene twoOstia(bool blocked, bool withRight = true) {
    Scene sc;
    SurfaceMesh& m = sc.surface.mesh;
    auto add = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
        const auto i = static_cast<std::int32_t>(m.points.size());
        m.points.insert(m.points.end(), {a, b, c});
        m.triangles.push_back({i, i + 1, i + 2});
        return static_cast<std::int32_t>(m.triangles.size() - 1);
    };
    SceneLabel ostia{"ostia", LabelKind::Ostium, LabelElement::SurfaceFace, {}, {}};
    ostia.indices.push_back(add({-15.0, -1.0, 59.0}, {-15.0, 1.0, 59.0}, {-15.0, 0.0, 61.0}));
    if (withRight)
        ostia.indices.push_back(add({15.0, -1.0, 59.0}, {15.0, 1.0, 59.0}, {15.0, 0.0, 61.0}));
    if (blocked) // the sight line from (0, 0, 45) to (-15, 0, 60) crosses x = -7.5 near z = 52
        add({-7.5, -5.0, 45.0}, {-7.5, 5.0, 45.0}, {-7.5, 0.0, 65.0});
    sc.labels.push_back(ostia);
    return sc;
}

} // namespace

TEST(ScopeView, LooksRoundTheCavityFromItsMiddleOrTheRoutesPointNearestItWithRoomForTheScope) {
    ScopePassage p;
    p.scopeDiameterMm = 2.9;
    p.landmarks = canalAlongZ(); // the middle: (0, 0, 45)
    auto point = [](double z, double width, PassagePart part) {
        PassagePoint q;
        q.positionMm = {0.0, 1.0, z};
        q.freeWidthMm = width;
        q.part = part;
        return q;
    };
    p.route = {point(45.0, 9.0, PassagePart::InternalOs), point(44.0, 2.0, PassagePart::Cavity),
               point(41.0, 6.0, PassagePart::Cavity), point(52.0, 8.0, PassagePart::Cavity)};
    Scene open; // nothing near the middle: the scope looks from there
    const Vec3 middle = cavityViewpoint(open, p);
    EXPECT_NEAR(middle.y, 0.0, 1e-12);
    EXPECT_NEAR(middle.z, 45.0, 1e-12);
    Scene crowded; // a face 1 mm from the middle, closer than the scope's radius: the route's nearest point with room
    crowded.surface.mesh.points = {{-5.0, -5.0, 46.0}, {5.0, -5.0, 46.0}, {0.0, 5.0, 46.0}};
    crowded.surface.mesh.triangles = {{0, 1, 2}};
    const Vec3 moved = cavityViewpoint(crowded, p);
    EXPECT_NEAR(moved.z, 41.0, 1e-12); // 45 is not in the cavity, 44 too narrow for the scope
    p.route.clear();                   // no route: the middle
    EXPECT_NEAR(cavityViewpoint(crowded, p).z, 45.0, 1e-12);
}

TEST(ScopeView, SeesBothOstiaFromTheCavitysMiddleUnlessAWallIsInTheWay) {
    const Vec3 l{0.0, 0.0, 45.0}; // the cavity's middle for canalAlongZ()
    auto clear = ostiaInSight(twoOstia(false), l);
    ASSERT_TRUE(clear.ok()) << clear.error().message();
    ASSERT_EQ(clear->size(), 2u);
    EXPECT_EQ((*clear)[0].side, "left");
    EXPECT_EQ((*clear)[1].side, "right");
    EXPECT_DOUBLE_EQ((*clear)[0].visibleFraction, 1.0);
    EXPECT_DOUBLE_EQ((*clear)[1].visibleFraction, 1.0);
    EXPECT_NEAR((*clear)[0].centreMm.x, -15.0, 1e-9);
    EXPECT_EQ((*clear)[0].faces, 1u);

    auto blocked = ostiaInSight(twoOstia(true), l);
    ASSERT_TRUE(blocked.ok());
    ASSERT_EQ(blocked->size(), 2u);
    EXPECT_DOUBLE_EQ((*blocked)[0].visibleFraction, 0.0);
    EXPECT_DOUBLE_EQ((*blocked)[1].visibleFraction, 1.0);
    EXPECT_EQ((*blocked)[0].hiddenBy, std::vector<std::string>{"wall"});
    EXPECT_TRUE((*blocked)[1].hiddenBy.empty());

    Scene behindAPolyp = twoOstia(true); // the blocking face is a pathology's
    behindAPolyp.labels.push_back({"contact:polyp-1", LabelKind::Contact, LabelElement::SurfaceFace, "polyp-1", {2}});
    auto polyp = ostiaInSight(behindAPolyp, l);
    ASSERT_TRUE(polyp.ok());
    EXPECT_EQ((*polyp)[0].hiddenBy, std::vector<std::string>{"polyp-1"});

    auto one = ostiaInSight(twoOstia(false, false), l); // a pathology took the right one's faces
    ASSERT_TRUE(one.ok());
    ASSERT_EQ(one->size(), 1u);
    EXPECT_EQ((*one)[0].side, "left");

    Scene none = twoOstia(false);
    none.labels.clear();
    auto refused = ostiaInSight(none, l);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().detail.find("no ostium label"), std::string::npos);
}
