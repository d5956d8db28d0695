#pragma once
/// The tissue model of a scene's uterus, one definition for `generate` (the hydrometra curve it writes into the
/// package) and the simulator (whose steps run it): the simulation mesh with its materials and the exponential
/// stiffening, held at the cervix (the portio fixed, the supravaginal cervix on the ligaments' springs) and by the
/// surrounding structures (soft springs on the serosa), the cavity's faces, its volume and the fluid's load on them
/// (docs/simulator.md, "Tissue", "Boundary", "Distension").
///
/// Lengths mm, pressures kPa, volumes mL, forces N; the solver itself works in metres.

#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/Vec3.h"
#include "hs/mechanics/CorotationalFem.h"
#include "hs/scene/Scene.h"

#include <vector>

namespace hs::mechanics {

/// myometrium's exponential stiffening, C = 0.05-0.14 (Pearsall & Roberts 1978), its geometric middle 0.085, for
/// |dev e| times sqrt(3/2) (FemMaterial::stiffeningStrain). No such data for the endometrium, the myoma or the
/// polyp: they get the myometrium's.
inline constexpr double kUterusStiffeningStrain = 0.085 * 1.2247;
/// The portio: the support's points this close to the external os along the canal are fixed, mm (about the vaginal
/// part of a 25-30 mm cervix; docs/references.md [CervixParity]).
inline constexpr double kHeldPortioMm = 12.0;
/// Total stiffness of what holds the corpus besides the cervix (broad and round ligaments, the organs around it),
/// N/m, spread over the serosa's free points by area (docs/simulator.md, "Boundary").
inline constexpr double kSurroundStiffnessNPerM = 1000.0;
/// Total stiffness of the cardinal and uterosacral ligaments on the supravaginal cervix, N/m, spread over its points:
/// the middle of 0.49-0.61 N/mm measured in vivo under cervical traction (docs/references.md [Luo2014]).
inline constexpr double kLigamentStiffnessNPerM = 550.0;

struct UterusModel {
    CorotationalFem fem;
    std::vector<Vec3> restMm;          ///< the simulation mesh's points at rest
    std::vector<Triangle> boundary;    ///< the simulation mesh's boundary faces, in its point indices
    std::vector<std::int32_t> region;  ///< per boundary face, the scene region of its tet
    std::vector<std::int32_t> faceTet; ///< per boundary face, its tet
    std::vector<char> faceCavity;      ///< a face of the cavity and the canal (the fluid presses on it)
    std::vector<char> pointHeld;       ///< per point: fixed (the portio)
    Vec3 externalOsMm, internalOsMm;
    double restCavityMl = 0.0;
    /// mL: the space the cuts opened, as it was when each was cut (cutTets adds to it). The tissue cut away stays in
    /// the cavity as chips, so the fluid's volume does not jump at a cut; cavityVolumeMl leaves it out.
    double cutSpaceMl = 0.0;

    /// The fluid's volume with the points at `pts` (mm), mL: between the cavity's faces, and the faces the cuts
    /// opened, and the external os (the canal's open end), less cutSpaceMl.
    double cavityVolumeMl(const std::vector<Vec3>& pts) const;
    /// The fluid's pressure `pressureKpa` on the cavity's faces as they lie in `pts` (mm), N per point: the cavity's
    /// faces of live tets and the faces the cuts opened (a removed tet's face against a live one; docs/simulator.md,
    /// "Cutting").
    void pressureForces(const std::vector<Vec3>& pts, double pressureKpa, std::vector<Vec3>& forces) const;
    /// Calls `visit(face)` for each face a cut opened, its points ordered so its normal points into the fluid (out of
    /// its live tet, judged by that tet's fourth point in `pts`).
    template <typename Visit>
    void forEachCutFace(const std::vector<Vec3>& pts, Visit&& visit) const;
    /// Removes `tets` from the solver (CorotationalFem::removeTets with `refactor`) with the points at `pts` (mm),
    /// and keeps the fluid's volume continuous across the cut (cutSpaceMl).
    CorotationalFem::Removal cutTets(const std::vector<std::size_t>& tets, const std::vector<Vec3>& pts,
                                     CorotationalFem::Refactor refactor);
};

/// Face `k` of tet `removed` (kTetFacePoints), which it shares with the live tet `live`, its points ordered so its
/// normal points out of `live` (into the fluid) with the points at `pts`. Oriented by the live tet's own fourth
/// point: the removed tet's points are carried by nothing once a cut has left them, so its fourth point may lie across
/// the face.
Triangle cutFace(const std::vector<Tet>& tets, std::size_t removed, std::size_t k, std::size_t live,
                 const std::vector<Vec3>& pts);

template <typename Visit>
void UterusModel::forEachCutFace(const std::vector<Vec3>& pts, Visit&& visit) const {
    if (fem.liveTetCount() == fem.tetCount())
        return;
    const std::vector<Tet>& tets = fem.tets();
    const auto& across = fem.neighbours();
    for (std::size_t t = 0; t < tets.size(); ++t) {
        if (!fem.tetRemoved(t))
            continue;
        for (std::size_t k = 0; k < 4; ++k) {
            const std::int32_t u = across[t][k];
            if (u >= 0 && !fem.tetRemoved(static_cast<std::size_t>(u)))
                visit(cutFace(tets, t, k, static_cast<std::size_t>(u), pts));
        }
    }
}

/// Builds the model of `scene` (its simulation mesh, materials and scope landmarks) with the solver's `settings`.
/// `portioHeld` false: the portio's outer surface hangs on the ligaments' springs with the supravaginal cervix
/// instead of being fixed (a scope pivoting at the introitus; docs/simulator.md, "What is not modelled yet").
/// `stiffening` false: the materials linear, without their exponential stiffening (the textbook's material, to check
/// the solver against moduli alone). InvalidInput for a scene without a simulation mesh or landmarks.
[[nodiscard]] Status buildUterusModel(const scene::Scene& scene, const FemSettings& settings, UterusModel& out,
                                      bool portioHeld = true, bool stiffening = true);

/// `still` built as the static solver of the model (its tissue with 1 s steps, 4 iterations and the line search): what
/// staticOpen and hydrometraCurve settle with, for callers that load the tissue otherwise.
[[nodiscard]] Status buildStaticSolver(const UterusModel& model, CorotationalFem& still);

/// The cavity opened at `pressureKpa` (0-40) by a static solve of the model from rest (1 s steps, the pressure raised
/// over 5 of them and following the faces as they open, until the cavity's volume settles): the points, mm.
/// InvalidInput out of range or when the tissue finds no equilibrium; Cancelled on request (checked every step).
[[nodiscard]] Status staticOpen(const UterusModel& model, double pressureKpa, std::vector<Vec3>& pts,
                                Progress& progress = Progress::none());

/// The model's hydrometra curve: the cavity's opening (mL over rest) at each of `pressuresKpa` (ascending, 0-40), one
/// static solve raised from each pressure to the next. Cancelled on request (checked every step).
[[nodiscard]] Result<std::vector<double>> hydrometraCurve(const UterusModel& model,
                                                          const std::vector<double>& pressuresKpa,
                                                          Progress& progress = Progress::none());

} // namespace hs::mechanics
