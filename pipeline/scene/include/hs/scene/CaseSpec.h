#pragma once
/// CaseSpec: the case file (case.json). Everything needed to regenerate a scene bit for bit: the patient, the
/// pathologies, every stage's parameters and the seed.
///
/// The document format, every field with its unit, default, range and source, and the versioning rule are in
/// docs/case-format.md. Defaults and ranges cite their published sources by key, e.g. [Verguts2013]: the entries
/// of docs/references.md.
/// Optional fields (std::optional) mean "not set": the stage derives the value itself (from the shape model or the
/// tissue defaults below); they are written as JSON null.

#include "hs/clinical/Clinical.h"
#include "hs/clinical/Figo.h"
#include "hs/clinical/PatientParams.h"
#include "hs/clinical/Placement.h"
#include "hs/clinical/Tissue.h"
#include "hs/core/Result.h"
#include "hs/core/Vec3.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace hs::scene {

/// Value of the document's "format" member.
constexpr std::string_view kCaseFormat = "hysteroscene-case";
/// The schema version this build writes and validates; older documents are upgraded to it first.
constexpr int kCaseSchemaVersion = 3;
/// The oldest schema version this build can upgrade.
constexpr int kOldestCaseSchemaVersion = 1;
/// A case file is a few kB; anything above this is refused before parsing (guards against huge allocations).
constexpr std::int64_t kMaxCaseFileBytes = 4 * 1024 * 1024;
/// Deeper nesting than this is not a case file (the schema itself nests 5 levels).
constexpr int kMaxCaseNestingDepth = 32;
/// Pathologies per case (the pathology stage's bar is 5; 16 leaves room without inviting absurd requests).
constexpr std::size_t kMaxPathologies = 16;
/// Longest pathology id (ids become file names in the scene package).
constexpr std::size_t kMaxPathologyIdLength = 32;
/// Longest title and longest file path in a case.
constexpr std::size_t kMaxTitleLength = 200;
constexpr std::size_t kMaxPathLength = 1024;

/// Closed interval of allowed values, in the unit of the field it guards.
struct Range {
    double min = 0.0;
    double max = 0.0;
    constexpr bool contains(double v) const { return v >= min && v <= max; } // false for NaN
};

/// Supported ranges. Values outside are rejected, never clamped: no stage extrapolates silently.
namespace limits {
// Patient. Adults only: pre-menarche proportions differ [CorpusCervixRatio] and the published adult
// morphometry ends at 80 years [Verguts2013]. The other bounds are those the default shape model's synthetic cohort
// covers (hs::anatomy::supportedPatientRanges()), so a valid case never asks the model to extrapolate.
constexpr Range kAgeYears{18.0, 80.0};
constexpr Range kParity{0.0, 6.0};     ///< births; "multiparous" is the highest published group [IraqParity]
constexpr Range kGravidity{0.0, 10.0}; ///< pregnancies; must also be >= parity
constexpr Range kHeightCm{140.0, 195.0};
constexpr Range kWeightKg{35.0, 160.0};
constexpr double kMenopausalMinAgeYears = 40.0;    ///< earlier is premature ovarian insufficiency: not modelled
constexpr double kPremenopausalMaxAgeYears = 60.0; ///< later lies beyond the cohort's ages at menopause
// Anatomy overrides (mm, degrees): the published spread (docs/references.md, "Anatomy and dimensions") with margin.
constexpr Range kVersionDeg{-90.0, 90.0};            ///< + anteverted, - retroverted [Retroversion]
constexpr Range kFlexionDeg{-90.0, 90.0};            ///< + anteflexed, - retroflexed [Retroversion]
constexpr Range kLengthMm{30.0, 95.0};               ///< 42 at 80 y .. 79 multiparous [Verguts2013], [NayabMultiparous]
constexpr Range kWidthMm{20.0, 65.0};                ///< 39.9 +- 7.2, +- 3 SD [Gao2018]
constexpr Range kApMm{20.0, 70.0};                   ///< 45.0 +- 8.1, +- 3 SD [Gao2018]
constexpr Range kCavityLengthMm{20.0, 55.0};         ///< 95 % range 26-38 [Chen2020]; 44.3 multiparous [Goldstuck2012]
constexpr Range kCavityWidthMm{20.0, 45.0};          ///< 95 % range 25-40 [Chen2020]
constexpr Range kCornualAngleDeg{30.0, 100.0};       ///< 95 % range 39-88 [Chen2020]
constexpr Range kFundalWallThicknessMm{5.0, 20.0};   ///< 10.8-13.6 by age [FundusMRI]; >= 5 mm wall
constexpr Range kCervixLengthMm{20.0, 45.0};         ///< about 30 [CervixParity]
constexpr Range kSurfaceCoordinateMm{-500.0, 500.0}; ///< a click on the organ lies well inside this box
/// Endometrial thickness as ultrasound reports it (both layers): 2-16 mm premenopausal, <= 4 postmenopausal
/// (docs/anatomy.md, "Tissue layers"), with margin; 1 mm is about the finest lining a 30 000-vertex mesh resolves.
constexpr Range kEndometrialThicknessMm{1.0, 20.0};
// Pathologies (mm).
constexpr Range kMyomaSizeMm{5.0, 100.0};  ///< Lasmar size classes <= 20, 20-50, > 50 mm [Lasmar2005]
constexpr Range kPolypSizeMm{3.0, 40.0};   ///< usually 5-30 mm [PolypSize]
constexpr Range kStalkLengthMm{1.0, 30.0}; ///< pedunculated polyps only
// Meshing.
constexpr Range kTargetEdgeLengthMm{0.2, 20.0};
constexpr Range kTargetVertices{500.0, 500000.0};
constexpr Range kParticlesPerVoxel{1.0, 8.0};
constexpr Range kRelaxationIterations{0.0, 1000.0};
constexpr Range kThreads{0.0, 256.0};     ///< 0 = all hardware threads
constexpr Range kHeterogeneity{0.0, 0.5}; ///< coefficient of variation of Young's modulus per tet
// Texture.
constexpr Range kTextureSizePx{64.0, 8192.0}; ///< and a power of two
constexpr Range kVesselDensity{0.0, 4.0};     ///< relative to the default network; 0 = no vessels
// Scene.
constexpr Range kHydrometraPressureKpa{0.0, 20.0}; ///< 0 = undistended; 20 kPa (150 mmHg) was measured [Bajka2009]
constexpr Range kPoissonRatio{0.45, 0.49};         ///< nearly incompressible [SoftTissue]
constexpr Range kDensityKgPerM3{1000.0, 1100.0};   ///< around the generic 1050 [SoftTissue]
} // namespace limits

// ---- Enumerations of the case's own choices. Each has a stable lower-case JSON key: toString() / fromString().
// The clinical ones (pathology kind, growth model, location, attachment, tissue) are in hs/clinical. ----

/// Healthy organ: a random instance of the conditional shape model, or its mean for the patient.
enum class ShapeMode { Sample, Mean };
enum class MeshingMethod { Particle, TetGen, Cgal };
/// How the particle mesher seeds inner voxels (the particle method only).
enum class MeshingSeeding {
    Lattice, ///< "lattice": body-centred cubic points (meets the meshing bars; docs/meshing.md)
    Random,  ///< "random": particlesPerInnerVoxel random points per voxel, as in Sierra et al. 2004 (sec. 2.2)
};

constexpr std::array<ShapeMode, 2> kShapeModes{ShapeMode::Sample, ShapeMode::Mean};
constexpr std::array<MeshingMethod, 3> kMeshingMethods{MeshingMethod::Particle, MeshingMethod::TetGen,
                                                       MeshingMethod::Cgal};
constexpr std::array<MeshingSeeding, 2> kMeshingSeedings{MeshingSeeding::Lattice, MeshingSeeding::Random};

std::string_view toString(ShapeMode value);
std::string_view toString(MeshingMethod value);  ///< "particle", "tetgen", "cgal"
std::string_view toString(MeshingSeeding value); ///< "lattice", "random"
/// Sets `out` and returns true when `key` is one of the JSON keys above.
bool fromString(std::string_view key, ShapeMode& out);
bool fromString(std::string_view key, MeshingMethod& out);
bool fromString(std::string_view key, MeshingSeeding& out);

// ---- The document. ----

/// Optional clinical measurements the shape model conditions on (mm, degrees); unset = derived from the patient.
struct UterusDimensions {
    std::optional<double> lengthMm;              ///< external corpus + cervix length [Verguts2013], [IraqParity]
    std::optional<double> widthMm;               ///< [Gao2018]
    std::optional<double> apMm;                  ///< antero-posterior depth [Gao2018]
    std::optional<double> cavityLengthMm;        ///< < lengthMm [Chen2020], [Goldstuck2012]
    std::optional<double> cavityWidthMm;         ///< fundal cavity width, < widthMm [Chen2020], [Benacerraf2010]
    std::optional<double> cornualAngleDeg;       ///< [Chen2020]
    std::optional<double> fundalWallThicknessMm; ///< [FundusMRI]
    std::optional<double> cervixLengthMm;        ///< [CervixParity]
};

struct AnatomyParams {
    ShapeMode shape = ShapeMode::Sample;  ///< a seeded sample for the patient, or the model's mean for the patient
    std::optional<std::string> modelPath; ///< statistical shape model file; unset = the bundled default model
    std::optional<double> versionDeg;     ///< degrees, cervix-vagina angle; + anteverted, - retroverted [Retroversion]
    std::optional<double> flexionDeg;     ///< degrees, corpus-cervix angle; + anteflexed, - retroflexed [Retroversion]
    UterusDimensions dimensions;
    /// mm, both layers as ultrasound measures them; unset = typical for the patient's cycle phase or menopause
    /// (clinical::typicalEndometrialThicknessMm). Each wall's lining is half of it.
    std::optional<double> endometrialThicknessMm;
};

struct PathologySpec {
    std::string id; ///< unique in the case; [A-Za-z0-9][A-Za-z0-9_-]*, <= 32 chars
    clinical::PathologyKind kind = clinical::PathologyKind::Myoma;
    clinical::GrowthModel growthModel = clinical::GrowthModel::Particles; ///< particles grow both kinds
    double sizeMm = 20.0;                                ///< mm, largest diameter (polyps: of the head)
    std::optional<clinical::FigoType> figo;              ///< myomas: required; polyps: must be unset
    std::optional<clinical::PolypAttachment> attachment; ///< polyps: required; myomas: must be unset
    std::optional<double> stalkLengthMm;                 ///< mm; pedunculated polyps: required; otherwise unset
    clinical::Placement placement = clinical::ClinicalPlacement{};
};

struct MeshingParams {
    MeshingMethod method = MeshingMethod::Particle;
    /// Exactly one of the two density controls is set. 30 000 vertices: the default scene's budget. In a file,
    /// giving only targetEdgeLengthMm unsets targetVertices.
    std::optional<double> targetEdgeLengthMm;
    std::optional<int> targetVertices = 30000;
    MeshingSeeding seeding = MeshingSeeding::Lattice;
    std::optional<int> particlesPerInnerVoxel; ///< random seeding only (required there, unset for the lattice)
    int relaxationIterations = 60;             ///< cap; relaxation also stops on convergence
    int threads = 0;                           ///< 0 = all hardware threads; never changes the result
};

/// Exemplar images for texture synthesis; unset = the bundled procedural exemplars.
struct TextureExemplars {
    std::optional<std::string> endometrium;
    std::optional<std::string> myoma;
    std::optional<std::string> polyp;
    std::optional<std::string> cervicalCanal; ///< the canal and the ectocervix's rim round the external os
};

struct TextureParams {
    int sizePx = 1024; ///< px, side of each square map; a power of two
    TextureExemplars exemplars;
    double vesselDensity = 1.0; ///< relative to the default vessel network; 0 = none
};

/// A tissue's mechanical parameters. Any unset field takes the tissue's default (defaultMaterial()).
struct MaterialOverride {
    std::optional<double> youngsModulusKpa; ///< kPa
    std::optional<double> poissonRatio;     ///< dimensionless
    std::optional<double> densityKgPerM3;   ///< kg/m^3
    /// Coefficient of variation of Young's modulus per tet, seeded (0 or unset: homogeneous). Myomas are
    /// heterogeneous [Kiss2006]; the spread is the user's.
    std::optional<double> heterogeneity;
};

struct SceneParams {
    double hydrometraPressureKpa = 8.0; ///< kPa; 8 kPa = 60 mmHg, middle of the clinical 45-75 mmHg [Vulgaropulos1992]
    std::array<MaterialOverride, clinical::kTissues.size()> materials{}; ///< indexed by clinical::Tissue
};

struct CaseSpec {
    std::string title;      ///< free text for lists and reports, <= 200 bytes
    std::uint64_t seed = 1; ///< every random choice of every stage derives from it
    clinical::PatientParams patient;
    AnatomyParams anatomy;
    std::vector<PathologySpec> pathologies;
    MeshingParams meshing;
    TextureParams texture;
    SceneParams scene;
};

bool operator==(const UterusDimensions& a, const UterusDimensions& b);
bool operator==(const AnatomyParams& a, const AnatomyParams& b);
bool operator==(const PathologySpec& a, const PathologySpec& b);
bool operator==(const MeshingParams& a, const MeshingParams& b);
bool operator==(const TextureExemplars& a, const TextureExemplars& b);
bool operator==(const TextureParams& a, const TextureParams& b);
bool operator==(const MaterialOverride& a, const MaterialOverride& b);
bool operator==(const SceneParams& a, const SceneParams& b);
bool operator==(const CaseSpec& a, const CaseSpec& b);
bool operator!=(const CaseSpec& a, const CaseSpec& b);

// ---- Tissue materials (docs/references.md, "Tissue mechanics"). ----

struct TissueMaterial {
    double youngsModulusKpa = 0.0; ///< kPa
    double poissonRatio = 0.0;
    double densityKgPerM3 = 0.0; ///< kg/m^3
};
/// The default of each tissue: myometrium 30 kPa, endometrium 26.2 kPa (proliferative: hysteroscopy is done in
/// the proliferative phase), cervix 30 kPa (no source: the myometrium's), myoma 65 kPa, polyp 15 kPa; Poisson
/// ratio 0.47 (middle of 0.45-0.49); density 1050 kg/m^3.
TissueMaterial defaultMaterial(clinical::Tissue tissue);
/// Allowed Young's modulus of each tissue (kPa): myometrium 6-90, endometrium 12.5-26.2, cervix 6-90,
/// myoma 13-206 (ratio 2.17-2.29 applied to the myometrium's range), polyp 1-32 (15.7 +- 2 SD, at least 1).
Range youngsModulusRangeKpa(clinical::Tissue tissue);
/// The tissue's default with the case's overrides applied.
TissueMaterial effectiveMaterial(const SceneParams& scene, clinical::Tissue tissue);

// ---- Validation, reading and writing. ----

/// One problem in a case: the JSON path (RFC 6901 pointer, e.g. "/pathologies/1/sizeMm") and what is wrong,
/// naming the value and the allowed range or choices.
struct CaseIssue {
    std::string path;
    std::string message;
    std::string text() const { return path + ": " + message; } ///< "/patient/ageYears: 130 is outside ..."
};

/// Every range and consistency rule of the current schema, on a spec built in code (GUI, tests). Empty when valid.
std::vector<CaseIssue> checkCase(const CaseSpec& spec);

/// Parses and validates a case document; older schema versions are upgraded first. On failure the Error lists
/// every problem found (up to 20), one per line, each "<sourceName>: <path>: <message>": first the structural
/// ones (types, unknown or missing fields, unknown choices) in reading order, then the value rules of
/// checkCase(). A syntax error stops at once and names where the parser was. Codes: InvalidInput (syntax, types,
/// unknown fields, ranges), Unsupported (newer or too old schema version), LimitExceeded (above
/// kMaxCaseFileBytes).
[[nodiscard]] Result<CaseSpec> parseCase(std::string_view jsonText, const std::string& sourceName);
/// Reads `path` (at most kMaxCaseFileBytes) and parses it; errors name the file.
[[nodiscard]] Result<CaseSpec> loadCase(const std::string& path);
/// The document of the current schema version: every field written, in a fixed order, 4-space indent, final
/// newline. Deterministic: equal specs give byte-identical text.
std::string toJson(const CaseSpec& spec);
/// Writes toJson(spec) atomically; refuses (InvalidInput) a spec that checkCase() rejects.
[[nodiscard]] Status saveCase(const CaseSpec& spec, const std::string& path);

/// The bundled default case (resources/cases/default.json): a 35-year-old primipara with a FIGO 2 left lateral
/// myoma of 20 mm and a sessile right cornual polyp of 10 mm; seed 1.
CaseSpec defaultCase();

/// A short human summary, one line per item, each "label       text" (12-column label), for `info` and `validate`.
std::vector<std::string> describe(const CaseSpec& spec);

} // namespace hs::scene
