// CaseSpec: the bundled default, round trips, files on disk, the summary.

#include "hs/scene/CaseSpec.h"
#include "TestSupport.h"
#include "hs/io/AtomicFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace hs;
using namespace hs::scene;

namespace {

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// A spec that sets every optional field and uses both placement forms, a hybrid FIGO type and awkward doubles.
CaseSpec richCase() {
    CaseSpec spec = defaultCase();
    spec.title = "Rich: \"quoted\", tab\there, umlaut \xC3\xBC";
    spec.seed = 18446744073709551615ull; // the largest seed
    spec.patient = {62.5, 3, 4, 158.3, 71.25, true};
    spec.anatomy.shape = ShapeMode::Mean;
    spec.anatomy.modelPath = "models/own-cohort.h5";
    spec.anatomy.versionDeg = -35.0; // retroverted
    spec.anatomy.flexionDeg = -12.5; // retroflexed
    spec.anatomy.dimensions = {71.0, 44.0, 36.0, 41.0, 31.0, 62.0, 12.3, 29.2};

    PathologySpec hybrid;
    hybrid.id = "myoma_2";
    hybrid.kind = clinical::PathologyKind::Myoma;
    hybrid.growthModel = clinical::GrowthModel::Particles;
    hybrid.sizeMm = 0.1 + 0.2 + 40.0; // not exactly representable: must survive the round trip bit for bit
    hybrid.figo = clinical::FigoType{2, 5};
    hybrid.placement = clinical::SurfacePlacement{{12.25, -3.0, 40.125}, {0.0, 0.6, 0.8}};
    spec.pathologies.push_back(hybrid);

    PathologySpec sessile;
    sessile.id = "P3";
    sessile.kind = clinical::PathologyKind::Polyp;
    sessile.growthModel = clinical::GrowthModel::Particles;
    sessile.sizeMm = 6.0;
    sessile.attachment = clinical::PolypAttachment::Sessile;
    sessile.placement = clinical::ClinicalPlacement{clinical::UterineLocation::CornualLeft};
    spec.pathologies.push_back(sessile);

    spec.meshing = {MeshingMethod::Cgal, 1.75, std::nullopt, MeshingSeeding::Lattice, std::nullopt, 120, 2};
    spec.patient.cyclePhase.reset(); // postmenopausal
    spec.anatomy.endometrialThicknessMm = 9.5;
    spec.texture.sizePx = 2048;
    spec.texture.exemplars.endometrium = "images/endometrium.png";
    spec.texture.exemplars.cervicalCanal = "images/canal.png";
    spec.texture.vesselDensity = 1.5;
    spec.scene.hydrometraPressureKpa = 10.0;
    spec.scene.materials[static_cast<std::size_t>(clinical::Tissue::Myoma)] = {80.0, 0.49, 1060.0, 0.2};
    spec.scene.materials[static_cast<std::size_t>(clinical::Tissue::Endometrium)].youngsModulusKpa = 12.5;
    return spec;
}

} // namespace

TEST(CaseSpec, DefaultCaseIsValid) {
    const auto issues = checkCase(defaultCase());
    for (const auto& issue : issues)
        ADD_FAILURE() << issue.text();
}

TEST(CaseSpec, BundledDefaultFileParsesToTheDefaultCase) {
    const auto spec = loadCase(HS_DEFAULT_CASE_FILE);
    ASSERT_TRUE(spec.ok()) << spec.error().message();
    EXPECT_TRUE(*spec == defaultCase()) << toJson(*spec);
}

TEST(CaseSpec, BundledDefaultFileIsExactlyTheSerializedDefaultCase) {
    EXPECT_EQ(readText(HS_DEFAULT_CASE_FILE), toJson(defaultCase()));
}

TEST(CaseSpec, DefaultCaseHoldsOneFigo2MyomaAndOneSessileCornualPolyp) {
    const CaseSpec spec = defaultCase();
    EXPECT_EQ(spec.seed, 1u);
    ASSERT_EQ(spec.pathologies.size(), 2u);
    const PathologySpec& myoma = spec.pathologies[0];
    EXPECT_EQ(myoma.kind, clinical::PathologyKind::Myoma);
    EXPECT_EQ(myoma.figo, (clinical::FigoType{2, -1}));
    EXPECT_DOUBLE_EQ(myoma.sizeMm, 20.0);
    const PathologySpec& polyp = spec.pathologies[1];
    EXPECT_EQ(polyp.kind, clinical::PathologyKind::Polyp);
    EXPECT_EQ(polyp.attachment, clinical::PolypAttachment::Sessile);
    EXPECT_EQ(std::get<clinical::ClinicalPlacement>(polyp.placement).location, clinical::UterineLocation::CornualRight);
    EXPECT_DOUBLE_EQ(polyp.sizeMm, 10.0);
}

TEST(CaseSpec, RoundTripGivesAnEqualSpecAndByteIdenticalJson) {
    for (const CaseSpec& original : {defaultCase(), richCase(), CaseSpec{}}) {
        ASSERT_TRUE(checkCase(original).empty()) << checkCase(original).front().text();
        const std::string text = toJson(original);
        const auto parsed = parseCase(text, "round-trip.json");
        ASSERT_TRUE(parsed.ok()) << parsed.error().message() << "\n" << text;
        EXPECT_TRUE(*parsed == original) << text;
        EXPECT_EQ(toJson(*parsed), text);
    }
}

TEST(CaseSpec, ToJsonIsDeterministicAndEndsWithANewline) {
    const std::string a = toJson(richCase());
    EXPECT_EQ(a, toJson(richCase()));
    ASSERT_FALSE(a.empty());
    EXPECT_EQ(a.back(), '\n');
    EXPECT_EQ(a.rfind("{\n    \"format\": \"hysteroscene-case\",\n    \"schemaVersion\": 3,", 0), 0u);
}

TEST(CaseSpec, MinimalDocumentTakesTheDocumentedDefaults) {
    const auto spec = parseCase(R"({"format": "hysteroscene-case", "schemaVersion": 1})", "minimal.json");
    ASSERT_TRUE(spec.ok()) << spec.error().message();
    EXPECT_TRUE(*spec == CaseSpec{});
    EXPECT_DOUBLE_EQ(spec->patient.ageYears, 35.0);
    EXPECT_EQ(spec->meshing.targetVertices, 30000);
    EXPECT_TRUE(spec->pathologies.empty());
}

TEST(CaseSpec, IntegersAreAcceptedWhereNumbersAreExpected) {
    const auto spec =
        parseCase(R"({"format": "hysteroscene-case", "schemaVersion": 1, "patient": {"ageYears": 40}})", "int.json");
    ASSERT_TRUE(spec.ok()) << spec.error().message();
    EXPECT_DOUBLE_EQ(spec->patient.ageYears, 40.0);
}

TEST(CaseSpec, EdgeLengthAloneReplacesTheDefaultVertexTarget) {
    const auto spec = parseCase(
        R"({"format": "hysteroscene-case", "schemaVersion": 1, "meshing": {"targetEdgeLengthMm": 1.5}})", "edge.json");
    ASSERT_TRUE(spec.ok()) << spec.error().message();
    EXPECT_EQ(spec->meshing.targetEdgeLengthMm, 1.5);
    EXPECT_FALSE(spec->meshing.targetVertices.has_value());
}

TEST(CaseSpec, SaveThenLoadGivesTheSameSpec) {
    test::TempDir dir;
    const std::string path = dir.file("case.json");
    const CaseSpec spec = richCase();
    const auto saved = saveCase(spec, path);
    ASSERT_TRUE(saved.ok()) << saved.error().message();
    const auto loaded = loadCase(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message();
    EXPECT_TRUE(*loaded == spec);
    EXPECT_EQ(readText(path), toJson(spec));
}

TEST(CaseSpec, SaveRefusesAnInvalidSpecAndLeavesTheOldFile) {
    test::TempDir dir;
    const std::string path = dir.file("case.json");
    ASSERT_TRUE(saveCase(defaultCase(), path).ok());
    CaseSpec bad = defaultCase();
    bad.patient.ageYears = 130.0;
    const auto saved = saveCase(bad, path);
    ASSERT_FALSE(saved.ok());
    EXPECT_EQ(saved.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(saved.error().detail.find(path), std::string::npos) << saved.error().detail;
    EXPECT_NE(saved.error().detail.find("/patient/ageYears: 130"), std::string::npos) << saved.error().detail;
    EXPECT_EQ(readText(path), toJson(defaultCase()));
}

TEST(CaseSpec, LoadNamesAMissingFile) {
    test::TempDir dir;
    const std::string path = dir.file("absent.json");
    const auto spec = loadCase(path);
    ASSERT_FALSE(spec.ok());
    EXPECT_EQ(spec.error().code, ErrorCode::NotFound);
    EXPECT_NE(spec.error().detail.find(path), std::string::npos) << spec.error().detail;
}

TEST(CaseSpec, LoadRefusesAHugeFileWithoutReadingIt) {
    test::TempDir dir;
    const std::string path = dir.file("huge.json");
    {
        std::ofstream out(path, std::ios::binary);
        const std::string chunk(1 << 20, ' ');
        for (int i = 0; i < 5; ++i)
            out << chunk;
        out << "{}";
    }
    const auto spec = loadCase(path);
    ASSERT_FALSE(spec.ok());
    EXPECT_EQ(spec.error().code, ErrorCode::LimitExceeded);
    EXPECT_NE(spec.error().detail.find(path), std::string::npos) << spec.error().detail;
}

TEST(CaseSpec, ParseRefusesTextAboveTheSizeLimit) {
    const std::string text(static_cast<std::size_t>(kMaxCaseFileBytes) + 1, ' ');
    const auto spec = parseCase(text, "big.json");
    ASSERT_FALSE(spec.ok());
    EXPECT_EQ(spec.error().code, ErrorCode::LimitExceeded);
    EXPECT_NE(spec.error().detail.find("big.json"), std::string::npos);
    EXPECT_NE(spec.error().detail.find(std::to_string(kMaxCaseFileBytes)), std::string::npos);
}

TEST(CaseSpec, EveryEnumerationKeyReadsBack) {
    for (const auto v : kShapeModes) {
        ShapeMode out{};
        ASSERT_TRUE(fromString(toString(v), out));
        EXPECT_EQ(out, v);
    }
    for (const auto v : kMeshingMethods) {
        MeshingMethod out{};
        ASSERT_TRUE(fromString(toString(v), out));
        EXPECT_EQ(out, v);
    }
    MeshingMethod method{};
    EXPECT_FALSE(fromString("Particle", method)); // keys are case-sensitive
}

TEST(CaseSpec, EffectiveMaterialAppliesOnlyTheOverriddenFields) {
    SceneParams scene;
    scene.materials[static_cast<std::size_t>(clinical::Tissue::Myoma)].youngsModulusKpa = 90.0;
    const TissueMaterial myoma = effectiveMaterial(scene, clinical::Tissue::Myoma);
    EXPECT_DOUBLE_EQ(myoma.youngsModulusKpa, 90.0);
    EXPECT_DOUBLE_EQ(myoma.poissonRatio, defaultMaterial(clinical::Tissue::Myoma).poissonRatio);
    EXPECT_DOUBLE_EQ(effectiveMaterial(scene, clinical::Tissue::Myometrium).youngsModulusKpa, 30.0);
    for (const clinical::Tissue tissue : clinical::kTissues) {
        EXPECT_TRUE(youngsModulusRangeKpa(tissue).contains(defaultMaterial(tissue).youngsModulusKpa));
        EXPECT_TRUE(limits::kPoissonRatio.contains(defaultMaterial(tissue).poissonRatio));
        EXPECT_TRUE(limits::kDensityKgPerM3.contains(defaultMaterial(tissue).densityKgPerM3));
    }
}

TEST(CaseSpec, DescribeSummarisesPatientPathologiesAndStages) {
    const auto lines = describe(defaultCase());
    std::string all;
    for (const auto& line : lines)
        all += line + "\n";
    EXPECT_NE(all.find("seed        1\n"), std::string::npos) << all;
    EXPECT_NE(all.find("35 years, gravida 1 para 1, 165 cm, 65 kg (BMI 23.9), premenopausal"), std::string::npos)
        << all;
    EXPECT_NE(all.find("myoma-1: myoma FIGO 2 (submucosal, >= 50 % intramural), 20 mm, left-lateral, growth skeleton"),
              std::string::npos)
        << all;
    EXPECT_NE(all.find("polyp-1: polyp sessile, 10 mm, cornual-right, growth skeleton"), std::string::npos) << all;
    EXPECT_NE(all.find("hydrometra 8 kPa (60 mmHg)"), std::string::npos) << all;
}

TEST(CaseSpec, ExampleInTheFormatDocumentIsAValidCase) {
    const std::string doc = readText(HS_CASE_FORMAT_DOC);
    const auto begin = doc.find("```json\n");
    ASSERT_NE(begin, std::string::npos);
    const auto end = doc.find("```", begin + 8);
    ASSERT_NE(end, std::string::npos);
    const auto spec = parseCase(doc.substr(begin + 8, end - begin - 8), "case-format.md example");
    ASSERT_TRUE(spec.ok()) << spec.error().message();
    EXPECT_EQ(spec->pathologies.at(0).figo, (clinical::FigoType{2, 5}));
    EXPECT_FALSE(spec->meshing.targetVertices.has_value());
}
