#pragma once
// Test helpers for hs::batch: a job made done by hand (its case, a package manifest, an ok record with its key).
#include "TestSupport.h"

#include "hs/batch/Job.h"
#include "hs/batch/JobStatus.h"
#include "hs/io/AtomicFile.h"
#include "hs/scene/Sha256.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace hs::batch::test {

/// `jobs` jobs j0, j1, ... with seeds 1, 2, ..., all of one case file, each with its own package folder.
inline Manifest manifestOf(std::size_t jobs) {
    Manifest m;
    for (std::size_t i = 0; i < jobs; ++i) {
        const std::string name = "j" + std::to_string(i);
        m.jobs.push_back({i, name, "cases/c.json", i + 1, "packages/" + name});
    }
    return m;
}

/// Makes `job` done: its case, a package manifest and an ok record with its checksum and content key.
inline void markDone(const std::string& folder, const Job& job) {
    const auto package = std::filesystem::path(folder) / job.output;
    std::filesystem::create_directories(package);
    const auto caseFile = std::filesystem::path(folder) / job.caseFile;
    std::filesystem::create_directories(caseFile.parent_path());
    std::filesystem::copy_file(hs::test::testDataDir() / "batch" / "light-case.json", caseFile,
                               std::filesystem::copy_options::overwrite_existing);
    const auto key = jobKey(folder, job);
    ASSERT_TRUE(key.ok()) << key.error().detail;
    ASSERT_TRUE(io::writeFileAtomically((package / "manifest.json").string(), "{}").ok());
    StatusRecord r = recordOf(job, JobState::Ok);
    r.packageManifestSha256 = scene::sha256Hex("{}");
    r.caseSha256 = key->caseSha256;
    r.tools = key->tools;
    ASSERT_TRUE(writeStatus(folder, r).ok());
}

} // namespace hs::batch::test
