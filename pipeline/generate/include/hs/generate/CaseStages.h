#pragma once
/// From a case to the parameters of each pipeline stage. The stages do not know the case format; this is the one
/// place that maps a CaseSpec onto their own parameter structs (the CLI's subcommands, generateScene and the
/// workstation's jobs all use it).

#include "hs/anatomy/ShapeModel.h"
#include "hs/core/Result.h"
#include "hs/generate/TissueLayers.h"
#include "hs/meshing/MeshTypes.h"
#include "hs/pathology/Pathology.h"
#include "hs/scene/CaseSpec.h"
#include "hs/texture/Bake.h"

#include <cstdint>
#include <optional>
#include <string>

namespace hs::generate {

/// The shape model file a case asks for: its anatomy.modelPath (relative paths are taken from the case file's
/// folder), else the bundled default model.
std::string modelPathFor(const scene::CaseSpec& spec, const std::string& caseFile);

struct OrganRequest {
    clinical::PatientParams patient;
    std::uint64_t seed = 1;
    bool mean = false;                    ///< the expected organ for the patient instead of a seeded sample
    std::optional<double> versionDeg;     ///< degrees; unset: drawn (sample) or the most common (mean)
    anatomy::DimensionTargets dimensions; ///< measured dimensions the organ must have (the case's anatomy block)
};

struct OrganInstance {
    SurfaceMesh mesh; ///< face label "tissue"
    anatomy::UterusDimensions dimensions;
    anatomy::TemplateLayout layout; ///< the shape model's own template layout: every later measurement uses it
};

/// Makes the organ: a sample or the mean for the patient, moved to the requested dimensions when there are any.
[[nodiscard]] Result<OrganInstance> makeOrgan(const anatomy::ShapeModel& model, const OrganRequest& request);

/// The organ request of a case; Unsupported for the cornual angle, which the model does not measure.
[[nodiscard]] Result<OrganRequest> organRequestFor(const scene::CaseSpec& spec, const std::string& caseFile);

/// The case's pathologies as the pathology stage's requests (the case is already validated); `override` replaces
/// every pathology's growth model. The stage's seed is the pathology stream of the case seed.
pathology::PathologyParams pathologyParamsFor(const scene::CaseSpec& spec,
                                              const std::optional<clinical::GrowthModel>& override = std::nullopt);

/// The meshing method the case asks for.
meshing::MeshMethod meshMethodFor(const scene::CaseSpec& spec);
/// The meshing stage's parameters; `threads` replaces the case's thread count (never changes the mesh).
meshing::MeshParams meshParamsFor(const scene::CaseSpec& spec, std::optional<int> threads = std::nullopt);

/// mm, the single endometrial layer the pathology stage keeps a myoma of FIGO 4-7 clear of: the case's thickness, or
/// else the thickest of the patient's cycle (so the phase does not move a myoma). The tissue stage lays the lining
/// the phase has, never thicker than this.
double placementLiningMm(const scene::CaseSpec& spec);

/// The wall's tissue layers the case asks for (the endometrium's thickness follows the patient).
TissueLayerParams tissueLayerParamsFor(const scene::CaseSpec& spec);

/// Face label of the visual surface that says which appearance a face takes: 0 wall (endometrium, serosa), 1 over a
/// myoma, 2 over a polyp.
inline constexpr const char* kAppearanceLabel = "appearance";
/// The texture stage's parameters; exemplar paths relative to the case file's folder (as given without a case file);
/// `threads` replaces the case's thread count (never changes the maps).
texture::BakeParams bakeParamsFor(const scene::CaseSpec& spec, const std::string& caseFile,
                                  std::optional<int> threads = std::nullopt);
/// The endometrium's look for the patient: atrophic after the menopause, else her cycle phase's (proliferative when
/// unset).
texture::EndometrialState endometrialState(const clinical::PatientParams& patient);

} // namespace hs::generate
