#pragma once
/// The fixed file names inside a scene package (private to hs::scene; docs/scene-format.md lists them).

#include "hs/core/Result.h"

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

namespace hs::scene::detail {

constexpr std::string_view kCaseFile = "case.json";
constexpr std::string_view kSceneFile = "scene.json";
constexpr std::string_view kLabelsFile = "labels.json";
constexpr std::string_view kReportFile = "report.json";
constexpr std::string_view kTetsFile = "tets.vtu";
constexpr std::string_view kSimulationFile = "simulation.vtu"; ///< schema version 2 on; optional
constexpr std::string_view kSurfaceVtpFile = "surface.vtp";
constexpr std::string_view kSurfaceGlbFile = "surface.glb";
constexpr std::string_view kSurfaceObjFile = "surface.obj";
constexpr std::string_view kGmshFile = "mesh.msh";
constexpr std::string_view kSofaFile = "scene.scn";
constexpr std::string_view kAlbedoFile = "maps/albedo.png";
constexpr std::string_view kNormalFile = "maps/normal.png";
constexpr std::string_view kRoughnessFile = "maps/roughness.png";

/// Files every package must list; the others are optional (options, or maps the scene does not have). Packages
/// before schema version 4 (kFirstUvInVtpSchemaVersion) must also list surface.glb: their UVs are read from it.
constexpr std::array<std::string_view, 6> kRequiredFiles{kCaseFile,   kSceneFile, kLabelsFile,
                                                         kReportFile, kTetsFile,  kSurfaceVtpFile};

/// Longest path a package may hold (manifest entries and zip entries alike).
constexpr std::size_t kMaxPackagePathLength = 255;

/// A package path: '/'-separated components of [A-Za-z0-9._-], none empty, "." or "..", not absolute, at most
/// kMaxPackagePathLength characters. InvalidInput naming `where` otherwise. The one rule for manifest entries and
/// zip entries, so that nothing is read or written outside the package folder.
Status checkPackagePath(const std::string& path, const std::string& where);

} // namespace hs::scene::detail
