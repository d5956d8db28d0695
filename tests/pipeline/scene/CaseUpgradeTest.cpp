// The schema upgrade chain. Version 1 is the first schema, so the real chain has no step yet; these tests run the
// mechanism with chains of their own that stand for hypothetical older versions of the current schema.

#include "CaseUpgrade.h"
#include "hs/scene/CaseSpec.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace hs;
using namespace hs::scene;
using nlohmann::json;

namespace {

/// Two hypothetical older versions: v(current-2) called the seed "randomSeed"; v(current-1) called the age
/// "patient.age". Each step records that it ran.
detail::CaseUpgradeChain twoStepChain(std::vector<int>& ran) {
    detail::CaseUpgradeChain chain;
    chain.oldestVersion = kCaseSchemaVersion - 2;
    chain.currentVersion = kCaseSchemaVersion;
    chain.steps.push_back([&ran](json& doc) -> Status {
        ran.push_back(1);
        if (auto it = doc.find("randomSeed"); it != doc.end()) {
            doc["seed"] = *it;
            doc.erase("randomSeed");
        }
        return {};
    });
    chain.steps.push_back([&ran](json& doc) -> Status {
        ran.push_back(2);
        auto patient = doc.find("patient");
        if (patient != doc.end() && patient->is_object() && patient->contains("age")) {
            (*patient)["ageYears"] = (*patient)["age"];
            patient->erase("age");
        }
        return {};
    });
    return chain;
}

std::string document(int version, const std::string& members) {
    return R"({"format": "hysteroscene-case", "schemaVersion": )" + std::to_string(version) + members + "}";
}

} // namespace

TEST(CaseUpgrade, ChainOfThisBuildCoversEveryVersionFromTheOldest) {
    const auto& chain = detail::caseUpgradeChain();
    EXPECT_EQ(chain.oldestVersion, kOldestCaseSchemaVersion);
    EXPECT_EQ(chain.currentVersion, kCaseSchemaVersion);
    EXPECT_EQ(chain.steps.size(), static_cast<std::size_t>(kCaseSchemaVersion - kOldestCaseSchemaVersion));
}

TEST(CaseUpgrade, OldestDocumentRunsEveryStepInOrderBeforeValidation) {
    std::vector<int> ran;
    const auto chain = twoStepChain(ran);
    const auto spec = detail::parseCaseWithChain(
        document(kCaseSchemaVersion - 2, R"(, "randomSeed": 7, "patient": {"age": 52})"), "old.json", chain);
    ASSERT_TRUE(spec.ok()) << spec.error().message();
    EXPECT_EQ(ran, (std::vector<int>{1, 2}));
    EXPECT_EQ(spec->seed, 7u);
    EXPECT_DOUBLE_EQ(spec->patient.ageYears, 52.0);
}

TEST(CaseUpgrade, MiddleVersionRunsOnlyTheRemainingSteps) {
    std::vector<int> ran;
    const auto chain = twoStepChain(ran);
    const auto spec =
        detail::parseCaseWithChain(document(kCaseSchemaVersion - 1, R"(, "patient": {"age": 44})"), "mid.json", chain);
    ASSERT_TRUE(spec.ok()) << spec.error().message();
    EXPECT_EQ(ran, (std::vector<int>{2}));
    EXPECT_DOUBLE_EQ(spec->patient.ageYears, 44.0);
}

TEST(CaseUpgrade, CurrentDocumentRunsNoStep) {
    std::vector<int> ran;
    const auto chain = twoStepChain(ran);
    const auto spec = detail::parseCaseWithChain(toJson(defaultCase()), "current.json", chain);
    ASSERT_TRUE(spec.ok()) << spec.error().message();
    EXPECT_TRUE(ran.empty());
    EXPECT_TRUE(*spec == defaultCase());
}

TEST(CaseUpgrade, UpgradedDocumentIsStillValidatedAgainstTheCurrentSchema) {
    std::vector<int> ran;
    const auto chain = twoStepChain(ran);
    // The old field name survives only in a place no step rewrites: the current schema rejects it.
    const auto spec = detail::parseCaseWithChain(
        document(kCaseSchemaVersion - 2, R"(, "patient": {"age": 130, "randomSeed": 3})"), "old.json", chain);
    ASSERT_FALSE(spec.ok());
    EXPECT_NE(spec.error().detail.find("old.json: /patient/randomSeed: unknown field"), std::string::npos)
        << spec.error().detail;
    EXPECT_NE(spec.error().detail.find("old.json: /patient/ageYears: 130 is outside"), std::string::npos)
        << spec.error().detail;
}

TEST(CaseUpgrade, FailingStepNamesTheSourceAndTheVersions) {
    detail::CaseUpgradeChain chain;
    chain.oldestVersion = kCaseSchemaVersion - 1;
    chain.currentVersion = kCaseSchemaVersion;
    chain.steps.push_back([](json&) -> Status { return fail(ErrorCode::InvalidInput, "no seed to carry over"); });
    const auto spec = detail::parseCaseWithChain(document(kCaseSchemaVersion - 1, ""), "old.json", chain);
    ASSERT_FALSE(spec.ok());
    EXPECT_EQ(spec.error().code, ErrorCode::InvalidInput);
    EXPECT_EQ(spec.error().detail, "old.json: upgrading from schema version " + std::to_string(kCaseSchemaVersion - 1) +
                                       " to " + std::to_string(kCaseSchemaVersion) + " failed: no seed to carry over");
}

TEST(CaseUpgrade, ChainWithAMissingStepIsAnInternalError) {
    detail::CaseUpgradeChain chain;
    chain.oldestVersion = kCaseSchemaVersion - 1;
    chain.currentVersion = kCaseSchemaVersion; // needs one step, has none
    const auto spec = detail::parseCaseWithChain(toJson(defaultCase()), "any.json", chain);
    ASSERT_FALSE(spec.ok());
    EXPECT_EQ(spec.error().code, ErrorCode::Internal);
}

TEST(CaseUpgrade, VersionOlderThanTheChainIsUnsupported) {
    std::vector<int> ran;
    const auto chain = twoStepChain(ran);
    const auto spec = detail::parseCaseWithChain(document(kCaseSchemaVersion - 3, ""), "ancient.json", chain);
    ASSERT_FALSE(spec.ok());
    EXPECT_EQ(spec.error().code, ErrorCode::Unsupported);
    EXPECT_NE(spec.error().detail.find("ancient.json: /schemaVersion:"), std::string::npos);
    EXPECT_TRUE(ran.empty());
}

TEST(CaseUpgrade, NewerVersionIsRefusedWithoutTouchingTheDocument) {
    const auto spec = parseCase(document(kCaseSchemaVersion + 1, R"(, "futureField": {"x": 1})"), "future.json");
    ASSERT_FALSE(spec.ok());
    EXPECT_EQ(spec.error().code, ErrorCode::Unsupported);
    EXPECT_EQ(spec.error().detail, "future.json: /schemaVersion: " + std::to_string(kCaseSchemaVersion + 1) +
                                       " is newer than this build supports (allowed 1.." +
                                       std::to_string(kCaseSchemaVersion) + "); open it with a newer hysteroscene");
}

TEST(CaseUpgrade, HugeVersionNumberIsRefusedAsNewer) {
    const auto spec = parseCase(R"({"format": "hysteroscene-case", "schemaVersion": 18446744073709551615})", "x.json");
    ASSERT_FALSE(spec.ok());
    EXPECT_EQ(spec.error().code, ErrorCode::Unsupported);
}

TEST(CaseUpgrade, AVersionOneCaseLosesTheFieldsThatDidNothingAndGainsItsTissueFields) {
    const std::string v1 = R"({"format": "hysteroscene-case", "schemaVersion": 1,
        "patient": {"ageYears": 62, "parity": 2, "gravidity": 2, "heightCm": 160, "weightKg": 70, "menopausal": true},
        "meshing": {"method": "particle", "targetEdgeLengthMm": null, "targetVertices": 30000,
                    "particlesPerInnerVoxel": 2, "particlesPerSurfaceVoxel": 1, "relaxationIterations": 60,
                    "threads": 0}})";
    const auto spec = parseCase(v1, "old.json");
    ASSERT_TRUE(spec.ok()) << spec.error().message();
    EXPECT_EQ(spec->meshing.seeding, MeshingSeeding::Lattice);
    EXPECT_FALSE(spec->meshing.particlesPerInnerVoxel.has_value());
    EXPECT_FALSE(spec->patient.cyclePhase.has_value()); // postmenopausal
    EXPECT_FALSE(spec->anatomy.endometrialThicknessMm.has_value());

    const auto young = parseCase(R"({"format": "hysteroscene-case", "schemaVersion": 1,
        "patient": {"ageYears": 30, "menopausal": false}})",
                                 "young.json");
    ASSERT_TRUE(young.ok()) << young.error().message();
    EXPECT_EQ(young->patient.cyclePhase, clinical::CyclePhase::Proliferative);
    // Written back, it is a document of the current version that reads the same.
    const auto again = parseCase(toJson(*young), "again.json");
    ASSERT_TRUE(again.ok()) << again.error().message();
    EXPECT_EQ(*again, *young);
}
