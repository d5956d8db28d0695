#pragma once
/// The scene package: a folder (optionally zipped) holding a Scene as files other tools read (VTU, MSH 4.1, VTP,
/// glTF binary, PNG, SOFA .scn) plus the project's JSON documents and a manifest with the SHA-256 and size of every
/// file. docs/scene-format.md describes every file, field and unit, the versioning rule and the replace protocol.
///
/// Writing is atomic at the folder level: the package is written into a temporary folder beside the target and
/// then swapped in, so a crash (even kill -9) leaves either the previous package or none at the target, never a
/// partial one. Reading treats the folder as untrusted: every path, size and checksum is checked against the
/// manifest before a file is parsed.

#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/scene/Scene.h"

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace hs::scene {

/// Value of the manifest's "format" member.
constexpr std::string_view kPackageFormat = "hysteroscene-scene";
/// The package schema version this build writes. Version 2 added the simulation mesh (simulation.vtu and its binding
/// of the visual surface). Version 3 wrote the visual surface's texture coordinates with their origin at the maps' top
/// left, as surface.glb (glTF) and VisualSurface document; versions 1 and 2 wrote the bake's own convention there
/// (origin at the bottom left), so every viewer read the maps upside down, and readers flip those (v -> 1 - v,
/// kFirstTopLeftUvSchemaVersion). Readers read versions kOldestPackageSchemaVersion..kPackageSchemaVersion and refuse
/// others (Unsupported).
constexpr int kPackageSchemaVersion = 4;
constexpr int kFirstTopLeftUvSchemaVersion = 3;
/// From version 4 the scene's UVs are read from surface.vtp (Float64, exact), and surface.glb is optional; before,
/// they were read from surface.glb, which every package held.
constexpr int kFirstUvInVtpSchemaVersion = 4;
constexpr int kOldestPackageSchemaVersion = 1;
/// The manifest's file name inside the package; it is the only file the manifest does not list.
constexpr std::string_view kManifestName = "manifest.json";
/// Name markers of the writer's temporary folders (".NAME.hs-tmp-PID-N") and of a replaced package awaiting
/// deletion (".NAME.hs-old"): hidden, so that listings skip them; never a package.
constexpr std::string_view kTempMarker = ".hs-tmp-";
constexpr std::string_view kOldMarker = ".hs-old";

/// The formats other tools need, written on request beside what the simulator and the workstation read (case,
/// scene, labels, report, tets.vtu, simulation.vtu, surface.vtp, maps/): none by default, so that a package of the
/// default case stays within its size budget (docs/scene-format.md, "Size").
struct PackageWriteOptions {
    bool gltf = false; ///< surface.glb (glTF 2.0 binary with the maps, metres)
    bool gmsh = false; ///< mesh.msh (Gmsh 4.1 ASCII)
    bool obj = false;  ///< surface.obj (Wavefront OBJ with UVs, mm)
    bool sofa = false; ///< scene.scn and the surface.obj its OglModel loads

    /// Every format on request.
    static PackageWriteOptions all() { return {true, true, true, true}; }
};

/// Reads a comma-separated list of format names ("gltf", "msh", "obj", "sofa", or "all"; "" for none) as options;
/// InvalidInput naming the unknown name and the allowed ones.
[[nodiscard]] Result<PackageWriteOptions> parsePackageFormats(const std::string& list);

/// One file as the manifest lists it.
struct PackageFile {
    std::string path; ///< relative, '/'-separated, e.g. "maps/albedo.png"
    std::int64_t bytes = 0;
    std::string sha256; ///< lower-case hex
};

struct PackageManifest {
    std::string format{kPackageFormat};
    int schemaVersion = kPackageSchemaVersion;
    std::string toolVersion; ///< the hysteroscene version that wrote it
    /// Every library that shaped the package, name -> version (the scene's toolVersions; optional when read:
    /// packages written before it was added have none).
    std::map<std::string, std::string> toolVersions;
    std::vector<PackageFile> files; ///< sorted by path
};

/// What a written package consists of.
struct PackageWriteResult {
    std::string folder;
    PackageManifest manifest;
};

/// Writes `scene` as a package folder at `folder` (created, or replaced when it exists: an existing folder must
/// itself be a package, i.e. hold manifest.json, or be empty — anything else is refused with InvalidInput so that
/// a typo never deletes a user's folder). Refuses a scene that checkScene() rejects. Deterministic: the same scene
/// gives byte-identical files. Runs recoverScenePackage(folder) first.
[[nodiscard]] Result<PackageWriteResult> writeScenePackage(const Scene& scene, const std::string& folder,
                                                           const PackageWriteOptions& options = {},
                                                           Progress& progress = Progress::none());

/// Zips a verified package folder into `zipPath` (atomically; stored entries in manifest order, manifest.json
/// first, fixed 1980-01-01 time stamps, so the same package gives the same bytes).
[[nodiscard]] Status zipScenePackage(const std::string& folder, const std::string& zipPath);

/// Finishes or undoes an interrupted replace of `folder` (see docs/scene-format.md, "Replacing a package"):
/// when `folder` is missing and ".NAME.hs-old" exists, the old package is moved back; a leftover ".NAME.hs-old"
/// beside a present package and the writer's temporary folders ".NAME.hs-tmp-*" whose process is gone are
/// deleted. Safe to call at any time when no writer for `folder` runs.
[[nodiscard]] Status recoverScenePackage(const std::string& folder);

/// True for names the writer uses for temporary or replaced folders; such folders are never packages.
bool isPackageTempName(std::string_view folderName);

/// Limits for reading untrusted packages. Defaults are far above what this project writes.
struct PackageReadLimits {
    std::int64_t maxManifestBytes = 1 << 20;    ///< manifest.json
    std::int64_t maxFileBytes = 2'000'000'000;  ///< any one file
    std::int64_t maxTotalBytes = 8'000'000'000; ///< all files together
    std::size_t maxFiles = 64;
    std::int64_t maxJsonBytes = 256 << 20;            ///< scene.json, labels.json, report.json
    int maxImageSide = Image<std::uint8_t>::kMaxSide; ///< maps
    std::size_t maxZipEntries = 256;                  ///< a zipped package: entries, folders included
    /// A zipped package: uncompressed / compressed size of one entry larger than 1 MiB (deflate reaches about
    /// 1000:1 on a run of zeros; what this project writes stays below 20:1). Guards against zip bombs together with
    /// maxFileBytes and maxTotalBytes, which are checked against the bytes actually inflated, not the declared ones.
    double maxCompressionRatio = 200.0;
};

/// Checks a package folder without parsing its content: the manifest (format, schema version, fields), every
/// listed path (relative, no "..", no absolute or backslash paths, no symlink anywhere on the way, inside the
/// folder), every size (as declared, within the limits) and every SHA-256, and that the files a package needs
/// are listed. Errors name the file and the problem: NotFound (no folder or manifest), Unsupported (other format
/// or schema version), LimitExceeded (a size above the limits), InvalidInput (everything else).
[[nodiscard]] Result<PackageManifest> verifyScenePackage(const std::string& folder,
                                                         const PackageReadLimits& limits = {});

/// Extracts a zipped package (as zipScenePackage writes it) into `folder`, which must not exist yet, then runs
/// verifyScenePackage on it. The zip is untrusted: at most limits.maxZipEntries entries; each entry's name follows
/// the manifest's path rules (no "..", no absolute path, no backslash: no zip slip); symbolic links, encrypted
/// entries, methods other than stored and deflate, repeated names, entries above limits.maxFileBytes (the manifest
/// above maxManifestBytes), all entries above maxTotalBytes and compression ratios above maxCompressionRatio are
/// refused (InvalidInput, Unsupported or LimitExceeded, naming the zip, the entry and the limit). On any failure
/// `folder` is removed again, so nothing half-extracted is left.
[[nodiscard]] Result<PackageManifest> unzipScenePackage(const std::string& zipPath, const std::string& folder,
                                                        const PackageReadLimits& limits = {});

/// verifyScenePackage, then reads every file into a Scene: tets.vtu (regions, material ids, labels),
/// surface.vtp with the UVs of surface.glb, the maps, scene.json, labels.json, report.json and case.json; the
/// result passes checkScene(). A path naming a regular file ending in ".zip" (any case) is read as a zipped
/// package: unzipScenePackage into a temporary folder, which is removed afterwards.
[[nodiscard]] Result<Scene> readScenePackage(const std::string& folder, const PackageReadLimits& limits = {});

} // namespace hs::scene
