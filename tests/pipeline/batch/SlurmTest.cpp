// sbatch scripts for a plan: chunks below MaxArraySize, several jobs per array task, only the jobs not done, and
// the options checked before they reach a script.
#include "BatchTestSupport.h"
#include "TestSupport.h"

#include "hs/batch/Job.h"
#include "hs/batch/JobStatus.h"
#include "hs/batch/Slurm.h"
#include "hs/io/AtomicFile.h"
#include "hs/scene/Sha256.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace hs;
using namespace hs::batch;
using hs::batch::test::manifestOf;
using hs::batch::test::markDone;

namespace {

SlurmParams params() {
    SlurmParams p;
    p.executable = "/usr/bin/hysteroscene-cli";
    return p;
}

} // namespace

TEST(Slurm, ChunksArraysAndRunsSeveralJobsPerTask) {
    hs::test::TempDir dir;
    SlurmParams p = params();
    p.arrayChunk = 4;
    p.tasksPerIndex = 3;
    p.partition = "short";
    auto scripts = planSlurmScripts(dir.path().string(), manifestOf(20), p); // 7 tasks: 0-3 and 4-6
    ASSERT_TRUE(scripts.ok()) << scripts.error().detail;
    ASSERT_EQ(scripts->size(), 2u);
    EXPECT_EQ((*scripts)[0].arraySpec, "0-3");
    EXPECT_EQ((*scripts)[1].arraySpec, "0-2");
    EXPECT_EQ((*scripts)[1].taskOffset, 4u);
    const std::string& text = (*scripts)[1].text;
    EXPECT_NE(text.find("#SBATCH --array=0-2\n"), std::string::npos) << text;
    EXPECT_NE(text.find("#SBATCH --partition=short\n"), std::string::npos) << text;
    EXPECT_NE(text.find("--task-index $((4 + SLURM_ARRAY_TASK_ID)) --tasks-per-index 3"), std::string::npos) << text;
    ASSERT_TRUE(writeSlurmScripts(*scripts).ok());
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "slurm" / "array-001.sbatch"));
}

TEST(Slurm, SubmitsOnlyTasksWithJobsNotDone) {
    hs::test::TempDir dir;
    std::filesystem::create_directories(dir.path() / "status");
    const Manifest m = manifestOf(6);
    for (std::size_t i : {0, 1, 2, 4})
        markDone(dir.path().string(), m.jobs[i]);
    SlurmParams p = params();
    p.tasksPerIndex = 2; // tasks {0,1} {2,3} {4,5}: the first is done
    auto scripts = planSlurmScripts(dir.path().string(), m, p);
    ASSERT_TRUE(scripts.ok()) << scripts.error().detail;
    ASSERT_EQ(scripts->size(), 1u);
    EXPECT_EQ((*scripts)[0].arraySpec, "1-2");
    for (std::size_t i : {3, 5})
        markDone(dir.path().string(), m.jobs[i]);
    EXPECT_TRUE(planSlurmScripts(dir.path().string(), m, p)->empty());
}

TEST(Slurm, RefusesOptionsThatAreNotSlurmValues) {
    SlurmParams p = params();
    p.time = "1h; rm -rf /";
    EXPECT_NE(checkSlurmParams(p).error().detail.find("--time"), std::string::npos);
    p = params();
    p.memory = "4GB";
    EXPECT_NE(checkSlurmParams(p).error().detail.find("--mem"), std::string::npos);
    p = params();
    p.partition = "a b";
    EXPECT_NE(checkSlurmParams(p).error().detail.find("--partition"), std::string::npos);
    EXPECT_TRUE(checkSlurmParams(params()).ok());
}
