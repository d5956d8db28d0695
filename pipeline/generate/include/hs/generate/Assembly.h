#pragma once
/// Scene assembly: the stage results of one case turned into the Scene a simulator loads (Sierra et al. 2004,
/// sec. 5): region ids, the visual surface's labels, materials, named labels, clinical descriptors, hydrometra,
/// quality and warnings. Each piece is its own function so it can be tested on small inputs.

#include "hs/core/LibraryVersions.h"
#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/TetMesh.h"
#include "hs/generate/CaseStages.h"
#include "hs/generate/TissueLayers.h"
#include "hs/merge/Merge.h"
#include "hs/meshing/MeshTypes.h"
#include "hs/pathology/Pathology.h"
#include "hs/scene/CaseSpec.h"
#include "hs/scene/Scene.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hs::generate {

/// Scene region ids (positive: they are also Gmsh physical tags). The merged body's wall (body region 0) is split
/// into its tissue layers, regions 1-3; the body's pathology i (body region i + 1) becomes region 4 + i.
inline constexpr std::int32_t kMyometriumRegion = 1;
inline constexpr std::int32_t kEndometriumRegion = 2;
inline constexpr std::int32_t kCervixRegion = 3;
inline constexpr std::int32_t kBodyWallRegion = 0; ///< the wall in the merged body and its mesh
std::int32_t pathologyRegion(std::size_t pathologyIndex);
/// Whether scene region `id` is one of the wall's tissues (myometrium, endometrium, cervix).
constexpr bool isWallRegion(std::int32_t id) {
    return id >= kMyometriumRegion && id <= kCervixRegion;
}

/// The regions of a case's scene, ascending id: the wall's tissues that `tets` has, then one per pathology named by
/// its id.
std::vector<scene::SceneRegion> sceneRegions(const scene::CaseSpec& spec, const TetMesh& tets);

/// The meshed body (body region ids) with scene region ids: wall tets by `layers` (myometrium when `layers` is
/// empty), pathology tets shifted.
TetMesh sceneTets(const TetMesh& meshed, const std::vector<WallLayer>& layers = {});

/// The texture stage's result: the visual surface (the tet mesh's boundary refined for close-ups, split along chart
/// seams, with UVs, normals, its embedding in the tets and the baked maps) and what the bake reported.
struct Appearance {
    scene::VisualSurface surface;
    texture::BakeStats stats;
    std::vector<std::string> warnings;
};

/// Edge length the visual surface aims at where the hysteroscope sees it, mm. The scope looks at the wall from a few
/// millimetres (a lesion inspected closely) to the cavity's length (26-44 mm, docs/references.md [Chen2020],
/// [Goldstuck2012]); at 5 mm a 0.75 mm facet spans under 9 degrees of a 90-degree view, and smooth normals hide its
/// shading. See docs/scene-format.md, "The visual surface".
inline constexpr double kVisualEdgeLengthMm = 0.75;
/// At most this many Loop levels (each quadruples the triangles; 3 levels of a 30 000-vertex scene's boundary is
/// about half a million triangles).
inline constexpr int kMaxVisualSurfaceLevels = 3;
/// Faces the hysteroscope sees: every boundary face but the serosa (cavity, canal, ectocervix, ostia, pathologies
/// in the cavity). 1 where seen, 0 elsewhere.
std::vector<std::int32_t> scopeSeenFaces(const SurfaceMesh& boundary);
/// Loop levels that bring the mean edge of the seen faces down to kVisualEdgeLengthMm (0..kMaxVisualSurfaceLevels).
int visualSurfaceLevels(const SurfaceMesh& boundary);
/// How far fairing may move a point of the visual surface away from the tets' boundary, mm: well under the lining's
/// thinnest 1 mm (scene::kEndometrialThicknessMm), so the surface stays on its tissue.
inline constexpr double kMaxVisualFairingMm = 0.75;
/// A tubal ostium as the visual surface shows it: a funnel into the cornu's wall, 2 mm across at its mouth, where the
/// interstitial part of the tube (about 1 cm long in the wall, lumen about 1 mm) opens into the cavity (El-Mowafi &
/// Diamond, "Fallopian tube", and Tubal microsurgery versus assisted reproduction, in Infertility and Assisted
/// Reproduction, Cambridge University Press 2008). The tets keep the wall closed: the tube is not modelled.
inline constexpr double kOstiumRadiusMm = 1.5;
inline constexpr double kOstiumDepthMm = 2.0; ///< the funnel's depth, mm: as deep as the light shows the opening
/// One tubal ostium of a labelled boundary: the area-weighted centre and outward (into the cavity) unit normal of
/// one connected set of its ostium faces; in order of their first face.
struct OstiumOpening {
    Vec3 centreMm;
    Vec3 normal;
};
std::vector<OstiumOpening> ostiumOpenings(const SurfaceMesh& boundary);
/// The albedo's dark spots over the openings (the funnel's inside, which the scope's light does not reach).
std::vector<texture::DarkSpot> ostiumDarkSpots(const std::vector<OstiumOpening>& ostia);
/// The cervical canal's frame for the bake's folds and the internal os's ring: the ora of the canal's faces
/// (scene::findScopeLandmarks), the organ's anterior (+y, docs/anatomy.md) and the canal's largest distance from its
/// axis. None when the boundary has no canal or no ostium faces to tell the ora apart.
std::optional<texture::CanalFrame> canalFrame(const SurfaceMesh& boundary);

/// The texture stage's close-up refinement of `boundary`: visualSurfaceLevels, the seen faces faired by Taubin
/// smoothing within kMaxVisualFairingMm; a funnel (kOstiumRadiusMm, kOstiumDepthMm) at each of `ostia`.
texture::CloseUpParams closeUpParamsFor(const SurfaceMesh& boundary, const std::vector<OstiumOpening>& ostia = {});

/// The boundary of `tets` with the body outline's "tissue" and "pathology" face labels carried over (within
/// `reachMm`), the tubal ostia kept although they are smaller than a triangle, and the kAppearanceLabel label
/// (0 wall, 1 over a myoma, 2 over a polyp, from the case's pathology kinds).
[[nodiscard]] Result<SurfaceMesh> labelledBoundary(const TetMesh& tets, const SurfaceMesh& outline,
                                                   const scene::CaseSpec& spec, double reachMm);

/// The faces of `mesh` whose face label `label` equals `value`, ascending.
std::vector<std::int32_t> facesWith(const SurfaceMesh& mesh, const std::string& label, std::int32_t value);

/// Tets of region `region` that share a face with a tet of region `other`, ascending: where a pathology sits on
/// the myometrium (a polyp's base, a myoma's intramural interface).
std::vector<std::int32_t> tetsTouching(const TetMesh& mesh, std::int32_t region, std::int32_t other);

/// The scene's named labels, in this order: contact:<id> (visual faces over pathology i), base:<id> (pathology
/// tets sharing a face with a wall tissue), ostia, cervical-canal. Empty sets give no label.
std::vector<scene::SceneLabel> sceneLabels(const scene::CaseSpec& spec, const TetMesh& tets, const SurfaceMesh& visual);

/// Clinical descriptors measured on the final scene, and what differs from what the case asked.
struct MeasuredDescriptors {
    scene::ClinicalDescriptors clinical;
    std::vector<std::string> warnings; ///< "myoma-1: asked FIGO 2, the final body measures FIGO 3", ...
    /// How the measurement itself went where it fell back ("organ: 0 of 1873 serosa and 213 of 1441 cavity vertices of
    /// the template found no body surface ..."): not a difference from the request.
    std::vector<std::string> measurementWarnings;
    /// Polyps that do not stand in the cavity: more of their surface against tissue on the final tets than
    /// scene::kPedunculatedPolypMaxContact or kSessilePolypMaxContact allow ("polyp-1: 52 % of its surface ...").
    std::vector<std::string> seatingWarnings;
};

/// How far beyond the endometrium laid over a pathology its surface's outward normal may run and still reach the
/// cavity (mm): the layer is resolved to about an edge of the tets (2 mm at the default density) plus the merge's
/// cover (0.8 mm).
inline constexpr double kDrapeMarginMm = 3.0;

/// Tolerance of a measured size or organ dimension against the case's request before it is reported, as a
/// fraction: the pathology stage's bar (docs/pathology.md, "Bars").
inline constexpr double kDescriptorTolerance = 0.10;

/// The descriptors of the final scene (docs/scene-format.md, "Where the clinical descriptors are measured"): the
/// organ's dimensions on `boundary`'s serosa and cavity by anatomy::measureBody (`organ`: the template instance nearest
/// to the body, the pathology stage's displaced organ, whose vertices are moved onto it; `layout`: the shape model's
/// own template layout, OrganInstance::layout), each pathology's size,
/// volume, FIGO type and Lasmar score from its region of `tets` (scene region ids) against `boundary` (tissue and
/// pathology face labels, labelledBoundary), by the pathology stage's rules (pathology::describeContact). Warnings name
/// every value that differs from `spec` (FIGO, or a size or dimension beyond kDescriptorTolerance). `roots`: where
/// each pathology grows from (pathology::GrownPathology::anchor; WallContact::root), one per pathology, or empty.
MeasuredDescriptors clinicalDescriptors(const scene::CaseSpec& spec, const SurfaceMesh& organ,
                                        const anatomy::TemplateLayout& layout, const TetMesh& tets,
                                        const SurfaceMesh& boundary, const std::vector<Vec3>& roots = {});

/// Warnings for every measured value of `measured` that differs from what `spec` asked ("descriptors: ..." is added
/// by the scene's assembly).
std::vector<std::string> descriptorWarnings(const scene::CaseSpec& spec, const scene::ClinicalDescriptors& measured);

/// The measured descriptors beside what the case asked, one line per value (a table for reports and tests).
std::string descriptorTable(const scene::CaseSpec& spec, const scene::ClinicalDescriptors& measured);

/// Where a real uterus is held, as the tet label scene::kSupportLabel: the cervix. The vagina grips the portio (in
/// hysteroscopy a tenaculum holds it as well) and the cardinal and uterosacral ligaments insert on the supravaginal
/// cervix up to the isthmus, the uterus's level I support (DeLancey, Am J Obstet Gynecol 1992;166:1717-28); the round
/// and broad ligaments carry little load and are left free, as is the corpus the scope pushes against. Marked: the
/// tets whose four vertices lie within `cervixLengthMm` (external to internal os) of the external os, which is the
/// organ frame's origin (anatomy/UterusGenerator.h).
scene::SceneLabel supportLabel(const TetMesh& tets, double cervixLengthMm);

/// Versions of every library that shapes the scene of `spec` (scene.json's and manifest.json's "toolVersions"): the
/// scene module's (scene::defaultToolVersions), each stage's (anatomy, meshing, texture) and the meshing method's.
/// Taken from the libraries' version macros at build time, so one build writes the same bytes every time.
LibraryVersions toolVersionsFor(const scene::CaseSpec& spec);

/// The meshing stage's quality report as scene data.
scene::MeshQuality qualityOf(const meshing::QualityReport& q);

/// The tissue stage's result: the mesh with scene region ids, its labelled boundary (the texture stage's input) and
/// the layers it measured.
struct TissueStage {
    TetMesh tets;         ///< scene region ids
    SurfaceMesh boundary; ///< labelledBoundary(tets, ...)
    TissueLayers layers;
    std::vector<scene::SceneRegion> regions;
};

/// Splits the mesh's wall into myometrium, endometrium (`params`' lining) and cervix and labels its boundary.
[[nodiscard]] Result<TissueStage> tissueStage(const scene::CaseSpec& spec, const merge::MergeResult& merged,
                                              const meshing::MeshResult& meshed, const TissueLayerParams& params);

/// The whole scene of a case from its stage results. InvalidInput when a material override is out of range or the
/// result breaks a rule of scene::checkScene (naming it).
[[nodiscard]] Result<scene::Scene> assembleScene(const scene::CaseSpec& spec, const OrganInstance& organ,
                                                 const pathology::PathologyResult& grown,
                                                 const merge::MergeResult& merged, const meshing::MeshResult& meshed,
                                                 const TissueStage& tissue, const Appearance& appearance);

} // namespace hs::generate
