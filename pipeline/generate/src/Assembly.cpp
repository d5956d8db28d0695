#include "hs/generate/Assembly.h"

#include "hs/anatomy/LibraryVersions.h"
#include "hs/anatomy/UterusGenerator.h"
#include "hs/clinical/Tissue.h"
#include "hs/core/LabelTransfer.h"
#include "hs/core/Subdivision.h"
#include "hs/core/Units.h"
#include "hs/generate/Seeds.h"
#include "hs/meshing/BaselineMeshers.h"
#include "hs/meshing/LibraryVersions.h"
#include "hs/texture/LibraryVersions.h"

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <variant>

namespace hs::generate {
namespace {

constexpr auto kTissueCervicalCanal = clinical::labelValue(clinical::SurfaceTissue::CervicalCanal);
constexpr auto kTissueOstium = clinical::labelValue(clinical::SurfaceTissue::TubalOstium);

/// The ostia are smaller than the mesh's triangles, so no boundary face may be nearest to an ostium face: carry
/// them the other way too, marking the boundary face nearest to each ostium face of the organ.
Status keepSmallTissueFeatures(const SurfaceMesh& outline, SurfaceMesh& boundary, double reach) {
    SurfaceMesh probe = outline;
    std::vector<std::int32_t> index(boundary.triangles.size());
    for (std::size_t f = 0; f < index.size(); ++f)
        index[f] = static_cast<std::int32_t>(f);
    boundary.faceLabels["faceIndex"] = std::move(index);
    const Status status = transferFaceLabels(boundary, probe, {"faceIndex"}, reach, -1);
    boundary.faceLabels.erase("faceIndex");
    HS_TRY(status);
    const auto& tissue = outline.faceLabels.at(clinical::kSurfaceTissueLabel);
    const auto& nearest = probe.faceLabels.at("faceIndex");
    auto& boundaryTissue = boundary.faceLabels.at(clinical::kSurfaceTissueLabel);
    for (std::size_t f = 0; f < tissue.size(); ++f)
        if (tissue[f] == kTissueOstium && nearest[f] >= 0)
            boundaryTissue[static_cast<std::size_t>(nearest[f])] = kTissueOstium;
    return {};
}

std::string locationKey(const scene::PathologySpec& p) {
    if (const auto* c = std::get_if<clinical::ClinicalPlacement>(&p.placement))
        return std::string(clinical::toString(c->location));
    return "";
}

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

std::vector<std::int32_t> scopeSeenFaces(const SurfaceMesh& boundary) {
    std::vector<std::int32_t> seen(boundary.triangles.size(), 1);
    const auto tissue = boundary.faceLabels.find(clinical::kSurfaceTissueLabel);
    if (tissue == boundary.faceLabels.end())
        return seen;
    for (std::size_t f = 0; f < seen.size(); ++f)
        seen[f] = tissue->second[f] == clinical::labelValue(clinical::SurfaceTissue::Serosa) ? 0 : 1;
    return seen;
}

int visualSurfaceLevels(const SurfaceMesh& boundary) {
    const SurfaceShape shape = measureSurfaceShape(boundary, scopeSeenFaces(boundary));
    int levels = 0;
    for (double edge = shape.meanEdgeMm; edge > kVisualEdgeLengthMm && levels < kMaxVisualSurfaceLevels; edge /= 2.0)
        ++levels;
    return levels;
}

std::vector<OstiumOpening> ostiumOpenings(const SurfaceMesh& boundary) {
    std::vector<OstiumOpening> out;
    const auto tissue = boundary.faceLabels.find(clinical::kSurfaceTissueLabel);
    if (tissue == boundary.faceLabels.end())
        return out;
    // Union-find over the ostium faces, joined through shared points.
    const std::size_t faces = boundary.triangles.size();
    std::vector<std::int32_t> parent(faces, -1), ownerOfPoint(boundary.points.size(), -1);
    const auto find = [&](std::int32_t f) {
        while (parent[static_cast<std::size_t>(f)] != f)
            f = parent[static_cast<std::size_t>(f)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(f)])];
        return f;
    };
    for (std::size_t f = 0; f < faces; ++f) {
        if (tissue->second[f] != kTissueOstium)
            continue;
        parent[f] = static_cast<std::int32_t>(f);
        for (std::int32_t v : boundary.triangles[f]) {
            std::int32_t& owner = ownerOfPoint[static_cast<std::size_t>(v)];
            if (owner < 0) {
                owner = static_cast<std::int32_t>(f);
                continue;
            }
            const std::int32_t a = find(owner), b = find(static_cast<std::int32_t>(f));
            if (a != b)
                parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
        }
    }
    std::map<std::int32_t, std::pair<Vec3, Vec3>> sums; // root -> (area-weighted centre, area-weighted normal)
    std::map<std::int32_t, double> areas;
    for (std::size_t f = 0; f < faces; ++f) {
        if (parent[f] < 0)
            continue;
        const Triangle& t = boundary.triangles[f];
        const Vec3& a = boundary.points[static_cast<std::size_t>(t[0])];
        const Vec3& b = boundary.points[static_cast<std::size_t>(t[1])];
        const Vec3& c = boundary.points[static_cast<std::size_t>(t[2])];
        const Vec3 n = cross(b - a, c - a); // |n| = 2 area
        const double area = 0.5 * norm(n);
        auto& sum = sums[find(static_cast<std::int32_t>(f))];
        sum.first += (a + b + c) * (area / 3.0);
        sum.second += n;
        areas[find(static_cast<std::int32_t>(f))] += area;
    }
    for (const auto& [root, sum] : sums) {
        const double area = areas.at(root);
        const double len = norm(sum.second);
        if (area <= 0.0 || len <= 0.0)
            continue;
        out.push_back({sum.first / area, sum.second / len});
    }
    return out;
}

std::vector<texture::DarkSpot> ostiumDarkSpots(const std::vector<OstiumOpening>& ostia) {
    std::vector<texture::DarkSpot> spots;
    for (const auto& o : ostia)
        spots.push_back({o.centreMm, 1.5 * kOstiumRadiusMm, 0.85});
    return spots;
}

texture::CloseUpParams closeUpParamsFor(const SurfaceMesh& boundary, const std::vector<OstiumOpening>& ostia) {
    texture::CloseUpParams p;
    for (const auto& o : ostia)
        p.pits.push_back({o.centreMm, o.normal, kOstiumRadiusMm, kOstiumDepthMm});
    p.levels = visualSurfaceLevels(boundary);
    p.seen = scopeSeenFaces(boundary);
    p.smoothing.iterations = 10;
    p.smoothing.maxDisplacement = kMaxVisualFairingMm;
    return p;
}

Result<SurfaceMesh> labelledBoundary(const TetMesh& tets, const SurfaceMesh& outline, const scene::CaseSpec& spec,
                                     double reachMm) {
    SurfaceMesh boundary = extractBoundary(tets);
    HS_TRY(transferFaceLabels(outline, boundary, {clinical::kSurfaceTissueLabel, merge::kPathologyLabel}, reachMm));
    HS_TRY(keepSmallTissueFeatures(outline, boundary, reachMm));
    std::vector<std::int32_t> appearance(boundary.triangles.size(), 0);
    const auto& over = boundary.faceLabels.at(merge::kPathologyLabel);
    for (std::size_t f = 0; f < appearance.size(); ++f) {
        const auto p = over[f] - 1; // 1 + index of the pathology a face is draped over
        if (p >= 0 && static_cast<std::size_t>(p) < spec.pathologies.size())
            appearance[f] =
                spec.pathologies[static_cast<std::size_t>(p)].kind == clinical::PathologyKind::Myoma ? 1 : 2;
    }
    boundary.faceLabels[kAppearanceLabel] = std::move(appearance);
    return boundary;
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

scene::ClinicalDescriptors clinicalDescriptors(const scene::CaseSpec& spec, const anatomy::UterusDimensions& organ,
                                               const pathology::PathologyResult& grown, const TetMesh& bodyTets) {
    scene::ClinicalDescriptors c;
    c.organ = {organ.lengthMm,       organ.widthMm,       organ.apDepthMm,
               organ.cavityLengthMm, organ.cavityWidthMm, organ.ellipsoidVolumeMl};
    const auto volumes = regionVolumes(bodyTets);
    for (std::size_t i = 0; i < grown.pathologies.size() && i < spec.pathologies.size(); ++i) {
        const auto& g = grown.pathologies[i];
        scene::PathologyDescriptor pd;
        pd.id = g.id;
        pd.kind = spec.pathologies[i].kind;
        pd.regionId = pathologyRegion(i);
        pd.sizeMm = g.descriptors.sizeMm;
        const auto v = volumes.find(static_cast<std::int32_t>(i + 1)); // body region of pathology i
        pd.volumeMl = v == volumes.end() ? 0.0 : units::mlFromMm3(v->second);
        if (g.kind == clinical::PathologyKind::Myoma) {
            pd.figo = g.descriptors.figo;
            pd.lasmar = g.descriptors.lasmar;
        }
        pd.location = locationKey(spec.pathologies[i]);
        c.pathologies.push_back(pd);
    }
    return c;
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
    s.clinical = clinicalDescriptors(spec, organ.dimensions, grown, meshed.mesh);
    auto hydrometra = scene::computeHydrometra(organ.dimensions.ellipsoidVolumeMl, spec.scene.hydrometraPressureKpa);
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
    HS_TRY(scene::checkScene(s));
    return s;
}

} // namespace hs::generate
