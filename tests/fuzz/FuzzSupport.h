#pragma once
/// Helpers the fuzz harnesses share. A harness defines LLVMFuzzerTestOneInput; the readers it drives take paths,
/// so the input is written to a scratch file first (in /dev/shm when there is one: memory, not disk).

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

#include <unistd.h>

namespace hs::fuzz {

/// This process's scratch folder, created on first use and kept for the whole run.
inline const std::filesystem::path& scratchFolder() {
    static const std::filesystem::path folder = [] {
        std::error_code ec;
        std::filesystem::path base = std::filesystem::is_directory("/dev/shm", ec)
                                         ? std::filesystem::path("/dev/shm")
                                         : std::filesystem::temp_directory_path(ec);
        std::filesystem::path dir = base / ("hs-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir, ec);
        return dir;
    }();
    return folder;
}

/// Writes `size` bytes to scratchFolder()/name (replacing it) and returns the path; empty on failure.
inline std::string writeScratch(const std::string& name, const std::uint8_t* data, std::size_t size) {
    const std::string path = (scratchFolder() / name).string();
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f)
        return {};
    const bool ok = size == 0 || std::fwrite(data, 1, size, f) == size;
    if (std::fclose(f) != 0 || !ok)
        return {};
    return path;
}

/// Removes scratchFolder()/name and everything below it.
inline void removeScratch(const std::string& name) {
    std::error_code ec;
    std::filesystem::remove_all(scratchFolder() / name, ec);
}

/// A failed property is a crash: the fuzzer keeps the input, the replay test fails on it.
inline void check(bool condition, const char* what, const std::string& detail = {}) {
    if (!condition) {
        std::fprintf(stderr, "fuzz property failed: %s\n%s\n", what, detail.c_str());
        std::abort();
    }
}

} // namespace hs::fuzz
