// Scene assembly: scene region ids and tets, the named labels, tool versions and quality, the tissue stage and the
// whole scene from the stage results.
#include "hs/generate/Assembly.h"

#include "AssemblySteps.h"
#include "hs/anatomy/LibraryVersions.h"
#include "hs/clinical/Tissue.h"
#include "hs/generate/Seeds.h"
#include "hs/meshing/BaselineMeshers.h"
#include "hs/meshing/LibraryVersions.h"
#include "hs/scene/MeshBars.h"
#include "hs/texture/LibraryVersions.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <utility>

namespace hs::generate {
namespace {

using detail::kTissueCervicalCanal;
using detail::kTissueOstium;

clinical::Tissue tissueOf(clinical::PathologyKind kind) {
    return kind == clinical::PathologyKind::Myoma ? clinical::Tissue::Myoma : clinical::Tissue::Polyp;
}

} // namespace

std::int32_t pathologyRegion(std::size_t pathologyIndex) {
    return static_cast<std::int32_t>(pathologyIndex) + kCervixRegion + 1;
}

std::vector<scene::SceneRegion> sceneRegions(const scene::CaseSpec& spec, const TetMesh& tets) {
    std::array<bool, 3> present{};
    for (std::size_t t = 0; t < tets.tets.size(); ++t)
        if (const auto r = tets.regionOf(t); isWallRegion(r))
            present[static_cast<std::size_t>(r - kMyometriumRegion)] = true;
    std::vector<scene::SceneRegion> regions;
    const std::array<clinical::Tissue, 3> wall{clinical::Tissue::Myometrium, clinical::Tissue::Endometrium,
                                               clinical::Tissue::Cervix};
    for (std::size_t k = 0; k < wall.size(); ++k)
        if (present[k])
            regions.push_back({kMyometriumRegion + static_cast<std::int32_t>(k),
                               std::string(clinical::toString(wall[k])), wall[k], ""});
    for (std::size_t i = 0; i < spec.pathologies.size(); ++i) {
        const auto& p = spec.pathologies[i];
        regions.push_back({pathologyRegion(i), p.id, tissueOf(p.kind), p.id});
    }
    return regions;
}

TetMesh sceneTets(const TetMesh& meshed, const std::vector<WallLayer>& layers) {
    TetMesh tets = meshed;
    tets.regions.resize(tets.tets.size(), kBodyWallRegion);
    for (std::size_t t = 0; t < tets.tets.size(); ++t) {
        const WallLayer layer = layers.empty() ? WallLayer::Myometrium : layers[t];
        auto& r = tets.regions[t];
        if (layer == WallLayer::Endometrium)
            r = kEndometriumRegion; // the wall's lining, or the cover of a pathology in the cavity
        else if (r == kBodyWallRegion)
            r = layer == WallLayer::Cervix ? kCervixRegion : kMyometriumRegion;
        else
            r = pathologyRegion(static_cast<std::size_t>(r - 1));
    }
    return tets;
}

std::vector<std::int32_t> facesWith(const SurfaceMesh& mesh, const std::string& label, std::int32_t value) {
    std::vector<std::int32_t> faces;
    const auto it = mesh.faceLabels.find(label);
    if (it == mesh.faceLabels.end())
        return faces;
    for (std::size_t f = 0; f < it->second.size(); ++f)
        if (it->second[f] == value)
            faces.push_back(static_cast<std::int32_t>(f));
    return faces;
}

namespace {

/// Tets of region `region` that share a face with a tet whose region satisfies `touches`, ascending.
template <class Pred>
std::vector<std::int32_t> tetsTouchingWhere(const TetMesh& mesh,
                                            const std::vector<std::array<std::int32_t, 4>>& adjacent,
                                            std::int32_t region, Pred touches) {
    std::vector<std::int32_t> out;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
        if (mesh.regionOf(t) != region)
            continue;
        for (const auto u : adjacent[t])
            if (u >= 0 && touches(mesh.regionOf(static_cast<std::size_t>(u)))) {
                out.push_back(static_cast<std::int32_t>(t));
                break;
            }
    }
    return out;
}

} // namespace

std::vector<std::int32_t> tetsTouching(const TetMesh& mesh, std::int32_t region, std::int32_t other) {
    return tetsTouchingWhere(mesh, tetNeighbours(mesh), region, [other](std::int32_t r) { return r == other; });
}

std::vector<scene::SceneLabel> sceneLabels(const scene::CaseSpec& spec, const TetMesh& tets,
                                           const SurfaceMesh& visual) {
    std::vector<scene::SceneLabel> labels;
    for (std::size_t i = 0; i < spec.pathologies.size(); ++i) {
        auto faces = facesWith(visual, merge::kPathologyLabel, static_cast<std::int32_t>(i + 1));
        if (!faces.empty())
            labels.push_back({"contact:" + spec.pathologies[i].id, scene::LabelKind::Contact,
                              scene::LabelElement::SurfaceFace, spec.pathologies[i].id, std::move(faces)});
    }
    const auto adjacent = tetNeighbours(tets);
    for (std::size_t i = 0; i < spec.pathologies.size(); ++i) {
        auto base = tetsTouchingWhere(tets, adjacent, pathologyRegion(i), isWallRegion);
        if (!base.empty())
            labels.push_back({"base:" + spec.pathologies[i].id, scene::LabelKind::PathologyBase,
                              scene::LabelElement::Tet, spec.pathologies[i].id, std::move(base)});
    }
    if (auto ostia = facesWith(visual, clinical::kSurfaceTissueLabel, kTissueOstium); !ostia.empty())
        labels.push_back({"ostia", scene::LabelKind::Ostium, scene::LabelElement::SurfaceFace, "", std::move(ostia)});
    if (auto canal = facesWith(visual, clinical::kSurfaceTissueLabel, kTissueCervicalCanal); !canal.empty())
        labels.push_back({"cervical-canal", scene::LabelKind::CervicalCanal, scene::LabelElement::SurfaceFace, "",
                          std::move(canal)});
    return labels;
}

scene::SceneLabel supportLabel(const TetMesh& tets, double cervixLengthMm) {
    scene::SceneLabel label;
    label.name = scene::kSupportLabel;
    label.kind = scene::LabelKind::Other;
    label.element = scene::LabelElement::Tet;
    const double reach2 = cervixLengthMm * cervixLengthMm;
    for (std::size_t t = 0; t < tets.tetCount(); ++t) {
        const auto& tet = tets.tets[t];
        if (std::all_of(tet.begin(), tet.end(), [&](std::int32_t v) {
                const Vec3& p = tets.points[static_cast<std::size_t>(v)];
                return p.x * p.x + p.y * p.y + p.z * p.z <= reach2;
            }))
            label.indices.push_back(static_cast<std::int32_t>(t));
    }
    return label;
}

LibraryVersions toolVersionsFor(const scene::CaseSpec& spec) {
    LibraryVersions versions = scene::defaultToolVersions();
    versions.merge(anatomy::libraryVersions());
    versions.merge(meshing::libraryVersions());
    versions.merge(meshing::methodLibraryVersions(meshMethodFor(spec)));
    versions.merge(texture::libraryVersions());
    return versions;
}

scene::MeshQuality qualityOf(const meshing::QualityReport& q) {
    scene::MeshQuality m;
    m.vertexCount = q.vertexCount;
    m.tetCount = q.tetCount;
    m.meanRadiusRatio = q.meanRadiusRatio;
    m.minRadiusRatio = q.minRadiusRatio;
    m.minDihedralDeg = q.minDihedralDeg;
    m.maxDihedralDeg = q.maxDihedralDeg;
    m.meanEdgeRatio = q.meanEdgeRatio;
    m.maxEdgeRatio = q.maxEdgeRatio;
    m.radiusRatioHistogram.assign(q.radiusRatioHistogram.begin(), q.radiusRatioHistogram.end());
    m.minDihedralHistogram.assign(q.minDihedralHistogram.begin(), q.minDihedralHistogram.end());
    m.sliverCount = q.sliverCount;
    m.invertedCount = q.invertedCount;
    m.degenerateCount = q.degenerateCount;
    m.hasReference = q.hasReference;
    m.hausdorffDistanceMm = q.hausdorffDistance;
    m.hausdorffRelative = q.hausdorffRelative;
    m.volumeError = q.volumeError;
    m.boundaryNonManifoldEdges = q.boundaryNonManifoldEdges;
    m.boundaryNonManifoldVertices = q.boundaryNonManifoldVertices;
    return m;
}

Result<TissueStage> tissueStage(const scene::CaseSpec& spec, const merge::MergeResult& merged,
                                const meshing::MeshResult& meshed, const TissueLayerParams& params) {
    const double reach = 3.0 * std::max(meshed.targetEdgeLength, 0.5);
    auto boundary = labelledBoundary(meshed.mesh, merged.body.surfaces.front().surface, spec, reach);
    if (!boundary)
        return boundary.failure();
    TissueStage out;
    out.layers = tissueLayers(meshed.mesh, kBodyWallRegion, *boundary, params);
    out.tets = sceneTets(meshed.mesh, out.layers.layer);
    out.regions = sceneRegions(spec, out.tets);
    // The boundary's faces do not depend on the region ids (no interfaces): take the scene's ids from the same
    // extraction of the relabelled mesh.
    out.boundary = std::move(boundary).value();
    out.boundary.faceLabels["region"] = extractBoundary(out.tets).faceLabels.at("region");
    return out;
}

Result<scene::Scene> assembleScene(const scene::CaseSpec& spec, const OrganInstance& organ,
                                   const pathology::PathologyResult& grown, const merge::MergeResult& merged,
                                   const meshing::MeshResult& meshed, const TissueStage& tissue,
                                   const Appearance& appearance) {
    scene::Scene s;
    s.tets = tissue.tets;
    s.regions = tissue.regions;
    s.surface = appearance.surface;

    scene::MaterialOptions materialOptions;
    materialOptions.seed = streamSeed(spec.seed, Stream::Material);
    auto materials = scene::assignMaterials(s.tets, s.regions, spec.scene, materialOptions);
    if (!materials)
        return materials.failure();
    s.materials = std::move(materials).value();

    s.labels = sceneLabels(spec, s.tets, s.surface.mesh);
    s.labels.push_back(supportLabel(s.tets, organ.dimensions.cervixLengthMm));
    // The displaced organ is the template instance nearest to the final body (the same frame, its rings moved where
    // the pathologies pushed them); without pathologies it is the organ itself.
    const SurfaceMesh& frame = grown.organ.points.size() == organ.mesh.points.size() ? grown.organ : organ.mesh;
    std::vector<Vec3> roots;
    for (const auto& p : grown.pathologies)
        roots.push_back(p.anchor);
    if (roots.size() != spec.pathologies.size())
        roots.clear();
    auto descriptors = clinicalDescriptors(spec, frame, organ.layout, tissue.tets, tissue.boundary, roots);
    s.clinical = std::move(descriptors.clinical);
    // The fitted hydrometra of the final body (its measured uterine volume, pathologies included); the organ's own
    // only when the body could not be measured, and then said (clinicalDescriptors warns why).
    double uterineVolumeMl = s.clinical.organ.uterineVolumeMl;
    std::string hydrometraWarning;
    if (!(uterineVolumeMl > 0.0)) {
        uterineVolumeMl = organ.dimensions.ellipsoidVolumeMl;
        char text[160];
        std::snprintf(text, sizeof text,
                      "hydrometra: from the organ before its pathologies (%.1f mL): the final body's volume was not "
                      "measured",
                      uterineVolumeMl);
        hydrometraWarning = text;
    }
    auto hydrometra = scene::computeHydrometra(uterineVolumeMl, spec.scene.hydrometraPressureKpa);
    if (!hydrometra)
        return hydrometra.failure();
    s.hydrometra = *hydrometra;
    s.quality = qualityOf(meshed.quality);
    s.caseSpec = spec;
    s.toolVersions = toolVersionsFor(spec);
    for (const auto& w : appearance.warnings)
        s.warnings.push_back("texture: " + w);
    for (const auto& w : grown.warnings)
        s.warnings.push_back("pathology: " + w);
    for (const auto& w : merged.warnings)
        s.warnings.push_back("merge: " + w);
    for (const auto& w : meshed.warnings)
        s.warnings.push_back("meshing: " + w);
    for (const auto& w : descriptors.warnings)
        s.warnings.push_back("descriptors: " + w);
    for (const auto& w : descriptors.measurementWarnings)
        s.warnings.push_back("measurement: " + w);
    for (const auto& w : descriptors.seatingWarnings)
        s.warnings.push_back("seating: " + w);
    if (!hydrometraWarning.empty())
        s.warnings.push_back(hydrometraWarning);
    for (const auto& w : scene::missedMeshBars(s.quality))
        s.warnings.push_back(w);
    HS_TRY(scene::checkScene(s));
    return s;
}

} // namespace hs::generate
