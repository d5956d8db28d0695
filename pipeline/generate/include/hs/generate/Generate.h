#pragma once
/// The chain from a case to its scene: organ -> pathologies -> merged body -> tetrahedral mesh -> visual surface
/// -> scene (Sierra et al. 2004). The command line's `generate`, the workstation and batch runs all call these
/// functions; none of them assembles the chain itself.
///
/// generateScene keeps every stage's result, so that an edit can rerun only the stages it touches:
/// regenerateFrom(Stage::Texture, previous, edited) keeps the organ, the pathologies, the body and the mesh.
/// Every stage is a deterministic function of the case fields it reads and of the previous stages' results, so a
/// regenerated scene is the same, byte for byte, as a full run of the edited case.

#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/Timings.h"
#include "hs/generate/Assembly.h"
#include "hs/generate/CaseStages.h"
#include "hs/generate/Seeds.h"
#include "hs/merge/Merge.h"
#include "hs/meshing/MeshTypes.h"
#include "hs/pathology/Pathology.h"
#include "hs/scene/CaseSpec.h"
#include "hs/scene/Scene.h"

#include <optional>
#include <string>

namespace hs::generate {

struct GenerateParams {
    /// Where the case was read from: relative model paths are taken from its folder, and messages name it. May be
    /// empty for a case built in code (relative paths are then taken from the working directory).
    std::string caseFile;
    /// Replaces the case's meshing.threads for every stage (0: all cores); never changes the result.
    std::optional<int> threads;
    /// Shown the pathologies' growth as it happens (pathology::GrowthFrame); never changes the result.
    pathology::GrowthObserver growthObserver;
};

/// Every stage's result for one case. A stage's result is set once the stage has run.
struct Generated {
    scene::CaseSpec spec; ///< the case these results were made from
    std::optional<OrganInstance> organ;
    std::optional<pathology::PathologyResult> pathologies; ///< the displaced organ and the grown pathologies
    std::optional<merge::MergeResult> body;                ///< the merged multi-region body
    std::optional<meshing::MeshResult> mesh;               ///< body region ids (0 the wall, i + 1 pathology i)
    std::optional<TissueStage> tissue;                     ///< scene region ids: the wall's layers, the pathologies
    std::optional<Appearance> appearance;                  ///< the textured visual surface
    std::optional<scene::Scene> scene;
    StageTimings timings; ///< one step per stage that ran, named by toString(Stage)

    /// Whether `stage`'s result is set.
    bool has(Stage stage) const;
};

/// Runs every stage on `spec` (a validated case). Errors name the case file, the field and the allowed range where
/// the case is at fault; Cancelled when `progress` is cancelled (checked between and inside stages).
[[nodiscard]] Result<Generated> generateScene(const scene::CaseSpec& spec, const GenerateParams& params = {},
                                              Progress& progress = Progress::none());

/// Where two cases first differ, as the stage that reads the field and the field's JSON path ("/pathologies").
struct CaseChange {
    Stage stage = Stage::Organ;
    std::string field;
};

/// The earliest stage whose inputs differ between `before` and `after`; std::nullopt when they give the same
/// scene. The seed is read by every stage (Stage::Organ); the patient's cycle phase and the anatomy's endometrial
/// thickness only by the tissue layers (Stage::Tissue); meshing.threads never changes a result and is ignored; the
/// title is only recorded in the scene (Stage::Scene).
std::optional<CaseChange> firstChangedStage(const scene::CaseSpec& before, const scene::CaseSpec& after);

/// Reruns `from` and every stage after it on `edited`, keeping `previous`'s results of the stages before `from`.
/// InvalidInput when the edit changes a field an earlier stage reads (naming the field and the stage to rerun
/// from) or when `previous` lacks a result that `from` needs. The result equals generateScene(edited).
[[nodiscard]] Result<Generated> regenerateFrom(Stage from, Generated previous, const scene::CaseSpec& edited,
                                               const GenerateParams& params = {},
                                               Progress& progress = Progress::none());

/// Brings `previous` up to date with `edited` through stage `last`, as an editor does: runs the earliest stage whose
/// inputs the edit changed or whose result is missing, and every stage after it through `last`; the results after
/// `last` are then cleared (they came from the old inputs). Runs nothing when the results through `last` are
/// already those of `edited` (the later ones are kept). The results equal those of generateScene(edited).
[[nodiscard]] Result<Generated> updateThrough(Stage last, Generated previous, const scene::CaseSpec& edited,
                                              const GenerateParams& params = {}, Progress& progress = Progress::none());

} // namespace hs::generate
