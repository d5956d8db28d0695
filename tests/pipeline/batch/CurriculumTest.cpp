// The curriculum: reading, the plan-time refusals of impossible combinations, deterministic drawing.
#include "TestSupport.h"

#include "hs/batch/Curriculum.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace hs;
using namespace hs::batch;

namespace {

std::string curriculumWith(const std::string& templates, const std::string& extra = "") {
    return R"({"format": "hysteroscene-curriculum", "schemaVersion": 1, "seed": 3, )" + extra + R"("templates": [)" +
           templates + "]}";
}

const std::string kPolypTemplate = R"({"name": "polyp", "cases": 3,
    "patient": {"ageYears": {"uniform": [25, 45]}, "parity": {"oneOf": [0, 1]}, "gravidity": 2},
    "pathologies": [{"id": "p1", "kind": "polyp", "sizeMm": {"uniform": [6, 12]}, "attachment": "sessile",
                     "location": {"oneOf": ["fundal", "posterior"]}}]})";

/// Every problem of a curriculum with default base cases (parse, then checkCurriculum), one per line.
std::string problems(const std::string& text) {
    auto parsed = parseCurriculum(text, "c.json");
    if (!parsed)
        return parsed.error().detail;
    std::vector<scene::CaseSpec> bases(parsed->templates.size(), scene::defaultCase());
    std::string all;
    for (const auto& issue : checkCurriculum(*parsed, bases))
        all += issue.text() + "\n";
    return all;
}

LoadedCurriculum loaded(const std::string& text) {
    auto parsed = parseCurriculum(text, "c.json");
    EXPECT_TRUE(parsed.ok()) << parsed.error().detail;
    LoadedCurriculum l{*parsed, std::vector<scene::CaseSpec>(parsed->templates.size(), scene::defaultCase()), "c"};
    return l;
}

} // namespace

TEST(Curriculum, ReadsSamplersAndWritesThemBack) {
    auto parsed = parseCurriculum(curriculumWith(kPolypTemplate, R"("title": "T", "variants": 2, )"), "c.json");
    ASSERT_TRUE(parsed.ok()) << parsed.error().detail;
    const CaseTemplate& t = parsed->templates.at(0);
    EXPECT_EQ(parsed->variants, 2);
    ASSERT_TRUE(t.patient.ageYears && t.patient.ageYears->range);
    EXPECT_EQ(t.patient.ageYears->range->min, 25.0);
    EXPECT_EQ(t.patient.parity->values.size(), 2u);
    EXPECT_TRUE(t.patient.gravidity->fixed());
    ASSERT_TRUE(t.pathologies);
    EXPECT_EQ((*t.pathologies)[0].location.values.size(), 2u);
    auto again = parseCurriculum(toJson(*parsed), "again.json");
    ASSERT_TRUE(again.ok()) << again.error().detail;
    EXPECT_EQ(toJson(*again), toJson(*parsed));
}

TEST(Curriculum, NamesUnknownFieldsWrongTypesAndBadSamplers) {
    const std::string text = curriculumWith(R"({"name": "a", "cases": 1, "patient": {"age": 30,
        "parity": {"uniform": [2, 1]}, "heightCm": {"between": [150, 170]}, "weightKg": [60, 70]}})");
    const std::string all = problems(text);
    EXPECT_NE(all.find("/templates/0/patient/age: unknown field"), std::string::npos) << all;
    EXPECT_NE(all.find("/templates/0/patient/parity/uniform: min 2 is greater than max 1"), std::string::npos) << all;
    EXPECT_NE(all.find("/templates/0/patient/heightCm/between: unknown field"), std::string::npos) << all;
    EXPECT_NE(all.find("/templates/0/patient/weightKg: expected a number"), std::string::npos) << all;
    EXPECT_NE(problems(R"({"format": "x", "schemaVersion": 2, "seed": 1, "templates": []})").find("/schemaVersion"),
              std::string::npos);
}

TEST(Curriculum, AcceptsAPlausibleTemplate) {
    EXPECT_EQ(problems(curriculumWith(kPolypTemplate)), "");
}

TEST(Curriculum, RefusesALargeMyomaInAPostmenopausalUterusNamingTheEntry) {
    const std::string text = curriculumWith(R"({"name": "old", "cases": 2,
        "patient": {"ageYears": {"uniform": [55, 70]}, "menopausal": true},
        "pathologies": [{"id": "m1", "kind": "myoma", "sizeMm": {"uniform": [20, 80]}, "figo": 4,
                         "location": "fundal"}]})");
    const std::string all = problems(text);
    EXPECT_NE(all.find("/templates/0/pathologies/0/sizeMm: up to 80 mm, but the expected uterus of a postmenopausal"),
              std::string::npos)
        << all;
}

TEST(Curriculum, RefusesFigoTypesAndLocationsThePlacementCannotGive) {
    const std::string text = curriculumWith(R"({"name": "figo", "cases": 1,
        "pathologies": [{"id": "m1", "kind": "myoma", "sizeMm": 20, "figo": {"oneOf": [2, 8, "4-5"]},
                         "location": {"oneOf": ["fundal", "cervical"]}},
                        {"id": "p1", "kind": "polyp", "sizeMm": 8, "attachment": "sessile", "figo": 1,
                         "location": "anterior"}]})");
    const std::string all = problems(text);
    EXPECT_NE(all.find("/templates/0/pathologies/0/figo: FIGO type 8 (cervical, parasitic) is not modelled"),
              std::string::npos)
        << all;
    EXPECT_NE(all.find("/templates/0/pathologies/0/location: \"cervical\" is not modelled"), std::string::npos) << all;
    EXPECT_NE(all.find("/templates/0/pathologies/0/figo: \"4-5\" is not a FIGO type"), std::string::npos) << all;
    EXPECT_NE(all.find("/templates/0/pathologies/1/figo: \"1\" is not allowed: a polyp has no FIGO type"),
              std::string::npos)
        << all;
}

TEST(Curriculum, RefusesPatientsTheCaseFormatRefuses) {
    const std::string text = curriculumWith(R"({"name": "p", "cases": 1,
        "patient": {"ageYears": {"uniform": [30, 65]}, "parity": {"oneOf": [0, 3]}, "gravidity": 2,
                    "menopausal": {"oneOf": [true, false]}, "heightCm": 120}})");
    const std::string all = problems(text);
    EXPECT_NE(all.find("/templates/0/patient/gravidity: 2 is less than the parity 3"), std::string::npos) << all;
    EXPECT_NE(all.find("/templates/0/patient/menopausal: true needs ageYears >= 40"), std::string::npos) << all;
    EXPECT_NE(all.find("/templates/0/patient/heightCm: 120 is outside the supported range"), std::string::npos) << all;
}

TEST(Curriculum, RefusesBadCountsAndNames) {
    const std::string text =
        curriculumWith(R"({"name": "a b", "cases": 0}, {"name": "x", "cases": 1}, {"name": "x", "cases": 20000})",
                       R"("variants": 0, )");
    const std::string all = problems(text);
    EXPECT_NE(all.find("/variants: 0 is outside"), std::string::npos) << all;
    EXPECT_NE(all.find("/templates/0/name: \"a b\" is not a valid name"), std::string::npos) << all;
    EXPECT_NE(all.find("/templates/0/cases: 0 is outside"), std::string::npos) << all;
    EXPECT_NE(all.find("/templates/2/name: \"x\" repeats the name of /templates/1"), std::string::npos) << all;
    EXPECT_NE(all.find("/templates/2/cases: 20000 is outside"), std::string::npos) << all;
}

TEST(Curriculum, DrawsTheSameValidCasesForTheSameSeed) {
    const LoadedCurriculum l = loaded(curriculumWith(kPolypTemplate));
    for (std::size_t k = 0; k < 3; ++k) {
        const scene::CaseSpec a = sampleCase(l, 0, k);
        EXPECT_EQ(a, sampleCase(l, 0, k));
        EXPECT_TRUE(scene::checkCase(a).empty()) << scene::checkCase(a).front().text();
        EXPECT_GE(a.patient.ageYears, 25.0);
        EXPECT_LE(a.patient.ageYears, 45.0);
        EXPECT_LT(a.seed, std::uint64_t{1} << 53);
        ASSERT_EQ(a.pathologies.size(), 1u);
        EXPECT_GE(a.pathologies[0].sizeMm, 6.0);
        EXPECT_LE(a.pathologies[0].sizeMm, 12.0);
    }
    EXPECT_NE(sampleCase(l, 0, 0).seed, sampleCase(l, 0, 1).seed);
}

TEST(Curriculum, DrawsEveryChoiceWithRoughlyEqualFrequency) {
    auto text = curriculumWith(R"({"name": "p", "cases": 400, "patient": {"parity": {"oneOf": [0, 1, 2, 3]},
        "gravidity": 3}})");
    const LoadedCurriculum l = loaded(text);
    int counts[4] = {0, 0, 0, 0};
    for (std::size_t k = 0; k < 400; ++k)
        ++counts[sampleCase(l, 0, k).patient.parity];
    for (int c : counts) {
        EXPECT_GT(c, 70);
        EXPECT_LT(c, 130);
    }
}

TEST(Curriculum, DropsTheCyclePhaseOfPostmenopausalCases) {
    const LoadedCurriculum l = loaded(curriculumWith(
        R"({"name": "old", "cases": 2, "patient": {"ageYears": {"uniform": [55, 60]}, "menopausal": true}})"));
    const scene::CaseSpec c = sampleCase(l, 0, 1);
    EXPECT_TRUE(c.patient.menopausal);
    EXPECT_FALSE(c.patient.cyclePhase.has_value());
    EXPECT_TRUE(scene::checkCase(c).empty());
}

TEST(Curriculum, LoadsTheBundledDefaultCurriculum) {
    auto l =
        loadCurriculum((hs::test::testDataDir() / ".." / ".." / "resources" / "curricula" / "default.json").string());
    ASSERT_TRUE(l.ok()) << l.error().detail;
    EXPECT_EQ(l->curriculum.templates.size(), 3u);
}

TEST(Curriculum, NamesAMissingBaseCase) {
    hs::test::TempDir dir;
    { std::ofstream(dir.file("c.json")) << curriculumWith(R"({"name": "a", "cases": 1, "base": "nowhere.json"})"); }
    auto l = loadCurriculum(dir.file("c.json"));
    ASSERT_FALSE(l.ok());
    EXPECT_NE(l.error().detail.find("/templates/0/base: "), std::string::npos) << l.error().detail;
    EXPECT_NE(l.error().detail.find("nowhere.json"), std::string::npos) << l.error().detail;
}

TEST(Curriculum, KeepsTheBaseCasesRelativePathsPointingWhereTheyDid) {
    hs::test::TempDir dir;
    std::filesystem::create_directories(dir.path() / "bases");
    scene::CaseSpec base = scene::defaultCase();
    base.anatomy.modelPath = "../models/uterus.h5";
    base.texture.exemplars.myoma = "/abs/myoma.png";
    ASSERT_TRUE(scene::saveCase(base, dir.file("bases/base.json")).ok());
    { std::ofstream(dir.file("c.json")) << curriculumWith(R"({"name": "a", "cases": 1, "base": "bases/base.json"})"); }
    auto l = loadCurriculum(dir.file("c.json"));
    ASSERT_TRUE(l.ok()) << l.error().detail;
    EXPECT_EQ(*l->bases[0].anatomy.modelPath, (dir.path() / "models" / "uterus.h5").string());
    EXPECT_EQ(*l->bases[0].texture.exemplars.myoma, "/abs/myoma.png");
    EXPECT_EQ(sampleCase(*l, 0, 0).anatomy.modelPath, l->bases[0].anatomy.modelPath);
}
