// Strict validation: each class of bad input fails with an error that names the source, the JSON path, the value
// and the allowed range or choices.

#include "hs/core/Rng.h"
#include "hs/scene/CaseSpec.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <limits>
#include <optional>
#include <string>
#include <vector>

using namespace hs;
using namespace hs::scene;
using ojson = nlohmann::ordered_json;

namespace {

/// One bad document: the default case with `pointer` set to `value` (JSON text) or removed (std::nullopt).
struct BadCase {
    const char* name;
    const char* pointer;
    std::optional<std::string> value;
    const char* path;                  ///< the path the first error must name
    std::vector<const char*> mentions; ///< value, range, choices...
    ErrorCode code = ErrorCode::InvalidInput;
};

void PrintTo(const BadCase& c, std::ostream* os) {
    *os << c.name;
}

std::string mutatedDefault(const BadCase& c) {
    ojson doc = ojson::parse(toJson(defaultCase()));
    const ojson::json_pointer pointer(c.pointer);
    if (c.value)
        doc[pointer] = ojson::parse(*c.value);
    else
        doc[pointer.parent_pointer()].erase(pointer.back());
    return doc.dump(4);
}

const std::vector<BadCase>& badCases() {
    static const std::vector<BadCase> cases = {
        // Patient
        {"AgeOfFive", "/patient/ageYears", "5", "/patient/ageYears", {"5", "18..80 years"}},
        {"AgeOf130", "/patient/ageYears", "130", "/patient/ageYears", {"130", "18..80 years"}},
        {"NegativeParity", "/patient/parity", "-1", "/patient/parity", {"-1", "0..6 births"}},
        {"ElevenBirths", "/patient/parity", "11", "/patient/parity", {"11", "0..6 births"}},
        {"MenopausalAt30",
         "/patient",
         R"({"ageYears": 30, "menopausal": true})",
         "/patient/menopausal",
         {"ageYears >= 40", "30"}},
        {"PremenopausalAt70",
         "/patient",
         R"({"ageYears": 70, "menopausal": false})",
         "/patient/menopausal",
         {"ageYears <= 60", "70"}},
        {"ParityAsText", "/patient/parity", "\"two\"", "/patient/parity", {"expected an integer", "\"two\""}},
        {"FractionalParity", "/patient/parity", "1.5", "/patient/parity", {"expected an integer", "1.5"}},
        {"GravidityBelowParity", "/patient/gravidity", "0", "/patient/gravidity", {"0", "less than the parity 1"}},
        {"TinyWeight", "/patient/weightKg", "3.5", "/patient/weightKg", {"3.5", "35..160 kg"}},
        {"MenopausalAsText", "/patient/menopausal", "\"yes\"", "/patient/menopausal", {"true or false", "\"yes\""}},
        {"PatientNotAnObject", "/patient", "[]", "/patient", {"expected an object", "array"}},
        // Anatomy
        {"UnknownShape", "/anatomy/shape", "\"average\"", "/anatomy/shape", {"\"average\"", "\"sample\", \"mean\""}},
        {"VersionBeyondRange", "/anatomy/versionDeg", "120", "/anatomy/versionDeg", {"120", "-90..90 degrees"}},
        {"CavityLongerThanUterus",
         "/anatomy/dimensions",
         R"({"lengthMm": 40, "cavityLengthMm": 45})",
         "/anatomy/dimensions/cavityLengthMm",
         {"45", "lengthMm 40"}},
        {"ThinWall",
         "/anatomy/dimensions/fundalWallThicknessMm",
         "3",
         "/anatomy/dimensions/fundalWallThicknessMm",
         {"3", "5..20 mm"}},
        {"EmptyModelPath", "/anatomy/modelPath", "\"\"", "/anatomy/modelPath", {"\"\"", "null"}},
        // Pathologies
        {"PathologiesNotAnArray", "/pathologies", "{}", "/pathologies", {"an array"}},
        {"FigoNine", "/pathologies/0/figo", "9", "/pathologies/0/figo", {"\"9\"", "0..8"}},
        {"FigoHybridWithSerosalSeven", "/pathologies/0/figo", "\"2-7\"", "/pathologies/0/figo", {"\"2-7\"", "5..6"}},
        {"FigoText", "/pathologies/0/figo", "\"submucosal\"", "/pathologies/0/figo", {"\"submucosal\"", "0..8"}},
        {"MyomaWithoutFigo", "/pathologies/0/figo", std::nullopt, "/pathologies/0/figo", {"needs a FIGO type"}},
        {"PolypWithFigo", "/pathologies/1/figo", "0", "/pathologies/1/figo", {"\"0\"", "a polyp has no FIGO type"}},
        {"MyomaWithAttachment",
         "/pathologies/0/attachment",
         "\"sessile\"",
         "/pathologies/0/attachment",
         {"\"sessile\"", "polyps only"}},
        {"DuplicatedIds", "/pathologies/1/id", "\"myoma-1\"", "/pathologies/1/id", {"\"myoma-1\"", "/pathologies/0"}},
        {"IdWithSpace", "/pathologies/0/id", "\"my oma\"", "/pathologies/0/id", {"\"my oma\"", "letters, digits"}},
        {"MissingId", "/pathologies/0/id", std::nullopt, "/pathologies/0/id", {"required field is missing"}},
        {"UnknownKind", "/pathologies/0/kind", "\"cyst\"", "/pathologies/0/kind", {"\"cyst\"", "\"myoma\", \"polyp\""}},
        {"UnknownGrowthModel",
         "/pathologies/0/growthModel",
         "\"magic\"",
         "/pathologies/0/growthModel",
         {"\"magic\"", "\"ca\", \"skeleton\", \"particles\""}},
        {"PolypGrownByTheAutomaton",
         "/pathologies/1/growthModel",
         "\"ca\"",
         "/pathologies/1/growthModel",
         {"\"ca\"", "\"skeleton\", \"particles\""}},
        {"ZeroSizeMyoma", "/pathologies/0/sizeMm", "0", "/pathologies/0/sizeMm", {"0", "5..100 mm"}},
        {"HugePolyp", "/pathologies/1/sizeMm", "60", "/pathologies/1/sizeMm", {"60", "3..40 mm"}},
        {"SessilePolypWithStalk",
         "/pathologies/1/stalkLengthMm",
         "8",
         "/pathologies/1/stalkLengthMm",
         {"8", "sessile polyp has no stalk"}},
        {"PedunculatedPolypWithoutStalk",
         "/pathologies/1/attachment",
         "\"pedunculated\"",
         "/pathologies/1/stalkLengthMm",
         {"needs a stalk length", "1..30 mm"}},
        {"PolypWithoutAttachment",
         "/pathologies/1/attachment",
         std::nullopt,
         "/pathologies/1/attachment",
         {"needs an attachment", "\"sessile\", \"pedunculated\""}},
        {"BothPlacementForms",
         "/pathologies/0/placement/pointMm",
         "[0, 0, 0]",
         "/pathologies/0/placement",
         {"not both"}},
        {"EmptyPlacement", "/pathologies/0/placement", "{}", "/pathologies/0/placement", {"empty placement"}},
        {"SurfacePlacementWithoutNormal",
         "/pathologies/0/placement",
         R"({"pointMm": [1, 2, 3]})",
         "/pathologies/0/placement/normal",
         {"required field is missing"}},
        {"ZeroNormal",
         "/pathologies/0/placement",
         R"({"pointMm": [1, 2, 3], "normal": [0, 0, 0]})",
         "/pathologies/0/placement/normal",
         {"length 0"}},
        {"PointWithTwoCoordinates",
         "/pathologies/0/placement",
         R"({"pointMm": [1, 2], "normal": [0, 0, 1]})",
         "/pathologies/0/placement/pointMm",
         {"an array of 3 numbers"}},
        {"PointFarAway",
         "/pathologies/0/placement",
         R"({"pointMm": [1, 2, 9000], "normal": [0, 0, 1]})",
         "/pathologies/0/placement/pointMm/2",
         {"9000", "-500..500 mm"}},
        {"UnknownLocation",
         "/pathologies/0/placement/location",
         "\"left\"",
         "/pathologies/0/placement/location",
         {"\"left\"", "\"left-lateral\""}},
        {"CervicalPolyp",
         "/pathologies/1/placement/location",
         "\"cervical\"",
         "/pathologies/1/placement/location",
         {"\"cervical\""}},
        {"CervicalMyomaOfType2",
         "/pathologies/0/placement/location",
         "\"cervical\"",
         "/pathologies/0/figo",
         {"\"2\"", "FIGO type 8"}},
        {"SeventeenPathologies",
         "/pathologies",
         "[{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}]",
         "/pathologies",
         {"17", "at most 16"}},
        {"CyclePhaseAfterMenopause",
         "/patient",
         R"({"ageYears": 58, "menopausal": true, "cyclePhase": "secretory"})",
         "/patient/cyclePhase",
         {"\"secretory\"", "postmenopausal", "null"}},
        {"NoCyclePhaseBeforeMenopause",
         "/patient/cyclePhase",
         "null",
         "/patient/cyclePhase",
         {"premenopausal", "\"menstrual\", \"proliferative\", \"secretory\""}},
        {"UnknownCyclePhase",
         "/patient/cyclePhase",
         "\"luteal\"",
         "/patient/cyclePhase",
         {"\"luteal\"", "\"proliferative\""}},
        {"ThickEndometrium",
         "/anatomy/endometrialThicknessMm",
         "25",
         "/anatomy/endometrialThicknessMm",
         {"25", "1..20 mm"}},
        // Root, format and version
        {"UnknownRootField", "/colour", "\"pink\"", "/colour", {"unknown field \"colour\"", "patient"}},
        {"UnknownNestedField", "/patient/hight", "170", "/patient/hight", {"unknown field \"hight\"", "heightCm"}},
        {"MissingFormat", "/format", std::nullopt, "/format", {"required field is missing"}},
        {"WrongFormat", "/format", "\"scene-package\"", "/format", {"\"scene-package\"", "\"hysteroscene-case\""}},
        {"FutureVersion", "/schemaVersion", "4", "/schemaVersion", {"4", "newer", "1..3"}, ErrorCode::Unsupported},
        {"VersionZero", "/schemaVersion", "0", "/schemaVersion", {"0", "older", "1..3"}, ErrorCode::Unsupported},
        {"VersionAsText", "/schemaVersion", "\"1\"", "/schemaVersion", {"expected an integer"}},
        {"NegativeSeed", "/seed", "-1", "/seed", {"unsigned integer", "-1"}},
        {"FractionalSeed", "/seed", "1.5", "/seed", {"unsigned integer", "1.5"}},
        {"LongTitle", "/title", "\"" + std::string(300, 'x') + "\"", "/title", {"300 bytes", "200"}},
        // Stages
        {"UnknownMeshingMethod",
         "/meshing/method",
         "\"gmsh\"",
         "/meshing/method",
         {"\"gmsh\"", "\"particle\", \"tetgen\", \"cgal\""}},
        {"BothDensityControls", "/meshing/targetEdgeLengthMm", "1.5", "/meshing/targetVertices", {"not both"}},
        {"NoDensityControl", "/meshing/targetVertices", "null", "/meshing/targetVertices", {"set one of them"}},
        {"BillionVertices",
         "/meshing/targetVertices",
         "1000000000",
         "/meshing/targetVertices",
         {"1000000000", "500..500000"}},
        {"NegativeThreads", "/meshing/threads", "-2", "/meshing/threads", {"-2", "0..256"}},
        {"ParticlesWithTheLattice",
         "/meshing/particlesPerInnerVoxel",
         "3",
         "/meshing/particlesPerInnerVoxel",
         {"3", "does nothing", "\"lattice\"", "null"}},
        {"RandomSeedingWithoutParticles",
         "/meshing/seeding",
         "\"random\"",
         "/meshing/particlesPerInnerVoxel",
         {"\"random\"", "1..8"}},
        {"UnknownSeeding",
         "/meshing/seeding",
         "\"poisson\"",
         "/meshing/seeding",
         {"\"poisson\"", "\"lattice\", \"random\""}},
        {"SurfaceVoxelFieldIsGone",
         "/meshing/particlesPerSurfaceVoxel",
         "1",
         "/meshing/particlesPerSurfaceVoxel",
         {"unknown field \"particlesPerSurfaceVoxel\""}},
        {"WildHeterogeneity",
         "/scene/materials/myoma/heterogeneity",
         "0.8",
         "/scene/materials/myoma/heterogeneity",
         {"0.8", "0..0.5"}},
        {"TextureNotPowerOfTwo", "/texture/sizePx", "1000", "/texture/sizePx", {"1000", "power of two", "64..8192"}},
        {"UnknownExemplar",
         "/texture/exemplars/cervix",
         "\"a.png\"",
         "/texture/exemplars/cervix",
         {"unknown field", "endometrium, myoma, polyp"}},
        {"EmptyCanalExemplar",
         "/texture/exemplars/cervicalCanal",
         "\"\"",
         "/texture/exemplars/cervicalCanal",
         {"\"\" is not a file path", "null"}},
        {"StiffEndometrium",
         "/scene/materials/endometrium/youngsModulusKpa",
         "100",
         "/scene/materials/endometrium/youngsModulusKpa",
         {"100", "12.5..26.2 kPa"}},
        {"CompressibleMyoma",
         "/scene/materials/myoma/poissonRatio",
         "0.3",
         "/scene/materials/myoma/poissonRatio",
         {"0.3", "0.45..0.49"}},
        {"UnknownTissue", "/scene/materials/bone", "{}", "/scene/materials/bone", {"unknown field \"bone\""}},
        {"HydrometraAbove20Kpa",
         "/scene/hydrometraPressureKpa",
         "30",
         "/scene/hydrometraPressureKpa",
         {"30", "0..20 kPa"}},
    };
    return cases;
}

class CaseValidation : public ::testing::TestWithParam<BadCase> {};

} // namespace

TEST_P(CaseValidation, RejectsTheDocumentNamingPathValueAndRange) {
    const BadCase& c = GetParam();
    const std::string text = mutatedDefault(c);
    const auto spec = parseCase(text, "bad.json");
    ASSERT_FALSE(spec.ok()) << text;
    EXPECT_EQ(spec.error().code, c.code) << spec.error().message();
    const std::string& detail = spec.error().detail;
    const std::string firstLine = detail.substr(0, detail.find('\n'));
    EXPECT_EQ(firstLine.rfind(std::string("bad.json: ") + c.path + ": ", 0), 0u) << detail;
    for (const char* mention : c.mentions)
        EXPECT_NE(firstLine.find(mention), std::string::npos) << "missing '" << mention << "' in: " << detail;
}

INSTANTIATE_TEST_SUITE_P(BadInput, CaseValidation, ::testing::ValuesIn(badCases()),
                         [](const ::testing::TestParamInfo<BadCase>& param) { return std::string(param.param.name); });

namespace {

std::string errorOf(std::string_view text) {
    const auto spec = parseCase(text, "raw.json");
    return spec.ok() ? std::string("(parsed)") : spec.error().detail;
}

} // namespace

TEST(CaseValidation, TruncatedJsonIsNotValidJsonAndNamesTheSource) {
    const std::string text = toJson(defaultCase());
    const auto spec = parseCase(std::string_view(text).substr(0, text.size() / 2), "cut.json");
    ASSERT_FALSE(spec.ok());
    EXPECT_EQ(spec.error().code, ErrorCode::InvalidInput);
    EXPECT_EQ(spec.error().detail.rfind("cut.json: /", 0), 0u) << spec.error().detail;
    EXPECT_NE(spec.error().detail.find(": not valid JSON: parse error at line"), std::string::npos)
        << spec.error().detail;
}

TEST(CaseValidation, NumberTooLargeForADoubleIsRejectedWithItsPath) {
    std::string text = toJson(defaultCase());
    const std::string height = "\"heightCm\": 165.0";
    text.replace(text.find(height), height.size(), "\"heightCm\": 1e999");
    const std::string detail = errorOf(text);
    EXPECT_EQ(detail, "raw.json: /patient/heightCm: not valid JSON: number overflow parsing '1e999'") << detail;
}

TEST(CaseValidation, EmptyTextIsNotValidJson) {
    EXPECT_EQ(errorOf("").rfind("raw.json: (root): not valid JSON", 0), 0u) << errorOf("");
}

TEST(CaseValidation, NonObjectRootIsRejected) {
    for (const char* text : {"[1, 2]", "42", "null", "\"case\""}) {
        const std::string detail = errorOf(text);
        EXPECT_EQ(detail.rfind("raw.json: (root): expected an object", 0), 0u) << text << " -> " << detail;
    }
}

TEST(CaseValidation, DuplicateKeysAreRejectedWithTheirPath) {
    const std::string detail = errorOf(R"({"format": "hysteroscene-case", "schemaVersion": 1,
        "pathologies": [{"id": "a", "kind": "myoma", "figo": 2, "sizeMm": 20, "sizeMm": 200,
                         "placement": {"location": "fundal"}}]})");
    EXPECT_EQ(detail.rfind("raw.json: /pathologies/0/sizeMm: duplicate key \"sizeMm\"", 0), 0u) << detail;
}

TEST(CaseValidation, DeepNestingIsRejectedBeforeParsing) {
    const std::string text = std::string(100000, '[') + std::string(100000, ']');
    const std::string detail = errorOf(text);
    EXPECT_NE(detail.find("nested 100000 deep"), std::string::npos) << detail;
}

TEST(CaseValidation, InvalidUtf8IsNotValidJson) {
    const std::string detail =
        errorOf("{\"format\": \"hysteroscene-case\", \"schemaVersion\": 1, \"title\": \"\xff\xfe\"}");
    EXPECT_EQ(detail.rfind("raw.json: /title: not valid JSON", 0), 0u) << detail;
}

TEST(CaseValidation, EveryProblemIsListedOnItsOwnLine) {
    const std::string detail = errorOf(R"({"format": "hysteroscene-case", "schemaVersion": 1,
        "patient": {"ageYears": 5, "parity": -1, "hight": 170}, "texture": {"sizePx": 3}})");
    const std::vector<std::string> expected = {
        "raw.json: /patient/hight: unknown field", "raw.json: /patient/ageYears: 5 is outside",
        "raw.json: /patient/parity: -1 is outside", "raw.json: /texture/sizePx: 3 is not a supported size"};
    std::size_t lines = 1;
    for (const char c : detail)
        lines += c == '\n' ? 1 : 0;
    EXPECT_EQ(lines, expected.size()) << detail;
    for (const auto& e : expected)
        EXPECT_NE(detail.find(e), std::string::npos) << e << "\n" << detail;
}

TEST(CaseValidation, ManyProblemsAreCappedWithACount) {
    std::string pathologies;
    for (int i = 0; i < 16; ++i)
        pathologies += std::string(i ? "," : "") + R"({"id": "x", "kind": "polyp", "sizeMm": 1, "figo": 1})";
    const std::string detail =
        errorOf(R"({"format": "hysteroscene-case", "schemaVersion": 1, "pathologies": [)" + pathologies + "]}");
    EXPECT_NE(detail.find("more problems"), std::string::npos) << detail;
}

TEST(CaseValidation, CheckCaseRejectsNonFiniteValuesBuiltInCode) {
    CaseSpec spec = defaultCase();
    spec.patient.ageYears = std::numeric_limits<double>::quiet_NaN();
    spec.pathologies[0].placement =
        clinical::SurfacePlacement{{0.0, std::numeric_limits<double>::infinity(), 0.0}, {0, 0, 1}};
    const auto issues = checkCase(spec);
    ASSERT_EQ(issues.size(), 2u);
    EXPECT_EQ(issues[0].text(), "/patient/ageYears: non-finite value nan (allowed 18..80 years)");
    EXPECT_EQ(issues[1].path, "/pathologies/0/placement/pointMm/1");
}

TEST(CaseValidation, EveryTruncationOfTheDefaultFileFailsCleanly) {
    const std::string text = toJson(defaultCase());
    for (std::size_t length = 0; length + 1 < text.size(); ++length) {
        const auto spec = parseCase(std::string_view(text).substr(0, length), "cut.json");
        ASSERT_FALSE(spec.ok()) << "prefix of " << length << " bytes parsed";
        ASSERT_EQ(spec.error().code, ErrorCode::InvalidInput) << spec.error().message();
        ASSERT_EQ(spec.error().detail.rfind("cut.json: ", 0), 0u) << spec.error().detail;
    }
}

TEST(CaseValidation, SeededByteMutationsNeverCrashOrThrow) {
    const std::string original = toJson(defaultCase());
    const std::string alphabet = "{}[]\",:0123456789.-+eE truefalsnul\\";
    Rng rng(20240601);
    for (int trial = 0; trial < 2000; ++trial) {
        std::string text = original;
        const int edits = 1 + static_cast<int>(rng.below(4));
        for (int e = 0; e < edits; ++e) {
            const auto at = static_cast<std::size_t>(rng.below(text.size()));
            text[at] = alphabet[static_cast<std::size_t>(rng.below(alphabet.size()))];
        }
        const auto spec = parseCase(text, "mutated.json");
        if (spec.ok())
            EXPECT_TRUE(checkCase(*spec).empty());
        else
            EXPECT_NE(spec.error().code, ErrorCode::Internal) << spec.error().message();
    }
}
