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
