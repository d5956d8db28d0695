#include "hs/core/Resources.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace hs {

std::string resourcesDir() {
    namespace fs = std::filesystem;
    if (const char* dir = std::getenv("HS_RESOURCES_DIR"); dir && *dir)
        return dir;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path installed = exe.parent_path().parent_path() / "share" / "hysteroscene" / "resources";
        if (fs::is_directory(installed, ec))
            return installed.string();
    }
    return HS_SOURCE_RESOURCES_DIR;
}

std::string resourcePath(const std::string& relative) {
    return (std::filesystem::path(resourcesDir()) / relative).string();
}

} // namespace hs
