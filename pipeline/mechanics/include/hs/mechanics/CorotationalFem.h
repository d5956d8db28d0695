#pragma once
// The soft tissue: corotational linear finite elements on the simulation mesh's tets (Muller & Gross, "Interactive
// Virtual Materials", GI 2004; Nesme et al., "Efficient, physically plausible finite elements", Eurographics 2005),
// the real density (lumped), Rayleigh damping, advanced by backward Euler. Each step solves the implicit equations by
// a chord (quasi-) Newton iteration whose matrix, H = M (1/h^2 + alpha/h) + (1 + beta/h) K0 + T, is built from the
// rest stiffness K0 and factored once (sparse LDL^T): every iteration evaluates the exact corotated forces, so a
// converged step, and every steady state, is the material's equilibrium; only the speed of convergence depends on
// how far the tets have turned. Contacts are unilateral constraints solved as a small linear complementarity problem
// with the solver's own compliance W = J H^-1 J^T (Duriez et al., "Realistic haptic rendering of interacting
// deformable objects in virtual environments", IEEE TVCG 12(1), 2006; the precomputed compliance of Saupin, Duriez &
// Cotin, "Contact model for haptic medical simulations", ISBMS 2008). docs/simulator.md ("Tissue") gives the
// verification against Boussinesq's punch and Lame's sphere.
//
// SI units inside (m, kg, s, Pa, N). Deterministic: the same inputs give the same state, bit for bit.

#include "hs/core/Parallel.h"
#include "hs/core/Result.h"
#include "hs/core/TetMesh.h"
#include "hs/core/Vec3.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace hs::mechanics {

struct FemMaterial {
    double youngsModulusPa = 30e3; ///< at small strain
    double poissonRatio = 0.47;
    double densityKgPerM3 = 1050.0;
    /// Soft tissue stiffens exponentially as it stretches (Fung, Am J Physiol 213:1532-1544, 1967): the deviatoric
    /// energy is 2 mu c^2 (cosh(|dev e| / c) - 1), mu |dev e|^2 at small strain, its tangent growing as e^(|e|/c).
    /// Human myometrium in vitro follows strain = C ln(stress) + B with tangent moduli of 70-200 psi at 10 psi
    /// (Pearsall & Roberts, J Biomech 11:167-176, 1978), so C = 0.05-0.14. c is that strain scale, for |dev e|
    /// (sqrt(3/2) times a uniaxial strain); 0: linear (the textbook verification).
    double stiffeningStrain = 0.0;
};

/// Where the last step's time went, ms (wall clock).
struct FemStepTimings {
    double forcesMs = 0.0;      ///< the corotated forces (and rotations)
    double solveMs = 0.0;       ///< the factor's solves
    double contactsMs = 0.0;    ///< the constraints' compliance and their complementarity problem
    int forwardIterations = 0;  ///< iterations whose constraints took forward solves (off the precomputed surface)
    int searchedIterations = 0; ///< iterations whose chord step the line search checked (a force evaluation or more)
};

struct FemSettings {
    double stepS = 0.005; ///< s, the time step h (up to 10 s: a static solve takes a long step)
    /// Rayleigh damping D = alpha M + beta K (docs/simulator.md, "Tissue": soft tissue's loss factor).
    double rayleighMassPerS = 1.0;    ///< alpha, 1/s
    double rayleighStiffnessS = 0.01; ///< beta, s
    int iterations = 2;               ///< chord iterations per step (the convergence study chose it)
    int contactSweeps = 60;           ///< projected Gauss-Seidel sweeps of a step's contact problem
    /// The volumetric strain averaged over each point's tets (the average nodal pressure tet of Bonet & Burton,
    /// Commun Numer Meth Eng 14:437-449, 1998): linear tets lock for nearly incompressible tissue (Poisson ratio
    /// 0.45-0.49) and come out too stiff; averaging the volume change at the points frees them.
    bool nodalPressure = true;
    /// The share of the volumetric energy kept per tet with the nodal pressure on (0-1). The nodal average alone lets a
    /// single small tet collapse at no cost in volume (the average nodal pressure tet's known spurious modes); a share
    /// held per tet stops that, at a little of the locking back (docs/simulator.md, "Verification").
    double tetPressureShare = 0.1;
    /// Assemble the iteration's matrix with the nodal pressure too. Off, the matrix keeps each tet's own pressure: a
    /// third of the factor's size and of a solve's time, while the forces (and so every converged state) stay the
    /// nodal pressure's; the iteration then converges a little slower in the volume-changing modes.
    bool nodalPressureMatrix = false;
    /// The stiffening's secant factor is held below this: the iteration's matrix is the rest stiffness, and a chord
    /// step converges only while the tissue is less than twice as stiff as that (docs/simulator.md, "Tissue").
    double maxStiffening = 1.9;
    /// (maxStiffening above applies to the forces; with refactorStiffened() called as the tissue stiffens it may be
    /// large.)
    /// The largest force a constraint row may carry (N for a contact): beyond it the row gives (a perforation's
    /// business, not the solver's); infinite by default.
    double maxConstraintForce = 1e300;
    /// Shorten a step whose residual would grow (a backtracking line search; one more force evaluation per iteration).
    /// Needed with stiffening materials, whose tangent outgrows the rest matrix.
    bool lineSearch = true;
    /// With lineSearch off, search anyway in an iteration that follows one with a tet held at the volume bound
    /// (minVolumeRatio below; its row carrying a force): a tet squeezed to a fifth of its volume no longer follows the
    /// warped rest matrix (its corotational forces leave that line), the cap on the stiffening no longer keeps a chord
    /// step from overshooting, and unchecked the overshoot can grow step on step until the tissue explodes. Costs
    /// nothing while no tet is at the bound.
    bool lineSearchAtVolumeBound = true;
    /// Threads for the force evaluation (each tet's and each point's work is independent, and the sums run in a
    /// fixed order: every thread count gives the same bits).
    int threads = 2;
    /// Solves per step spent refreshing the precomputed surface compliance near cuts (a dof's column each; see
    /// removeTets); 0: never (the rows near cuts keep solving until refactor()).
    int surfaceRefreshDofs = 1;
    /// Evaluate the residual at the end of each step (reactionN, residualN): one more force evaluation per step.
    bool endResidual = true;
    /// The correction of constraint rows off the precomputed surface (a volume row's interior points, rows near a
    /// cut) by one whole solve on every point. Off (the default), it is exact only on the points the rows and the
    /// changed forces touch (their columns of L^-1) and goes through the block on the rest of the surface; the
    /// other interior points follow in the next step's free motion, as they do for rows on the surface. The
    /// equilibrium is the same; the whole solve costs about as much as the step's chord solve.
    bool wholeCorrection = false;
    /// No tet's volume falls below this share of its rest volume (0: no such bound). Tissue is nearly incompressible
    /// (Poisson ratio 0.45-0.49), but the nodal-averaged pressure above lets a single tet lose its volume at little
    /// cost (the average nodal pressure tet's spurious modes), so a load concentrated on a point of a coarse mesh (a
    /// scope's tip on a node) can push that point through the tets behind it. Each tet that comes within
    /// `volumeGuardBand` of the bound is a unilateral constraint row (its volume ratio >= the bound), solved with the
    /// contacts by the same complementarity problem: it carries what the collapsing tet cannot, so the load spreads
    /// to its neighbours as an incompressible material's would. Rows on interior points sum their points' columns of
    /// L^-1 (a forward solve each, the first time a row meets the point after a change of the factor).
    double minVolumeRatio = 0.0;
    double volumeGuardBand = 0.25;
    /// The points of volume rows join the precomputed surface (extendPrecomputedSurface), up to this many in all: a
    /// tet held near the bound for a while (the cervix's stroma under a shaft levered in the canal) then costs its rows
    /// a sum on the block instead of forward solves in every step, once the refresh has computed its points' columns
    /// (surfaceRefreshDofs a step). 0: volume rows always take forward solves. Nothing without a precomputed surface.
    std::size_t volumeRowSurfacePoints = 256;
};

/// A unilateral constraint, linear in the points: C(x) = offset + sum_k gradient[k] . x[points[k]] >= 0, with a
/// force lambda >= 0 that acts on the tissue as lambda * gradient (N on each point when C is a length in m), and
/// lambda C = 0 (Signorini). A contact of a point of the surface with an obstacle is one (C the gap along the contact
/// normal); so is the cavity's volume against the fluid in it (C the room the cavity leaves the fluid, m^3, lambda the
/// pressure, Pa). `selfCompliance` adds give to the row itself (the fluid's outflow over a step, m^3/Pa; 0: none).
struct FemConstraint {
    std::vector<std::int32_t> points;
    std::vector<Vec3> gradient; ///< dC/dx at each point
    double offset = 0.0;
    double selfCompliance = 0.0;
    double force = 0.0; ///< out: lambda after the step
};

/// The complementarity problem of k contact rows: gap + W lambda >= 0, 0 <= lambda <= maxForce, complementary,
/// by projected Gauss-Seidel (Duriez et al. 2006) from the `lambda` given, at most `sweeps` sweeps (W k x k,
/// row-major; rows with no positive diagonal are left as they are). Allocates nothing (the haptics loop calls it).
void solveComplementarity(const std::vector<double>& w, const std::vector<double>& gap, double maxForce, int sweeps,
                          std::vector<double>& lambda);

/// A point of the tissue (sum of weights[k] x[points[k]]) kept behind the plane through `planePointM` with the unit
/// `normal` pointing away from the tissue: C = dot(normal, planePoint - point), the gap, in m; lambda in N.
FemConstraint contactRow(const std::array<std::int32_t, 3>& points, const std::array<double, 3>& weights,
                         const Vec3& normal, const Vec3& planePointM);

/// The give a flat punch of radius `punchRadiusM` finds below the resolution of a mesh whose surface edges are
/// `edgeM` long, pressing a face at the barycentric `weights`, m/N: what a contact row needs in `selfCompliance` so
/// that the press meets Boussinesq's F = 2 a E delta / (1 - nu^2) on that mesh (docs/simulator.md, "Verification").
/// The mesh's own local give for such a load (the same material's half-space):
/// - a load on one point of elements of size h acts as a punch of radius alpha h: (1 - nu^2) / (2 E alpha h), with
///   alpha 0.418 / 0.430 / 0.492 at nu 0.45 / 0.47 / 0.49 (`bench_tissue --coarse-punch`, h 2-8 mm; interpolated
///   between, held beyond);
/// - spread over the face's three points by the weights w, the points' cross terms at a distance h are the point
///   load's far field on a half-space, (1 - nu^2) / (pi E h) (Boussinesq; Johnson, Contact Mechanics, 1985, 3.2):
///   the give is (1 - nu^2) / (E h) (S / (2 alpha) + (1 - S) / pi), S = sum w^2 (1 at a point, 1/3 at the centre).
/// The difference from the punch's (1 - nu^2) / (2 E a) is added in series; 0 where the mesh is softer already.
/// Small-strain modulus: the material's stiffening is the mesh's part.
double punchSubElementCompliance(double punchRadiusM, double edgeM, const std::array<double, 3>& weights,
                                 const FemMaterial& material);

/// The stiffening of a punch's dimple `dimpleM` deep under a punch of radius `punchRadiusM`: the secant factor of
/// the material's own law (FemMaterial::stiffeningStrain; sinh x / x, x = |dev e| / c) at the representative strain
/// delta / a of a uniaxial compression (|dev e| = sqrt(2/3) delta / a), held below `maxStiffening` as the solver
/// holds its tets' (FemSettings::maxStiffening). 1 for a linear material. Divides punchSubElementCompliance.
double punchDimpleStiffening(double dimpleM, double punchRadiusM, const FemMaterial& material, double maxStiffening);

/// The obstacles' own compliance between constraints (row-major k x k, in C per unit force; empty: rigid obstacles
/// held in place). A scope held by a virtual coupling gives way by G K^-1 G^T.
struct ObstacleCompliance {
    std::vector<double> matrix;
};

class CorotationalFem {
public:
    CorotationalFem();
    ~CorotationalFem();
    CorotationalFem(CorotationalFem&&) noexcept;
    CorotationalFem& operator=(CorotationalFem&&) noexcept;

    /// `pointsM` at rest (m); one material per tet; `fixedDof` per point 3 flags (x, y, z held at their target,
    /// initially the rest position); `tethers` (point, N/m) pull a point back to its rest position isotropically.
    /// Fails (InvalidInput) for a bad material, an inverted or flat tet or a step out of range.
    [[nodiscard]] Status build(const std::vector<Vec3>& pointsM, const std::vector<Tet>& tets,
                               const std::vector<FemMaterial>& materials,
                               const std::vector<std::array<bool, 3>>& fixedDof,
                               const std::vector<std::pair<std::int32_t, double>>& tethers,
                               const FemSettings& settings);

    /// Factors the iteration's matrix again with each tet's tangent stiffening at the current shape (the precomputed
    /// surface compliance is kept: it only guides the contacts' first guess). Returns the largest factor. Call it
    /// at a fixed point of the step (replays stay bit for bit) when the tissue has stiffened or relaxed.
    double refactorStiffened();

    /// The same tissue as `other` (its rest shape, tets, materials, supports, tethers and removed tets) with other
    /// settings, at rest: a static solve of a running model takes a long step.
    [[nodiscard]] Status buildLike(const CorotationalFem& other, const FemSettings& settings);

    /// Where the held degrees of freedom of `point` are (m; the free ones ignore it).
    void setTarget(std::size_t point, const Vec3& positionM);

    /// One step: external forces (N per point, held constant over the step) and the constraints (linearized by the
    /// caller between steps; their force is set), with the obstacles' compliance between them (the caller moves its
    /// obstacles by that compliance times the forces). Rows naming a point out of range are dropped.
    void step(const std::vector<Vec3>& externalForcesN, std::vector<FemConstraint>& constraints,
              const ObstacleCompliance& obstacle = {});

    /// Removes tets (they carry no force from then on) and keeps what is left a valid solid
    /// (docs/simulator.md, "Cutting"; Forest, Delingette & Ayache, Med Image Anal 9(2):113-122, 2005):
    /// - every piece the removal cuts free goes too: the live tets fall into pieces joined through shared faces, and
    ///   a piece with no held or tethered point (one that hangs on by an edge or a point, or floats) is removed and
    ///   returned as a chip;
    /// - the boundary stays a manifold: a point the removal touches whose live tets no longer meet it as one disk (two
    ///   parts touching at the point, or along an edge through it) keeps the part of most volume, the others are
    ///   removed (with the chips they make); where one part still does not close into a disk, every live tet of the
    ///   point goes.
    /// Points left without a tet are held where they are; the points' masses and volumes are the live tets'.
    /// `refactor` Now rebuilds the iteration's matrix and factors it again (about 100 ms on a simulation mesh of 9k
    /// tets); Later keeps the factor, which is then stiffer than the tissue: the chord iteration still converges to
    /// the live tets' equilibrium (its matrix bounds their stiffness from above), only more slowly near the cut, until
    /// refactor() is called. Out-of-range and removed tets are ignored.
    /// Downdate: each removed tet's stiffness is taken out of the factor by rank-one downdates along the elimination
    /// tree's paths (Davis & Hager, SIAM J Matrix Anal Appl 20(3):606-627, 1999): the factor stays the live tets'
    /// (their masses kept: the matrix a little heavier than the tissue). The precomputed surface compliance becomes
    /// stale until refactor(): contact rows on points within a tet of a removed tet take the forward solves on their
    /// reach (exact) until step() has computed their columns again (FemSettings::surfaceRefreshDofs a step); rows
    /// elsewhere keep the block from before the cut, a little stiffer than the tissue now (removing tets only adds
    /// give): like a stale factor it only slows the convergence of those rows, the steps' residual being the live
    /// tets' (docs/simulator.md, "Cutting"). With the nodal pressure in the matrix,
    /// or a pivot that would not stay positive, it rebuilds instead.
    enum class Refactor { Now, Later, Downdate };
    struct Removal {
        std::vector<std::size_t> removed;            ///< every tet this call removed, ascending
        std::vector<std::vector<std::size_t>> chips; ///< the pieces cut free, each ascending, by their first tet
        std::size_t manifoldTets = 0;                ///< of `removed`, the tets taken to keep the boundary a manifold
        std::size_t danglingTets = 0;                ///< of `removed`, tets the cut left held by one face or none
        /// Of `removed`, the tets taken out of the factor by downdates (Refactor::Downdate): a chip's inside, whose
        /// points all lost their last live tet, stays in it (it reaches no live point's solve).
        std::size_t downdated = 0;
    };
    Removal removeTets(const std::vector<std::size_t>& tets, Refactor refactor = Refactor::Now);
    /// The material of `tet` (as built).
    const FemMaterial& material(std::size_t tet) const { return m_materials[tet]; }
    bool tetRemoved(std::size_t tet) const { return tet < m_removed.size() && m_removed[tet] != 0; }
    /// The factor by which `tet`'s exponential stiffening multiplies its modulus at the current positions: the secant
    /// sinh(x) / x the forces use (FemMaterial::stiffeningStrain), held below FemSettings::maxStiffening. 1 for a
    /// linear material, a removed tet or one out of range.
    double stiffeningAt(std::size_t tet) const;
    std::size_t liveTetCount() const { return m_liveTets; }
    /// Whether tets were removed since the matrix was factored (removeTets with Refactor::Later).
    bool factorStale() const { return m_factorStale; }
    /// How stale the factor is: the largest share of its volume a point of live tets has lost since the factor was
    /// built (0: fresh; near 1: a point hangs on a sliver of what the factor holds it by). The chord steps converge
    /// for any staleness, but a constraint row's compliance comes from the factor, so a row on such a point is solved
    /// as far stiffer than it is and overshoots (beyond a factor of two it diverges): rebuild before that.
    double factorStaleness() const;
    /// Rebuilds the matrix from the live tets, factors it and precomputes the surface compliance again (about 1.5 s
    /// with the surface of a simulation mesh of 9k tets precomputed). Drops a rebuild startRefactor began.
    void refactor();
    /// The same on a thread of its own from the live tets as they are now, while the steps go on with the factor
    /// they have (the caller's cores are shared with it). False (nothing started) while one runs.
    bool startRefactor();
    bool refactorRunning() const { return m_rebuild != nullptr; }
    /// Waits for the rebuild startRefactor began and takes its factor and surface compliance in (nothing without
    /// one). Call it at a fixed step (e.g. a fixed number of steps after the start) and a replay takes the same
    /// factor at the same step: the result does not depend on when the thread finished. Tets removed since the start
    /// with Refactor::Later leave the factor stale again; removed by downdates (Refactor::Downdate), the factor in use
    /// already lacks them and the rebuilt one does not: the rebuilt one is dropped (false; start another). True when
    /// it was taken in.
    bool finishRefactor();
    /// Whether the surface's compliance is precomputed for the factor in use (precomputeCompliance; a downdate drops
    /// it, a rebuild restores it).
    bool surfacePrecomputed() const { return m_compliantList.empty() || (m_compliantCount > 0 && !m_complianceStale); }
    /// Whether the precomputed surface compliance is the one of the factor before the downdates since (kept for the
    /// contacts away from the cut: see removeTets).
    bool surfaceComplianceStale() const { return m_complianceStale; }
    /// Points the live tets meet as more than one disk (a singular point of the boundary) or whose live tets' faces
    /// opposite them do not close into one disk or sphere: 0 in a valid solid.
    std::vector<std::int32_t> singularPoints() const;
    /// Live pieces (joined through faces) with no held or tethered point: 0 after every removeTets.
    std::size_t looseLivePieces() const;
    /// The rest volume of tet `t`, m^3.
    double restVolumeM3(std::size_t t) const { return t < m_volume.size() ? m_volume[t] : 0.0; }
    const std::vector<Tet>& tets() const { return m_tets; }
    /// Per tet, the tet across each of its faces (face k opposite its point k), -1 on the mesh's boundary.
    const std::vector<std::array<std::int32_t, 4>>& neighbours() const { return m_neighbours; }

    /// The give of the tissue over one step under the load pattern `forces` (N per point): f^T R H^-1 R^T f, in m per
    /// N times the pattern's units squared (one solve). For the cavity's pressure pattern (m^2 per point) it is the
    /// cavity's volume change per pascal, m^3/Pa.
    double loadCompliance(const std::vector<Vec3>& forces) const;

    /// Precomputes the compliance H^-1 between the degrees of freedom of `points` (the surface a tool can touch), so a
    /// step's contact problem costs no solve per contact; rows on other points, or on more than a few dozen points
    /// (the cavity's volume), get their column from a solve.
    void precomputeCompliance(const std::vector<std::int32_t>& points);
    /// Adds `points` (those not on it yet) to the precomputed surface: faces a cut bared, which a tool now touches.
    /// Their columns are computed by the steps' refresh (FemSettings::surfaceRefreshDofs); until then rows on them
    /// solve. Nothing without a precomputed surface.
    void extendPrecomputedSurface(const std::vector<std::int32_t>& points);

    const std::vector<Vec3>& positionsM() const { return m_x; }
    const std::vector<Vec3>& restM() const { return m_rest; }
    const std::vector<Vec3>& velocitiesMPerS() const { return m_v; }
    std::size_t pointCount() const { return m_x.size(); }
    std::size_t tetCount() const { return m_tets.size(); }
    const FemSettings& settings() const { return m_settings; }
    const FemStepTimings& lastTimings() const { return m_timings; }
    /// The line search's last step length (1: the full chord step).
    double lastStepLength() const { return m_stepLength; }
    /// Non-zeros of the factor's L: what a solve reads.
    std::size_t factorNonZeros() const;

    /// The force the supports exert on `point` to hold its fixed degrees of freedom (N; zero on free ones), from
    /// the last step's final residual: at rest, minus the tissue's force on the support.
    Vec3 reactionN(std::size_t point) const;
    /// The norm of the free degrees of freedom's residual (N) after the last step: the equations' imbalance.
    double residualN() const { return m_residualNorm; }
    /// Steps whose result was not finite and were undone (the tissue held still instead): 0 in a healthy run.
    std::size_t recoveries() const { return m_recoveries; }
    /// The compliance W = J H^-1 J^T of the last step's constraints (row-major k x k): the solver's own give at the
    /// contacts, which the haptics loop renders between steps.
    const std::vector<double>& lastContactCompliance() const { return m_lastW; }
    /// The volume rows (FemSettings::minVolumeRatio) the last step's last iteration solved.
    std::size_t lastVolumeRows() const { return m_lastVolumeRows; }
    /// Those of them that carried a force (a tet held at the bound).
    std::size_t lastBoundRows() const { return m_lastBoundRows; }

    /// Elastic energy of the corotated linear material (J), the smallest tet volume ratio (<= 0: inverted) with the
    /// count of inverted tets, the largest speed (m/s): the stability checks.
    double elasticEnergyJ() const;
    double minVolumeRatio(std::size_t& inverted) const;
    double maxSpeedMPerS() const;
    double kineticEnergyJ() const;

private:
    struct Factor;
    /// What the iteration's matrix is built from.
    struct FactorInputs {
        const FemSettings& settings;
        const std::vector<Vec3>& rest;
        const std::vector<Tet>& tets;
        const std::vector<std::array<double, 9>>& dmInv;
        const std::vector<double>& volume;
        const std::vector<double>& mu;
        const std::vector<double>& lambda;
        const std::vector<char>& removed;
        const std::vector<std::array<bool, 3>>& fixed;
        const std::vector<double>& mass;
        const std::vector<double>& pointVolume;
        const std::vector<double>& pointBulk;
        const std::vector<double>& matrixStiffening;
        const std::vector<double>& tetherStiffness;
    };
    FactorInputs factorInputs() const;
    /// Assembles the matrix of `in` and factors it into `f` (`partition`: the factor's halves, cut when empty).
    static void buildFactor(const FactorInputs& in, std::vector<int>& partition, Factor& f);
    /// H^-1 b by the factor `f` (the held dofs of `fixed` zero).
    static void solveWith(const Factor& f, const std::vector<std::array<bool, 3>>& fixed, WorkerTeam& team,
                          std::vector<double>& b);
    /// L^-T y in place, y in the factor's order (solveWith's second half).
    static void backwardWith(const Factor& f, WorkerTeam& team, std::vector<double>& y);
    /// The dense compliance between the dofs of `list`'s points, and their columns of L^-1 (f.columnY).
    static void precomputeInto(Factor& f, const std::vector<std::int32_t>& list,
                               const std::vector<std::array<bool, 3>>& fixed, WorkerTeam& team,
                               std::vector<double>& compliance);
    /// Takes tet `t`'s stiffness out of the factor (Refactor::Downdate); false when a pivot would not stay positive
    /// (the factor is then half modified: the caller rebuilds it).
    bool downdateTet(std::size_t t);
    struct Rebuild;
    std::unique_ptr<Rebuild> m_rebuild; ///< a factor being rebuilt on its own thread (startRefactor)
    void assembleAndFactor();
    /// Internal elastic plus damping forces at positions x with velocity v (N per point), updating the rotations.
    void internalForces(const std::vector<Vec3>& x, const std::vector<Vec3>& v, std::vector<Vec3>& out);
    void solveInPlace(std::vector<double>& b) const;
    /// R H^-1 R^T b with each point's rotation R (the rest factor warped to the tissue's turn: Muller & Gross 2004's
    /// stiffness warping applied to the preconditioner, as SOFA's PrecomputedWarpPreconditioner does), so parts that
    /// turn far (the corpus tilting, a flap left by a cut) converge as fast as at rest.
    void solveWarped(std::vector<double>& b) const;
    void buildIncidence();
    /// Each point's mass, volume and bulk modulus from its live tets (after a removal).
    void updatePointMeasures();
    /// Whether the live tets of `point` meet it as one disk or sphere (their faces opposite it edge-connected, their
    /// border one simple cycle); otherwise `keep` gets the live tets of its part of most volume (empty when that part
    /// alone does not close into a disk either).
    bool pointIsManifold(std::size_t point, std::vector<std::size_t>* keep) const;
    /// The live tets' pieces with no held or tethered point, each ascending, by their first tet.
    std::vector<std::vector<std::size_t>> loosePieces() const;
    /// The exponential stiffening's secant factor sinh(x)/x, x = |dev e| / c, for a tet's corotated stretch `s`.
    double stiffening(std::size_t tet, const std::array<double, 9>& s) const;
    double stiffeningArgument(std::size_t tet, const std::array<double, 9>& s) const;
    /// R^T F of tet `t` at the current positions (its rotation found from the last one, which stays as it was).
    std::array<double, 9> corotatedStretch(std::size_t t, int iterations) const;
    /// W = J R H^-1 R^T J^T of the rows: between two rows on the precomputed surface from its block, for a pair with
    /// a row elsewhere from the rows' columns of L^-1 (forwardRows; `forwarded`: already done for these rows).
    void complianceBetween(const std::vector<FemConstraint>& rows, bool forwarded, std::vector<double>& w);
    void solveContacts(std::vector<FemConstraint>& rows, std::size_t external, const ObstacleCompliance& obstacle,
                       const std::vector<double>& gap, bool forwarded, std::vector<double>& lambda);
    /// The (dof, value) entries of P R^T f in the factor's order, held dofs left out.
    void forwardEntries(const std::vector<std::pair<std::int32_t, Vec3>>& forces,
                        std::vector<std::pair<int, double>>& b) const;
    /// L^-1 P R^T g for each row's gradient g, on its reach (the factor's rowY), on the team's threads.
    void forwardRows(const std::vector<FemConstraint>& rows) const;
    /// L^-1 P R^T f for the constraints' last forces (the factor's forcedY).
    void forwardForced() const;
    /// Each row's gradient times R H^-1 R^T f_last: the last forces' motion along the row (after forwardRows and
    /// forwardForced).
    void forwardProducts(std::vector<double>& out) const;
    /// The step's correction off the precomputed surface: x moves by R H^-1 R^T df exactly on the points of `change`
    /// (df) and of `rows`, from their columns of L^-1, and by the block on the rest of the surface (false, nothing
    /// moved: too many points or a row on many, which take one whole solve).
    bool correctByColumns(const std::vector<std::pair<std::int32_t, Vec3>>& change,
                          const std::vector<FemConstraint>& rows, std::vector<Vec3>& x) const;
    /// The volume rows (settings.minVolumeRatio) of the tets within the guard band of the bound at positions x.
    void volumeRows(const std::vector<Vec3>& x, std::vector<FemConstraint>& rows) const;
    bool onPrecomputedSurface(const std::vector<FemConstraint>& rows) const;
    bool held(std::size_t point) const;
    /// R S R^T f on the precomputed points for forces f on some of them.
    void surfaceResponse(const std::vector<std::pair<std::int32_t, Vec3>>& forces, std::vector<Vec3>& out) const;

    std::unique_ptr<Factor> m_factor;
    std::vector<int> m_partition; ///< per point, the factor's half (0, 1) or the separator (2); kept while tets go
    std::unique_ptr<WorkerTeam> m_team; ///< the force evaluation's threads (settings.threads, kept between steps)
    FemSettings m_settings;
    std::vector<Vec3> m_rest, m_x, m_v, m_target, m_xStart, m_force, m_reaction;
    std::vector<std::array<bool, 3>> m_fixed;
    std::vector<double> m_mass; ///< kg, lumped
    std::vector<Tet> m_tets;
    std::vector<FemMaterial> m_materials;
    std::vector<double> m_matrixStiffening; ///< per tet, the deviatoric stiffness factor the matrix was built with
    std::vector<char> m_removed;
    std::size_t m_liveTets = 0;
    bool m_factorStale = false;
    std::vector<std::array<std::int32_t, 4>> m_neighbours; ///< the tet across each face (kTetFacePoints), -1: none
    std::vector<std::array<double, 9>> m_dmInv;            ///< inverse rest shape matrix, row-major
    std::vector<double> m_volume;                          ///< m^3 at rest
    std::vector<double> m_restDet;                  ///< det of the rest shape matrix (6 V, with the tet's orientation)
    std::vector<double> m_mu, m_lambda;             ///< Pa
    std::vector<double> m_pointVolume;              ///< m^3, a quarter of each tet round a point
    std::vector<double> m_factorPointVolume;        ///< m_pointVolume when the factor was built
    std::vector<std::array<bool, 3>> m_factorFixed; ///< m_fixed when the factor was built
    std::vector<double> m_pointBulk;                ///< Pa, the bulk modulus averaged over a point's tets by volume
    std::vector<double> m_tetDilatation, m_tetRate, m_pointDilatation, m_pointRate; ///< scratch of internalForces
    std::vector<std::array<double, 9>> m_tetR;
    std::vector<std::array<double, 9>> m_tetStrain, m_tetStrainRate;  ///< scratch: sym parts' sources per tet
    std::vector<std::array<Vec3, 4>> m_tetForces;                     ///< scratch: each tet's corner forces
    std::vector<std::size_t> m_incidenceStart;                        ///< CSR offsets into m_incidence, per point
    std::vector<std::pair<std::uint32_t, std::uint32_t>> m_incidence; ///< (tet, corner) per point, tet order
    std::vector<std::array<double, 9>> m_pointR;    ///< each point's rotation (identity where a dof is held)
    std::vector<std::array<double, 4>> m_pointQuat; ///< its warm start
    std::size_t m_recoveries = 0;                   ///< scratch: each tet's rotation in the last force evaluation
    std::vector<std::array<double, 4>> m_rotation;
    std::vector<std::pair<std::int32_t, double>> m_tethers;
    std::vector<double> m_tetherStiffness; ///< N/m per point
    // Precomputed compliance between surface dofs: index of a point in it (-1: none), the dense block.
    std::vector<std::int32_t> m_compliantIndex, m_compliantList;
    std::vector<Vec3> m_constraintForce;      ///< N per point: the constraints' forces of the last step
    std::vector<std::int32_t> m_forcedPoints; ///< the points those act on
    std::vector<double> m_compliance;         ///< (3 m) x (3 m), row-major
    std::size_t m_compliantCount = 0;
    /// Downdates since the surface was precomputed: its block is the factor's before them. Rows on points near no
    /// removed tet keep using it; rows on points near one (m_staleNear) solve until their columns are refreshed.
    bool m_complianceStale = false;
    /// Per point: a point of a tet removed since its columns were computed, or of a tet sharing a point with one.
    std::vector<char> m_staleNear;
    /// Computes `dofs` columns of the block again with the factor in use, for the points near a cut in list order
    /// (from where the last call stopped: every replay refreshes the same columns at the same step); the block is no
    /// longer stale once no point near a cut is left.
    void refreshStaleSurface(int dofs);
    std::size_t m_complianceStride = 0; ///< the block's row length (3 m and room for points the cuts bare)
    std::size_t m_refreshPoint = 0;     ///< the list index the refresh goes on from
    std::size_t m_refreshDof = 0;       ///< and the dof of that point
    /// Marks the points near the tets removed (`removed`) in m_staleNear.
    void markStaleNear(const std::vector<std::size_t>& removed);
    /// Point `p` has a precomputed column that holds for the factor in use, or near enough: on the list, and, with
    /// the block stale, no removed tet within a tet of it.
    bool precomputedAt(std::size_t p) const;
    std::vector<double> m_lastW;
    std::size_t m_volumeRowPointsAdded = 0; ///< points volume rows brought onto the precomputed surface
    std::size_t m_lastVolumeRows = 0;
    std::size_t m_lastBoundRows = 0;
    double m_residualNorm = 0.0;
    double m_stepLength = 1.0; ///< the line search's last step length
    mutable FemStepTimings m_timings;
};

} // namespace hs::mechanics
