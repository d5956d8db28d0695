#pragma once
/// Verification of the tissue solver against textbook solutions of linear elasticity, on meshes built for them
/// (docs/simulator.md, "Verification"): the tests assert the bars, `bench_simulator` prints the table.
///
/// - Boussinesq's rigid flat cylindrical punch of radius a pressed by delta into an elastic half-space:
///   F = 2 a E delta / (1 - nu^2) (Sneddon, Int J Eng Sci 3:47-57, 1965; Johnson, Contact Mechanics, 1985, 3.8).
///   Modelled on a quarter cylinder (symmetry planes), 20 a wide and deep, sliding on its base, frictionless punch.
/// - Lame's thick-walled hollow sphere under internal pressure p, outer surface free: the inner wall moves by
///   u(a) = p a^3 / (E (b^3 - a^3)) ((1 - 2 nu) a + (1 + nu) b^3 / (2 a^2)) (Timoshenko & Goodier, Theory of
///   Elasticity, 3rd ed. 1970, 141). Modelled on an octant (symmetry planes).
/// Both run the simulator's solver through time (real density, its damping and step) to the steady state.

#include "hs/core/Result.h"
#include "hs/mechanics/CorotationalFem.h"

#include <cstddef>

namespace hs::mechanics {

struct PunchParams {
    double youngsModulusKpa = 30.0;
    double poissonRatio = 0.47;
    double punchRadiusMm = 1.45;   ///< a 2.9 mm scope's radius
    double depthMm = 0.15;         ///< delta, the press (small against a: the linear regime of the solution)
    double domainRadii = 20.0;     ///< the block's radius and depth, in punch radii
    double finestMm = 0.25;        ///< mm, the elements' size under the punch
    double growth = 1.25;          ///< the elements' size grows by this from ring to ring beyond the punch (1: uniform)
    int sectors = 8;               ///< elements round the quarter circle
    double stiffeningStrain = 0.0; ///< FemMaterial::stiffeningStrain (0: linear, the textbook's material)
    FemSettings solver;            ///< the solver's step, iterations, damping, pressure (its defaults)
    double settleS = 1.0;          ///< s, held at depth after a 0.1 s ramp
    double rampS = 0.1;            ///< s, the press's ramp to depth
    /// In-plane strain the block is stretched by before the press (its rim drawn out radially over 0.5 s, held 1.5 s),
    /// as the distension stretches the cavity's wall; the top thins freely, the punch follows it down until the press.
    /// 0: the block at rest (the textbook's).
    double preStretch = 0.0;
};

struct VerificationResult {
    double simulated = 0.0;    ///< N (punch) or mm (sphere)
    double analytic = 0.0;     ///< the same, textbook
    double errorPercent = 0.0; ///< 100 (simulated - analytic) / analytic
    std::size_t points = 0, tets = 0;
    double residualN = 0.0; ///< the free degrees of freedom's imbalance at the end
    /// Punch: the tissue's stiffening within 3 punch radii of the punch's centre as the press began (the secant factor,
    /// volume-weighted, CorotationalFem::stiffeningAt), which `analytic` takes into its modulus; 1 at rest.
    double preStiffening = 1.0;
    double seconds = 0.0; ///< wall time of the run (mesh, factor, steps)
};

/// The punch on uniform elements of `edgeMm` (4 per quarter circle, the block at least 8 elements wide), coarser than
/// the punch: its load falls on the axis point alone, as a scope's tip on a simulation mesh's face.
PunchParams coarsePunchParams(double edgeMm);

/// Boussinesq's punch: `simulated` and `analytic` are forces, N.
[[nodiscard]] Result<VerificationResult> runPunch(const PunchParams& params);
double boussinesqPunchForceN(double radiusMm, double depthMm, double youngsModulusKpa, double poissonRatio);

struct LameParams {
    double youngsModulusKpa = 30.0;
    double poissonRatio = 0.47;
    double innerRadiusMm = 10.0;
    double outerRadiusMm = 20.0;
    double pressureKpa = 1.0;      ///< 7.5 mmHg: strains of a few percent, the linear regime of the solution
    double stiffeningStrain = 0.0; ///< FemMaterial::stiffeningStrain (0: linear, the textbook's material)
    int layers = 8;                ///< elements through the wall
    int subdivisions = 10;         ///< elements along an octant's edge
    FemSettings solver;
    double settleS = 0.5; ///< s, after a 0.1 s ramp of the pressure
};

/// Lame's sphere: `simulated` and `analytic` are the inner wall's radial displacement, mm.
[[nodiscard]] Result<VerificationResult> runLameSphere(const LameParams& params);
double lameInnerDisplacementMm(double innerMm, double outerMm, double pressureKpa, double youngsModulusKpa,
                               double poissonRatio);

} // namespace hs::mechanics
