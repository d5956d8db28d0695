// `hysteroscene-cli batch`: plan, the job contract, the local runner (also after a kill), status, bad input. The
// curriculum (tests/data/batch/two-templates.json) makes 3 light scenes (3000-vertex meshes, 256 px maps).
#include "TestSupport.h"

#include "hs/batch/JobStatus.h"
#include "hs/batch/Manifest.h"
#include "hs/io/AtomicFile.h"
#include "hs/scene/ScenePackage.h"
#include "hs/scene/Sha256.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

using CliRun = hs::test::CommandRun;

std::string quote(const std::string& s) {
    return hs::test::shellQuote(s);
}

CliRun cli(const std::string& args) {
    return hs::test::runCommand(quote(HS_CLI_PATH) + " " + args);
}

std::string curriculum() {
    return (hs::test::testDataDir() / "batch" / "two-templates.json").string();
}

std::string readText(const fs::path& path) {
    auto text = hs::io::readFile(path.string(), 1 << 30);
    return text ? *text : std::string();
}

/// Every file of a package folder, relative path -> bytes.
std::map<std::string, std::string> packageFiles(const fs::path& folder) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file())
            files[fs::relative(entry.path(), folder).string()] = readText(entry.path());
    return files;
}

hs::batch::Manifest manifestOf(const fs::path& folder) {
    auto m = hs::batch::readManifest(folder.string());
    EXPECT_TRUE(m.ok()) << m.error().detail;
    return m ? *m : hs::batch::Manifest{};
}

void expectAllPackagesValid(const fs::path& folder) {
    for (const auto& job : manifestOf(folder).jobs) {
        auto verified = hs::scene::verifyScenePackage((folder / job.output).string());
        EXPECT_TRUE(verified.ok()) << job.name << ": " << verified.error().detail;
        auto record = hs::batch::readStatus(folder.string(), job.name);
        ASSERT_TRUE(record.ok() && record->has_value()) << job.name;
        EXPECT_EQ((*record)->state, hs::batch::JobState::Ok) << job.name;
    }
}

} // namespace

TEST(BatchCli, PlansDeterministicallyAndRefusesImpossibleCurricula) {
    hs::test::TempDir dir;
    const CliRun a = cli("batch plan " + quote(curriculum()) + " -o " + quote(dir.file("a")));
    ASSERT_EQ(a.exitCode, 0) << a.out;
    EXPECT_NE(a.out.find("3 jobs (3 cases x 1 variants)"), std::string::npos) << a.out;
    ASSERT_EQ(cli("batch plan " + quote(curriculum()) + " -o " + quote(dir.file("b"))).exitCode, 0);
    EXPECT_EQ(readText(dir.path() / "a" / "manifest.tsv"), readText(dir.path() / "b" / "manifest.tsv"));
    EXPECT_EQ(readText(dir.path() / "a" / "cases" / "polyp-0001.json"),
              readText(dir.path() / "b" / "cases" / "polyp-0001.json"));

    std::ofstream(dir.file("bad.json")) << R"({"format": "hysteroscene-curriculum", "schemaVersion": 1, "seed": 1,
        "templates": [{"name": "old", "cases": 1, "patient": {"ageYears": 65, "menopausal": true},
        "pathologies": [{"id": "m1", "kind": "myoma", "sizeMm": 80, "figo": 8, "location": "fundal"}]}]})";
    const CliRun bad = cli("batch plan " + quote(dir.file("bad.json")) + " -o " + quote(dir.file("c")));
    EXPECT_EQ(bad.exitCode, 3) << bad.out;
    EXPECT_NE(bad.out.find("/templates/0/pathologies/0/sizeMm: up to 80 mm"), std::string::npos) << bad.out;
    EXPECT_NE(bad.out.find("/templates/0/pathologies/0/figo: FIGO type 8"), std::string::npos) << bad.out;
    EXPECT_FALSE(fs::exists(dir.path() / "c" / "manifest.tsv"));
}

TEST(BatchCli, RefusesAHandEditedManifestWhoseOutputsCollideOrEscape) {
    hs::test::TempDir dir;
    ASSERT_EQ(cli("batch plan " + quote(curriculum()) + " -o " + quote(dir.file("b"))).exitCode, 0);
    const fs::path manifest = dir.path() / "b" / "manifest.tsv";
    std::string text = readText(manifest);
    const std::string original = text;
    text.replace(text.find("packages/polyp-0001-v00"), 23, "packages/polyp-0000-v00");
    std::ofstream(manifest) << text;
    CliRun run = cli("batch run " + quote(dir.file("b")) + " --task-index 0");
    EXPECT_EQ(run.exitCode, 3) << run.out;
    EXPECT_NE(run.out.find("collides with the output \"packages/polyp-0000-v00\" of line 3"), std::string::npos)
        << run.out;
    text = original;
    text.replace(text.find("packages/healthy-0000-v00"), 25, "packages/../../outside");
    std::ofstream(manifest) << text;
    run = cli("batch status " + quote(dir.file("b")));
    EXPECT_EQ(run.exitCode, 3) << run.out;
    EXPECT_NE(run.out.find("escapes the batch folder"), std::string::npos) << run.out;
}

TEST(BatchCli, RunsTheJobContractIdempotentlyAndTheLocalRunnerGivesTheSameBytes) {
    hs::test::TempDir dir;
    const fs::path a = dir.path() / "a";
    const fs::path b = dir.path() / "b";
    ASSERT_EQ(cli("batch plan " + quote(curriculum()) + " -o " + quote(a.string())).exitCode, 0);
    ASSERT_EQ(cli("batch plan " + quote(curriculum()) + " -o " + quote(b.string())).exitCode, 0);

    // The job contract, one task index at a time (as a Slurm array task runs it).
    CliRun first = cli("batch run " + quote(a.string()) + " --task-index 0 --tasks-per-index 2");
    ASSERT_EQ(first.exitCode, 0) << first.out;
    EXPECT_NE(first.out.find("ok          polyp-0000-v00"), std::string::npos) << first.out;
    EXPECT_NE(first.out.find("ok          polyp-0001-v00"), std::string::npos) << first.out;
    const CliRun again = cli("batch run " + quote(a.string()) + " --task-index 0 --tasks-per-index 2");
    ASSERT_EQ(again.exitCode, 0) << again.out;
    EXPECT_NE(again.out.find("skipped     polyp-0000-v00"), std::string::npos) << again.out;
    ASSERT_EQ(cli("batch run " + quote(a.string()) + " --task-index 1 --tasks-per-index 2").exitCode, 0);
    EXPECT_EQ(cli("batch run " + quote(a.string()) + " --task-index 2 --tasks-per-index 2").exitCode, 3);

    // The local runner on the other plan.
    const CliRun local = cli("batch run " + quote(b.string()) + " --jobs 2");
    ASSERT_EQ(local.exitCode, 0) << local.out;
    EXPECT_NE(local.out.find("3 ok, 0 failed"), std::string::npos) << local.out;
    EXPECT_NE(local.out.find("scenes/hour"), std::string::npos) << local.out;

    expectAllPackagesValid(a);
    expectAllPackagesValid(b);
    for (const auto& job : manifestOf(a).jobs)
        EXPECT_EQ(packageFiles(a / job.output), packageFiles(b / job.output)) << job.name;

    const CliRun status = cli("batch status " + quote(b.string()));
    EXPECT_EQ(status.exitCode, 0) << status.out;
    EXPECT_NE(status.out.find("3 ok, 0 failed, 0 running, 0 pending"), std::string::npos) << status.out;
}

TEST(BatchCli, ResumesAfterTheRunnerIsKilled) {
    hs::test::TempDir dir;
    const fs::path folder = dir.path() / "k";
    ASSERT_EQ(cli("batch plan " + quote(curriculum()) + " -o " + quote(folder.string())).exitCode, 0);
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        setpgid(0, 0);
        const std::string log = (dir.path() / "runner.log").string();
        std::freopen(log.c_str(), "w", stdout);
        std::freopen(log.c_str(), "a", stderr);
        execl(HS_CLI_PATH, HS_CLI_PATH, "batch", "run", folder.c_str(), "--jobs", "1", static_cast<char*>(nullptr));
        _exit(127);
    }
    setpgid(pid, pid);
    // Kill the runner and its job process once the first job has finished and the second has started.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (!fs::exists(folder / "status" / "polyp-0000-v00.json") && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    kill(-pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(fs::exists(folder / "status" / "polyp-0000-v00.json"));

    const CliRun resumed = cli("batch run " + quote(folder.string()) + " --jobs 1");
    ASSERT_EQ(resumed.exitCode, 0) << resumed.out;
    EXPECT_NE(resumed.out.find("1 already done"), std::string::npos) << resumed.out;
    expectAllPackagesValid(folder);
    for (const auto& entry : fs::directory_iterator(folder / "packages"))
        EXPECT_FALSE(hs::scene::isPackageTempName(entry.path().filename().string())) << entry.path();
}

TEST(BatchCli, KillsAJobOverItsMemoryLimitAndRerunsAJobWhoseCaseWasEdited) {
    hs::test::TempDir dir;
    const fs::path folder = dir.path() / "m";
    ASSERT_EQ(cli("batch plan " + quote(curriculum()) + " -o " + quote(folder.string())).exitCode, 0);
    // A light job reaches about 280 MiB resident: 100 MiB stops every one, and nothing of theirs is left.
    const CliRun limited = cli("batch run " + quote(folder.string()) + " --jobs 2 --mem 100M");
    EXPECT_EQ(limited.exitCode, 4) << limited.out;
    EXPECT_NE(limited.out.find("0 ok, 3 failed"), std::string::npos) << limited.out;
    EXPECT_NE(limited.out.find("limits      per job: wall clock 3600 s, resident memory 100 MiB"), std::string::npos)
        << limited.out;
    for (const auto& job : manifestOf(folder).jobs) {
        auto record = hs::batch::readStatus(folder.string(), job.name);
        ASSERT_TRUE(record.ok() && record->has_value()) << job.name;
        ASSERT_TRUE((*record)->error.has_value()) << job.name;
        EXPECT_EQ((*record)->error->code, hs::ErrorCode::LimitExceeded) << job.name;
        EXPECT_NE((*record)->error->detail.find("resident: over its memory limit of 100 MiB"), std::string::npos)
            << (*record)->error->detail;
    }
    EXPECT_TRUE(fs::is_empty(folder / "packages"));
    EXPECT_EQ(cli("batch run " + quote(folder.string()) + " --mem 10X").exitCode, 3);

    // The job contract: run, edit the case, run again: the package is made anew from the edited case.
    ASSERT_EQ(cli("batch run " + quote(folder.string()) + " --task-index 0").exitCode, 0);
    const fs::path caseFile = folder / "cases" / "polyp-0000.json";
    std::string text = readText(caseFile);
    const auto at = text.find("\"ageYears\": ");
    ASSERT_NE(at, std::string::npos);
    const auto end = text.find(',', at);
    const std::string age = text.substr(at, end - at) == "\"ageYears\": 40.0" ? "41.0" : "40.0";
    text.replace(at, end - at, "\"ageYears\": " + age); // inside the template's 25-45 years
    std::ofstream(caseFile) << text;
    const CliRun edited = cli("batch run " + quote(folder.string()) + " --task-index 0");
    ASSERT_EQ(edited.exitCode, 0) << edited.out;
    EXPECT_NE(edited.out.find("rerun       polyp-0000-v00: its case was edited after its package was written"),
              std::string::npos)
        << edited.out;
    EXPECT_NE(edited.out.find("ok          polyp-0000-v00"), std::string::npos) << edited.out;
    EXPECT_NE(readText(folder / "packages" / "polyp-0000-v00" / "case.json").find("\"ageYears\": " + age),
              std::string::npos);
    auto record = hs::batch::readStatus(folder.string(), "polyp-0000-v00");
    ASSERT_TRUE(record.ok() && record->has_value());
    EXPECT_EQ((*record)->caseSha256,
              hs::scene::sha256Hex(readText(folder / "packages" / "polyp-0000-v00" / "case.json")));
}

TEST(BatchCli, ReportsEveryCaseAndThePagePlotsInHeadlessChromium) {
    hs::test::TempDir dir;
    const fs::path folder = dir.path() / "r";
    ASSERT_EQ(cli("batch plan " + quote(curriculum()) + " -o " + quote(folder.string())).exitCode, 0);
    ASSERT_EQ(cli("batch run " + quote(folder.string()) + " --task-index 0 --tasks-per-index 2").exitCode, 0);
    // A case file broken by hand: its job fails with a named error, recorded in its status.
    std::string broken = readText(folder / "cases" / "healthy-0000.json");
    broken.replace(broken.find("\"ageYears\": "), 12, "\"ageYears\": 130, \"x\": ");
    std::ofstream(folder / "cases" / "healthy-0000.json") << broken;
    const CliRun failed = cli("batch run " + quote(folder.string()) + " --task-index 2");
    EXPECT_EQ(failed.exitCode, 3) << failed.out;
    EXPECT_NE(failed.out.find("failed      healthy-0000-v00: invalid-input: "), std::string::npos) << failed.out;
    // Two scenes with the same kind of warning, numbers and names apart: the index counts them as one kind.
    for (const auto& [job, text] : {std::pair<std::string, std::string>{"polyp-0000-v00", "pathology: polyp 'p-1': "
                                                                                          "seated 8.6 mm away"},
                                    {"polyp-0001-v00", "pathology: polyp 'p-2': seated 13.8 mm away"}}) {
        auto record = hs::batch::readStatus(folder.string(), job);
        ASSERT_TRUE(record.ok() && record->has_value() && (*record)->scene.has_value()) << job;
        (*record)->scene->warnings.push_back(text);
        ASSERT_TRUE(hs::batch::writeStatus(folder.string(), **record).ok());
    }
    const CliRun report = cli("batch report " + quote(folder.string()));
    ASSERT_EQ(report.exitCode, 0) << report.out;
    const std::string csv = readText(folder / "report" / "report.csv");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4) << csv; // the header and 3 jobs
    EXPECT_NE(csv.find("polyp-0000-v00,polyp,ok,"), std::string::npos) << csv;
    EXPECT_NE(csv.find("healthy-0000-v00,healthy,failed,\"invalid-input: "), std::string::npos) << csv;
    EXPECT_NE(report.out.find("1 page of cases"), std::string::npos) << report.out;
    EXPECT_NE(csv.find(",warnings,output\n"), std::string::npos) << csv;
    EXPECT_NE(csv.find("pathology: polyp 'p-2': seated 13.8 mm away"), std::string::npos) << csv;
    const std::string html = readText(folder / "report" / "report.html");
    EXPECT_NE(html.find("<a href=\"pages/cases-0001.html\">1</a></td><td>1-3</td>"), std::string::npos);
    // The failed job is listed on the index with its error, linked to its row.
    EXPECT_NE(html.find("<li><a href=\"pages/cases-0001.html#healthy-0000-v00\">healthy-0000-v00</a>: invalid-input: "),
              std::string::npos);
    EXPECT_NE(html.find("<tr><td>2</td><td>pathology: polyp &#39;...&#39;: seated N mm away</td></tr>"),
              std::string::npos)
        << html.substr(html.find("<h2>Warnings</h2>"), 2000);
    const std::string page = readText(folder / "report" / "pages" / "cases-0001.html");
    EXPECT_NE(page.find("data:image/png;base64,"), std::string::npos); // organ thumbnails, inlined
    EXPECT_NE(page.find("<tr id=\"polyp-0000-v00\" class=\"ok\">"), std::string::npos);
    for (const std::string& text : {html, page}) {
        EXPECT_EQ(text.find("src=\"http"), std::string::npos); // self-contained
        EXPECT_EQ(text.find("src=\"file"), std::string::npos);
    }
    // A report with fewer cases than the last one leaves no page of the old one behind.
    std::ofstream(folder / "report" / "pages" / "cases-0002.html") << "old";
    ASSERT_EQ(cli("batch report " + quote(folder.string())).exitCode, 0);
    EXPECT_FALSE(fs::exists(folder / "report" / "pages" / "cases-0002.html"));

    const hs::test::CommandRun which = hs::test::runCommand("command -v chromium");
    if (which.exitCode != 0)
        GTEST_SKIP() << "chromium is not installed (tools/setup.sh installs it): the page was not opened";
    if (report.out.find(" charts, ") == std::string::npos || report.out.find("(0 charts, ") != std::string::npos)
        GTEST_SKIP() << "libjs-chart.js is not installed: the page has no plots to check";
    const hs::test::CommandRun dom =
        hs::test::runCommand("timeout 120 chromium --headless --no-sandbox --disable-gpu --dump-dom " +
                             quote("file://" + (folder / "report" / "report.html").string()) + " 2>/dev/null");
    ASSERT_EQ(dom.exitCode, 0) << dom.out;
    EXPECT_EQ(dom.out.find("data-chart-error"), std::string::npos) << dom.out.substr(0, 2000);
    // The page's script sets data-charts to the number of charts drawn once Chart.js has drawn them all.
    const auto at = dom.out.find("data-charts=\"");
    ASSERT_NE(at, std::string::npos) << dom.out.substr(0, 2000);
    EXPECT_GT(std::stoi(dom.out.substr(at + 13)), 0);
}
