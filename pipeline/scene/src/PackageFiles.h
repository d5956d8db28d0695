#pragma once
/// The fixed file names inside a scene package (private to hs::scene; docs/scene-format.md lists them).

#include <array>
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

/// Files every package must list; the others are optional (options, or maps the scene does not have).
constexpr std::array<std::string_view, 7> kRequiredFiles{kCaseFile, kSceneFile,      kLabelsFile,    kReportFile,
                                                         kTetsFile, kSurfaceVtpFile, kSurfaceGlbFile};

} // namespace hs::scene::detail
