#pragma once
/// Export: a case into one scene package, or into several variants of it, each generated, written, read back against
/// its manifest and swept by the scope. The one function behind `hysteroscene-cli generate`, the workstation's
/// Export and a batch job: what "exported" means (the files, their checksums, the scope's criterion) is decided here
/// and nowhere else.

#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/generate/Generate.h"
#include "hs/scene/ScenePackage.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hs::generate {

/// What the scope's sweep (scene::checkScopePassage with its default 2.9 mm scope) says of one scene.
struct ScopeVerdict {
    bool checked = false; ///< false: the scene lacks the landmarks the sweep needs (`uncheckedBecause` says why)
    std::string uncheckedBecause;
    double scopeDiameterMm = 0.0; ///< mm
    /// The one criterion of a scene the scope can explore, as `validate` has it ("passes"): a ball of the scope's
    /// diameter gets from outside the external os through the cervical canal into the cavity
    /// (ScopePassage::canalPasses).
    bool passes = false;
    double canalNarrowestMm = 0.0; ///< mm, the least free width from outside the external os to the cavity
    /// Also all the way to the fundus (ScopePassage::ballPasses): information, not the criterion; a pathology that
    /// fills the cavity can block it and the scene is still one to train in.
    bool reachesFundus = false;
    double narrowestMm = 0.0; ///< mm, the least free width on the whole route to the fundus
};

/// One package of an export.
struct ExportedPackage {
    std::size_t index = 0; ///< the variant's index (0 for a single package)
    std::uint64_t seed = 0;
    std::string folder;
    std::string zipPath;               ///< empty when no zip was asked for
    std::optional<Error> error;        ///< this package failed (the others of the export still ran)
    std::size_t files = 0;             ///< files of the manifest, each read back with a matching checksum
    std::vector<std::string> warnings; ///< the scene's warnings (scene.json)
    ScopeVerdict scope;
    StageTimings timings; ///< the chain's stages, then "package" (write, read back, zip) and "scope"
};

struct ExportParams {
    std::string folder;                 ///< the package; with variants > 1 the folder that holds variant-NNN
    std::size_t variants = 1;           ///< scenes, variant i with exportSeed(spec.seed, i, variants)
    std::size_t jobs = 1;               ///< variants generated at the same time (each stage's own threads come on top)
    bool zip = false;                   ///< also folder.zip
    scene::PackageWriteOptions formats; ///< the other tools' formats written besides
    bool checkScope = true;             ///< sweep the scope through each scene
    /// Results of an earlier run of this very case to bring up to date instead of starting afresh (one package
    /// only; variants are new patients and always start afresh). Never changes the scene.
    std::shared_ptr<const Generated> previous;
    /// Each variant's progress on its own scale (stage key, fraction of that variant), from the thread that runs it.
    std::function<void(std::size_t variant, std::string_view stage, double fraction)> variantProgress;
    /// Called once a variant's package is written and checked, on the thread that ran it, with the chain's results
    /// to summarise or to keep (move them out; they are freed after the call otherwise).
    std::function<void(const ExportedPackage&, Generated&&)> onExported;
};

/// Generates every variant of `spec` (a validated case) and writes each package: the chain (updateThrough
/// Stage::Scene from `params.previous` when given), scene::writeScenePackage (atomic: a failed write leaves the
/// folder as it was), scene::verifyScenePackage, the zip, then the scope's sweep. Creates the folders it needs. A
/// variant that fails has its `error` set and the others still run; the whole call fails only for a folder it cannot
/// create, a cancel (Cancelled, checked inside every step) or parameters out of range (InvalidInput naming them).
/// `progress` gets variant i's progress in [i/n, (i+1)/n] (with several jobs these ranges interleave).
[[nodiscard]] Result<std::vector<ExportedPackage>> exportScenes(const scene::CaseSpec& spec,
                                                                const GenerateParams& generateParams,
                                                                const ExportParams& params,
                                                                Progress& progress = Progress::none());

/// The first failed package's error, naming its variant when there are several; ok when none failed.
[[nodiscard]] Status firstFailure(const std::vector<ExportedPackage>& packages);

} // namespace hs::generate
