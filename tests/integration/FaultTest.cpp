// Faults a user meets: `generate` killed at any moment, a full disk, output folders it may not write or read.
// Each runs hysteroscene-cli in a child process (fork + exec) so that it can be killed or given limits.
#include "TestSupport.h"

#include "hs/scene/ScenePackage.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <cstring>
#include <fcntl.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

constexpr uid_t kNobody = 65534;
constexpr int kCannotDropRoot = 125; ///< the child's exit code when it may not become nobody (no CAP_SETUID)

struct ChildOptions {
    rlim_t maxFileBytes = RLIM_INFINITY; ///< RLIMIT_FSIZE: writes beyond it fail with EFBIG, as on a full disk
    bool asNobody = false;               ///< drop root, so that file permissions apply
};

/// Starts the CLI with `args`, stdout and stderr to `logPath`.
pid_t startCli(const std::vector<std::string>& args, const std::string& logPath, const ChildOptions& options = {}) {
    const pid_t pid = ::fork();
    if (pid != 0)
        return pid;
    const int log = ::open(logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (log >= 0) {
        ::dup2(log, 1);
        ::dup2(log, 2);
    }
    if (options.maxFileBytes != RLIM_INFINITY) {
        std::signal(SIGXFSZ, SIG_IGN); // the write fails with EFBIG instead of killing the process
        const rlimit limit{options.maxFileBytes, options.maxFileBytes};
        ::setrlimit(RLIMIT_FSIZE, &limit);
    }
    if (options.asNobody && (::setgid(kNobody) != 0 || ::setuid(kNobody) != 0))
        ::_exit(kCannotDropRoot);
    std::vector<char*> argv{const_cast<char*>(HS_CLI_PATH)};
    for (const auto& a : args)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(HS_CLI_PATH, argv.data());
    ::_exit(127);
}

/// The exit code, or 128 + the signal that ended the child.
int waitFor(pid_t pid) {
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

struct CliRun {
    int exitCode = -1;
    std::string out;
};

CliRun runCli(const std::vector<std::string>& args, const hs::test::TempDir& tmp, const ChildOptions& options = {}) {
    const std::string log = (tmp.path().parent_path() / (tmp.path().filename().string() + ".log")).string();
    CliRun run;
    run.exitCode = waitFor(startCli(args, log, options));
    run.out = readText(log);
    fs::remove(log);
    return run;
}

/// The smallest case that still runs every stage: the default case without pathologies, 500 mesh vertices, 5
/// relaxation steps, 64 px maps without vessels (a few seconds).
std::string writeTinyCase(const hs::test::TempDir& tmp, std::uint64_t seed) {
    std::ifstream in(std::string(HS_SOURCE_DIR) + "/resources/cases/default.json");
    auto j = nlohmann::json::parse(in);
    j["seed"] = seed;
    j["meshing"]["targetVertices"] = 500;
    j["meshing"]["relaxationIterations"] = 5;
    j["texture"]["sizePx"] = 64;
    j["texture"]["vesselDensity"] = 0;
    j["pathologies"] = nlohmann::json::array();
    const std::string path = tmp.file("tiny-" + std::to_string(seed) + ".json");
    std::ofstream(path) << j.dump(2);
    fs::permissions(path,
                    fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read);
    return path;
}

bool isRoot() {
    return ::geteuid() == 0;
}

/// Lets the unprivileged child reach the scratch folder (TempDir makes it 0700).
void openToOthers(const fs::path& folder) {
    fs::permissions(folder, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                fs::perms::others_read | fs::perms::others_exec);
}

/// Names in `folder` (recursively) that a writer leaves while it works: none may survive a finished run.
std::vector<std::string> strayTemporaries(const fs::path& folder) {
    std::vector<std::string> stray;
    for (const auto& e : fs::recursive_directory_iterator(folder)) {
        const std::string name = e.path().filename().string();
        if (name.find(std::string(hs::scene::kTempMarker)) != std::string::npos ||
            name.find(std::string(hs::scene::kOldMarker)) != std::string::npos ||
            name.find(".tmp-") != std::string::npos)
            stray.push_back(fs::relative(e.path(), folder).string());
    }
    return stray;
}

/// "old", "new", "none" or "half": what a killed run left at `target`.
std::string packageState(const std::string& target, const std::string& oldManifest, const std::string& newManifest) {
    std::error_code ec;
    if (!fs::exists(target, ec))
        return "none";
    if (!hs::scene::verifyScenePackage(target).ok())
        return "half";
    const std::string manifest = readText(fs::path(target) / "manifest.json");
    if (manifest == oldManifest)
        return "old";
    return manifest == newManifest ? "new" : "half";
}

/// True while the writer's temporary folder for `target` (".NAME.hs-tmp-PID-N") exists beside it.
bool writing(const fs::path& target) {
    const std::string prefix = "." + target.filename().string() + std::string(hs::scene::kTempMarker);
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(target.parent_path(), ec))
        if (e.path().filename().string().rfind(prefix, 0) == 0)
            return true;
    return false;
}

using Clock = std::chrono::steady_clock;

/// Runs `generate CASE -o target` to the end; returns how long it took and how long it wrote the package (from the
/// moment its temporary folder appeared).
std::pair<Clock::duration, Clock::duration> timedRun(const std::string& caseFile, const fs::path& target,
                                                     const hs::test::TempDir& tmp) {
    const auto start = Clock::now();
    const pid_t pid = startCli({"generate", caseFile, "-o", target.string()}, tmp.file("timed.log"));
    auto writeStart = Clock::time_point{};
    int status = 0;
    while (::waitpid(pid, &status, WNOHANG) == 0) {
        if (writeStart == Clock::time_point{} && writing(target))
            writeStart = Clock::now();
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    const auto end = Clock::now();
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << readText(tmp.file("timed.log"));
    return {end - start, writeStart == Clock::time_point{} ? Clock::duration{} : end - writeStart};
}

} // namespace

TEST(Faults, GenerateKilledAtAnyMomentLeavesThePreviousPackageOrNone) {
    hs::test::TempDir tmp("hs-kill");
    const std::string tiny = writeTinyCase(tmp, 1);
    const std::string older = writeTinyCase(tmp, 2);
    // Reference runs: the package a finished run writes, the one a previous run left, how long a run takes and how
    // long it spends writing the package.
    const auto [runTime, writeTime] = timedRun(tiny, tmp.path() / "new", tmp);
    ASSERT_EQ(runCli({"generate", older, "-o", tmp.file("old")}, tmp).exitCode, 0);
    const std::string newManifest = readText(tmp.file("new/manifest.json"));
    const std::string oldManifest = readText(tmp.file("old/manifest.json"));
    ASSERT_NE(newManifest, oldManifest);

    // 20 kills: 10 with no package at the target, 10 replacing the previous one. In each ten, five at times spread
    // over a whole run and five at times spread over the writing of the package (counted from the moment its
    // temporary folder appears), the window that matters.
    const fs::path target = tmp.path() / "scene";
    int kills = 0;
    int half = 0;
    int whileWriting = 0;
    std::map<std::string, int> states;
    for (int i = 0; i < 20; ++i) {
        const bool replacing = i >= 10;
        const bool duringWrite = i % 2 == 1;
        const double fraction = ((i % 10) / 2 + 0.5) / 5.0;
        fs::remove_all(target); // leftovers of the previous kill stay: the next run must clean them
        if (replacing)
            fs::copy(tmp.file("old"), target, fs::copy_options::recursive);
        const pid_t pid = startCli({"generate", tiny, "-o", target.string()}, tmp.file("kill.log"));
        if (duringWrite) {
            int status = 0;
            while (!writing(target) && ::waitpid(pid, &status, WNOHANG) == 0)
                std::this_thread::sleep_for(std::chrono::microseconds(500));
            std::this_thread::sleep_for(writeTime * fraction);
        } else {
            std::this_thread::sleep_for(runTime * fraction);
        }
        whileWriting += writing(target) ? 1 : 0;
        ::kill(pid, SIGKILL);
        waitFor(pid);
        ++kills;
        std::string state = packageState(target.string(), oldManifest, newManifest);
        if (state == "none" && replacing) {
            // Killed between the two renames of the fallback swap: the next writer (or any reader's recovery)
            // moves the previous package back.
            ASSERT_TRUE(hs::scene::recoverScenePackage(target.string()).ok());
            state = packageState(target.string(), oldManifest, newManifest) == "old" ? "old (recovered)" : "half";
        }
        if (state == "half" || (state == "none" && replacing))
            ++half;
        ++states[state];
        EXPECT_NE(state, "half") << "kill " << i;
        if (!replacing)
            EXPECT_TRUE(state == "none" || state == "new") << state;
        else
            EXPECT_TRUE(state.rfind("old", 0) == 0 || state == "new") << state;
    }
    std::cout << "[ kill test ] " << kills << " kills (" << whileWriting << " while the package was being written), "
              << half << " half packages; states:";
    for (const auto& [state, count] : states)
        std::cout << " " << state << " " << count;
    std::cout << "; a run takes " << std::chrono::duration_cast<std::chrono::milliseconds>(runTime).count()
              << " ms, writing " << std::chrono::duration_cast<std::chrono::milliseconds>(writeTime).count() << " ms\n";
    EXPECT_EQ(half, 0);
    EXPECT_GE(whileWriting, 5);

    // The next run finishes the package and removes what the killed ones left.
    ASSERT_EQ(runCli({"generate", tiny, "-o", target.string()}, tmp).exitCode, 0);
    EXPECT_EQ(readText(target / "manifest.json"), newManifest);
    EXPECT_EQ(strayTemporaries(tmp.path()), std::vector<std::string>{});
}

TEST(Faults, AFullDiskGivesANamedErrorAndLeavesNoHalfPackage) {
    hs::test::TempDir tmp("hs-full");
    const std::string tiny = writeTinyCase(tmp, 1);
    ChildOptions full;
    full.maxFileBytes = 64 * 1024; // files stop growing at 64 KiB: tets.vtu and the maps do not fit
    const std::string target = tmp.file("scene");
    auto run = runCli({"generate", tiny, "-o", target}, tmp, full);
    EXPECT_NE(run.exitCode, 0) << run.out;
    EXPECT_NE(run.out.find("File too large"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find(target), std::string::npos) << run.out;
    EXPECT_FALSE(fs::exists(target));
    EXPECT_EQ(strayTemporaries(tmp.path()), std::vector<std::string>{});

    // Replacing a package on a full disk leaves the previous one as it was.
    ASSERT_EQ(runCli({"generate", writeTinyCase(tmp, 2), "-o", target}, tmp).exitCode, 0);
    const std::string before = readText(fs::path(target) / "manifest.json");
    run = runCli({"generate", tiny, "-o", target}, tmp, full);
    EXPECT_NE(run.exitCode, 0) << run.out;
    EXPECT_NE(run.out.find("File too large"), std::string::npos) << run.out;
    EXPECT_TRUE(hs::scene::verifyScenePackage(target).ok());
    EXPECT_EQ(readText(fs::path(target) / "manifest.json"), before);
    EXPECT_EQ(strayTemporaries(tmp.path()), std::vector<std::string>{});
}

/// A size-limited tmpfs mounted at `folder` for the test's life; unmounted (lazily) when it ends.
class SmallFileSystem {
public:
    SmallFileSystem(const fs::path& folder, std::uintmax_t bytes) : m_folder(folder) {
        fs::create_directories(folder);
        const std::string options = "size=" + std::to_string(bytes) + ",mode=0755";
        if (::mount("tmpfs", folder.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, options.c_str()) == 0)
            m_mounted = true;
        else
            m_why = std::strerror(errno);
    }
    ~SmallFileSystem() {
        if (m_mounted)
            ::umount2(m_folder.c_str(), MNT_DETACH);
    }
    SmallFileSystem(const SmallFileSystem&) = delete;
    SmallFileSystem& operator=(const SmallFileSystem&) = delete;
    bool mounted() const { return m_mounted; }
    const std::string& why() const { return m_why; }

private:
    fs::path m_folder;
    bool m_mounted = false;
    std::string m_why;
};

std::uintmax_t folderBytes(const fs::path& folder) {
    std::uintmax_t bytes = 0;
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file())
            bytes += entry.file_size();
    return bytes;
}

// A real full file system, not a per-file size limit: a tmpfs with room for one package and a half. The first package
// fits; replacing it needs room for a second beside it (the writer's temporary folder), runs out of space, and says
// so by name, leaving the first package as it was and nothing else.
TEST(Faults, AFullFileSystemGivesANamedErrorAndLeavesThePackageAsItWas) {
    hs::test::TempDir tmp("hs-fullfs");
    const std::string first = writeTinyCase(tmp, 1);
    ASSERT_EQ(runCli({"generate", first, "-o", tmp.file("reference")}, tmp).exitCode, 0);
    const std::uintmax_t packageBytes = folderBytes(tmp.path() / "reference");
    const fs::path mountPoint = tmp.path() / "small";
    SmallFileSystem small(mountPoint, packageBytes * 3 / 2);
    if (!small.mounted())
        GTEST_SKIP() << "cannot mount a size-limited tmpfs here (" << small.why()
                     << "; it needs root with CAP_SYS_ADMIN): the full file system was not tested";
    const std::string target = (mountPoint / "scene").string();
    ASSERT_EQ(runCli({"generate", first, "-o", target}, tmp).exitCode, 0);
    const std::string before = readText(fs::path(target) / "manifest.json");
    const auto run = runCli({"generate", writeTinyCase(tmp, 2), "-o", target}, tmp);
    EXPECT_NE(run.exitCode, 0) << run.out;
    EXPECT_NE(run.out.find("No space left on device"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find(target), std::string::npos) << run.out;
    EXPECT_TRUE(hs::scene::verifyScenePackage(target).ok());
    EXPECT_EQ(readText(fs::path(target) / "manifest.json"), before);
    EXPECT_EQ(strayTemporaries(mountPoint), std::vector<std::string>{});
    // The space the failed write took is given back: the package alone is left.
    EXPECT_EQ(folderBytes(mountPoint), packageBytes);
}

TEST(Faults, AReadOnlyOutputFolderGivesANamedError) {
    hs::test::TempDir tmp("hs-readonly");
    const std::string tiny = writeTinyCase(tmp, 1);
    const fs::path folder = tmp.path() / "read-only";
    fs::create_directory(folder);
    fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
    openToOthers(tmp.path());
    ChildOptions user;
    user.asNobody = isRoot(); // root writes anywhere; the check is for the permissions a user has
    const std::string target = (folder / "scene").string();
    const auto run = runCli({"generate", tiny, "-o", target}, tmp, user);
    if (run.exitCode == kCannotDropRoot)
        GTEST_SKIP() << "running as root without the right to become nobody: permissions cannot be tested";
    EXPECT_NE(run.exitCode, 0) << run.out;
    EXPECT_NE(run.out.find(folder.string()), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("Permission denied"), std::string::npos) << run.out;
    EXPECT_TRUE(fs::is_empty(folder));
    fs::permissions(folder, fs::perms::owner_all);
}

TEST(Faults, AnUnreadablePackageFolderGivesANamedError) {
    hs::test::TempDir tmp("hs-unreadable");
    const std::string tiny = writeTinyCase(tmp, 1);
    const std::string package = tmp.file("scene");
    ASSERT_EQ(runCli({"generate", tiny, "-o", package}, tmp).exitCode, 0);
    fs::permissions(package, fs::perms::none);
    openToOthers(tmp.path());
    ChildOptions user;
    user.asNobody = isRoot();
    // Reading it, and replacing it, both fail with the folder named; nothing is deleted.
    auto run = runCli({"validate", package}, tmp, user);
    if (run.exitCode == kCannotDropRoot) {
        fs::permissions(package, fs::perms::owner_all);
        GTEST_SKIP() << "running as root without the right to become nobody: permissions cannot be tested";
    }
    EXPECT_NE(run.exitCode, 0) << run.out;
    EXPECT_NE(run.out.find(package), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("Permission denied"), std::string::npos) << run.out;
    run = runCli({"generate", tiny, "-o", package}, tmp, user);
    EXPECT_NE(run.exitCode, 0) << run.out;
    EXPECT_NE(run.out.find(package), std::string::npos) << run.out;
    fs::permissions(package, fs::perms::owner_all);
    EXPECT_TRUE(hs::scene::verifyScenePackage(package).ok());
}
