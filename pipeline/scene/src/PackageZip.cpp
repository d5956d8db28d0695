// zipScenePackage: a verified package folder as one deterministic .zip (minizip).

#include "hs/io/AtomicFile.h"
#include "hs/scene/ScenePackage.h"

#include <minizip/zip.h>

#include <filesystem>

namespace hs::scene {

namespace {

/// Adds one entry, deflated, with a fixed 1980-01-01 00:00 time stamp and no extra fields.
Status addEntry(zipFile zip, const std::string& name, const std::string& bytes, const std::string& zipPath) {
    zip_fileinfo info{};
    info.tmz_date.tm_year = 1980;
    info.tmz_date.tm_mday = 1;
    if (zipOpenNewFileInZip64(zip, name.c_str(), &info, nullptr, 0, nullptr, 0, nullptr, Z_DEFLATED,
                              Z_DEFAULT_COMPRESSION, bytes.size() >= 0xffffffffu ? 1 : 0) != ZIP_OK)
        return fail(ErrorCode::IoError, zipPath + ": cannot add " + name);
    const int written =
        bytes.empty() ? ZIP_OK : zipWriteInFileInZip(zip, bytes.data(), static_cast<unsigned>(bytes.size()));
    if (zipCloseFileInZip(zip) != ZIP_OK || written != ZIP_OK)
        return fail(ErrorCode::IoError, zipPath + ": cannot write " + name);
    return {};
}

} // namespace

Status zipScenePackage(const std::string& folder, const std::string& zipPath) {
    auto manifest = verifyScenePackage(folder);
    if (!manifest)
        return manifest.failure();
    const std::filesystem::path root(folder);
    return io::writeAtomically(zipPath, [&](const std::string& tmpPath) -> Status {
        zipFile zip = zipOpen64(tmpPath.c_str(), APPEND_STATUS_CREATE);
        if (!zip)
            return fail(ErrorCode::IoError, zipPath + ": cannot create");
        Status status;
        std::vector<std::string> names{std::string(kManifestName)};
        for (const auto& f : manifest->files)
            names.push_back(f.path);
        for (const auto& name : names) {
            auto bytes = io::readFile((root / name).string(), INT64_MAX);
            status = bytes ? addEntry(zip, name, *bytes, zipPath) : Status(bytes.failure());
            if (!status.ok())
                break;
        }
        if (zipClose(zip, nullptr) != ZIP_OK && status.ok())
            status = fail(ErrorCode::IoError, zipPath + ": cannot finish the archive");
        return status;
    });
}

} // namespace hs::scene
