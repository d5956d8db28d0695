// writeScenePackage and recoverScenePackage: every file into a temporary folder, then the folder swapped in.

#include "Gltf.h"
#include "PackageFiles.h"
#include "Png.h"
#include "SceneJson.h"
#include "Sofa.h"
#include "SurfaceEmbedding.h"
#include "hs/io/MeshIO.h"
#include "hs/scene/ScenePackage.h"
#include "hs/scene/Sha256.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <system_error>

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

namespace hs::scene {

namespace fs = std::filesystem;

namespace {

std::string systemMessage(int error) {
    return std::error_code(error, std::generic_category()).message();
}

/// fsync of a file or folder, so a crash after the rename cannot leave renamed-but-empty files.
Status syncPath(const fs::path& path, bool directory) {
    const int fd = ::open(path.c_str(), (directory ? O_RDONLY | O_DIRECTORY : O_RDONLY) | O_CLOEXEC);
    if (fd < 0)
        return fail(ErrorCode::IoError, path.string() + ": cannot open for syncing: " + systemMessage(errno));
    const int rc = ::fsync(fd);
    const int error = errno;
    ::close(fd);
    if (rc != 0)
        return fail(ErrorCode::IoError, path.string() + ": cannot sync to disk: " + systemMessage(error));
    return {};
}

/// Plain write of a new file inside the (still private) temporary folder, then fsync.
Status writeNewFile(const fs::path& path, const std::string& bytes) {
    std::FILE* file = std::fopen(path.c_str(), "wbx");
    if (!file)
        return fail(ErrorCode::IoError, path.string() + ": cannot create: " + systemMessage(errno));
    const std::size_t written = bytes.empty() ? 0 : std::fwrite(bytes.data(), 1, bytes.size(), file);
    const int error = errno;
    const bool closed = std::fclose(file) == 0;
    if (written != bytes.size() || !closed)
        return fail(ErrorCode::IoError, path.string() + ": write failed: " + systemMessage(error));
    return syncPath(path, false);
}

fs::path siblingPath(const fs::path& target, std::string_view marker, const std::string& suffix) {
    return target.parent_path() / ("." + target.filename().string() + std::string(marker) + suffix);
}

fs::path temporaryFolderFor(const fs::path& target) {
    static std::atomic<unsigned long> counter{0};
    return siblingPath(target, kTempMarker, std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1)));
}

/// An existing target must be a package (has a manifest) or an empty folder: the writer never replaces anything
/// else, so a wrong -o cannot delete a user's folder.
Status checkReplaceable(const fs::path& target) {
    std::error_code ec;
    const auto status = fs::symlink_status(target, ec);
    if (ec || status.type() == fs::file_type::not_found)
        return {};
    if (status.type() == fs::file_type::symlink)
        return fail(ErrorCode::InvalidInput, target.string() + ": is a symbolic link; give the real folder");
    if (status.type() != fs::file_type::directory)
        return fail(ErrorCode::InvalidInput, target.string() + ": exists and is not a folder");
    if (fs::is_empty(target, ec) || fs::is_regular_file(target / std::string(kManifestName), ec))
        return {};
    return fail(ErrorCode::InvalidInput, target.string() +
                                             ": exists and is neither empty nor a scene package (no manifest.json); "
                                             "refusing to replace it");
}

/// One file of the package: its relative path and a function writing it at an absolute path.
struct PendingFile {
    std::string path;
    std::function<Status(const fs::path&)> write;
};

Result<std::string> metallicRoughnessPng(const ImageU8& roughness) {
    auto packed = ImageU8::create(roughness.width(), roughness.height(), 3);
    if (!packed)
        return packed.failure();
    // glTF: roughness in G, metalness in B (0: tissue is a dielectric), R unused.
    for (int y = 0; y < roughness.height(); ++y)
        for (int x = 0; x < roughness.width(); ++x)
            packed->at(x, y, 1) = roughness.at(x, y);
    return detail::encodePng(*packed);
}

Result<std::vector<PendingFile>> planFiles(const Scene& scene, const PackageWriteOptions& options) {
    std::vector<PendingFile> files;
    const auto bytesFile = [&files](std::string path, std::string bytes) {
        files.push_back(
            {std::move(path), [bytes = std::move(bytes)](const fs::path& p) { return writeNewFile(p, bytes); }});
    };
    bytesFile(std::string(detail::kCaseFile), toJson(scene.caseSpec));
    bytesFile(std::string(detail::kSceneFile), detail::sceneJson(scene));
    bytesFile(std::string(detail::kLabelsFile), detail::labelsJson(scene));
    bytesFile(std::string(detail::kReportFile), detail::reportJson(scene));
    files.push_back({std::string(detail::kTetsFile),
                     [&scene](const fs::path& p) { return io::writeTetMesh(scene.tets, p.string()); }});
    files.push_back({std::string(detail::kSurfaceVtpFile), [&scene](const fs::path& p) {
                         io::WriteOptions vtp;
                         // VTK's texture coordinates have their origin at the image's bottom left (as OBJ's), the
                         // scene's at its top left: the writer flips them, exactly.
                         vtp.textureCoordinates = scene.surface.uvs.empty() ? nullptr : &scene.surface.uvs;
                         vtp.textureOriginTopLeft = true;
                         vtp.normals = scene.surface.normals.empty() ? nullptr : &scene.surface.normals;
                         if (scene.surface.embedding.empty() && !scene.simulation)
                             return io::writeSurface(scene.surface.mesh, p.string(), vtp);
                         SurfaceMesh mesh = scene.surface.mesh;
                         io::PointArrays arrays;
                         if (!scene.surface.embedding.empty())
                             detail::splitEmbedding(scene.surface.embedding, mesh, arrays);
                         if (scene.simulation)
                             detail::splitEmbedding(scene.simulation->surfaceEmbedding, mesh, arrays,
                                                    detail::kSimEmbedTetLabel, detail::kSimEmbedWeightsArray);
                         vtp.pointArrays = &arrays;
                         return io::writeSurface(mesh, p.string(), vtp);
                     }});
    if (scene.simulation)
        files.push_back({std::string(detail::kSimulationFile),
                         [&scene](const fs::path& p) { return io::writeTetMesh(scene.simulation->tets, p.string()); }});
    if (options.gmsh || options.sofa) // SOFA's MeshGmshLoader reads mesh.msh
        files.push_back({std::string(detail::kGmshFile),
                         [&scene](const fs::path& p) { return io::writeTetMesh(scene.tets, p.string()); }});

    detail::GltfTextures textures;
    const auto map = [&](const ImageU8& image, std::string_view path, std::string* keep) -> Status {
        if (image.empty())
            return {};
        auto png = detail::encodePng(image);
        if (!png)
            return png.failure();
        if (keep)
            *keep = *png;
        bytesFile(std::string(path), std::move(*png));
        return {};
    };
    HS_TRY(map(scene.surface.albedo, detail::kAlbedoFile, options.gltf ? &textures.albedoPng : nullptr));
    HS_TRY(map(scene.surface.normal, detail::kNormalFile, options.gltf ? &textures.normalPng : nullptr));
    HS_TRY(map(scene.surface.roughness, detail::kRoughnessFile, nullptr));
    if (options.gltf) {
        if (!scene.surface.roughness.empty()) {
            auto mr = metallicRoughnessPng(scene.surface.roughness);
            if (!mr)
                return mr.failure();
            textures.metallicRoughnessPng = std::move(*mr);
        }
        const auto tool = scene.toolVersions.find("hysteroscene");
        auto glb =
            detail::encodeGlb(scene.surface, textures,
                              "hysteroscene " + (tool == scene.toolVersions.end() ? std::string() : tool->second));
        if (!glb)
            return glb.failure();
        bytesFile(std::string(detail::kSurfaceGlbFile), std::move(*glb));
    }
    if (options.sofa)
        bytesFile(std::string(detail::kSofaFile), detail::sofaScene(scene, !scene.surface.albedo.empty()));
    if (options.sofa || options.obj)
        bytesFile(std::string(detail::kSurfaceObjFile), detail::visualObj(scene));
    std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) { return a.path < b.path; });
    return files;
}

} // namespace

Result<PackageWriteOptions> parsePackageFormats(const std::string& list) {
    PackageWriteOptions options;
    std::size_t start = 0;
    while (start <= list.size() && !list.empty()) {
        const std::size_t end = std::min(list.find(',', start), list.size());
        const std::string name = list.substr(start, end - start);
        if (name == "gltf")
            options.gltf = true;
        else if (name == "msh")
            options.gmsh = true;
        else if (name == "obj")
            options.obj = true;
        else if (name == "sofa")
            options.sofa = true;
        else if (name == "all")
            options = PackageWriteOptions::all();
        else
            return fail(ErrorCode::InvalidInput, "--formats: \"" + name +
                                                     "\" is not a format; allowed: gltf, msh, obj, sofa, all "
                                                     "(comma-separated)");
        start = end + 1;
    }
    return options;
}

namespace {

std::string manifestJson(const PackageManifest& manifest) {
    nlohmann::ordered_json j;
    j["format"] = manifest.format;
    j["schemaVersion"] = manifest.schemaVersion;
    j["toolVersion"] = manifest.toolVersion;
    j["toolVersions"] = nlohmann::ordered_json::object();
    for (const auto& [tool, version] : manifest.toolVersions)
        j["toolVersions"][tool] = version;
    auto files = nlohmann::ordered_json::array();
    for (const auto& f : manifest.files)
        files.push_back({{"path", f.path}, {"bytes", f.bytes}, {"sha256", f.sha256}});
    j["files"] = files;
    return j.dump(2) + "\n";
}

/// Writes every file into `tmp` and returns the manifest (written last, so a folder without one is unfinished).
Result<PackageManifest> writeInto(const fs::path& tmp, const Scene& scene, const PackageWriteOptions& options,
                                  Progress& progress) {
    auto files = planFiles(scene, options);
    if (!files)
        return files.failure();
    PackageManifest manifest;
    const auto tool = scene.toolVersions.find("hysteroscene");
    manifest.toolVersion = tool == scene.toolVersions.end() ? std::string(HS_VERSION) : tool->second;
    manifest.toolVersions = scene.toolVersions;
    std::error_code ec;
    for (std::size_t i = 0; i < files->size(); ++i) {
        HS_TRY(progress.check("scene package export"));
        const PendingFile& file = (*files)[i];
        const fs::path path = tmp / file.path;
        if (!fs::exists(path.parent_path(), ec)) {
            fs::create_directories(path.parent_path(), ec);
            if (ec)
                return fail(ErrorCode::IoError, path.parent_path().string() + ": cannot create: " + ec.message());
        }
        HS_TRY(file.write(path));
        auto digest = sha256File(path.string(), INT64_MAX);
        if (!digest)
            return digest.failure();
        manifest.files.push_back({file.path, digest->bytes, digest->sha256});
        progress.report("scene.write", static_cast<double>(i + 1) / static_cast<double>(files->size() + 1));
    }
    HS_TRY(writeNewFile(tmp / std::string(kManifestName), manifestJson(manifest)));
    for (const auto& sub : {tmp / "maps", tmp})
        if (fs::is_directory(sub, ec))
            HS_TRY(syncPath(sub, true));
    return manifest;
}

/// Puts the finished temporary folder at `target`. With an existing package, Linux's renameat2(RENAME_EXCHANGE)
/// swaps both names in one step; where the file system lacks it, the old package is first renamed to
/// ".NAME.hs-old" (a crash here leaves no package at the target, and recoverScenePackage moves the old one back).
Status swapIntoPlace(const fs::path& tmp, const fs::path& target) {
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(target, ec))) {
        fs::rename(tmp, target, ec);
        if (ec)
            return fail(ErrorCode::IoError,
                        target.string() + ": cannot rename the new package into place: " + ec.message());
        return syncPath(target.parent_path().empty() ? fs::path(".") : target.parent_path(), true);
    }
    if (::renameat2(AT_FDCWD, tmp.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0) {
        fs::remove_all(tmp, ec); // now holds the previous package
    } else {
        const fs::path old = siblingPath(target, kOldMarker, "");
        fs::remove_all(old, ec);
        fs::rename(target, old, ec);
        if (ec)
            return fail(ErrorCode::IoError,
                        target.string() + ": cannot move the previous package aside: " + ec.message());
        fs::rename(tmp, target, ec);
        if (ec) {
            std::error_code back;
            fs::rename(old, target, back);
            return fail(ErrorCode::IoError,
                        target.string() + ": cannot rename the new package into place: " + ec.message());
        }
        fs::remove_all(old, ec);
    }
    return syncPath(target.parent_path().empty() ? fs::path(".") : target.parent_path(), true);
}

bool processIsGone(const std::string& suffix) {
    // suffix: "PID-N"
    const auto dash = suffix.find('-');
    const std::string pidText = suffix.substr(0, dash);
    if (pidText.empty() || pidText.size() > 9 ||
        !std::all_of(pidText.begin(), pidText.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return true;
    const auto pid = static_cast<pid_t>(std::stol(pidText));
    if (pid == ::getpid())
        return false;
    return ::kill(pid, 0) != 0 && errno == ESRCH;
}

} // namespace

bool isPackageTempName(std::string_view name) {
    if (name.empty() || name.front() != '.')
        return false;
    const bool old = name.size() > kOldMarker.size() && name.substr(name.size() - kOldMarker.size()) == kOldMarker;
    return old || name.find(kTempMarker) != std::string_view::npos;
}

Status recoverScenePackage(const std::string& folder) {
    const fs::path target = fs::path(folder).lexically_normal();
    if (target.filename().empty())
        return fail(ErrorCode::InvalidInput, folder + ": give the package folder's name, not a path ending in /");
    std::error_code ec;
    const fs::path old = siblingPath(target, kOldMarker, "");
    if (fs::exists(fs::symlink_status(old, ec))) {
        if (!fs::exists(fs::symlink_status(target, ec))) {
            fs::rename(old, target, ec);
            if (ec)
                return fail(ErrorCode::IoError,
                            old.string() + ": cannot restore the previous package: " + ec.message());
        } else {
            fs::remove_all(old, ec);
        }
    }
    const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    const std::string prefix = "." + target.filename().string() + std::string(kTempMarker);
    for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.rfind(prefix, 0) == 0 && processIsGone(name.substr(prefix.size()))) {
            std::error_code removeError;
            fs::remove_all(it->path(), removeError);
        }
    }
    return {};
}

Result<PackageWriteResult> writeScenePackage(const Scene& scene, const std::string& folder,
                                             const PackageWriteOptions& options, Progress& progress) {
    HS_TRY(checkScene(scene));
    const fs::path target = fs::path(folder).lexically_normal();
    if (target.filename().empty() || target.filename() == "." || target.filename() == "..")
        return fail(ErrorCode::InvalidInput, folder + ": not a folder name a package can take");
    if (isPackageTempName(target.filename().string()))
        return fail(ErrorCode::InvalidInput, folder + ": names like this are reserved for temporary folders");
    std::error_code ec;
    const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    if (!fs::is_directory(parent, ec))
        return fail(ErrorCode::NotFound, folder + ": the folder " + parent.string() + " does not exist");
    HS_TRY(recoverScenePackage(target.string()));
    HS_TRY(checkReplaceable(target));

    const fs::path tmp = temporaryFolderFor(target);
    if (!fs::create_directory(tmp, ec) || ec)
        return fail(ErrorCode::IoError, tmp.string() + ": cannot create the temporary folder: " + ec.message());
    auto manifest = writeInto(tmp, scene, options, progress);
    Status placed = manifest.ok() ? swapIntoPlace(tmp, target) : Status(manifest.failure());
    if (!placed.ok()) {
        fs::remove_all(tmp, ec);
        // Name the package the caller asked for: the temporary path in the detail means nothing to a user.
        return fail(placed.error().code,
                    folder + ": the package was not written (what was there is unchanged): " + placed.error().detail);
    }
    progress.report("scene.write", 1.0);
    return PackageWriteResult{target.string(), std::move(*manifest)};
}

} // namespace hs::scene
