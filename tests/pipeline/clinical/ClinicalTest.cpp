// The clinical vocabulary: every key reads back, FIGO and Lasmar follow their definitions, the stored label values
// and the default patient stay what files and cases rely on.
#include "hs/clinical/Clinical.h"
#include "hs/clinical/Figo.h"
#include "hs/clinical/PatientParams.h"
#include "hs/clinical/Placement.h"
#include "hs/clinical/Tissue.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

using namespace hs::clinical;

namespace {

/// Every value's key reads back to the value, and no two values share a key.
template <class E, std::size_t N>
void expectKeysReadBack(const std::array<E, N>& values) {
    std::set<std::string> keys;
    for (const E v : values) {
        E out{};
        const std::string key(toString(v));
        EXPECT_FALSE(key.empty());
        EXPECT_TRUE(keys.insert(key).second) << key;
        ASSERT_TRUE(fromString(key, out)) << key;
        EXPECT_EQ(out, v) << key;
    }
}

} // namespace

TEST(ClinicalKeys, EveryEnumerationKeyReadsBack) {
    expectKeysReadBack(kPathologyKinds);
    expectKeysReadBack(kGrowthModels);
    expectKeysReadBack(kUterineLocations);
    expectKeysReadBack(kPolypAttachments);
    expectKeysReadBack(kTissues);
    expectKeysReadBack(kSurfaceTissues);
}

TEST(ClinicalKeys, KeysAreTheOnesWrittenInCaseFiles) {
    EXPECT_EQ(toString(GrowthModel::CellularAutomaton), "ca");
    EXPECT_EQ(toString(UterineLocation::LeftLateral), "left-lateral");
    EXPECT_EQ(toString(UterineLocation::CornualRight), "cornual-right");
    EXPECT_EQ(toString(PolypAttachment::Pedunculated), "pedunculated");
    EXPECT_EQ(toString(Tissue::Myometrium), "myometrium");
    PathologyKind kind{};
    EXPECT_FALSE(fromString("Myoma", kind)); // keys are case-sensitive
}

TEST(FigoType, ReadsPlainAndHybridForms) {
    EXPECT_EQ(FigoType::parse("0"), (FigoType{0, -1}));
    EXPECT_EQ(FigoType::parse("2-5"), (FigoType{2, 5}));
    EXPECT_FALSE(FigoType::parse(""));
    EXPECT_FALSE(FigoType::parse("10"));
    EXPECT_FALSE(FigoType::parse("2 - 5"));
    EXPECT_FALSE(FigoType::parse("2-"));
    EXPECT_TRUE((FigoType{8, -1}).isValid());
    EXPECT_FALSE((FigoType{9, -1}).isValid());
    EXPECT_TRUE((FigoType{3, 5}).isValid());
    EXPECT_FALSE((FigoType{2, 7}).isValid());
    EXPECT_FALSE((FigoType{0, 5}).isValid());
    EXPECT_EQ((FigoType{2, 5}).toString(), "2-5");
    EXPECT_EQ((FigoType{4, -1}).toString(), "4");
    EXPECT_TRUE((FigoType{2, 5}).isHysteroscopicallyResectable());
    EXPECT_FALSE((FigoType{3, -1}).isHysteroscopicallyResectable());
}

TEST(FigoType, AnUnclassifiedTypeIsInvalidAndPrintsAsADash) {
    const FigoType none{-1, -1};
    EXPECT_FALSE(none.isValid());
    EXPECT_FALSE(none.isHysteroscopicallyResectable());
    EXPECT_EQ(none.toString(), "-");
}

TEST(FigoType, DefinitionsCoverThePlainTypesOnly) {
    for (int type = 0; type <= 8; ++type)
        EXPECT_FALSE(figoDefinition(type).empty()) << type;
    EXPECT_TRUE(figoDefinition(9).empty());
    EXPECT_TRUE(figoDefinition(-1).empty());
}

TEST(LasmarScore, IsNotComputedUntilEveryComponentIsSet) {
    LasmarScore s;
    EXPECT_FALSE(s.complete());
    EXPECT_EQ(s.total(), -1);
    s = LasmarScore{1, 2, 1, 2, 0};
    EXPECT_TRUE(s.complete());
    EXPECT_EQ(s.total(), 6);
    s.wall = -1;
    EXPECT_EQ(s.total(), -1);
}

TEST(PatientParams, DefaultsAreTheDefaultCasesPrimipara) {
    const PatientParams p;
    EXPECT_EQ(p.ageYears, 35.0);
    EXPECT_EQ(p.parity, 1);
    EXPECT_EQ(p.gravidity, 1);
    EXPECT_EQ(p.heightCm, 165.0);
    EXPECT_EQ(p.weightKg, 65.0);
    EXPECT_FALSE(p.menopausal);
    PatientParams q = p;
    EXPECT_EQ(p, q);
    q.heightCm = 164.0;
    EXPECT_NE(p, q);
}

TEST(SurfaceTissue, LabelValuesAreTheStoredIntegers) {
    EXPECT_EQ(labelValue(SurfaceTissue::Serosa), 1);
    EXPECT_EQ(labelValue(SurfaceTissue::Endometrium), 2);
    EXPECT_EQ(labelValue(SurfaceTissue::CervicalCanal), 3);
    EXPECT_EQ(labelValue(SurfaceTissue::TubalOstium), 4);
    EXPECT_EQ(labelValue(SurfaceTissue::Ectocervix), 5);
    EXPECT_STREQ(kSurfaceTissueLabel, "tissue");
}

TEST(Placement, EqualityComparesEveryField) {
    EXPECT_EQ(ClinicalPlacement{UterineLocation::Fundal}, ClinicalPlacement{});
    const SurfacePlacement a{{1.0, 2.0, 3.0}, {0.0, 0.0, 1.0}};
    SurfacePlacement b = a;
    EXPECT_EQ(a, b);
    b.normal = {0.0, 1.0, 0.0};
    EXPECT_FALSE(a == b);
}
