// The scene model: label keys, material assignment, tool versions and the consistency check.

#include "hs/scene/Scene.h"

#include "Format.h"
#include "hs/core/LibraryVersions.h"
#include "hs/core/Rng.h"
#include "hs/io/LibraryVersions.h"

#include <nlohmann/json.hpp>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace hs::scene {

namespace {

constexpr double kMaxHeterogeneity = 0.5;
constexpr std::size_t kMaxLabelNameLength = 64;

bool isLabelNameChar(char c, bool first) {
    const bool alnum = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
    return first ? alnum : (alnum || c == '_' || c == ':' || c == '.' || c == '-');
}

Status checkMaterialRange(const SceneRegion& region, const TissueMaterial& m) {
    const Range eRange = youngsModulusRangeKpa(region.tissue);
    if (!eRange.contains(m.youngsModulusKpa))
        return fail(ErrorCode::InvalidInput, "region " + std::to_string(region.id) + " (" + region.name +
                                                 "): Young's modulus " + detail::formatNumber(m.youngsModulusKpa) +
                                                 " kPa is outside " + detail::formatRange(eRange));
    if (!limits::kPoissonRatio.contains(m.poissonRatio))
        return fail(ErrorCode::InvalidInput, "region " + std::to_string(region.id) + ": Poisson ratio " +
                                                 detail::formatNumber(m.poissonRatio) + " is outside " +
                                                 detail::formatRange(limits::kPoissonRatio));
    if (!limits::kDensityKgPerM3.contains(m.densityKgPerM3))
        return fail(ErrorCode::InvalidInput, "region " + std::to_string(region.id) + ": density " +
                                                 detail::formatNumber(m.densityKgPerM3) + " kg/m^3 is outside " +
                                                 detail::formatRange(limits::kDensityKgPerM3));
    return {};
}

/// Per-tet Young's modulus in Pa: log-normal around the mean with coefficient of variation `cv`, clamped to the
/// tissue's range. Each tet draws from its own derived generator, so the value depends only on seed and tet index.
std::int32_t heterogeneousModulusPa(const SceneMaterial& m, const Rng& base, std::size_t tet) {
    Rng rng = base.derive(static_cast<std::uint64_t>(tet));
    const double sigma = std::sqrt(std::log1p(m.heterogeneity * m.heterogeneity));
    // Mean-preserving log-normal: E = mean * exp(sigma z - sigma^2 / 2).
    const double e = m.material.youngsModulusKpa * std::exp(sigma * rng.normal() - 0.5 * sigma * sigma);
    const double clamped = std::clamp(e, m.youngsModulusRangeKpa.min, m.youngsModulusRangeKpa.max);
    return static_cast<std::int32_t>(std::lround(clamped * 1000.0));
}

Status checkLabels(const Scene& scene) {
    std::set<std::string> names;
    for (const auto& label : scene.labels) {
        if (label.name.empty() || label.name.size() > kMaxLabelNameLength || !isLabelNameChar(label.name[0], true) ||
            !std::all_of(label.name.begin(), label.name.end(), [](char c) { return isLabelNameChar(c, false); }))
            return fail(ErrorCode::InvalidInput,
                        "label name " + detail::quoteText(label.name) +
                            " must be 1-64 characters of A-Z a-z 0-9 _ : . - starting with a letter or digit");
        if (!names.insert(label.name).second)
            return fail(ErrorCode::InvalidInput, "label name " + detail::quoteText(label.name) + " is used twice");
        const std::size_t count =
            label.element == LabelElement::Tet ? scene.tets.tetCount() : scene.surface.mesh.faceCount();
        for (std::size_t i = 0; i < label.indices.size(); ++i) {
            const std::int32_t v = label.indices[i];
            if (v < 0 || static_cast<std::size_t>(v) >= count)
                return fail(ErrorCode::InvalidInput, "label " + label.name + ": index " + std::to_string(v) +
                                                         " is outside 0.." + std::to_string(count) + " (exclusive)");
            if (i > 0 && v <= label.indices[i - 1])
                return fail(ErrorCode::InvalidInput, "label " + label.name +
                                                         ": indices must be ascending and unique (at position " +
                                                         std::to_string(i) + ")");
        }
    }
    return {};
}

Status checkSurface(const VisualSurface& surface) {
    HS_TRY(validate(surface.mesh));
    if (surface.mesh.faceCount() == 0)
        return fail(ErrorCode::InvalidInput, "the visual surface has no triangles");
    if (surface.uvs.size() != surface.mesh.vertexCount())
        return fail(ErrorCode::InvalidInput, "the visual surface has " + std::to_string(surface.uvs.size()) +
                                                 " UVs for " + std::to_string(surface.mesh.vertexCount()) +
                                                 " points (one per point expected)");
    for (std::size_t i = 0; i < surface.uvs.size(); ++i)
        for (const float c : surface.uvs[i])
            if (!(c >= 0.0f && c <= 1.0f))
                return fail(ErrorCode::InvalidInput, "UV of point " + std::to_string(i) + " is outside [0, 1]");
    const auto checkMap = [](const ImageU8& image, const char* name, int channels) -> Status {
        if (!image.empty() && image.channels() != channels)
            return fail(ErrorCode::InvalidInput, std::string(name) + " map has " + std::to_string(image.channels()) +
                                                     " channels, expected " + std::to_string(channels));
        return {};
    };
    HS_TRY(checkMap(surface.albedo, "albedo", 3));
    HS_TRY(checkMap(surface.normal, "normal", 3));
    HS_TRY(checkMap(surface.roughness, "roughness", 1));
    if (!surface.normals.empty()) {
        if (surface.normals.size() != surface.mesh.vertexCount())
            return fail(ErrorCode::InvalidInput, "the visual surface has " + std::to_string(surface.normals.size()) +
                                                     " normals for " + std::to_string(surface.mesh.vertexCount()) +
                                                     " points (one per point expected)");
        for (std::size_t i = 0; i < surface.normals.size(); ++i)
            if (!isFinite(surface.normals[i]) || std::abs(norm(surface.normals[i]) - 1.0) > 1e-3)
                return fail(ErrorCode::InvalidInput, "normal of point " + std::to_string(i) + " is not a unit vector");
    }
    return {};
}

/// Every surface point bound to an existing tet of `tets`, with weights that sum to 1, stay within the allowed
/// extrapolation and give the point back (1e-6 of the scene's size). `what` names the embedding in messages.
Status checkEmbedding(const std::vector<TetEmbedding>& embedding, const SurfaceMesh& surface, const TetMesh& tetMesh,
                      const std::string& what, double toleranceMm = -1.0) {
    if (embedding.empty())
        return {};
    const auto& points = surface.points;
    if (embedding.size() != points.size())
        return fail(ErrorCode::InvalidInput, what + ": " + std::to_string(embedding.size()) + " embedded points for " +
                                                 std::to_string(points.size()) +
                                                 " points of the visual surface (one per point expected)");
    const Bounds box = bounds(surface);
    const double tolerance = toleranceMm >= 0.0 ? toleranceMm : 1e-6 * std::max(1.0, norm(box.max - box.min));
    const auto tets = static_cast<std::int64_t>(tetMesh.tetCount());
    for (std::size_t i = 0; i < embedding.size(); ++i) {
        const TetEmbedding& e = embedding[i];
        const std::string where = what + ": surface point " + std::to_string(i) + ": ";
        if (e.tet < 0 || e.tet >= tets)
            return fail(ErrorCode::InvalidInput, where + "embedded in tet " + std::to_string(e.tet) + ", allowed 0.." +
                                                     std::to_string(tets - 1));
        double sum = 0.0;
        for (double w : e.weights) {
            if (!std::isfinite(w) || w < -kMaxEmbeddingExtrapolation || w > 1.0 + kMaxEmbeddingExtrapolation)
                return fail(ErrorCode::InvalidInput, where + "barycentric weight " + std::to_string(w) +
                                                         " outside the allowed " +
                                                         std::to_string(-kMaxEmbeddingExtrapolation) + ".." +
                                                         std::to_string(1.0 + kMaxEmbeddingExtrapolation));
            sum += w;
        }
        if (std::abs(sum - 1.0) > 1e-6)
            return fail(ErrorCode::InvalidInput,
                        where + "barycentric weights sum to " + std::to_string(sum) + ", not 1");
        const double off = distance(embeddedPoint(tetMesh, e), points[i]);
        if (off > tolerance)
            return fail(ErrorCode::InvalidInput, where + "its embedding in tet " + std::to_string(e.tet) + " lies " +
                                                     std::to_string(off) + " mm away from it");
    }
    return {};
}

/// The simulation mesh: a valid tet mesh whose regions the scene names, its material array pointing at the material
/// of each tet's region, 0/1 support and cavity arrays, and the visual surface bound to it.
Status checkSimulation(const Scene& scene) {
    if (!scene.simulation)
        return {};
    const SimulationMesh& sim = *scene.simulation;
    const std::string what = "simulation mesh";
    if (auto valid = validate(sim.tets); !valid)
        return fail(valid.error().code, what + ": " + valid.error().detail);
    if (sim.tets.tetCount() == 0)
        return fail(ErrorCode::InvalidInput, what + ": has no tets");
    std::map<std::int32_t, std::int32_t> materialOfRegion;
    for (const auto& m : scene.materials)
        materialOfRegion[m.regionId] = m.id;
    const auto materials = sim.tets.tetLabels.find(kMaterialLabel);
    const auto support = sim.tets.tetLabels.find(kSupportTetLabel);
    const auto cavity = sim.tets.pointLabels.find(kCavityPointLabel);
    if (materials == sim.tets.tetLabels.end() || support == sim.tets.tetLabels.end() ||
        cavity == sim.tets.pointLabels.end())
        return fail(ErrorCode::InvalidInput, what + ": needs the tet arrays '" + std::string(kMaterialLabel) +
                                                 "' and '" + kSupportTetLabel + "' and the point array '" +
                                                 kCavityPointLabel + "'");
    for (std::size_t t = 0; t < sim.tets.tetCount(); ++t) {
        const auto it = materialOfRegion.find(sim.tets.regionOf(t));
        if (it == materialOfRegion.end())
            return fail(ErrorCode::InvalidInput, what + ": tet " + std::to_string(t) + " lies in region " +
                                                     std::to_string(sim.tets.regionOf(t)) +
                                                     ", which the scene does not name");
        if (materials->second[t] != it->second)
            return fail(ErrorCode::InvalidInput, what + ": tet " + std::to_string(t) + " has material " +
                                                     std::to_string(materials->second[t]) + ", its region's is " +
                                                     std::to_string(it->second));
        if (support->second[t] != 0 && support->second[t] != 1)
            return fail(ErrorCode::InvalidInput, what + ": '" + std::string(kSupportTetLabel) + "' of tet " +
                                                     std::to_string(t) + " is " + std::to_string(support->second[t]) +
                                                     ", allowed 0 or 1");
    }
    for (std::size_t i = 0; i < cavity->second.size(); ++i)
        if (cavity->second[i] != 0 && cavity->second[i] != 1)
            return fail(ErrorCode::InvalidInput, what + ": '" + std::string(kCavityPointLabel) + "' of point " +
                                                     std::to_string(i) + " is " + std::to_string(cavity->second[i]) +
                                                     ", allowed 0 or 1");
    if (sim.surfaceEmbedding.size() != scene.surface.mesh.vertexCount())
        return fail(ErrorCode::InvalidInput, what + ": binds " + std::to_string(sim.surfaceEmbedding.size()) +
                                                 " points of the visual surface's " +
                                                 std::to_string(scene.surface.mesh.vertexCount()));
    return checkEmbedding(sim.surfaceEmbedding, scene.surface.mesh, sim.tets, what, kMaxSimulationEmbeddingOffsetMm);
}

Status checkMaterials(const Scene& scene) {
    const auto& mesh = scene.tets;
    std::set<std::int32_t> regionIds;
    for (const auto& r : scene.regions)
        regionIds.insert(r.id);
    for (std::size_t t = 0; t < mesh.tetCount(); ++t)
        if (!regionIds.count(mesh.regionOf(t)))
            return fail(ErrorCode::InvalidInput, "tet " + std::to_string(t) + " lies in region " +
                                                     std::to_string(mesh.regionOf(t)) +
                                                     ", which the scene does not name");
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].id != static_cast<std::int32_t>(i))
            return fail(ErrorCode::InvalidInput, "material " + std::to_string(i) + " has id " +
                                                     std::to_string(scene.materials[i].id) + " (ids are positions)");
    const auto it = mesh.tetLabels.find(kMaterialLabel);
    if (it == mesh.tetLabels.end())
        return fail(ErrorCode::InvalidInput, "the tet mesh has no \"material\" array (call assignMaterials)");
    for (std::size_t t = 0; t < it->second.size(); ++t) {
        const std::int32_t m = it->second[t];
        if (m < 0 || static_cast<std::size_t>(m) >= scene.materials.size())
            return fail(ErrorCode::InvalidInput, "tet " + std::to_string(t) + " has material " + std::to_string(m) +
                                                     " of " + std::to_string(scene.materials.size()));
    }
    return {};
}

} // namespace

std::string_view toString(LabelKind kind) {
    switch (kind) {
    case LabelKind::Contact:
        return "contact";
    case LabelKind::Ostium:
        return "ostium";
    case LabelKind::CervicalCanal:
        return "cervical-canal";
    case LabelKind::PathologyBase:
        return "pathology-base";
    case LabelKind::Other:
        break;
    }
    return "other";
}

std::string_view toString(LabelElement element) {
    return element == LabelElement::Tet ? "tet" : "surface-face";
}

bool fromString(std::string_view key, LabelKind& out) {
    for (const LabelKind k :
         {LabelKind::Contact, LabelKind::Ostium, LabelKind::CervicalCanal, LabelKind::PathologyBase, LabelKind::Other})
        if (toString(k) == key) {
            out = k;
            return true;
        }
    return false;
}

bool fromString(std::string_view key, LabelElement& out) {
    for (const LabelElement e : {LabelElement::SurfaceFace, LabelElement::Tet})
        if (toString(e) == key) {
            out = e;
            return true;
        }
    return false;
}

Result<std::vector<SceneMaterial>> assignMaterials(TetMesh& tets, const std::vector<SceneRegion>& regions,
                                                   const SceneParams& params, const MaterialOptions& options) {
    if (!(options.heterogeneity >= 0.0 && options.heterogeneity <= kMaxHeterogeneity))
        return fail(ErrorCode::InvalidInput,
                    "heterogeneity " + detail::formatNumber(options.heterogeneity) + " is outside 0..0.5");
    std::vector<SceneMaterial> materials;
    std::map<std::int32_t, std::int32_t> materialOfRegion;
    for (const auto& region : regions) {
        if (materialOfRegion.count(region.id))
            return fail(ErrorCode::InvalidInput, "region id " + std::to_string(region.id) + " is listed twice");
        SceneMaterial m;
        m.id = static_cast<std::int32_t>(materials.size());
        m.regionId = region.id;
        m.name = region.name;
        m.tissue = region.tissue;
        m.material = effectiveMaterial(params, region.tissue);
        m.youngsModulusRangeKpa = youngsModulusRangeKpa(region.tissue);
        m.heterogeneity =
            params.materials[static_cast<std::size_t>(region.tissue)].heterogeneity.value_or(options.heterogeneity);
        if (!(m.heterogeneity >= 0.0 && m.heterogeneity <= kMaxHeterogeneity))
            return fail(ErrorCode::InvalidInput, "/scene/materials/" + std::string(toString(region.tissue)) +
                                                     "/heterogeneity: " + detail::formatNumber(m.heterogeneity) +
                                                     " is outside 0..0.5");
        HS_TRY(checkMaterialRange(region, m.material));
        materialOfRegion[region.id] = m.id;
        materials.push_back(std::move(m));
    }
    std::vector<std::int32_t> materialIds(tets.tetCount());
    for (std::size_t t = 0; t < tets.tetCount(); ++t) {
        const auto it = materialOfRegion.find(tets.regionOf(t));
        if (it == materialOfRegion.end())
            return fail(ErrorCode::InvalidInput, "tet " + std::to_string(t) + " lies in region " +
                                                     std::to_string(tets.regionOf(t)) + ", which has no material");
        materialIds[t] = it->second;
    }
    bool heterogeneous = false;
    for (const auto& m : materials)
        heterogeneous = heterogeneous || m.heterogeneity > 0.0;
    if (heterogeneous) {
        const Rng base(options.seed);
        std::vector<std::int32_t> modulusPa(tets.tetCount());
        for (std::size_t t = 0; t < tets.tetCount(); ++t)
            modulusPa[t] = heterogeneousModulusPa(materials[static_cast<std::size_t>(materialIds[t])], base, t);
        tets.tetLabels[kYoungsModulusLabel] = std::move(modulusPa);
    } else {
        tets.tetLabels.erase(kYoungsModulusLabel);
    }
    tets.tetLabels[kMaterialLabel] = std::move(materialIds);
    return materials;
}

std::map<std::string, std::string> defaultToolVersions() {
    // HS_TINYGLTF_VERSION and HS_MINIZIP_VERSION come from the build (pipeline/scene/CMakeLists.txt): neither library
    // has a version macro. hs::io reports VTK, which writes tets.vtu and surface.vtp.
    LibraryVersions versions{
        {"hysteroscene", HS_VERSION},
        {"compiler", compilerVersion()},
        {"minizip", HS_MINIZIP_VERSION},
        {"nlohmann-json", std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." +
                              std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." +
                              std::to_string(NLOHMANN_JSON_VERSION_PATCH)},
        {"tinygltf", HS_TINYGLTF_VERSION},
        {"zlib", ZLIB_VERSION},
    };
    versions.merge(io::libraryVersions());
    return versions;
}

Status checkScene(const Scene& scene) {
    HS_TRY(validate(scene.tets));
    if (scene.tets.tetCount() == 0)
        return fail(ErrorCode::InvalidInput, "the tet mesh has no tetrahedra");
    HS_TRY(checkSurface(scene.surface));
    HS_TRY(checkEmbedding(scene.surface.embedding, scene.surface.mesh, scene.tets, "the visual surface"));
    HS_TRY(checkMaterials(scene));
    HS_TRY(checkSimulation(scene));
    HS_TRY(checkLabels(scene));
    const auto issues = checkCase(scene.caseSpec);
    if (!issues.empty())
        return fail(ErrorCode::InvalidInput, "the scene's case is invalid: " + issues.front().text());
    for (const auto& [tool, version] : scene.toolVersions)
        if (tool.empty() || version.empty() || tool.size() > 64 || version.size() > 64)
            return fail(ErrorCode::InvalidInput, "tool versions need a name and a version of 1-64 characters");
    return {};
}

} // namespace hs::scene
