// kill -9 during an export: the target holds a complete package (the previous or the new one) or none, never a
// partial one; recovery then leaves exactly one package and no temporary folders.

#include "SyntheticScene.h"
#include "TestSupport.h"
#include "hs/core/Rng.h"
#include "hs/scene/ScenePackage.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <set>
#include <thread>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace hs;
using namespace hs::scene;
namespace fs = std::filesystem;

namespace {

std::string manifestKey(const PackageManifest& manifest) {
    std::string key;
    for (const auto& f : manifest.files)
        key += f.path + ":" + f.sha256 + ";";
    return key;
}

std::size_t strayFolders(const fs::path& parent) {
    std::size_t count = 0;
    for (const auto& entry : fs::directory_iterator(parent))
        count += isPackageTempName(entry.path().filename().string()) ? 1 : 0;
    return count;
}

} // namespace

TEST(ScenePackageKill, LeavesTheOldPackageOrNoneWhenTheWriterIsKilled) {
    test::TempDir dir("hs-scene-kill");
    const std::string target = dir.file("scene");
    test::SyntheticSceneOptions small;
    small.cells = 3;
    const auto old = writeScenePackage(test::syntheticScene(small), target);
    ASSERT_TRUE(old.ok()) << old.error().message();
    test::SyntheticSceneOptions large;
    large.cells = 10; // 6000 tets, 256^2 maps: tens of milliseconds per export
    large.mapSize = 256;
    const Scene next = test::syntheticScene(large);
    const auto reference = writeScenePackage(next, dir.file("reference"));
    ASSERT_TRUE(reference.ok());
    const std::set<std::string> complete{manifestKey(old->manifest), manifestKey(reference->manifest)};

    Rng rng(20240611);
    int sawNone = 0, sawPackage = 0, midExport = 0;
    for (int round = 0; round < 12; ++round) {
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            for (;;)
                if (!writeScenePackage(next, target).ok())
                    ::_exit(3);
        }
        std::this_thread::sleep_for(std::chrono::microseconds(rng.between(1000, 120000)));
        ::kill(child, SIGKILL);
        int status = 0;
        ::waitpid(child, &status, 0);
        ASSERT_TRUE(WIFSIGNALED(status)) << "the writer failed on its own (exit " << WEXITSTATUS(status) << ")";

        const auto verified = verifyScenePackage(target);
        if (verified.ok()) {
            ++sawPackage;
            EXPECT_TRUE(complete.count(manifestKey(*verified))) << "round " << round << ": an unknown package";
        } else {
            ++sawNone;
            EXPECT_EQ(verified.error().code, ErrorCode::NotFound)
                << "round " << round << ": a partial package: " << verified.error().message();
        }
        midExport += strayFolders(dir.path()) > 0 ? 1 : 0;
        for (const auto& entry : fs::directory_iterator(dir.path())) {
            if (isPackageTempName(entry.path().filename().string())) {
                EXPECT_FALSE(verifyScenePackage(entry.path().string()).ok()) << entry.path();
            }
        }

        ASSERT_TRUE(recoverScenePackage(target).ok());
        const auto recovered = verifyScenePackage(target);
        ASSERT_TRUE(recovered.ok()) << "round " << round << ": " << recovered.error().message();
        EXPECT_TRUE(complete.count(manifestKey(*recovered)));
        EXPECT_EQ(strayFolders(dir.path()), 0u) << "round " << round;
    }
    EXPECT_EQ(sawNone + sawPackage, 12);
    EXPECT_GT(midExport, 0) << "no kill landed inside an export: the test proves nothing";
    std::cout << "killed 12 exports: " << midExport << " mid-export, " << sawPackage << " left a package, " << sawNone
              << " left none\n";
}
