#include "MeshingTestShapes.h"

#include "hs/core/RegionModel.h"

#include <gtest/gtest.h>

using namespace hs;

TEST(RegionModel, AcceptsNestedDisjointSurfaces) {
    const RegionModel body = RegionModel::fromSurfaces(
        {test::icosphere(10, 2), test::icosphere(3, 2, {4, 0, 0}), test::icosphere(2, 2, {-5, 0, 0})});
    EXPECT_TRUE(validate(body).ok());
    EXPECT_EQ(body.surfaces[2].regionId, 2);
}

TEST(RegionModel, NamesTheSurfaceThatIsOpen) {
    SurfaceMesh open = test::icosphere(3, 1);
    open.triangles.pop_back();
    const RegionModel body = RegionModel::fromSurfaces({test::icosphere(10, 2), open}, {"wall.off", "myoma.off"});
    const Status s = validate(body);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().detail.find("myoma.off"), std::string::npos) << s.error().detail;
    EXPECT_NE(s.error().detail.find("open"), std::string::npos);
}

TEST(RegionModel, WindingNumberIsOneInsideAndZeroOutside) {
    const SurfaceMesh s = test::icosphere(10, 2);
    EXPECT_NEAR(windingNumber(s, {0, 0, 0}), 1.0, 1e-9);
    EXPECT_NEAR(windingNumber(s, {0, 0, 20}), 0.0, 1e-9);
}
