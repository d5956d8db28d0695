#include "TestSupport.h"

#include <array>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <sys/wait.h>
#include <system_error>

namespace hs::test {

std::filesystem::path testDataDir() {
    const char* dir = std::getenv("HS_TEST_DATA_DIR");
    return dir ? std::filesystem::path(dir) : std::filesystem::path("tests/data");
}

std::filesystem::path sharedDataDir() {
    const char* dir = std::getenv("HS_SHARED_DATA_DIR");
    std::filesystem::path p = dir ? std::filesystem::path(dir) : std::filesystem::path("../shared/data");
    std::error_code ec;
    return std::filesystem::is_directory(p, ec) ? p : std::filesystem::path();
}

CommandRun runCommand(const std::string& command) {
    CommandRun run;
    const std::string folded = command + " 2>&1";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(folded.c_str(), "r"), pclose);
    if (!pipe)
        return run;
    std::array<char, 4096> buffer{};
    std::size_t n = 0;
    while ((n = fread(buffer.data(), 1, buffer.size(), pipe.get())) > 0)
        run.out.append(buffer.data(), n);
    const int status = pclose(pipe.release());
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

std::string shellQuote(const std::string& text) {
    std::string q = "'";
    for (char c : text)
        q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

TempDir::TempDir(const std::string& prefix) {
    static std::atomic<unsigned> counter{0};
    std::random_device rd; // only for a unique folder name, not for test data
    const auto name = prefix + "-" + std::to_string(rd()) + "-" + std::to_string(counter++);
    m_path = std::filesystem::temp_directory_path() / name;
    std::filesystem::create_directories(m_path);
}

TempDir::~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(m_path, ec);
}

} // namespace hs::test
