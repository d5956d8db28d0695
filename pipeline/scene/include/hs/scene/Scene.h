#pragma once
/// Scene: the coherent scene a simulator loads (Sierra et al. 2004, sec. 5): the tetrahedral body with per-tet
/// region and material ids, the textured visual surface, a material per region, named labels, clinical
/// descriptors, the mesh quality report, the case it was made from and the versions of the tools that made it.
///
/// The model holds data only: it does not depend on the stages that fill it (their results are converted into
/// these plain structs), so the package writer and reader, the simulator and the GUI share one small type.
/// docs/scene-format.md describes every field as it appears on disk.

#include "hs/core/Image.h"
#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/TetEmbedding.h"
#include "hs/core/TetMesh.h"
#include "hs/scene/CaseSpec.h"
#include "hs/scene/Hydrometra.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace hs::scene {

/// Names of the per-tet arrays the scene keeps in TetMesh::tetLabels.
constexpr const char* kMaterialLabel = "material";             ///< index into Scene::materials
constexpr const char* kYoungsModulusLabel = "youngsModulusPa"; ///< per-tet E in Pa (heterogeneous scenes only)

/// One tissue region of the body: the tets whose TetMesh::regions entry is `id`.
struct SceneRegion {
    std::int32_t id = 0;
    std::string name; ///< "myometrium", "endometrium", or the pathology id ("myoma-1")
    clinical::Tissue tissue = clinical::Tissue::Myometrium;
    std::string pathologyId; ///< the case's pathology id for pathology regions; empty otherwise
};

/// The mechanical parameters of one region (docs/references.md, "Tissue mechanics").
struct SceneMaterial {
    std::int32_t id = 0; ///< index in Scene::materials; the value of the "material" tet array
    std::int32_t regionId = 0;
    std::string name; ///< the region's name
    clinical::Tissue tissue = clinical::Tissue::Myometrium;
    TissueMaterial material;     ///< kPa, dimensionless, kg/m^3: the region's mean
    Range youngsModulusRangeKpa; ///< the tissue's allowed range; heterogeneous values stay inside it
    double heterogeneity = 0.0;  ///< coefficient of variation of E per tet (0: homogeneous)
};

/// What a label marks.
enum class LabelKind {
    Contact,       ///< "contact": where a pathology touches the organ
    Ostium,        ///< "ostium": a tubal ostium
    CervicalCanal, ///< "cervical-canal"
    PathologyBase, ///< "pathology-base": the base (attachment) of a pathology
    Other,         ///< "other"
};
/// Which elements a label's indices refer to.
enum class LabelElement {
    SurfaceFace, ///< "surface-face": triangles of Scene::surface.mesh
    Tet,         ///< "tet": tetrahedra of Scene::tets
};
std::string_view toString(LabelKind kind);
std::string_view toString(LabelElement element);
bool fromString(std::string_view key, LabelKind& out);
bool fromString(std::string_view key, LabelElement& out);

/// A named set of faces or tets ("contact:myoma-1", "ostium-left", "cervical-canal", "base:polyp-1").
struct SceneLabel {
    std::string name; ///< unique in the scene; [A-Za-z0-9][A-Za-z0-9_:.-]*, <= 64 chars
    LabelKind kind = LabelKind::Other;
    LabelElement element = LabelElement::SurfaceFace;
    std::string pathologyId;           ///< for contact and pathology-base labels; empty otherwise
    std::vector<std::int32_t> indices; ///< ascending, unique, in range of the element array
};

/// The tet label (kind Other) that says where the body is held: the SOFA scene fixes every vertex of its tets
/// (FixedProjectiveConstraint). hs::generate marks the cervix (generate/Assembly.h, supportLabel); a scene without
/// it is written free.
inline constexpr const char* kSupportLabel = "support:cervix";

/// The largest extrapolation of an embedding: a surface point may lie outside its tet (the smooth surface runs just
/// inside and outside the tets' faceted boundary), but no weight below -kMaxEmbeddingExtrapolation or above
/// 1 + kMaxEmbeddingExtrapolation, so a deformation moves it like its tet (docs/scene-format.md, surface.vtp).
inline constexpr double kMaxEmbeddingExtrapolation = 2.0;

/// The visual surface: triangles in mm, a UV per vertex, and the baked maps (all share the UV atlas).
struct VisualSurface {
    SurfaceMesh mesh;                      ///< with its face and vertex labels
    std::vector<std::array<float, 2>> uvs; ///< one per mesh point, in [0, 1]; origin at the image's top left
    std::vector<Vec3> normals;             ///< unit, one per mesh point, smooth across seams; empty: not stored
    /// One per mesh point: where it is bound in Scene::tets (hs/core/TetEmbedding.h); empty: not bound (a package
    /// read without it gets it computed).
    std::vector<TetEmbedding> embedding;
    ImageU8 albedo;    ///< RGB, sRGB-encoded base colour
    ImageU8 normal;    ///< RGB, tangent-space normal map (OpenGL convention, +Y up)
    ImageU8 roughness; ///< 1 channel, linear perceptual roughness 0..255
};

/// The simulation mesh: a coarser tetrahedral mesh of the same body, sized for a real-time solver, with the visual
/// surface bound to it (so a simulator deforms what it shows). Written by hs::generate (generate/Simulation.h);
/// docs/scene-format.md, "simulation.vtu".
struct SimulationMesh {
    /// mm; regions = SceneRegion ids; tet arrays kMaterialLabel (index into Scene::materials) and kSupportTetLabel;
    /// point array kCavityPointLabel.
    TetMesh tets;
    /// One per point of Scene::surface.mesh: where it is bound in `tets` (weights within kMaxEmbeddingExtrapolation).
    std::vector<TetEmbedding> surfaceEmbedding;
};
/// How far a visual surface point may lie from where its binding to the simulation mesh puts it, mm. The coarse mesh
/// is thinner than the surface in places (a polyp's thin stalk, a cornual recess): a point there is bound to its
/// nearest tet with its weights clamped to kMaxEmbeddingExtrapolation, and moves with that tet.
inline constexpr double kMaxSimulationEmbeddingOffsetMm = 5.0;
/// Tet array of the simulation mesh: 1 where the body is held (the tets of kSupportLabel's rule), else 0.
inline constexpr const char* kSupportTetLabel = "support";
/// Point array of the simulation mesh: 1 on its boundary where it faces the cavity, the canal or the ostia (the
/// surfaces the scope sees and the distension fluid presses on), else 0.
inline constexpr const char* kCavityPointLabel = "cavity";

/// A pathology as the final scene measures it: its region of the tets against the scene's boundary
/// (docs/scene-format.md, "Where the clinical descriptors are measured").
struct PathologyDescriptor {
    std::string id;
    clinical::PathologyKind kind = clinical::PathologyKind::Myoma;
    std::int32_t regionId = -1;                  ///< its region in the tet mesh (-1: not meshed as a region)
    double sizeMm = 0.0;                         ///< mm, largest diameter of its region (stalked: of the head)
    double volumeMl = 0.0;                       ///< mL, as meshed
    std::optional<clinical::FigoType> figo;      ///< myomas; where the region lies against cavity and serosa
    std::optional<clinical::LasmarScore> lasmar; ///< myomas
    std::string location;                        ///< a UterineLocation key ("fundal", ...) or empty
    /// Polyps: share of its region's surface (by area) against tissue on the final tets rather than in the cavity
    /// under the endometrium laid over it (docs/scene-format.md, "Polyp seating"). Unset for myomas and in
    /// packages written before it was measured.
    std::optional<double> tissueContactFraction;
};

/// A polyp stands in the cavity: at most this share of its surface lies against tissue on the final tets (a
/// pedunculated polyp: its stalk; a sessile one: its broad base).
inline constexpr double kPedunculatedPolypMaxContact = 0.20;
inline constexpr double kSessilePolypMaxContact = 0.40;

/// Organ dimensions as measured on the final body's serosa and cavity (mm, mL); 0 when not measured.
struct OrganDimensions {
    double lengthMm = 0.0;
    double widthMm = 0.0;
    double apMm = 0.0;
    double cavityLengthMm = 0.0;
    double cavityWidthMm = 0.0;
    double uterineVolumeMl = 0.0; ///< mL; the clinical estimate L x W x AP x 0.523 (docs/references.md [Ellipsoid])
};

struct ClinicalDescriptors {
    OrganDimensions organ;
    std::vector<PathologyDescriptor> pathologies;
};

/// The mesh quality report, as data (the meshing stage's report converted; see docs/scene-format.md).
struct MeshQuality {
    std::size_t vertexCount = 0;
    std::size_t tetCount = 0;
    double meanRadiusRatio = 0.0;
    double minRadiusRatio = 0.0;
    double minDihedralDeg = 0.0;
    double maxDihedralDeg = 0.0;
    double meanEdgeRatio = 0.0;
    double maxEdgeRatio = 0.0;
    std::vector<std::size_t> radiusRatioHistogram; ///< buckets of 0.1 from 0 to 1
    std::vector<std::size_t> minDihedralHistogram; ///< buckets of 10 degrees from 0 to 90
    std::size_t sliverCount = 0;
    std::size_t invertedCount = 0;
    std::size_t degenerateCount = 0;
    bool hasReference = false;
    double hausdorffDistanceMm = 0.0;
    double hausdorffRelative = 0.0;
    double volumeError = 0.0; ///< largest relative per-region volume error
    /// Non-manifold edges and vertices of the outer boundary; unset in packages written before they were measured.
    std::optional<std::size_t> boundaryNonManifoldEdges;
    std::optional<std::size_t> boundaryNonManifoldVertices;
};

struct Scene {
    TetMesh tets; ///< mm; regions = SceneRegion ids; tetLabels["material"] = material ids
    VisualSurface surface;
    std::optional<SimulationMesh> simulation; ///< unset in packages of schema version 1
    std::vector<SceneRegion> regions;         ///< ascending id
    std::vector<SceneMaterial> materials;
    std::vector<SceneLabel> labels;
    ClinicalDescriptors clinical;
    MeshQuality quality;
    Hydrometra hydrometra;
    CaseSpec caseSpec;                               ///< the full case the scene was generated from
    std::map<std::string, std::string> toolVersions; ///< "hysteroscene" -> HS_VERSION, "vtk" -> ..., sorted
    std::vector<std::string> warnings;               ///< from the stages, for report.json
};

/// Options of the material assignment; the mean of each material is the case's effective material.
struct MaterialOptions {
    /// Coefficient of variation of Young's modulus per tet (0: homogeneous; <= 0.5). Myomas are heterogeneous
    /// (docs/references.md [Kiss2006]); the draw is log-normal with this spread, clamped to the tissue's range.
    double heterogeneity = 0.0;
    std::uint64_t seed = 1; ///< same seed, same per-tet values
};

/// Gives each region its material (effectiveMaterial of its tissue with the case's overrides), writes the
/// "material" tet array and, with heterogeneity > 0, the per-tet "youngsModulusPa" array. InvalidInput when a tet's
/// region has no SceneRegion, an override lies outside the tissue's range, or the options are out of range.
[[nodiscard]] Result<std::vector<SceneMaterial>> assignMaterials(TetMesh& tets, const std::vector<SceneRegion>& regions,
                                                                 const SceneParams& params,
                                                                 const MaterialOptions& options = {});

/// The default tool versions: "hysteroscene" (this build), "compiler", and the libraries the scene module and hs::io
/// use (minizip, nlohmann-json, tinygltf, vtk, zlib). hs::generate adds those of the stages (generate/Assembly.h).
std::map<std::string, std::string> defaultToolVersions();

/// Consistency of a scene before it is written: valid meshes, regions cover the tet regions, materials and their
/// tet array, labels in range and sorted, UVs one per point in [0, 1], maps of matching size. InvalidInput naming
/// the first offence.
[[nodiscard]] Status checkScene(const Scene& scene);

} // namespace hs::scene
