// The merge stage: one valid RegionModel with contact labels.
#include "SampleOrgans.h"

#include "hs/merge/Merge.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace hs::merge {
namespace {

TEST(Merge, SubmucosalMyomaBecomesANestedRegionWithContactLabels) {
    pathology::PathologyParams params;
    params.pathologies.push_back(test::myoma("m", pathology::GrowthModel::Skeleton, {2, -1}, 20.0));
    auto grown = pathology::growPathologies(test::testOrgan(1), params);
    ASSERT_TRUE(grown.ok()) << grown.error().detail;
    auto merged = mergeBody(*grown);
    ASSERT_TRUE(merged.ok()) << merged.error().detail;
    const RegionModel& body = merged->body;
    ASSERT_EQ(body.surfaces.size(), 2u);
    EXPECT_TRUE(validate(body).ok());
    EXPECT_EQ(body.surfaces[1].regionId, 1);
    const auto& contact = body.surfaces[1].surface.faceLabels.at(kContactLabel);
    const auto count = [&](Contact c) {
        return std::count(contact.begin(), contact.end(), static_cast<std::int32_t>(c));
    };
    EXPECT_GT(count(Contact::Myometrium), 0);  // intramural part
    EXPECT_GT(count(Contact::Endometrium), 0); // bulging into the cavity, endometrium draped over it
    const auto& draped = body.surfaces[0].surface.faceLabels.at(kPathologyLabel);
    EXPECT_GT(std::count(draped.begin(), draped.end(), 1), 0);
    EXPECT_EQ(body.surfaces[0].surface.faceLabels.at("tissue").size(), body.surfaces[0].surface.triangles.size());
}

TEST(Merge, RefusesANonPositiveCover) {
    pathology::PathologyResult empty;
    MergeParams params;
    params.coverMm = 0.0;
    EXPECT_FALSE(mergeBody(empty, params).ok());
}

} // namespace
} // namespace hs::merge
