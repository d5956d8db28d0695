// The local runner's limits (a job process over its wall clock is killed, recorded failed with the limit, and what it
// began to write is removed) through a fake job program, and the content key that decides whether a job is done.
// The CLI tests run real jobs (the memory limit, an edited case).
#include "BatchTestSupport.h"
#include "TestSupport.h"

#include "hs/batch/Job.h"
#include "hs/batch/JobStatus.h"
#include "hs/batch/LocalRunner.h"
#include "hs/batch/Slurm.h"
#include "hs/io/AtomicFile.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <sys/stat.h>

using namespace hs;
using namespace hs::batch;
using hs::batch::test::manifestOf;
using hs::batch::test::markDone;

namespace fs = std::filesystem;

namespace {

/// A job program that begins a package as the writer does (a temporary folder named after its process id, a partial
/// file in it) and then hangs: called as `PROGRAM batch run BATCH --task-index I`.
std::string hangingJobProgram(const fs::path& folder) {
    const fs::path program = folder / "hanging-job.sh";
    const std::string text = "#!/bin/sh\n"
                             "tmp=\"$3/packages/.j$5.hs-tmp-$$-0\"\n"
                             "mkdir -p \"$tmp\" && echo partial > \"$tmp/tets.vtu\"\n"
                             "exec sleep 60\n";
    EXPECT_TRUE(io::writeFileAtomically(program.string(), text).ok());
    chmod(program.c_str(), 0755);
    return program.string();
}

void makeBatchFolders(const fs::path& folder) {
    for (const char* sub : {"cases", "packages", "status", "logs"})
        fs::create_directories(folder / sub);
}

} // namespace

TEST(LocalRunner, KillsAJobOverItsWallClockLimitAndRemovesWhatItBeganToWrite) {
    hs::test::TempDir dir;
    makeBatchFolders(dir.path());
    const Manifest manifest = manifestOf(2);
    LocalRunParams params;
    params.executable = hangingJobProgram(dir.path());
    params.jobs = 2;
    params.timeLimitSeconds = 0.5;
    const auto start = std::chrono::steady_clock::now();
    auto result = runLocally(dir.path().string(), manifest, params);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_TRUE(result.ok()) << result.error().detail;
    EXPECT_EQ(result->counts.failed, 2u);
    EXPECT_EQ(result->failedJobs, (std::vector<std::string>{"j0", "j1"}));
    EXPECT_LT(seconds, 10.0); // killed at the limit, not after the program's 60 s
    for (const Job& job : manifest.jobs) {
        auto record = readStatus(dir.path().string(), job.name);
        ASSERT_TRUE(record.ok() && record->has_value()) << job.name;
        EXPECT_EQ((*record)->state, JobState::Failed);
        ASSERT_TRUE((*record)->error.has_value());
        EXPECT_EQ((*record)->error->code, ErrorCode::LimitExceeded);
        EXPECT_NE((*record)->error->detail.find("over its wall-clock limit of 0.5 s"), std::string::npos)
            << (*record)->error->detail;
        EXPECT_GE((*record)->seconds, 0.5);
    }
    // Nothing half-written is left: the temporary package folders the killed processes began are gone.
    EXPECT_TRUE(fs::is_empty(dir.path() / "packages"));
}

TEST(LocalRunner, TakesItsLimitsInSlurmsFormats) {
    EXPECT_EQ(slurmTimeSeconds("30"), 1800.0);
    EXPECT_EQ(slurmTimeSeconds("0:30"), 30.0);
    EXPECT_EQ(slurmTimeSeconds("01:00:00"), 3600.0);
    EXPECT_EQ(slurmTimeSeconds("1-00:00:00"), 86400.0);
    EXPECT_EQ(slurmTimeSeconds("2-3"), 2 * 86400.0 + 3 * 3600.0);
    EXPECT_EQ(slurmTimeSeconds("1-2:30"), 86400.0 + 2 * 3600.0 + 30 * 60.0);
    EXPECT_EQ(slurmTimeSeconds("0"), 0.0); // no limit, as Slurm reads it
    for (const char* bad : {"", "1h", "1:2:3:4", "1--2", "-1", ":5", "1-", "1-2:3:4:5", "99999999999"})
        EXPECT_FALSE(slurmTimeSeconds(bad).has_value()) << bad;
    EXPECT_EQ(slurmMemoryMib("4G"), 4096.0);
    EXPECT_EQ(slurmMemoryMib("4000"), 4000.0); // megabytes without a unit
    EXPECT_EQ(slurmMemoryMib("512K"), 0.5);
    EXPECT_EQ(slurmMemoryMib("1T"), 1024.0 * 1024.0);
    for (const char* bad : {"", "G", "4GB", "4g", "-4G", "4.5G"})
        EXPECT_FALSE(slurmMemoryMib(bad).has_value()) << bad;
}

TEST(JobKey, AJobWhoseCaseOrToolsChangedIsNotDoneAndSaysWhy) {
    hs::test::TempDir dir;
    fs::create_directories(dir.path() / "status");
    const std::string folder = dir.path().string();
    const Manifest manifest = manifestOf(2);
    const Job& job = manifest.jobs[0];
    markDone(folder, job);
    EXPECT_TRUE(checkJobDone(folder, job).done);

    // Another seed is another case: the key follows the job's seed, not the file's.
    Job reseeded = job;
    reseeded.seed = job.seed + 1;
    EXPECT_NE(jobKey(folder, reseeded)->caseSha256, jobKey(folder, job)->caseSha256);

    // The tools changed.
    auto record = **readStatus(folder, job.name);
    const StatusRecord done = record;
    record.tools = "hysteroscene 0.0.1";
    ASSERT_TRUE(writeStatus(folder, record).ok());
    DoneCheck check = checkJobDone(folder, job);
    EXPECT_FALSE(check.done);
    EXPECT_EQ(check.rerunReason.find("the tools changed since its package was written (was: hysteroscene 0.0.1; now: "
                                     "cgal "),
              0u)
        << check.rerunReason;

    // A record written before content keys.
    record = done;
    record.caseSha256.clear();
    record.tools.clear();
    ASSERT_TRUE(writeStatus(folder, record).ok());
    EXPECT_NE(checkJobDone(folder, job).rerunReason.find("predates content keys"), std::string::npos);

    // The case edited after the package was written; a change of white space alone is no edit.
    ASSERT_TRUE(writeStatus(folder, done).ok());
    const fs::path caseFile = dir.path() / job.caseFile;
    std::string text = *io::readFile(caseFile.string(), 1 << 20);
    ASSERT_TRUE(io::writeFileAtomically(caseFile.string(), "\n" + text).ok());
    EXPECT_TRUE(checkJobDone(folder, job).done);
    text.replace(text.find("\"ageYears\": 35.0"), 16, "\"ageYears\": 36.0");
    ASSERT_TRUE(io::writeFileAtomically(caseFile.string(), text).ok());
    check = checkJobDone(folder, job);
    EXPECT_FALSE(check.done);
    EXPECT_EQ(check.rerunReason, "its case was edited after its package was written");
}
