#include "TestSupport.h"

#include <atomic>
#include <cstdlib>
#include <random>
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
