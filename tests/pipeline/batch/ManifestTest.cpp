// The manifest as untrusted input, planBatch's determinism, and status records.
#include "TestSupport.h"

#include "hs/batch/JobStatus.h"
#include "hs/batch/Manifest.h"
#include "hs/io/AtomicFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace hs;
using namespace hs::batch;

namespace {

const std::string kHeader = "# hysteroscene-batch-manifest 1\nindex\tjob\tcase\tseed\toutput\n";

std::string manifestError(const std::string& lines) {
    auto parsed = parseManifest(kHeader + lines, "m.tsv");
    return parsed ? std::string() : parsed.error().detail;
}

LoadedCurriculum smallCurriculum(int variants) {
    auto parsed = parseCurriculum(R"({"format": "hysteroscene-curriculum", "schemaVersion": 1, "seed": 11,
        "variants": )" + std::to_string(variants) +
                                      R"(, "templates": [
        {"name": "a", "cases": 2, "patient": {"ageYears": {"uniform": [30, 40]}}},
        {"name": "b", "cases": 1, "pathologies": []}]})",
                                  "c.json");
    EXPECT_TRUE(parsed.ok()) << parsed.error().detail;
    return LoadedCurriculum{*parsed, {scene::defaultCase(), scene::defaultCase()}, "c.json"};
}

std::string readText(const std::filesystem::path& path) {
    auto text = io::readFile(path.string(), 1 << 24);
    return text ? *text : std::string();
}

} // namespace

TEST(Manifest, WritesAndReadsBackEveryField) {
    Manifest m;
    m.jobs.push_back({0, "a-0000-v00", "cases/a-0000.json", 18446744073709551615ull, "packages/a-0000-v00"});
    m.jobs.push_back({1, "a-0000-v01", "cases/a-0000.json", 5, "packages/a-0000-v01"});
    auto parsed = parseManifest(formatManifest(m), "m.tsv");
    ASSERT_TRUE(parsed.ok()) << parsed.error().detail;
    ASSERT_EQ(parsed->jobs.size(), 2u);
    EXPECT_EQ(parsed->jobs[0].seed, 18446744073709551615ull);
    EXPECT_EQ(parsed->jobs[1].output, "packages/a-0000-v01");
    EXPECT_EQ(formatManifest(*parsed), formatManifest(m));
}

TEST(Manifest, RefusesOutputsThatEscapeTheBatchFolder) {
    EXPECT_NE(manifestError("0\tj\tcases/a.json\t1\t../elsewhere\n")
                  .find("line 3: output \"../elsewhere\" climbs "
                        "with \"..\": it escapes the batch folder"),
              std::string::npos);
    EXPECT_NE(manifestError("0\tj\tcases/a.json\t1\tpackages/../../x\n").find("escapes the batch folder"),
              std::string::npos);
    EXPECT_NE(manifestError("0\tj\tcases/a.json\t1\t/tmp/x\n").find("is absolute: it escapes the batch folder"),
              std::string::npos);
    EXPECT_NE(manifestError("0\tj\t/etc/passwd\t1\tpackages/x\n").find("case \"/etc/passwd\" is absolute"),
              std::string::npos);
    EXPECT_NE(manifestError("0\tj\tcases/a.json\t1\tstatus/x\n").find("lies outside packages/"), std::string::npos);
    EXPECT_NE(manifestError("0\tj\tcases/a.json\t1\tpackages\\x\n").find("backslash"), std::string::npos);
}

TEST(Manifest, RefusesOutputsThatCollide) {
    EXPECT_NE(manifestError("0\tj\tcases/a.json\t1\tpackages/x\n1\tk\tcases/a.json\t2\tpackages/x\n")
                  .find("line 4: output \"packages/x\" collides with the output \"packages/x\" of line 3"),
              std::string::npos);
    EXPECT_NE(manifestError("0\tj\tcases/a.json\t1\tpackages/x\n1\tk\tcases/a.json\t2\tpackages/X\n").find("collides"),
              std::string::npos);
    EXPECT_NE(
        manifestError("0\tj\tcases/a.json\t1\tpackages/x\n1\tk\tcases/a.json\t2\tpackages/x/y\n").find("nests with"),
        std::string::npos);
}

TEST(Manifest, RefusesMalformedLines) {
    EXPECT_NE(parseManifest("index\tjob\n", "m.tsv").error().detail.find("line 1: expected"), std::string::npos);
    EXPECT_NE(manifestError("1\tj\tcases/a.json\t1\tpackages/x\n").find("index \"1\" (expected 0"), std::string::npos);
    EXPECT_NE(manifestError("0\tj\tcases/a.json\t-1\tpackages/x\n").find("seed \"-1\""), std::string::npos);
    EXPECT_NE(manifestError("0\tj\tcases/a.json\t1\n").find("4 tab-separated fields"), std::string::npos);
    EXPECT_NE(manifestError("0\tj j\tcases/a.json\t1\tpackages/x\n").find("not a valid name"), std::string::npos);
    EXPECT_NE(manifestError("0\tj\tcases/a.json\t1\tpackages/x\n1\tj\tcases/a.json\t1\tpackages/y\n")
                  .find("repeats the job of line 3"),
              std::string::npos);
}

TEST(Manifest, PlansTheSameBytesForTheSameCurriculum) {
    hs::test::TempDir a("hs-batch-a");
    hs::test::TempDir b("hs-batch-b");
    const LoadedCurriculum c = smallCurriculum(2);
    auto planA = planBatch(c, "{}\n", a.file("plan"));
    auto planB = planBatch(c, "{}\n", b.file("plan"));
    ASSERT_TRUE(planA.ok()) << planA.error().detail;
    ASSERT_TRUE(planB.ok()) << planB.error().detail;
    EXPECT_EQ(planA->manifest.jobs.size(), 6u);
    EXPECT_EQ(planA->cases, 3u);
    EXPECT_EQ(readText(a.path() / "plan" / "manifest.tsv"), readText(b.path() / "plan" / "manifest.tsv"));
    for (const char* file : {"cases/a-0000.json", "cases/a-0001.json", "cases/b-0000.json"}) {
        EXPECT_FALSE(readText(a.path() / "plan" / file).empty()) << file;
        EXPECT_EQ(readText(a.path() / "plan" / file), readText(b.path() / "plan" / file)) << file;
    }
    const Job& second = planA->manifest.jobs[1];
    EXPECT_EQ(second.name, "a-0000-v01");
    EXPECT_EQ(second.caseFile, "cases/a-0000.json");
    EXPECT_EQ(second.output, "packages/a-0000-v01");
    EXPECT_NE(second.seed, planA->manifest.jobs[0].seed);

    auto again = planBatch(c, "{}\n", a.file("plan"));
    ASSERT_TRUE(again.ok()) << again.error().detail;
    EXPECT_TRUE(again->unchanged);
    auto other = planBatch(smallCurriculum(1), "{}\n", a.file("plan"));
    ASSERT_FALSE(other.ok());
    EXPECT_NE(other.error().detail.find("holds another plan"), std::string::npos);
    auto read = readManifest(a.file("plan"));
    ASSERT_TRUE(read.ok()) << read.error().detail;
    EXPECT_EQ(read->jobs.size(), 6u);
}

TEST(JobStatus, WritesAndReadsBackARecord) {
    hs::test::TempDir dir;
    std::filesystem::create_directories(dir.path() / "status");
    StatusRecord r;
    r.job = "a-0000-v00";
    r.index = 3;
    r.seed = 42;
    r.output = "packages/a-0000-v00";
    r.state = JobState::Failed;
    r.error = Error{ErrorCode::InvalidInput, "polyp 'p1': does not fit"};
    r.seconds = 1.5;
    r.peakMemoryMb = 300;
    r.host = "h";
    r.finishedUtc = utcNow();
    r.caseSha256 = std::string(64, 'a');
    r.tools = "hysteroscene 0.1.0, vtk 9.1.0";
    ASSERT_TRUE(writeStatus(dir.path().string(), r).ok());
    auto read = readStatus(dir.path().string(), r.job);
    ASSERT_TRUE(read.ok()) << read.error().detail;
    ASSERT_TRUE(read->has_value());
    EXPECT_EQ(toJson(**read), toJson(r));

    SceneSummary s;
    s.vertices = 10;
    s.pathologies.push_back({"p1", "polyp", 8.0, "", -1});
    s.stageSeconds.emplace_back("organ", 0.5);
    s.warnings.push_back("pathology: polyp 'p1': seated 2.0 mm away");
    r.state = JobState::Ok;
    r.error.reset();
    r.scene = s;
    auto parsed = parseStatus(toJson(r), "s.json");
    ASSERT_TRUE(parsed.ok()) << parsed.error().detail;
    EXPECT_EQ(toJson(*parsed), toJson(r));
    EXPECT_FALSE(parsed->scene->scopePasses); // not checked: no "scope" written or read
    // The export's scope verdict round-trips too.
    r.scene->scopePasses = false;
    r.scene->scopeNarrowestMm = 2.25;
    auto swept = parseStatus(toJson(r), "s.json");
    ASSERT_TRUE(swept.ok()) << swept.error().detail;
    EXPECT_EQ(toJson(*swept), toJson(r));
    ASSERT_TRUE(swept->scene->scopePasses);
    EXPECT_FALSE(*swept->scene->scopePasses);
    EXPECT_EQ(swept->scene->scopeNarrowestMm, 2.25);
    EXPECT_FALSE(readStatus(dir.path().string(), "none")->has_value());
}

TEST(JobStatus, ReadsAVersion1RecordWithoutAContentKey) {
    auto parsed = parseStatus(R"({"format": "hysteroscene-batch-status", "schemaVersion": 1, "job": "j",
        "index": 0, "seed": 1, "output": "packages/j", "state": "ok", "error": null, "seconds": 1,
        "peakMemoryMb": 1, "host": "", "finishedUtc": "", "reused": false, "packageManifestSha256": "",
        "scene": null})",
                              "s.json");
    ASSERT_TRUE(parsed.ok()) << parsed.error().detail;
    EXPECT_TRUE(parsed->caseSha256.empty());
    EXPECT_TRUE(parsed->tools.empty());
    // From version 2 on the key is required.
    auto v2 = parseStatus(R"({"format": "hysteroscene-batch-status", "schemaVersion": 2, "job": "j",
        "index": 0, "seed": 1, "output": "packages/j", "state": "ok", "error": null, "seconds": 1,
        "peakMemoryMb": 1, "host": "", "finishedUtc": "", "reused": false, "packageManifestSha256": "",
        "scene": null})",
                          "s.json");
    ASSERT_FALSE(v2.ok());
    EXPECT_NE(v2.error().detail.find("caseSha256"), std::string::npos) << v2.error().detail;
}

TEST(JobStatus, RefusesAMalformedRecordNamingTheField) {
    auto parsed = parseStatus(R"({"format": "hysteroscene-batch-status", "schemaVersion": 1, "job": "j",
        "index": 0, "seed": 1, "output": "packages/j", "state": "done", "error": null, "seconds": "1",
        "peakMemoryMb": 1, "host": "", "finishedUtc": "", "reused": false, "packageManifestSha256": "",
        "scene": null})",
                              "s.json");
    ASSERT_FALSE(parsed.ok());
    EXPECT_NE(parsed.error().detail.find("s.json: /state: \"done\" is not one of"), std::string::npos)
        << parsed.error().detail;
    EXPECT_NE(parsed.error().detail.find("s.json: /seconds: expected a number"), std::string::npos)
        << parsed.error().detail;
}
