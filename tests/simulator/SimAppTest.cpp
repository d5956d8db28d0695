// hysteroscene-sim end to end: the command line's usage errors, the headless scripted run and its replay giving the
// same report bit for bit, and the trial report (JSON with 17 significant digits; the page with its plots, opened
// in headless Chromium when it is installed).
#include "SimPackage.h"
#include "TestSupport.h"
#include "hs/generate/Generate.h"
#include "hs/io/HtmlPage.h"
#include "hs/scene/ScenePackage.h"
#include "hs/sim/Metrics.h"
#include "hs/sim/Script.h"
#include "hs/sim/World.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

namespace fs = std::filesystem;
using hs::test::shellQuote;

namespace {

hs::test::CommandRun sim(const std::string& arguments) {
    return hs::test::runCommand(std::string(HS_SIM_PATH) + " " + arguments);
}

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A report with every field set, a minute of series and a few thousand surface samples.
hs::sim::TrialReport sampleReport() {
    hs::sim::TrialReport r;
    r.header.sceneSha256 = std::string(64, 'a');
    r.header.seed = 7;
    r.header.physics.engine = "corotational-fem/8";
    r.header.device = "scripted:<test>.json"; // escaped in the page
    r.header.startedUtc = "2026-01-02T03:04:05Z";
    r.samples = 60000;
    r.metrics.timeS = 60.0;
    r.metrics.pathLengthMm = 1.0 / 3.0;
    r.metrics.cavitySurfaceVisualizedPercent = 72.5;
    r.metrics.targets = {{"ostium-left", 100.0, true, 12.5}, {"fundus", 20.0, false, -1.0}};
    r.metrics.perforations = {{30.0, {1.0, 2.0, 3.0}, 1.5, "myometrium"}};
    r.metrics.pathologies = {{"myoma-1", "myoma", true, true, 40.0}};
    r.metrics.peakForceN = 0.1 + 0.2; // 0.30000000000000004: needs 17 digits
    for (int i = 0; i <= 600; ++i)
        r.series.push_back({i / 10.0, 0.5 + 0.5 * std::sin(i / 20.0), 9.0 + std::cos(i / 30.0), i * 0.5, 0.0,
                            i < 300 ? 10.7 : 11.4}); // the pump raised half way
    for (int i = 0; i < 3000; ++i)
        r.surface.push_back({-180.0 + (i % 72) * 5.0, (i / 72) * 1.0, (i % 7) != 0});
    return r;
}

constexpr const char* kScript = R"({"format": "hysteroscene-script", "version": 1, "keyframes": [
  {"t": 0.0, "insertionMm": -5, "inflow": 1, "outflow": 0.3},
  {"t": 0.5, "insertionMm": 20},
  {"t": 1.0, "insertionMm": 32, "rollDeg": 60, "pitchDeg": 5},
  {"t": 1.25, "insertionMm": 30, "yawDeg": -8, "buttons": 1},
  {"t": 1.5, "insertionMm": 28, "rollDeg": -30, "buttons": 0}]})";
constexpr const char* kShortScript = R"({"format": "hysteroscene-script", "version": 1, "keyframes": [
  {"t": 0.0, "insertionMm": -5, "inflow": 1}, {"t": 0.1, "insertionMm": -4}]})";

} // namespace

TEST(SimCommandLine, RefusesBadArgumentsWithUsageErrors) {
    for (const char* arguments : {"--optic 45 scene", "--diameter 3 scene", "--exercise surgery scene",
                                  "--frobnicate scene", "scene --headless", "scene --device joystick",
                                  "scene --device hid:xyz:1", "scene --replay t.trial --device scripted:s.json",
                                  "scene --demo --device hid", "scene --demo --replay t.trial", "--write-demo d.json",
                                  "scene --headless --demo --seconds 0", "scene --headless --demo --seconds -1",
                                  "scene --headless --replay t.trial --seconds 5", "scene --demo --seconds 5"}) {
        const auto run = sim(arguments);
        EXPECT_EQ(run.exitCode, 2) << arguments << "\n" << run.out;
    }
    const auto help = sim("--help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("--device"), std::string::npos) << help.out;
}

TEST(SimCommandLine, NamesAMissingInputFile) {
    hs::test::TempDir tmp;
    const auto replay = sim(shellQuote(tmp.file("pkg")) + " --headless --replay " + shellQuote(tmp.file("no.trial")));
    EXPECT_EQ(replay.exitCode, 3) << replay.out;
    EXPECT_NE(replay.out.find("no.trial"), std::string::npos) << replay.out;
    const auto script =
        sim(shellQuote(tmp.file("pkg")) + " --headless --device scripted:" + shellQuote(tmp.file("no.json")));
    EXPECT_EQ(script.exitCode, 3) << script.out;
    EXPECT_NE(script.out.find("no.json"), std::string::npos) << script.out;
}

TEST(TrialReport, WritesDoublesWithSeventeenDigits) {
    const std::string json = hs::sim::reportJson(sampleReport());
    EXPECT_NE(json.find("\"peakForceN\":0.30000000000000004"), std::string::npos) << json.substr(0, 2000);
    EXPECT_NE(json.find("\"format\":\"hysteroscene-trial-report\""), std::string::npos);
    EXPECT_NE(json.find("\"firstSeenS\":-1"), std::string::npos);
    EXPECT_EQ(json, hs::sim::reportJson(sampleReport()));
}

TEST(TrialReport, PageNamesAMissingChartLibrary) {
    auto page = hs::sim::reportHtml(sampleReport(), "/nonexistent/chart.min.js");
    ASSERT_FALSE(page.ok());
    EXPECT_NE(page.error().message().find("/nonexistent/chart.min.js"), std::string::npos);
}

TEST(TrialReport, ReadsBackToTheSameBytes) {
    // The workstation reviews a trial from its report: what it reads is what was written, to the last bit.
    hs::sim::TrialReport operative = sampleReport();
    operative.header.exercise = hs::sim::Exercise::Myomectomy;
    operative.metrics.resection.pathologies = {{"myoma-1", "myoma", 4.19, 3.77, 90.0}};
    operative.metrics.resection.firstCutS = 12.25;
    operative.metrics.resection.chipsLeft = 3;
    for (const hs::sim::TrialReport& r : {sampleReport(), operative}) {
        const std::string json = hs::sim::reportJson(r);
        auto read = hs::sim::parseReport(json, "r.json");
        ASSERT_TRUE(read) << read.error().detail;
        EXPECT_EQ(hs::sim::reportJson(*read), json);
    }
    hs::test::TempDir tmp;
    ASSERT_TRUE(hs::sim::writeReport(operative, tmp.file("r.json")).ok());
    auto read = hs::sim::readReport(tmp.file("r.json"));
    ASSERT_TRUE(read) << read.error().detail;
    EXPECT_EQ(read->metrics.resection.chipsLeft, 3u);
    EXPECT_EQ(read->series.size(), 601u);
    auto missing = hs::sim::readReport(tmp.file("none.json"));
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().detail.find("none.json"), std::string::npos) << missing.error().detail;
}

/// `json` with the first `from` replaced by `to` (the test fails when `from` is not there).
std::string edited(std::string json, const std::string& from, const std::string& to) {
    const auto at = json.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? json : json.replace(at, from.size(), to);
}

TEST(TrialReport, RefusesABadReportNamingTheFileTheFieldAndTheRange) {
    const std::string json = hs::sim::reportJson(sampleReport());
    const struct {
        std::string from, to, expected;
    } cases[] = {
        {"\"cavitySurfaceVisualizedPercent\":72.5", "\"cavitySurfaceVisualizedPercent\":172.5",
         "/metrics/cavitySurfaceVisualizedPercent: 172.5 is outside 0-100 %"},
        {"\"firstSeenS\":-1", "\"firstSeenS\":-0.5", "/metrics/targets/1/firstSeenS"},
        {"\"format\":\"hysteroscene-trial-report\"", "\"format\":\"hysteroscene-trial\"", "/format"},
        {"\"version\":2", "\"version\":3", "/version: 3 is not a version this build reads (1-2)"},
        {"\"exercise\":\"exploration\"", "\"exercise\":\"surgery\"", "/header/exercise"},
        {"\"forceN\":[", "\"forceN\":[0.5,", "/series/forceN: 602 entries where the first column has 601"},
        {"\"timeS\":[0,", "\"timeS\":[0.2,", "/series/timeS/1: times must increase"},
        {"\"seen\":[", "\"seen\":[3,", "/surface/seen/0"},
        {"\"wallContacts\":0", "\"wallContacts\":-4", "/metrics/wallContacts"},
        {"\"samples\":60000", "\"samples\":60000,\"extra\":1", "unknown field \"extra\""},
        {"\"sceneSha256\":\"aaaa", "\"sceneSha256\":\"AAAA", "header.sceneSha256"},
    };
    for (const auto& c : cases) {
        auto read = hs::sim::parseReport(edited(json, c.from, c.to), "bad.json");
        ASSERT_FALSE(read) << c.to;
        EXPECT_NE(read.error().detail.find("bad.json"), std::string::npos) << read.error().detail;
        EXPECT_NE(read.error().detail.find(c.expected), std::string::npos) << read.error().detail;
    }
    hs::sim::ReportReadLimits small;
    small.maxSeries = 100;
    auto tooLong = hs::sim::parseReport(json, "long.json", small);
    ASSERT_FALSE(tooLong);
    EXPECT_NE(tooLong.error().detail.find("/series/timeS: 601 entries, more than the 100"), std::string::npos)
        << tooLong.error().detail;
    for (const std::string& garbage :
         {std::string(), std::string("[]"), std::string("{\"format\":"), json.substr(0, 900)})
        EXPECT_FALSE(hs::sim::parseReport(garbage, "g.json"));
}

TEST(TrialReport, AFirstVersionReportReadsWithThePumpWhereItsHeaderSetIt) {
    // Version 1 had no pump column: its pump line is the header's set pressure, as that report's page drew it.
    std::string json = hs::sim::reportJson(sampleReport());
    json = edited(json, "\"version\":2", "\"version\":1");
    const auto pump = json.find(",\"pumpSetKpa\":[");
    ASSERT_NE(pump, std::string::npos);
    json.erase(pump, json.find(']', pump) + 1 - pump);
    auto read = hs::sim::parseReport(json, "v1.json");
    ASSERT_TRUE(read) << read.error().detail;
    ASSERT_EQ(read->series.size(), 601u);
    EXPECT_EQ(read->series.back().pumpSetKpa, read->header.fluid.pumpPressureKpa);
    // A version 2 report must have it.
    auto missing = hs::sim::parseReport(edited(json, "\"version\":1", "\"version\":2"), "v2.json");
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().detail.find("/series/pumpSetKpa: required field is missing"), std::string::npos)
        << missing.error().detail;
}

TEST(TrialReport, ThePumpLineFollowsTheSetPressureAsTheTraineeMovedIt) {
    // The tables and plots the page and the workstation share: the pump's line is the set pressure at each moment,
    // not the one the trial started with.
    const auto plots = hs::sim::reportPlots(sampleReport());
    ASSERT_EQ(plots.size(), 3u); // force, pressure, deficit: no blood loss outside the operative exercises
    ASSERT_EQ(plots[1].lines.size(), 3u);
    const hs::sim::ReportLine& pump = plots[1].lines[2];
    EXPECT_EQ(pump.label, "pump set pressure");
    ASSERT_EQ(pump.points.size(), 601u);
    EXPECT_EQ(pump.points.front().second, 10.7);
    EXPECT_EQ(pump.points.back().second, 11.4);
    const auto tables = hs::sim::reportTables(sampleReport());
    ASSERT_FALSE(tables.empty());
    EXPECT_EQ(tables.front().section, "Overview");
    bool fluid = false;
    for (const auto& t : tables)
        fluid = fluid || t.section == "Fluid";
    EXPECT_TRUE(fluid);
}

/// The page's DOM after headless Chromium has run its scripts (exit code 0 and the DOM on success).
hs::test::CommandRun openedInChromium(const hs::test::TempDir& tmp, const std::string& html) {
    return hs::test::runCommand(
        "timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-background-networking "
        "--disable-component-update --disable-sync --no-first-run --user-data-dir=" +
        shellQuote(tmp.file("profile")) + " --dump-dom " + shellQuote("file://" + html) + " 2>/dev/null");
}

TEST(TrialReport, PageDrawsItsPlotsInHeadlessChromium) {
    if (!fs::exists(std::string(hs::io::kDefaultChartLibrary)))
        GTEST_SKIP() << "libjs-chart.js is not installed: the page has no plots to check";
    hs::test::TempDir tmp;
    ASSERT_TRUE(hs::sim::writeReport(sampleReport(), tmp.file("r.json"), tmp.file("r.html")).ok());
    const std::string html = readText(tmp.file("r.html"));
    EXPECT_EQ(html.find("src=\"http"), std::string::npos); // self-contained
    EXPECT_NE(html.find("scripted:&lt;test&gt;.json"), std::string::npos);
    EXPECT_NE(html.find("myometrium"), std::string::npos);
    if (hs::test::runCommand("command -v chromium").exitCode != 0)
        GTEST_SKIP() << "chromium is not installed (tools/setup.sh installs it): the page was not opened";
    const auto dom = openedInChromium(tmp, tmp.file("r.html"));
    ASSERT_EQ(dom.exitCode, 0) << dom.out.substr(0, 2000);
    EXPECT_EQ(dom.out.find("data-chart-error"), std::string::npos) << dom.out.substr(0, 3000);
    // Force, pressure, deficit and the visualized surface.
    EXPECT_NE(dom.out.find("data-charts=\"4\""), std::string::npos) << dom.out.substr(0, 3000);

    // An operative exercise's page plots the blood lost too, with the plots over time (a fifth canvas).
    hs::sim::TrialReport operative = sampleReport();
    operative.header.exercise = hs::sim::Exercise::Polypectomy;
    operative.metrics.resection.pathologies = {{"polyp-1", "polyp", 0.24, 0.12, 50.0}};
    for (std::size_t i = 0; i < operative.series.size(); ++i)
        operative.series[i].bloodLossMl = 0.01 * static_cast<double>(i);
    ASSERT_TRUE(hs::sim::writeReport(operative, tmp.file("o.json"), tmp.file("o.html")).ok());
    const auto drawn = openedInChromium(tmp, tmp.file("o.html"));
    ASSERT_EQ(drawn.exitCode, 0) << drawn.out.substr(0, 2000);
    EXPECT_EQ(drawn.out.find("data-chart-error"), std::string::npos) << drawn.out.substr(0, 3000);
    EXPECT_NE(drawn.out.find("data-charts=\"5\""), std::string::npos) << drawn.out.substr(0, 3000);
    EXPECT_NE(drawn.out.find("Blood loss"), std::string::npos);
}

/// The simulator tests' package (SimPackage.h), generated once per binary.
class SimHeadless : public ::testing::Test {
protected:
    void SetUp() override {
        s_package = hs::test::SimPackage::folder();
        if (s_package.empty())
            GTEST_SKIP() << "no package";
    }
    static std::string s_package;
};
std::string SimHeadless::s_package;

TEST_F(SimHeadless, ScriptedRunAndItsReplayReportTheSameBytes) {
    hs::test::TempDir tmp;
    std::ofstream(tmp.file("script.json")) << kScript;
    const std::string common = shellQuote(s_package) + " --headless --optic 12 --pump-mmhg 90 --seed 3";
    const auto scripted = sim(common + " --device scripted:" + shellQuote(tmp.file("script.json")) + " --record " +
                              shellQuote(tmp.file("t.trial")) + " --report " + shellQuote(tmp.file("a.json")) +
                              " --html " + shellQuote(tmp.file("a.html")));
    ASSERT_EQ(scripted.exitCode, 0) << scripted.out;
    const auto replayed = sim(shellQuote(s_package) + " --headless --replay " + shellQuote(tmp.file("t.trial")) +
                              " --report " + shellQuote(tmp.file("b.json")));
    ASSERT_EQ(replayed.exitCode, 0) << replayed.out;
    const std::string a = readText(tmp.file("a.json")), b = readText(tmp.file("b.json"));
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, b);
    EXPECT_NE(a.find("\"opticDeg\":12"), std::string::npos) << a.substr(0, 1000);
    EXPECT_NE(a.find("\"samples\":1505"), std::string::npos) << a.substr(0, 1000);
    EXPECT_TRUE(fs::exists(tmp.file("a.html")));
}

TEST_F(SimHeadless, TheDemoPlaysTheBuiltInExplorationAndRecordsItsTrial) {
    // `--demo` (also `--device demo`): the exploration the world plans on its own scene (sim::explorationScript), so
    // a supervisor can watch it and a check can run it; its trial replays to the same report. The whole 60 s
    // exploration is World.AScriptedExplorationSeesBothOstiaWithoutPerforation's (test_sim_core); here `--seconds`
    // plays its first 12 s (the canal and into the cavity), and the trial records just the samples played.
    hs::test::TempDir tmp;
    const auto demo = sim(shellQuote(s_package) + " --exercise exploration --demo --headless --seconds 12 --record " +
                          shellQuote(tmp.file("t.trial")) + " --report " + shellQuote(tmp.file("a.json")));
    ASSERT_EQ(demo.exitCode, 0) << demo.out;
    const std::string a = readText(tmp.file("a.json"));
    EXPECT_NE(a.find("\"device\":\"demo\""), std::string::npos) << a.substr(0, 1000);
    EXPECT_NE(a.find("\"perforations\":[]"), std::string::npos) << a.substr(0, 3000);
    EXPECT_NE(a.find("\"samples\":12000"), std::string::npos) << a.substr(0, 1000);
    const auto replayed = sim(shellQuote(s_package) + " --headless --replay " + shellQuote(tmp.file("t.trial")) +
                              " --report " + shellQuote(tmp.file("b.json")));
    ASSERT_EQ(replayed.exitCode, 0) << replayed.out;
    EXPECT_EQ(a, readText(tmp.file("b.json")));
    // --write-demo: the same demonstration as a script file, to edit and play as a scripted device.
    const auto written =
        sim(shellQuote(s_package) + " --exercise exploration --write-demo " + shellQuote(tmp.file("demo.json")));
    ASSERT_EQ(written.exitCode, 0) << written.out;
    auto script = hs::sim::readScript(tmp.file("demo.json"));
    ASSERT_TRUE(script) << script.error().detail;
    EXPECT_GT(script->keyframes.size(), 10u);
    EXPECT_NE(written.out.find("demo.json"), std::string::npos) << written.out;
}

TEST_F(SimHeadless, RefusesATrialOfAnotherScene) {
    hs::test::TempDir tmp;
    std::ofstream(tmp.file("script.json")) << kShortScript;
    ASSERT_EQ(sim(shellQuote(s_package) + " --headless --device scripted:" + shellQuote(tmp.file("script.json")) +
                  " --record " + shellQuote(tmp.file("t.trial")) + " --report " + shellQuote(tmp.file("a.json")))
                  .exitCode,
              0);
    // The same package with another manifest checksum: a copy whose manifest gained a byte.
    fs::copy(s_package, tmp.file("other"), fs::copy_options::recursive);
    std::ofstream(tmp.file("other") + "/manifest.json", std::ios::app) << "\n";
    const auto run = sim(shellQuote(tmp.file("other")) + " --headless --replay " + shellQuote(tmp.file("t.trial")));
    EXPECT_EQ(run.exitCode, 3) << run.out;
    EXPECT_NE(run.out.find(tmp.file("t.trial")), std::string::npos) << run.out;
}
