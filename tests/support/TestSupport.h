#pragma once
/// Paths for tests: fixtures in tests/data, public surfaces in ../shared/data, and scratch folders.

#include <filesystem>
#include <string>

namespace hs::test {

/// tests/data of this repository (from HS_TEST_DATA_DIR, set by ctest).
std::filesystem::path testDataDir();
/// The public test surfaces (from HS_SHARED_DATA_DIR); empty path when they are not present.
std::filesystem::path sharedDataDir();
/// What a shell command printed (stdout and stderr together) and its exit code (-1 when it did not exit).
struct CommandRun {
    int exitCode = -1;
    std::string out;
};
/// Runs `command` with /bin/sh, stderr folded into stdout.
CommandRun runCommand(const std::string& command);
/// `text` in single quotes for the shell.
std::string shellQuote(const std::string& text);

/// Whether a test checks an issue's time bar (seconds on this machine): in optimized builds without AddressSanitizer
/// only. Debug and sanitized builds run the same code several times slower (docs/build-and-test.md); there the test
/// still checks what was computed and prints the time.
#if defined(__OPTIMIZE__) && !defined(__SANITIZE_ADDRESS__)
constexpr bool kTimeBarsApply = true;
#else
constexpr bool kTimeBarsApply = false;
#endif

/// A fresh, empty folder under the system temp dir, removed when the object dies.
class TempDir {
public:
    explicit TempDir(const std::string& prefix = "hs-test");
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return m_path; }
    std::string file(const std::string& name) const { return (m_path / name).string(); }

private:
    std::filesystem::path m_path;
};

} // namespace hs::test
