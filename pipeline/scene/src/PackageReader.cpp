// verifyScenePackage and readScenePackage: the package is untrusted input.

#include "Gltf.h"
#include "PackageFiles.h"
#include "Png.h"
#include "SceneJson.h"
#include "SurfaceEmbedding.h"
#include "hs/io/AtomicFile.h"
#include "hs/io/MeshIO.h"
#include "hs/scene/JsonText.h"
#include "hs/scene/ScenePackage.h"
#include "hs/scene/Sha256.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <set>
#include <system_error>

#include <sys/stat.h>

namespace hs::scene {

namespace fs = std::filesystem;

namespace detail {

/// A manifest path: '/'-separated components of [A-Za-z0-9._-], none empty, "." or "..", not absolute.
Status checkPackagePath(const std::string& path, const std::string& where) {
    if (path.empty() || path.size() > kMaxPackagePathLength)
        return fail(ErrorCode::InvalidInput, where + ": path must have 1-255 characters");
    if (path.front() == '/')
        return fail(ErrorCode::InvalidInput, where + ": \"" + path + "\" is an absolute path");
    std::size_t start = 0;
    while (start <= path.size()) {
        const std::size_t end = std::min(path.find('/', start), path.size());
        const std::string part = path.substr(start, end - start);
        if (part.empty() || part == "." || part == "..")
            return fail(ErrorCode::InvalidInput,
                        where + ": \"" + path +
                            "\" leaves or escapes the package folder (empty, \".\" or \"..\" part)");
        for (const char c : part)
            if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
                  c == '-'))
                return fail(ErrorCode::InvalidInput,
                            where + ": \"" + path.substr(0, 80) + "\" has a character outside A-Z a-z 0-9 . _ - /");
        start = end + 1;
    }
    return {};
}

} // namespace detail

namespace {

using nlohmann::json;

std::string systemMessage(int error) {
    return std::error_code(error, std::generic_category()).message();
}

/// Walks `relative` below `root` with lstat, so that no component may be a symbolic link; the last must be a
/// regular file. Returns its size.
Result<std::int64_t> regularFileSize(const fs::path& root, const std::string& relative) {
    fs::path current = root;
    std::size_t start = 0;
    for (;;) {
        const std::size_t end = std::min(relative.find('/', start), relative.size());
        current /= relative.substr(start, end - start);
        struct stat st {};
        if (::lstat(current.c_str(), &st) != 0)
            return fail(errno == ENOENT ? ErrorCode::NotFound : ErrorCode::IoError,
                        relative + ": listed in the manifest but " +
                            (errno == ENOENT ? std::string("missing") : systemMessage(errno)));
        if (S_ISLNK(st.st_mode))
            return fail(ErrorCode::InvalidInput, relative + ": is or passes through a symbolic link (" +
                                                     current.filename().string() + "), which a package may not hold");
        if (end == relative.size()) {
            if (!S_ISREG(st.st_mode))
                return fail(ErrorCode::InvalidInput, relative + ": is not a regular file");
            return static_cast<std::int64_t>(st.st_size);
        }
        if (!S_ISDIR(st.st_mode))
            return fail(ErrorCode::InvalidInput, relative + ": " + current.filename().string() + " is not a folder");
        start = end + 1;
    }
}

Result<PackageFile> parseFileEntry(const json& entry, std::size_t index) {
    const std::string where = "manifest.json: /files/" + std::to_string(index);
    if (!entry.is_object() || !entry.contains("path") || !entry.contains("bytes") || !entry.contains("sha256"))
        return fail(ErrorCode::InvalidInput, where + " needs \"path\", \"bytes\" and \"sha256\"");
    const json& path = entry["path"];
    const json& bytes = entry["bytes"];
    const json& sha = entry["sha256"];
    if (!path.is_string() || !bytes.is_number_integer() || !sha.is_string())
        return fail(ErrorCode::InvalidInput, where + ": path and sha256 must be strings, bytes an integer");
    PackageFile file;
    file.path = path.get<std::string>();
    file.bytes = bytes.get<std::int64_t>();
    file.sha256 = sha.get<std::string>();
    HS_TRY(detail::checkPackagePath(file.path, where));
    if (file.path == kManifestName)
        return fail(ErrorCode::InvalidInput, where + ": the manifest cannot list itself");
    if (file.bytes < 0)
        return fail(ErrorCode::InvalidInput, where + " (" + file.path + "): negative size");
    if (file.sha256.size() != 64 || !std::all_of(file.sha256.begin(), file.sha256.end(), [](char c) {
            return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
        }))
        return fail(ErrorCode::InvalidInput, where + " (" + file.path + "): sha256 must be 64 lower-case hex digits");
    return file;
}

/// The optional "toolVersions" object: at most 64 names and versions of 1-64 characters each (checkScene's bounds).
Status parseToolVersions(const json& j, std::map<std::string, std::string>& out) {
    const auto it = j.find("toolVersions");
    if (it == j.end())
        return {};
    if (!it->is_object() || it->size() > 64)
        return fail(ErrorCode::InvalidInput, "manifest.json: \"toolVersions\" must be an object of at most 64 entries");
    for (const auto& [tool, version] : it->items()) {
        if (!version.is_string() || tool.empty() || tool.size() > 64 || version.get<std::string>().empty() ||
            version.get<std::string>().size() > 64)
            return fail(ErrorCode::InvalidInput,
                        "manifest.json: /toolVersions needs names and string versions of 1-64 characters");
        out[tool] = version.get<std::string>();
    }
    return {};
}

Result<PackageManifest> parseManifest(const std::string& text, const PackageReadLimits& limits) {
    if (const int depth = jsonNestingDepth(text); depth > kMaxCaseNestingDepth)
        return fail(ErrorCode::InvalidInput, "manifest.json: arrays and objects nested " + std::to_string(depth) +
                                                 " deep (at most " + std::to_string(kMaxCaseNestingDepth) + ")");
    const json j = json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object())
        return fail(ErrorCode::InvalidInput, "manifest.json: not a JSON object");
    if (!j.contains("format") || j["format"] != std::string(kPackageFormat))
        return fail(ErrorCode::InvalidInput,
                    "manifest.json: \"format\" must be \"" + std::string(kPackageFormat) + "\": not a scene package");
    if (!j.contains("schemaVersion") || !j["schemaVersion"].is_number_integer())
        return fail(ErrorCode::InvalidInput, "manifest.json: \"schemaVersion\" must be an integer");
    const auto version = j["schemaVersion"].get<std::int64_t>();
    if (version < kOldestPackageSchemaVersion || version > kPackageSchemaVersion)
        return fail(ErrorCode::Unsupported, "manifest.json: schema version " + std::to_string(version) +
                                                " is not supported; this build reads versions " +
                                                std::to_string(kOldestPackageSchemaVersion) + " to " +
                                                std::to_string(kPackageSchemaVersion));
    if (!j.contains("toolVersion") || !j["toolVersion"].is_string() || !j.contains("files") || !j["files"].is_array())
        return fail(ErrorCode::InvalidInput, "manifest.json: needs a string \"toolVersion\" and a \"files\" array");
    if (j["files"].size() > limits.maxFiles)
        return fail(ErrorCode::LimitExceeded, "manifest.json: lists " + std::to_string(j["files"].size()) +
                                                  " files, more than the allowed " + std::to_string(limits.maxFiles));
    PackageManifest manifest;
    manifest.schemaVersion = static_cast<int>(version);
    manifest.toolVersion = j["toolVersion"].get<std::string>();
    HS_TRY(parseToolVersions(j, manifest.toolVersions));
    std::set<std::string> seen;
    for (std::size_t i = 0; i < j["files"].size(); ++i) {
        auto file = parseFileEntry(j["files"][i], i);
        if (!file)
            return file.failure();
        if (!seen.insert(file->path).second)
            return fail(ErrorCode::InvalidInput, "manifest.json: " + file->path + " is listed twice");
        manifest.files.push_back(std::move(*file));
    }
    for (const std::string_view required : detail::kRequiredFiles)
        if (!seen.count(std::string(required)))
            return fail(ErrorCode::InvalidInput,
                        "manifest.json: does not list " + std::string(required) + ", which every package holds");
    if (manifest.schemaVersion < kFirstUvInVtpSchemaVersion && !seen.count(std::string(detail::kSurfaceGlbFile)))
        return fail(ErrorCode::InvalidInput, "manifest.json: does not list " + std::string(detail::kSurfaceGlbFile) +
                                                 ", which every package of schema version " +
                                                 std::to_string(manifest.schemaVersion) + " holds");
    return manifest;
}

Status checkFile(const fs::path& root, const PackageFile& file, const PackageReadLimits& limits) {
    if (file.bytes > limits.maxFileBytes)
        return fail(ErrorCode::LimitExceeded, file.path + ": declared size " + std::to_string(file.bytes) +
                                                  " bytes is above the limit of " +
                                                  std::to_string(limits.maxFileBytes));
    auto size = regularFileSize(root, file.path);
    if (!size)
        return size.failure();
    if (*size > file.bytes)
        return fail(ErrorCode::InvalidInput, file.path + ": is " + std::to_string(*size) + " bytes, larger than the " +
                                                 std::to_string(file.bytes) + " the manifest declares");
    if (*size < file.bytes)
        return fail(ErrorCode::InvalidInput, file.path + ": is " + std::to_string(*size) + " bytes, smaller than the " +
                                                 std::to_string(file.bytes) + " the manifest declares (truncated?)");
    auto digest = sha256File((root / file.path).string(), file.bytes);
    if (!digest)
        return fail(digest.error().code, file.path + ": " + digest.error().detail);
    if (digest->sha256 != file.sha256)
        return fail(ErrorCode::InvalidInput,
                    file.path + ": checksum mismatch (the file was changed or damaged after export)");
    return {};
}

const PackageFile* findFile(const PackageManifest& manifest, std::string_view path) {
    for (const auto& f : manifest.files)
        if (f.path == path)
            return &f;
    return nullptr;
}

/// Reads a verified file into memory, up to its declared size, and checks the bytes against the manifest again
/// (the folder may have changed since verification).
Result<std::string> readVerified(const fs::path& root, const PackageFile& file, std::int64_t limit) {
    if (file.bytes > limit)
        return fail(ErrorCode::LimitExceeded, file.path + ": " + std::to_string(file.bytes) +
                                                  " bytes is above the limit of " + std::to_string(limit));
    auto bytes = io::readFile((root / file.path).string(), file.bytes);
    if (!bytes)
        return fail(bytes.error().code, file.path + ": " + bytes.error().detail);
    if (static_cast<std::int64_t>(bytes->size()) != file.bytes || sha256Hex(*bytes) != file.sha256)
        return fail(ErrorCode::InvalidInput, file.path + ": changed while the package was being read");
    return bytes;
}

Status readMaps(const fs::path& root, const PackageManifest& manifest, const PackageReadLimits& limits,
                VisualSurface& surface) {
    const std::pair<std::string_view, ImageU8*> maps[] = {{detail::kAlbedoFile, &surface.albedo},
                                                          {detail::kNormalFile, &surface.normal},
                                                          {detail::kRoughnessFile, &surface.roughness}};
    for (const auto& [path, image] : maps) {
        const PackageFile* file = findFile(manifest, path);
        if (!file)
            continue;
        auto bytes = readVerified(root, *file, limits.maxFileBytes);
        if (!bytes)
            return bytes.failure();
        auto decoded = detail::decodePng(*bytes, std::string(path), limits.maxImageSide);
        if (!decoded)
            return decoded.failure();
        *image = std::move(*decoded);
    }
    return {};
}

Status readMeshes(const fs::path& root, const PackageManifest& manifest, const PackageReadLimits& limits,
                  Scene& scene) {
    io::ReadLimits meshLimits;
    meshLimits.maxFileBytes = limits.maxFileBytes;
    auto tets = io::readTetMesh((root / std::string(detail::kTetsFile)).string(), meshLimits);
    if (!tets)
        return fail(tets.error().code, std::string(detail::kTetsFile) + ": " + tets.error().detail);
    scene.tets = std::move(*tets);
    io::PointArrays arrays;
    auto surface =
        io::readSurfaceWithArrays((root / std::string(detail::kSurfaceVtpFile)).string(), arrays, meshLimits);
    if (!surface)
        return fail(surface.error().code, std::string(detail::kSurfaceVtpFile) + ": " + surface.error().detail);
    scene.surface.mesh = std::move(*surface);
    HS_TRY(detail::joinEmbedding(scene.surface.mesh, arrays, scene.surface.embedding));
    if (findFile(manifest, detail::kSimulationFile)) {
        auto sim = io::readTetMesh((root / std::string(detail::kSimulationFile)).string(), meshLimits);
        if (!sim)
            return fail(sim.error().code, std::string(detail::kSimulationFile) + ": " + sim.error().detail);
        SimulationMesh simulation;
        simulation.tets = std::move(*sim);
        HS_TRY(detail::joinEmbedding(scene.surface.mesh, arrays, simulation.surfaceEmbedding, detail::kSimEmbedTetLabel,
                                     detail::kSimEmbedWeightsArray));
        if (simulation.surfaceEmbedding.empty())
            return fail(ErrorCode::InvalidInput, std::string(detail::kSurfaceVtpFile) + ": has no '" +
                                                     detail::kSimEmbedTetLabel + "' binding to " +
                                                     std::string(detail::kSimulationFile));
        scene.simulation = std::move(simulation);
    }
    if (scene.surface.embedding.empty()) // a package written before the surface was bound to the tets
        scene.surface.embedding = embedPoints(scene.tets, scene.surface.mesh.points);
    if (const auto normals = arrays.find("normals"); normals != arrays.end()) {
        if (normals->second.components != 3)
            return fail(ErrorCode::InvalidInput, std::string(detail::kSurfaceVtpFile) + ": 'normals' has " +
                                                     std::to_string(normals->second.components) +
                                                     " components, expected 3");
        const auto& v = normals->second.values;
        for (std::size_t i = 0; i + 2 < v.size(); i += 3)
            scene.surface.normals.push_back({v[i], v[i + 1], v[i + 2]});
    }
    if (manifest.schemaVersion >= kFirstUvInVtpSchemaVersion) {
        const auto uv = arrays.find("uv");
        if (uv == arrays.end())
            return {}; // a surface without texture coordinates (a scene without maps)
        if (uv->second.components != 2)
            return fail(ErrorCode::InvalidInput, std::string(detail::kSurfaceVtpFile) + ": 'uv' has " +
                                                     std::to_string(uv->second.components) + " components, expected 2");
        // Stored with VTK's bottom-left origin as (u, 1 - v) in Float64 (io::WriteOptions::textureOriginTopLeft).
        const auto& v = uv->second.values;
        if (v.size() != 2 * scene.surface.mesh.points.size())
            return fail(ErrorCode::InvalidInput, std::string(detail::kSurfaceVtpFile) + ": 'uv' has " +
                                                     std::to_string(v.size() / 2) + " tuples for " +
                                                     std::to_string(scene.surface.mesh.points.size()) + " points");
        scene.surface.uvs.reserve(v.size() / 2);
        for (std::size_t i = 0; i + 1 < v.size(); i += 2)
            scene.surface.uvs.push_back({static_cast<float>(v[i]), static_cast<float>(1.0 - v[i + 1])});
        return {};
    }
    auto glbBytes = readVerified(root, *findFile(manifest, detail::kSurfaceGlbFile), limits.maxFileBytes);
    if (!glbBytes)
        return glbBytes.failure();
    auto glb = detail::decodeGlb(*glbBytes, std::string(detail::kSurfaceGlbFile));
    if (!glb)
        return glb.failure();
    if (glb->points.size() != scene.surface.mesh.vertexCount() || glb->triangles != scene.surface.mesh.triangles)
        return fail(ErrorCode::InvalidInput, "surface.glb and surface.vtp describe different surfaces");
    scene.surface.uvs = std::move(glb->uvs);
    if (manifest.schemaVersion < kFirstTopLeftUvSchemaVersion) // written with the bake's bottom-left origin
        for (auto& uv : scene.surface.uvs)
            uv[1] = 1.0f - uv[1];
    return {};
}

Status readDocuments(const fs::path& root, const PackageManifest& manifest, const PackageReadLimits& limits,
                     Scene& scene) {
    const auto read = [&](std::string_view path) {
        return readVerified(root, *findFile(manifest, path), limits.maxJsonBytes);
    };
    auto caseText = read(detail::kCaseFile);
    if (!caseText)
        return caseText.failure();
    auto spec = parseCase(*caseText, std::string(detail::kCaseFile));
    if (!spec)
        return spec.failure();
    scene.caseSpec = std::move(*spec);
    auto sceneText = read(detail::kSceneFile);
    if (!sceneText)
        return sceneText.failure();
    HS_TRY(detail::parseSceneJson(*sceneText, std::string(detail::kSceneFile), scene));
    auto labelsText = read(detail::kLabelsFile);
    if (!labelsText)
        return labelsText.failure();
    HS_TRY(detail::parseLabelsJson(*labelsText, std::string(detail::kLabelsFile), scene));
    auto reportText = read(detail::kReportFile);
    if (!reportText)
        return reportText.failure();
    return detail::parseReportJson(*reportText, std::string(detail::kReportFile), scene);
}

/// A path naming a regular file ending in ".zip" (any case): a zipped package.
bool isZipFile(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext)
        c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    struct stat st {};
    return ext == ".zip" && ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

/// Extracts a zipped package into a fresh temporary folder, calls `use(folder, manifest)`, and removes the folder.
template <class T, class Use>
Result<T> withUnzipped(const std::string& zipPath, const PackageReadLimits& limits, Use use) {
    std::error_code ec;
    std::string pattern = (fs::temp_directory_path(ec) / "hs-unzip-XXXXXX").string();
    if (ec || !::mkdtemp(pattern.data()))
        return fail(ErrorCode::IoError, zipPath + ": cannot create a temporary folder to extract it into");
    const fs::path scratch(pattern);
    Result<T> result = [&]() -> Result<T> {
        auto manifest = unzipScenePackage(zipPath, (scratch / "package").string(), limits);
        if (!manifest)
            return manifest.failure();
        auto used = use((scratch / "package").string(), *manifest);
        if (!used)
            return fail(used.error().code, zipPath + " (extracted): " + used.error().detail);
        return used;
    }();
    fs::remove_all(scratch, ec);
    return result;
}

} // namespace

Result<PackageManifest> verifyScenePackage(const std::string& folder, const PackageReadLimits& limits) {
    if (isZipFile(folder))
        return withUnzipped<PackageManifest>(
            folder, limits,
            [](const std::string&, const PackageManifest& manifest) -> Result<PackageManifest> { return manifest; });
    const fs::path root = fs::path(folder).lexically_normal();
    const std::string name = (root.filename().empty() ? root.parent_path() : root).filename().string();
    if (isPackageTempName(name))
        return fail(ErrorCode::InvalidInput, folder + ": a temporary folder of an unfinished or replaced export, "
                                                      "not a scene package");
    struct stat st {};
    if (::lstat(root.c_str(), &st) != 0)
        return fail(ErrorCode::NotFound, folder + ": no such scene package folder");
    if (S_ISLNK(st.st_mode))
        return fail(ErrorCode::InvalidInput, folder + ": is a symbolic link; open the real folder");
    if (!S_ISDIR(st.st_mode))
        return fail(ErrorCode::InvalidInput, folder + ": is not a folder");
    const std::string manifestName(kManifestName);
    auto manifestSize = regularFileSize(root, manifestName);
    if (!manifestSize) {
        if (manifestSize.error().code == ErrorCode::NotFound)
            return fail(ErrorCode::NotFound, folder + ": no manifest.json: not a scene package (or an unfinished one)");
        return fail(manifestSize.error().code, folder + ": " + manifestSize.error().detail);
    }
    if (*manifestSize > limits.maxManifestBytes)
        return fail(ErrorCode::LimitExceeded, folder + ": manifest.json is " + std::to_string(*manifestSize) +
                                                  " bytes, above the limit of " +
                                                  std::to_string(limits.maxManifestBytes));
    auto text = io::readFile((root / manifestName).string(), limits.maxManifestBytes);
    if (!text)
        return text.failure();
    auto manifest = parseManifest(*text, limits);
    if (!manifest)
        return fail(manifest.error().code, folder + ": " + manifest.error().detail);
    std::int64_t total = 0;
    for (const auto& file : manifest->files) {
        total += std::min(file.bytes, limits.maxFileBytes + 1);
        if (total > limits.maxTotalBytes)
            return fail(ErrorCode::LimitExceeded, folder + ": the files add up to more than the limit of " +
                                                      std::to_string(limits.maxTotalBytes) + " bytes");
        const Status ok = checkFile(root, file, limits);
        if (!ok.ok())
            return fail(ok.error().code, folder + ": " + ok.error().detail);
    }
    return manifest;
}

Result<Scene> readScenePackage(const std::string& folder, const PackageReadLimits& limits) {
    if (isZipFile(folder))
        return withUnzipped<Scene>(folder, limits, [&limits](const std::string& extracted, const PackageManifest&) {
            return readScenePackage(extracted, limits);
        });
    auto manifest = verifyScenePackage(folder, limits);
    if (!manifest)
        return manifest.failure();
    const fs::path root = fs::path(folder).lexically_normal();
    Scene scene;
    const auto named = [&folder](const Error& e) { return fail(e.code, folder + ": " + e.detail); };
    if (Status s = readDocuments(root, *manifest, limits, scene); !s.ok())
        return named(s.error());
    if (Status s = readMeshes(root, *manifest, limits, scene); !s.ok())
        return named(s.error());
    if (Status s = readMaps(root, *manifest, limits, scene.surface); !s.ok())
        return named(s.error());
    if (Status s = checkScene(scene); !s.ok())
        return fail(ErrorCode::InvalidInput, folder + ": the package's files do not agree: " + s.error().detail);
    return scene;
}

} // namespace hs::scene
