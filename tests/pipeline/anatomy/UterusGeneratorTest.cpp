#include "hs/anatomy/UterusGenerator.h"
#include "hs/anatomy/OrganChecks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace hs::anatomy;

TEST(UterusGenerator, DefaultOrganIsAValidClosedWallOfGenusZero) {
    const auto organ = generateUterus(UterusShapeParams{});
    ASSERT_TRUE(organ.ok()) << organ.error().message();
    ASSERT_TRUE(hs::validate(organ->mesh).ok());
    const auto check = checkOrgan(organ->mesh, organ->layout);
    ASSERT_TRUE(check.ok());
    EXPECT_TRUE(check->topology.isWatertight());
    EXPECT_EQ(check->topology.components, 1u);
    EXPECT_EQ(check->genus, 0);
    EXPECT_FALSE(check->selfIntersecting);
    EXPECT_TRUE(check->cavityInside);
    EXPECT_GE(check->minWallMm, 5.0);
    EXPECT_GT(hs::enclosedVolume(organ->mesh), 0.0); // outward orientation: the surface bounds the tissue
}

TEST(UterusGenerator, MeasuredDimensionsFollowTheControls) {
    UterusShapeParams p;
    p.flexionDeg = 0.0;
    const auto organ = generateUterus(p);
    ASSERT_TRUE(organ.ok());
    const auto d = measureUterus(organ->mesh, organ->layout);
    ASSERT_TRUE(d.ok());
    EXPECT_NEAR(d->lengthMm, p.lengthMm, 0.5);
    EXPECT_NEAR(d->widthMm, p.widthMm, 0.5);
    EXPECT_NEAR(d->apDepthMm, p.apDepthMm, 0.5);
    EXPECT_NEAR(d->cavityLengthMm, p.cavityLengthMm, 0.5);
    EXPECT_NEAR(d->cavityWidthMm, p.cavityWidthMm, 0.5);
    EXPECT_NEAR(d->fundalWallMm, p.fundalWallMm, 0.01);
    EXPECT_NEAR(d->internalOsWidthMm, p.internalOsWidthMm, 0.01);
    EXPECT_NEAR(d->flexionDeg, 0.0, 0.5);
    EXPECT_GT(d->cavityVolumeMl, 0.6); // distended cavity volume range of Bajka et al. 2009
    EXPECT_LT(d->cavityVolumeMl, 11.4);
}

TEST(UterusGenerator, EveryInstanceSharesTheTemplateTopology) {
    const auto base = generateUterus(UterusShapeParams{});
    UterusShapeParams other;
    other.lengthMm = 60.0;
    other.cavityLengthMm = 25.0;
    other.flexionDeg = -30.0;
    other.versionDeg = -25.0;
    other.lateralAsymmetry = 0.1;
    const auto bent = generateUterus(other);
    ASSERT_TRUE(base.ok() && bent.ok());
    EXPECT_EQ(base->mesh.triangles, bent->mesh.triangles);
    EXPECT_EQ(base->mesh.faceLabels, bent->mesh.faceLabels);
    EXPECT_EQ(base->mesh.triangles, uterusTemplate().triangles);
    EXPECT_NE(base->mesh.points, bent->mesh.points);
}

TEST(UterusGenerator, LabelsTheFiveTissues) {
    const auto organ = generateUterus(UterusShapeParams{});
    ASSERT_TRUE(organ.ok());
    const auto& labels = organ->mesh.faceLabels.at(hs::clinical::kSurfaceTissueLabel);
    const std::set<std::int32_t> found(labels.begin(), labels.end());
    EXPECT_EQ(found, (std::set<std::int32_t>{1, 2, 3, 4, 5}));
    EXPECT_EQ(
        std::count(labels.begin(), labels.end(), hs::clinical::labelValue(hs::clinical::SurfaceTissue::TubalOstium)),
        16);
}

TEST(UterusGenerator, RetroflexedRetrovertedOrganIsValid) {
    UterusShapeParams p;
    p.flexionDeg = -45.0;
    p.versionDeg = -40.0;
    const auto organ = generateUterus(p);
    ASSERT_TRUE(organ.ok());
    const auto check = checkOrgan(organ->mesh, organ->layout);
    ASSERT_TRUE(check.ok());
    EXPECT_TRUE(check->valid());
    const auto d = measureUterus(organ->mesh, organ->layout);
    EXPECT_LT(d->flexionDeg, -30.0);
}

TEST(UterusGenerator, ControlOutsideItsRangeIsRejectedByName) {
    UterusShapeParams p;
    p.cornualAngleDeg = 150.0;
    const auto organ = generateUterus(p);
    ASSERT_FALSE(organ.ok());
    EXPECT_EQ(organ.error().code, hs::ErrorCode::InvalidInput);
    EXPECT_NE(organ.error().detail.find("cornualAngleDeg"), std::string::npos);
}

TEST(UterusGenerator, ControlsLeavingNoCanalAreRejected) {
    UterusShapeParams p;
    p.lengthMm = 40.0;
    p.cavityLengthMm = 30.0;
    EXPECT_FALSE(generateUterus(p).ok());
}
