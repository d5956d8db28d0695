// unzipScenePackage: a zipped package is untrusted input (zip slip, zip bombs, links, repeated names).

#include "PackageFiles.h"
#include "hs/scene/ScenePackage.h"

#include <minizip/unzip.h>

#include <cerrno>
#include <filesystem>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace hs::scene {

namespace fs = std::filesystem;

namespace {

constexpr std::uint64_t kRatioCheckedAbove = 1 << 20; ///< bytes; small entries may compress as well as they like
constexpr std::size_t kMaxZipNameLength = 1024;       ///< longer names are refused before they are read
constexpr unsigned kUnixHost = 3;                     ///< "version made by" high byte of a zip written on Unix
constexpr std::uint16_t kEncryptedFlag = 1;

std::string systemMessage(int error) {
    return std::error_code(error, std::generic_category()).message();
}

std::string limitText(std::int64_t value) {
    return std::to_string(value);
}

/// Removes the folder it guards unless released: nothing half-extracted stays behind.
class FolderGuard {
public:
    explicit FolderGuard(fs::path folder) : m_folder(std::move(folder)) {}
    FolderGuard(const FolderGuard&) = delete;
    FolderGuard& operator=(const FolderGuard&) = delete;
    ~FolderGuard() {
        if (!m_released) {
            std::error_code ec;
            fs::remove_all(m_folder, ec);
        }
    }
    void release() { m_released = true; }

private:
    fs::path m_folder;
    bool m_released = false;
};

struct ZipCloser {
    void operator()(void* zip) const {
        if (zip)
            unzClose(zip);
    }
};

/// The checks on an entry's header, before anything is inflated.
Status checkEntryHeader(const std::string& zipPath, const std::string& name, const unz_file_info64& info,
                        const PackageReadLimits& limits) {
    const std::string where = zipPath + ": entry \"" + name.substr(0, 80) + "\"";
    if ((info.version >> 8) == kUnixHost && ((info.external_fa >> 16) & S_IFMT) == S_IFLNK)
        return fail(ErrorCode::InvalidInput, where + " is a symbolic link, which a package may not hold");
    if (info.flag & kEncryptedFlag)
        return fail(ErrorCode::Unsupported, where + " is encrypted");
    if (info.compression_method != 0 && info.compression_method != Z_DEFLATED)
        return fail(ErrorCode::Unsupported, where + ": compression method " + std::to_string(info.compression_method) +
                                                " (allowed: 0 stored, 8 deflate)");
    const std::int64_t limit = name == kManifestName ? limits.maxManifestBytes : limits.maxFileBytes;
    if (info.uncompressed_size > static_cast<std::uint64_t>(limit))
        return fail(ErrorCode::LimitExceeded, where + " declares " + std::to_string(info.uncompressed_size) +
                                                  " bytes, above the limit of " + limitText(limit));
    if (info.uncompressed_size > kRatioCheckedAbove &&
        static_cast<double>(info.uncompressed_size) >
            limits.maxCompressionRatio * static_cast<double>(std::max<std::uint64_t>(info.compressed_size, 1)))
        return fail(ErrorCode::LimitExceeded,
                    where + " inflates " + std::to_string(info.compressed_size) + " to " +
                        std::to_string(info.uncompressed_size) + " bytes, above the allowed compression ratio of " +
                        std::to_string(static_cast<int>(limits.maxCompressionRatio)) + ":1 (a zip bomb?)");
    return {};
}

/// Creates the folders of `relative` below `root` (each a fresh folder the extraction made; a link cannot exist
/// there because link entries are refused).
Status makeParents(const fs::path& root, const std::string& relative, const std::string& where) {
    std::size_t start = 0;
    fs::path current = root;
    for (std::size_t slash = relative.find('/'); slash != std::string::npos; slash = relative.find('/', start)) {
        current /= relative.substr(start, slash - start);
        if (::mkdir(current.c_str(), 0755) != 0 && errno != EEXIST)
            return fail(ErrorCode::IoError, where + ": cannot create its folder: " + systemMessage(errno));
        struct stat st {};
        if (::lstat(current.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
            return fail(ErrorCode::InvalidInput,
                        where + ": " + current.filename().string() + " is a file and a folder");
        start = slash + 1;
    }
    return {};
}

/// Inflates the current entry into `target` (a new file; a repeated name fails), counting the bytes actually
/// produced against the entry's declared size and the total budget.
Status extractEntry(void* zip, const fs::path& target, const std::string& where, const unz_file_info64& info,
                    std::int64_t& budget) {
    if (unzOpenCurrentFile(zip) != UNZ_OK)
        return fail(ErrorCode::InvalidInput, where + ": cannot be opened (damaged archive)");
    const int fd = ::open(target.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0) {
        const int error = errno;
        unzCloseCurrentFile(zip);
        if (error == EEXIST)
            return fail(ErrorCode::InvalidInput, where + " is repeated in the archive");
        return fail(ErrorCode::IoError, where + ": cannot be written: " + systemMessage(error));
    }
    std::vector<char> buffer(1 << 16);
    std::uint64_t produced = 0;
    Status status;
    for (;;) {
        const int n = unzReadCurrentFile(zip, buffer.data(), static_cast<unsigned>(buffer.size()));
        if (n < 0) {
            status = fail(ErrorCode::InvalidInput, where + ": damaged data (zip error " + std::to_string(n) + ")");
            break;
        }
        if (n == 0)
            break;
        produced += static_cast<std::uint64_t>(n);
        budget -= n;
        if (produced > info.uncompressed_size || budget < 0) {
            status = fail(ErrorCode::LimitExceeded,
                          where + " inflates to more bytes than it declares or than the package limit allows");
            break;
        }
        for (std::size_t done = 0; done < static_cast<std::size_t>(n);) {
            const ssize_t w = ::write(fd, buffer.data() + done, static_cast<std::size_t>(n) - done);
            if (w < 0 && errno == EINTR)
                continue;
            if (w <= 0) {
                status = fail(ErrorCode::IoError, where + ": cannot be written: " + systemMessage(errno));
                break;
            }
            done += static_cast<std::size_t>(w);
        }
        if (!status.ok())
            break;
    }
    if (::close(fd) != 0 && status.ok())
        status = fail(ErrorCode::IoError, where + ": cannot be written: " + systemMessage(errno));
    const int closed = unzCloseCurrentFile(zip);
    if (status.ok() && closed == UNZ_CRCERROR)
        status = fail(ErrorCode::InvalidInput, where + ": CRC mismatch (damaged archive)");
    if (status.ok() && produced != info.uncompressed_size)
        status = fail(ErrorCode::InvalidInput, where + ": " + std::to_string(produced) + " bytes instead of the " +
                                                   std::to_string(info.uncompressed_size) + " declared");
    return status;
}

Status extractAll(void* zip, const std::string& zipPath, const fs::path& root, const PackageReadLimits& limits) {
    unz_global_info64 global{};
    if (unzGetGlobalInfo64(zip, &global) != UNZ_OK)
        return fail(ErrorCode::InvalidInput, zipPath + ": not a zip archive (no central directory)");
    if (global.number_entry > limits.maxZipEntries)
        return fail(ErrorCode::LimitExceeded, zipPath + ": " + std::to_string(global.number_entry) +
                                                  " entries, above the limit of " +
                                                  std::to_string(limits.maxZipEntries));
    std::int64_t budget = limits.maxTotalBytes;
    std::size_t count = 0;
    for (int step = unzGoToFirstFile(zip); step != UNZ_END_OF_LIST_OF_FILE; step = unzGoToNextFile(zip)) {
        if (step != UNZ_OK)
            return fail(ErrorCode::InvalidInput, zipPath + ": damaged central directory");
        if (++count > limits.maxZipEntries)
            return fail(ErrorCode::LimitExceeded,
                        zipPath + ": more entries than the limit of " + std::to_string(limits.maxZipEntries));
        unz_file_info64 info{};
        if (unzGetCurrentFileInfo64(zip, &info, nullptr, 0, nullptr, 0, nullptr, 0) != UNZ_OK)
            return fail(ErrorCode::InvalidInput, zipPath + ": damaged entry " + std::to_string(count));
        if (info.size_filename == 0 || info.size_filename > kMaxZipNameLength)
            return fail(ErrorCode::InvalidInput, zipPath + ": entry " + std::to_string(count) + " has a name of " +
                                                     std::to_string(info.size_filename) + " bytes (allowed: 1-" +
                                                     std::to_string(kMaxZipNameLength) + ")");
        std::string name(info.size_filename, '\0');
        if (unzGetCurrentFileInfo64(zip, &info, name.data(), static_cast<uLong>(name.size()), nullptr, 0, nullptr, 0) !=
            UNZ_OK)
            return fail(ErrorCode::InvalidInput, zipPath + ": damaged entry " + std::to_string(count));
        const bool isFolder = name.back() == '/';
        if (isFolder)
            name.pop_back();
        HS_TRY(detail::checkPackagePath(name, zipPath + ": entry " + std::to_string(count)));
        HS_TRY(checkEntryHeader(zipPath, name, info, limits));
        const std::string where = zipPath + ": entry \"" + name + "\"";
        HS_TRY(makeParents(root, isFolder ? name + "/" : name, where));
        if (!isFolder)
            HS_TRY(extractEntry(zip, root / name, where, info, budget));
    }
    return {};
}

} // namespace

Result<PackageManifest> unzipScenePackage(const std::string& zipPath, const std::string& folder,
                                          const PackageReadLimits& limits) {
    struct stat st {};
    if (::lstat(zipPath.c_str(), &st) != 0)
        return fail(ErrorCode::NotFound, zipPath + ": no such zipped scene package");
    if (!S_ISREG(st.st_mode))
        return fail(ErrorCode::InvalidInput, zipPath + ": is not a regular file");
    const fs::path root(folder);
    if (::mkdir(root.c_str(), 0755) != 0)
        return fail(errno == EEXIST ? ErrorCode::InvalidInput : ErrorCode::IoError,
                    folder + ": cannot extract " + zipPath + " here: " + systemMessage(errno) +
                        " (the folder must not exist yet)");
    FolderGuard guard(root);
    std::unique_ptr<void, ZipCloser> zip(unzOpen64(zipPath.c_str()));
    if (!zip)
        return fail(ErrorCode::InvalidInput, zipPath + ": not a zip archive (or unreadable)");
    HS_TRY(extractAll(zip.get(), zipPath, root, limits));
    auto manifest = verifyScenePackage(folder, limits);
    if (!manifest)
        return fail(manifest.error().code, zipPath + " (extracted): " + manifest.error().detail);
    guard.release();
    return manifest;
}

} // namespace hs::scene
