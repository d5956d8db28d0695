// Two masses in one cavity, in the default patient's organ: the pathology stage makes room for both and the merge
// takes the displaced organ. A 24 mm FIGO 0 myoma on a stalk from the left wall fills the cavity's width, so the
// pedunculated polyp asked for in the right cornu finds no clear seat there: the myoma slides along its own wall
// instead (docs/pathology.md, "Placement"). Before, this pair was refused as an overlap.
#include "CaseOrgan.h"

#include "hs/anatomy/OrganChecks.h"
#include "hs/anatomy/ShapeModel.h"
#include "hs/generate/CaseStages.h"
#include "hs/generate/Generate.h"
#include "hs/merge/Merge.h"
#include "hs/pathology/Pathology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

using namespace hs;

namespace {

scene::PathologySpec pedunculatedPolyp() {
    scene::PathologySpec p;
    p.id = "polyp-1";
    p.kind = clinical::PathologyKind::Polyp;
    p.growthModel = clinical::GrowthModel::Skeleton;
    p.sizeMm = 10.0;
    p.attachment = clinical::PolypAttachment::Pedunculated;
    p.stalkLengthMm = 6.0;
    p.placement = clinical::ClinicalPlacement{clinical::UterineLocation::CornualRight};
    return p;
}

scene::PathologySpec stalkedMyoma(double sizeMm) {
    scene::PathologySpec m;
    m.id = "myoma-1";
    m.kind = clinical::PathologyKind::Myoma;
    m.growthModel = clinical::GrowthModel::Skeleton;
    m.sizeMm = sizeMm;
    m.figo = clinical::FigoType{0, -1};
    m.placement = clinical::ClinicalPlacement{clinical::UterineLocation::LeftLateral};
    return m;
}

/// The pathology stage on the default case's organ with `pathologies` in place of the case's.
Result<pathology::PathologyResult> grownInTheDefaultPatient(const std::vector<scene::PathologySpec>& pathologies) {
    auto loaded = scene::loadCase(HS_DEFAULT_CASE_FILE);
    if (!loaded)
        return loaded.failure();
    scene::CaseSpec spec = *loaded;
    spec.pathologies = pathologies;
    auto organ = test::caseOrgan(spec, HS_DEFAULT_CASE_FILE);
    if (!organ)
        return organ.failure();
    return pathology::growPathologies(organ->mesh, generate::pathologyParamsFor(spec));
}

} // namespace

TEST(CrowdedCavity, AStalkedMyomaAndACornualPolypBothFit) {
    auto grown = grownInTheDefaultPatient({stalkedMyoma(24.0), pedunculatedPolyp()});
    ASSERT_TRUE(grown.ok()) << grown.error().message();
    ASSERT_EQ(grown->pathologies.size(), 2u);
    const auto& myoma = grown->pathologies[0].descriptors;
    const auto& polyp = grown->pathologies[1].descriptors;
    std::printf("myoma %.1f mm FIGO %s, stalk %.1f mm; polyp %.1f mm, stalk %.1f mm, %.0f %% in the wall\n",
                myoma.sizeMm, myoma.figo.toString().c_str(), myoma.stalkLengthMm, polyp.sizeMm, polyp.stalkLengthMm,
                100.0 * polyp.intramuralFraction);
    for (const auto& w : grown->warnings)
        std::printf("warning: %s\n", w.c_str());
    // Pathologies placed by location keep off the tubal ostia: the polyp moves off the right one (before, it sat on
    // it, and the myoma had to move off the polyp), and says so; the 24 mm head on the left wall hides the left
    // ostium from the cavity's middle wherever it stands on that wall, and that is said too.
    const auto said = [&](const std::string& start, const std::string& then) {
        return std::any_of(grown->warnings.begin(), grown->warnings.end(), [&](const std::string& w) {
            return w.rfind(start, 0) == 0 && w.find(then) != std::string::npos;
        });
    };
    EXPECT_TRUE(
        said("polyp 'polyp-1': at its nominal seat it would cover or hide the right tubal ostium", "; seated "));
    EXPECT_TRUE(said("myoma 'myoma-1': covers or hides the left tubal ostium", "no seat on the same wall"));
    // Both are what was asked: a head on a stalk each, of the asked size.
    EXPECT_EQ(myoma.figo.toString(), "0");
    EXPECT_NEAR(myoma.sizeMm, 24.0, 2.4);
    EXPECT_TRUE(polyp.pedunculated);
    EXPECT_NEAR(polyp.sizeMm, 10.0, 1.0);
    EXPECT_LT(polyp.intramuralFraction, 0.5);
    // The displaced organ does not cross itself: the merge takes it.
    EXPECT_FALSE(anatomy::hasSelfIntersections(grown->organ));
    auto merged = merge::mergeBody(*grown);
    EXPECT_TRUE(merged.ok()) << merged.error().message();
}

TEST(CrowdedCavity, ALateralSubmucosalMyomaStandsInTheCavity) {
    // A FIGO 1 myoma on the left wall is wider than the default cavity is deep: the anterior and posterior walls
    // across it part (docs/pathology.md, "The organ adapts"). Before, they stayed and embedded it: it measured FIGO 2.
    scene::PathologySpec m = stalkedMyoma(20.0);
    m.figo = clinical::FigoType{1, -1};
    auto grown = grownInTheDefaultPatient({m});
    ASSERT_TRUE(grown.ok()) << grown.error().message();
    const auto& d = grown->pathologies[0].descriptors;
    std::printf("FIGO 1 on the left wall: measured FIGO %s, %.0f %% in the wall, %.0f %% in the cavity\n",
                d.figo.toString().c_str(), 100.0 * d.intramuralFraction, 100.0 * d.cavityFraction);
    EXPECT_EQ(d.figo.toString(), "1");
    EXPECT_LT(d.intramuralFraction, 0.5);
    // No warning but the tubal ostium's (a head this size on the left wall hides the left ostium from the cavity's
    // middle): the type and size are what was asked.
    for (const auto& w : grown->warnings)
        EXPECT_NE(w.find("the left tubal ostium"), std::string::npos) << w;
}
