#include "hs/io/AtomicFile.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace hs::io {
namespace {

namespace fs = std::filesystem;

/// A name in the same folder as `path` (so the rename stays on one file system), unique per process and call.
std::string temporaryNameFor(const std::string& path) {
    static std::atomic<unsigned long> counter{0};
    const fs::path target(path);
    const std::string name = "." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                             std::to_string(counter.fetch_add(1));
    return (target.parent_path() / name).string();
}

std::string systemMessage(int error) {
    return std::error_code(error, std::generic_category()).message();
}

/// Flushes a written file to the disk, so a crash after the rename cannot leave an empty file in place.
Status syncFile(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return fail(ErrorCode::IoError, path + ": cannot reopen for syncing: " + systemMessage(errno));
    const int rc = ::fsync(fd);
    const int syncError = errno;
    ::close(fd);
    if (rc != 0)
        return fail(ErrorCode::IoError, path + ": cannot sync to disk: " + systemMessage(syncError));
    return {};
}

} // namespace

Status writeAtomically(const std::string& path, const std::function<Status(const std::string& tmpPath)>& write) {
    if (path.empty())
        return fail(ErrorCode::InvalidInput, "empty output file name");
    std::error_code ec;
    if (fs::is_directory(path, ec))
        return fail(ErrorCode::InvalidInput, path + ": is a directory");
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty() && !fs::is_directory(parent, ec))
        return fail(ErrorCode::NotFound, path + ": the folder " + parent.string() + " does not exist");

    const std::string tmpPath = temporaryNameFor(path);
    Status written = write(tmpPath);
    if (written.ok())
        written = syncFile(tmpPath);
    if (written.ok()) {
        fs::rename(tmpPath, path, ec);
        if (ec)
            written = fail(ErrorCode::IoError, path + ": cannot rename the temporary file into place: " + ec.message());
    }
    if (!written.ok())
        fs::remove(tmpPath, ec); // best effort; the original file is untouched either way
    return written;
}

Status writeFileAtomically(const std::string& path, const std::string& bytes) {
    return writeAtomically(path, [&bytes](const std::string& tmpPath) -> Status {
        std::FILE* file = std::fopen(tmpPath.c_str(), "wb");
        if (!file)
            return fail(ErrorCode::IoError, tmpPath + ": cannot create: " + systemMessage(errno));
        const std::size_t written = bytes.empty() ? 0 : std::fwrite(bytes.data(), 1, bytes.size(), file);
        const int writeError = errno;
        const bool closed = std::fclose(file) == 0;
        if (written != bytes.size() || !closed)
            return fail(ErrorCode::IoError, tmpPath + ": write failed: " + systemMessage(writeError));
        return {};
    });
}

Result<std::string> readFile(const std::string& path, std::int64_t maxBytes) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status))
        return fail(ErrorCode::NotFound, path + ": no such file");
    if (fs::is_directory(status))
        return fail(ErrorCode::InvalidInput, path + ": is a directory, not a file");
    if (!fs::is_regular_file(status))
        return fail(ErrorCode::InvalidInput, path + ": is not a regular file");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec)
        return fail(ErrorCode::IoError, path + ": cannot get the file size: " + ec.message());
    if (maxBytes < 0 || size > static_cast<std::uintmax_t>(maxBytes))
        return fail(ErrorCode::LimitExceeded,
                    path + ": " + std::to_string(size) + " bytes, limit " + std::to_string(maxBytes) + " bytes");

    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file)
        return fail(ErrorCode::IoError, path + ": cannot open: " + systemMessage(errno));
    std::string bytes(static_cast<std::size_t>(size), '\0');
    const std::size_t got = size == 0 ? 0 : std::fread(bytes.data(), 1, bytes.size(), file);
    const bool readError = std::ferror(file) != 0;
    std::fclose(file);
    if (readError || got != bytes.size())
        return fail(ErrorCode::IoError, path + ": read " + std::to_string(got) + " of " + std::to_string(size) +
                                            " bytes (the file changed or the disk failed)");
    return bytes;
}

} // namespace hs::io
