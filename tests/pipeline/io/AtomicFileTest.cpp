#include "hs/io/AtomicFile.h"
#include "IoTestMeshes.h"
#include "TestSupport.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace hs::io {
namespace {

int countFiles(const std::filesystem::path& dir) {
    int n = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir))
        ++n;
    return n;
}

TEST(AtomicFile, WritesAndReplacesAFile) {
    test::TempDir dir;
    const std::string path = dir.file("a.txt");
    ASSERT_TRUE(writeFileAtomically(path, "first").ok());
    EXPECT_EQ(test::readBytes(path), "first");
    ASSERT_TRUE(writeFileAtomically(path, std::string("second\0binary", 13)).ok());
    EXPECT_EQ(test::readBytes(path), std::string("second\0binary", 13));
    EXPECT_EQ(countFiles(dir.path()), 1);
}

TEST(AtomicFile, KeepsTheOldFileWhenTheWriterFails) {
    test::TempDir dir;
    const std::string path = dir.file("a.txt");
    test::writeBytes(path, "old");
    std::string seenTmp;
    const Status status = writeAtomically(path, [&](const std::string& tmp) -> Status {
        seenTmp = tmp;
        test::writeBytes(tmp, "half a fi");
        return fail(ErrorCode::IoError, "disk full");
    });
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().detail, "disk full");
    EXPECT_EQ(test::readBytes(path), "old");
    EXPECT_EQ(std::filesystem::path(seenTmp).parent_path(), dir.path()) << "same folder, so rename is atomic";
    EXPECT_FALSE(std::filesystem::exists(seenTmp));
    EXPECT_EQ(countFiles(dir.path()), 1);
}

TEST(AtomicFile, RefusesADirectoryAsTarget) {
    test::TempDir dir;
    const auto status = writeFileAtomically(dir.path().string(), "x");
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().code, ErrorCode::InvalidInput);
}

TEST(AtomicFile, ReadsWholeFileWithinTheLimit) {
    test::TempDir dir;
    const std::string path = dir.file("b.bin");
    test::writeBytes(path, std::string(1000, 'x'));
    const auto ok = readFile(path, 1000);
    ASSERT_TRUE(ok.ok());
    EXPECT_EQ(ok->size(), 1000u);
    const auto tooBig = readFile(path, 999);
    ASSERT_FALSE(tooBig.ok());
    EXPECT_EQ(tooBig.error().code, ErrorCode::LimitExceeded);
    EXPECT_NE(tooBig.error().detail.find(path), std::string::npos);
}

TEST(AtomicFile, ReportsMissingFilesAndDirectories) {
    test::TempDir dir;
    const auto missing = readFile(dir.file("none"), 100);
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::NotFound);
    EXPECT_NE(missing.error().detail.find("none"), std::string::npos);
    const auto directory = readFile(dir.path().string(), 100);
    ASSERT_FALSE(directory.ok());
    EXPECT_EQ(directory.error().code, ErrorCode::InvalidInput);
}

} // namespace
} // namespace hs::io
