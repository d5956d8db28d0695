#pragma once
/// Scene assembly: the stage results of one case turned into the Scene a simulator loads (Sierra et al. 2004,
/// sec. 5): region ids, the visual surface's labels, materials, named labels, clinical descriptors, hydrometra,
/// quality and warnings. Each piece is its own function so it can be tested on small inputs.

#include "hs/core/LibraryVersions.h"
#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/TetMesh.h"
#include "hs/generate/CaseStages.h"
#include "hs/merge/Merge.h"
#include "hs/meshing/MeshTypes.h"
#include "hs/pathology/Pathology.h"
#include "hs/scene/CaseSpec.h"
#include "hs/scene/Scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace hs::generate {

/// Scene region ids: the merged body's region r becomes r + 1 (Gmsh physical tags must be positive). Region 1 is
/// the wall (myometrium); region 2 + i is the case's pathology i.
inline constexpr std::int32_t kSceneRegionOffset = 1;
inline constexpr std::int32_t kWallRegion = 1;
std::int32_t pathologyRegion(std::size_t pathologyIndex);

/// The regions of a case's scene, ascending id: the wall, then one per pathology named by its id.
std::vector<scene::SceneRegion> sceneRegions(const scene::CaseSpec& spec);

/// The meshed body with scene region ids (every region shifted by kSceneRegionOffset).
TetMesh sceneTets(const TetMesh& meshed);

/// The texture stage's result: the visual surface (the tet mesh's boundary split along chart seams, with UVs and
/// the baked maps) and what the bake reported.
struct Appearance {
    scene::VisualSurface surface;
    texture::BakeStats stats;
    std::vector<std::string> warnings;
};

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
/// tets touching the wall), ostia, cervical-canal. Empty sets give no label.
std::vector<scene::SceneLabel> sceneLabels(const scene::CaseSpec& spec, const TetMesh& tets, const SurfaceMesh& visual);

/// Organ dimensions and one descriptor per grown pathology (size and FIGO/Lasmar as the pathology stage measured
/// them, volume as meshed).
scene::ClinicalDescriptors clinicalDescriptors(const scene::CaseSpec& spec, const anatomy::UterusDimensions& organ,
                                               const pathology::PathologyResult& grown, const TetMesh& tets);

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

/// The whole scene of a case from its stage results. InvalidInput when a material override is out of range or the
/// result breaks a rule of scene::checkScene (naming it).
[[nodiscard]] Result<scene::Scene> assembleScene(const scene::CaseSpec& spec, const OrganInstance& organ,
                                                 const pathology::PathologyResult& grown,
                                                 const merge::MergeResult& merged, const meshing::MeshResult& meshed,
                                                 const Appearance& appearance);

} // namespace hs::generate
