#pragma once
/// The simulator's world: a scene package's simulation mesh as soft tissue held at the cervix, the rigid scope
/// about the cervical pivot, the distension fluid and the trial's metrics, advanced by a fixed step. The world is a
/// deterministic function of its package, its options and the device samples it is given: replaying a trial's
/// samples gives the same state and metrics, bit for bit (docs/simulator.md).
///
/// Threads: step() and everything that reads the running state belong to one thread (the physics thread).
/// visualPoints() and the accessors of the loaded scene only read data fixed at load and may be called from any
/// thread; the physics thread hands state to others through snapshot() and hapticFrame().

#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/TetMesh.h"
#include "hs/core/Vec3.h"
#include "hs/scene/Scene.h"
#include "hs/sim/Device.h"
#include "hs/sim/HapticFrame.h"
#include "hs/sim/Metrics.h"
#include "hs/sim/Scope.h"
#include "hs/sim/Script.h"
#include "hs/sim/Trial.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace hs::sim {

struct WorldOptions {
    ScopeConfig scope;
    FluidSettings fluid;
    Exercise exercise = Exercise::Exploration;
    std::uint64_t seed = 1;
    double stepS = 0.005;     ///< s, the fixed physics step (200 Hz); 0.001-0.02, a whole number of device ticks
    int solverIterations = 1; ///< the tissue solver's iterations per step, 1-50 (docs/simulator.md: the study)
    /// mm; 0 (the default): the scope pivots at the external os and the portio is held. 40-120 (a bench option, not
    /// recorded in a trial): it pivots at the introitus that far behind the os, on the canal's axis or on the approach
    /// setApproach gives, and the portio hangs on the cervix's supports with the rest of it (docs/simulator.md, "What
    /// is not modelled yet").
    double introitusMm = 0.0;
    /// The tissue without its exponential stiffening, linear as the textbook's material (a bench option, not recorded
    /// in a trial: the press against the moduli alone; docs/simulator.md, "What is not modelled yet").
    bool linearTissue = false;
};
/// InvalidInput naming the field and its range.
[[nodiscard]] Status checkWorldOptions(const WorldOptions& options);

/// The distension fluid's state.
struct FluidState {
    double pressureKpa = 0.0; ///< intrauterine pressure
    double inflowMlPerS = 0.0;
    double outflowMlPerS = 0.0;
    double intravasationMlPerS = 0.0;
    double inflowTotalMl = 0.0;
    double outflowTotalMl = 0.0;
    double deficitMl = 0.0;    ///< inflow - outflow
    double distensionMl = 0.0; ///< fluid held in the cavity beyond its rest volume
    double turbidity = 0.0;    ///< 0 clear .. 1 opaque (debris stirred by contact, washed out by flow)
    double redOut = 0.0;       ///< 0 .. 1: the walls closing on the lens (low pressure or the lens on tissue)
    bool deficitWarning = false;
    bool deficitLimit = false;
    double pumpSetKpa = 0.0; ///< the pump's set pressure now: the trial's, moved by the pump's buttons
    /// The cut surface's open vessels (docs/simulator.md, "Bleeding"): blood into the cavity below the vessels'
    /// pressure, fluid into the veins above theirs (part of intravasationMlPerS).
    double bleedingMlPerS = 0.0;
    double cutIntravasationMlPerS = 0.0;
    double intravasationTotalMl = 0.0;
    double bloodLossMl = 0.0;     ///< blood from the cut vessels so far
    double bloodInCavityMl = 0.0; ///< of it, still in the cavity (the rest washed out)
    double bloodFraction = 0.0;   ///< blood's share of the cavity's fluid, 0..1 (what reddens the view)
};

struct ContactState {
    bool touching = false;   ///< the scope touches the tissue this step
    double forceN = 0.0;     ///< N, the tissue's force on the scope
    double tipForceN = 0.0;  ///< N, of it the force on the tip
    Vec3 pointMm;            ///< where (the strongest contact)
    bool perforated = false; ///< the tip is beyond the wall
};

/// The instrument out of the scope as the step left it (the operative exercises), to draw it. The resectoscope's
/// loop: loopWire(LoopElectrode with widthMm, middleMm, axis, down) gives its wire; scissors and grasper: jawWire(a
/// JawInstrument of jawLengthMm, middleMm as the hinge, axis, down, jawOpenDeg) their jaws.
struct LoopState {
    bool out = false; ///< an instrument is in use (an operative exercise)
    std::uint32_t instrument = kInstrumentNone;
    bool cutting = false;     ///< the cutting pedal is down (the loop), the scissors' blades are closing
    bool coagulating = false; ///< the coagulating pedal is down (and the cutting pedal up)
    double widthMm = 0.0;     ///< the loop's span
    double travelMm = 0.0;    ///< the working element: the loop's middle (the jaws' hinge) this far beyond the tip
    double jawLengthMm = 0.0; ///< scissors and grasper
    double jawOpenDeg = 0.0;  ///< each jaw's angle off the shaft (0: shut)
    bool holding = false;     ///< the grasper holds a chip
    Vec3 middleMm, axis, down;
};

/// What one step left: the scope, the fluid, the contact.
/// Blood from the cut vessels not yet mixed through the cavity's fluid (docs/simulator.md, "Blood clouds"): each a
/// Gaussian cloud, its blood `bloodMl` spread about `centreMm` with the standard deviation `sigmaMm`.
struct BloodCloud {
    Vec3 centreMm;
    double sigmaMm = 0.0;
    double bloodMl = 0.0;
    double ageS = 0.0; ///< s since the vessels began giving its blood
};
inline constexpr std::size_t kMaxBloodClouds = 12;
struct BloodClouds {
    std::array<BloodCloud, kMaxBloodClouds> clouds{}; ///< the first `count`, oldest first
    std::size_t count = 0;
    /// The blood in the cavity outside the clouds, mixed through the fluid: its share of the fluid, 0..1 (the view's
    /// even reddening; FluidState::bloodFraction counts the clouds' blood too).
    double mixedFraction = 0.0;
};

struct WorldState {
    std::uint64_t step = 0;
    double timeS = 0.0;
    DeviceSample sample; ///< the newest device sample the step consumed
    ScopePose scope;
    FluidState fluid;
    ContactState contact;
    double horizonErrorDeg = 0.0;
    bool inCavity = false;        ///< the tip is beyond the internal os
    double cavityOpeningMl = 0.0; ///< mL, the cavity's volume in the deformed tissue beyond its volume at rest
    LoopState loop;
    BloodClouds blood;
};

/// What the cuts have done to the tissue so far, to draw it: shared between threads, never changed once published
/// (a cut publishes a new one).
struct CutView {
    std::uint64_t events = 0;                 ///< cut events so far (a new view per event)
    std::vector<char> removedTets;            ///< per simulation tet, removed
    std::vector<Triangle> faces;              ///< the live faces the cuts bared, in simulation point indices
    std::vector<clinical::Tissue> faceTissue; ///< each one's tissue (its live tet's)
};

/// A piece of tissue the loop cut away, in the cavity's fluid (docs/simulator.md, "Chips").
struct Chip {
    Vec3 positionMm;
    double volumeMl = 0.0;
    double radiusMm = 0.0; ///< of a sphere of its volume
    clinical::Tissue tissue = clinical::Tissue::Myometrium;
    bool hooked = false;  ///< caught by the drawn-in loop: it leaves the cavity with the scope (let go when the
                          ///< loop is exchanged for the scissors or the grasper)
    bool grasped = false; ///< held in the grasper's jaws: it goes where they go until they open
};

/// The state other threads draw: the simulation mesh's points and the world's state, copied at the end of a step,
/// what the cuts have done (null before the first cut) and the chips in the cavity.
struct WorldSnapshot {
    std::vector<Vec3> simulationPointsMm;
    WorldState state;
    std::shared_ptr<const CutView> cut;
    std::vector<Chip> chips;
};

class World {
public:
    /// Reads the package (scene::readScenePackage), checks it has a simulation mesh (InvalidInput naming the
    /// package otherwise: "regenerate it with this version"), and builds the world.
    [[nodiscard]] static Result<std::unique_ptr<World>>
    load(const std::string& packageFolder, const WorldOptions& options, Progress& progress = Progress::none());
    /// The same from a scene in memory; `sceneSha256` identifies it in trials (the manifest's checksum).
    [[nodiscard]] static Result<std::unique_ptr<World>> fromScene(scene::Scene scene, std::string sceneSha256,
                                                                  const WorldOptions& options,
                                                                  Progress& progress = Progress::none());
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    /// Device ticks per step (stepS * kDeviceRateHz).
    std::size_t ticksPerStep() const;
    /// One physics step consuming ticksPerStep() samples (in tick order, continuing the previous step's ticks).
    /// InvalidInput for a wrong count, a tick out of sequence or an invalid sample (the world is unchanged).
    [[nodiscard]] Status step(const DeviceSample* samples, std::size_t count);

    const WorldOptions& options() const;
    const scene::Scene& scene() const;
    const std::string& sceneSha256() const;
    const ScopeFrame& frame() const;
    /// With options().introitusMm > 0 and before the first step: the introitus on the line through the external os
    /// along `shaft` (unit, towards the os). InvalidInput otherwise.
    [[nodiscard]] Status setApproach(const Vec3& shaft);
    const scene::ScopeLandmarks& landmarks() const;
    /// The simulation mesh at rest (scene region ids) and its boundary (the surface the scope touches).
    const TetMesh& simulationMesh() const;
    const SurfaceMesh& contactSurface() const;

    const WorldState& state() const;
    const std::vector<Vec3>& simulationPointsMm() const;
    WorldSnapshot snapshot() const;
    /// The newest haptic frame (published at the end of every step).
    std::shared_ptr<const HapticFrame> hapticFrame() const;
    /// The visual surface's points for a state of the simulation mesh (its barycentric embedding); thread-safe.
    void visualPoints(const std::vector<Vec3>& simulationPointsMm, std::vector<Vec3>& out) const;
    /// The same for the points `only` (indices into the visual surface; empty: all): `out` has every point, those
    /// not in `only` are left as they were (zero when `out` grows).
    void visualPoints(const std::vector<Vec3>& simulationPointsMm, std::vector<Vec3>& out,
                      const std::vector<std::int32_t>& only) const;
    /// Per visual surface point, whether the tet it is embedded in was removed by a cut (`cut` from a snapshot; all
    /// false without one): the view hides the faces on such points.
    std::vector<char> visualPointsCut(const CutView* cut) const;

    const TrialMetrics& metrics() const;
    /// The report of the trial so far (with the header the trial would record).
    TrialReport report() const;
    /// The trial header of this world's options.
    TrialHeader trialHeader() const;

    /// Physics statistics: elastic energy (J), the smallest tet volume ratio (current / rest; <= 0 inverted) and the
    /// largest point speed (mm/s) after the last step: the stability checks.
    struct Health {
        double elasticEnergyJ = 0.0;
        double minVolumeRatio = 1.0;
        double maxSpeedMmPerS = 0.0;
        std::size_t invertedTets = 0;
        /// Steps whose tissue motion was shortened, and refused, because it inverted a tet (the tissue moves as far as
        /// no tet inverts; docs/simulator.md, "Tissue"): since load.
        std::size_t shortenedSteps = 0;
        std::size_t refusedSteps = 0;
    };
    Health health() const;
    /// The tissue's Young's modulus around `pointMm` in the state the last step left, kPa: over the live tets with a
    /// point within `radiusMm` of it (as the points lie now), each tet's small-strain modulus times the secant factor
    /// of its exponential stiffening (CorotationalFem::stiffeningAt; `stiffened` false: without it), averaged by rest
    /// volume. 0 where no tet is that near. What a press there meets, as the material law has it.
    double tissueModulusNearKpa(const Vec3& pointMm, double radiusMm, bool stiffened = true) const;
    /// Whether the tissue's surface compliance is precomputed for the factor in use: false from a cut until the
    /// rebuilt factor is taken in (the contacts then cost forward solves; docs/simulator.md, "Cutting").
    bool surfacePrecomputed() const;

    /// The cavity's opening (mL over rest) at `pressureKpa` (0-40) by a static solve of the same tissue model the
    /// steps run (from rest, no scope): the steady state the simulation's distension must reach. Takes about a second.
    [[nodiscard]] Result<double> staticCavityOpeningMl(double pressureKpa) const;

    /// Where the physics steps' wall-clock time went since load, ms summed over steps (the benchmark's breakdown; never
    /// read by the physics, so it does not touch replays).
    struct StepTimings {
        std::uint64_t steps = 0;
        double totalMs = 0.0;
        double tissueForcesMs = 0.0;  ///< the solver's corotated forces
        double tissueSolvesMs = 0.0;  ///< the solver's factor solves
        double contactSolveMs = 0.0;  ///< the contacts' compliance and complementarity problem
        double contactSearchMs = 0.0; ///< the scope's contact candidates
        double visibilityMs = 0.0;    ///< what the optic sees, marking
        double cutMs = 0.0; ///< the loop: its cuts (topology, the contact surface), coagulation, the factor's rebuild
        std::uint64_t forwardContactSteps = 0; ///< steps whose contacts took forward solves (not the surface's block)
        std::uint64_t volumeRowSteps = 0; ///< steps with a tet at the volume bound among the rows (interior points)
        /// Steps whose chord step the line search checked (a tet held at the volume bound).
        std::uint64_t searchedSteps = 0;
    };
    const StepTimings& stepTimings() const;

private:
    friend Script explorationScript(const World& world, double durationS);
    friend Result<struct PressPlan> pressScript(const World& world, int pathology, double depthMm, double holdS,
                                                std::size_t rank);
    friend Script roughScript(const World& world, double durationS, std::uint64_t seed);
    friend Script entryScript(const World& world, double offAxisDeg, double towardDeg);
    friend Vec3 entryShaft(const World& world, double offAxisDeg, double towardDeg);
    friend Script entryScriptAlong(const World& world, const Vec3& shaft);
    friend Result<Script> resectionScript(const World& world, int pathology);
    World();
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// The physics engine and its version, recorded in every trial: bumped whenever a change alters what a step computes,
/// so a trial recorded by another engine is refused instead of replayed into different results.
std::string_view physicsEngine();

/// Whether a trial recorded with `trial` can be replayed bit for bit by a world with `options`: InvalidInput naming
/// the header field that differs (header.physics.engine, header.physics.stepS, header.physics.solverIterations,
/// header.seed, header.exercise, header.scope, header.fluid).
[[nodiscard]] Status checkReplay(const TrialHeader& trial, const WorldOptions& options);

/// Replays a trial on a world built from `packageFolder`: refuses (InvalidInput) a trial whose scene checksum is not
/// the package's or that another physics engine recorded, then steps through every sample. The world's options come
/// from the trial's header.
[[nodiscard]] Result<TrialReport> replayTrial(const std::string& packageFolder, const Trial& trial,
                                              Progress& progress = Progress::none());

/// A scripted exploration of `world`'s scene: in through the canal with the inflow open, then the fundus, each ostium
/// and each wall in turn, and out (tests, demonstrations, the benchmark). `durationS` stretches it.
Script explorationScript(const World& world, double durationS = 60.0);

/// A rough trial (the solver's stress test): in through the canal, then `durationS` of presses at random into the
/// cavity's walls and its pathologies (a third of them a pathology's face), each from the cavity's axis to the face and
/// up to 3 mm beyond it at 10-50 mm/s (a hand's speeds), held 0.2-1 s, the optic rolled at random; out at the end.
/// The same seed gives the same script.
Script roughScript(const World& world, double durationS = 60.0, std::uint64_t seed = 1);

/// A scripted entry through the cervical canal (the check that the canal is an obstacle): the device outside the
/// external os, aimed along the canal's clearest straight line turned `offAxisDeg` (0-45) towards `towardDeg` about the
/// canal's axis (0 anterior, 90 the patient's left), pushed in at 5 mm/s until its tip would stand 5 mm beyond the
/// internal os, held there 1 s, with the inflow open.
Script entryScript(const World& world, double offAxisDeg = 0.0, double towardDeg = 0.0);
/// The shaft's direction of that entry (unit, towards the os), and the entry along a given direction through the os.
Vec3 entryShaft(const World& world, double offAxisDeg = 0.0, double towardDeg = 0.0);
Script entryScriptAlong(const World& world, const Vec3& shaft);

/// How far around a pressed face the tissue's modulus is taken (World::tissueModulusNearKpa), in radii of the scope's
/// tip: where the stress under a uniformly loaded circle of radius a on a half-space has fallen to about a seventh of
/// its value at the surface: on its axis p (1 - z^3 / (a^2 + z^2)^(3/2)), 0.15 p at z = 3a (Johnson 1985, 3.4).
inline constexpr double kPressReachTipRadii = 3.0;

/// A scripted press (the check that the device feels the tissue): in through the canal with the inflow open, the tip
/// brought head-on to a face of the cavity as the fluid opens it (60 mmHg), then the device pushed `depthMm` beyond
/// that surface and held there.
struct PressPlan {
    Script script;
    Vec3 surfaceMm;                ///< the face's centre in the opened cavity
    Vec3 normal;                   ///< its normal, into the cavity
    double alignment = 0.0;        ///< cos of the angle between the shaft and the face's normal (1: head-on)
    std::string region;            ///< the region the face bounds
    double youngsModulusKpa = 0.0; ///< the face's tet's material, at small strain
    double poissonRatio = 0.0;
    double pressFromS = 0.0; ///< the tip leaves its stand-off off the face here (the tissue untouched until then)
    double holdFromS = 0.0;  ///< the device is at depth from here to the script's end
};
/// `pathology`: an index into metrics().pathologies (a face of that pathology), or -1 (a face of the cavity's wall
/// away from every pathology; a pathology's own faces). InvalidInput when no such face can be reached within 60
/// degrees of head-on with the scope 1 mm clear of the walls. `rank`: not the face met most nearly head-on but the
/// rank-th after it, counting only faces a tip's diameter from those before (to press one tissue at several places).
[[nodiscard]] Result<PressPlan> pressScript(const World& world, int pathology, double depthMm = 3.0, double holdS = 2.0,
                                            std::size_t rank = 0);
/// How far the face `plan` presses stands now off where the plan has it, along its normal (+: towards the scope), mm:
/// the contact surface's point nearest the plan's face centre, on the simulation mesh's points as they lie. The plan
/// counts its depth from the face as the static solve at the planning pressure left it; stepped up to
/// plan.pressFromS, a world whose face the fluid has moved off that place presses by a depth counted from the live
/// face with the plan made again for the depth less this offset (the script is the same up to pressFromS).
double pressFaceOffsetMm(const World& world, const PressPlan& plan);
/// The press's own indentation now, mm: how far the physics' scope (where the contacts hold it, the tip's sub-element
/// dimple included; HapticFrame::scopeDofs) has its tip's sphere beyond the face `plan` presses as it stood
/// `faceOffsetMm` off the plan's place (pressFaceOffsetMm as the press began). The punch's displacement, whatever the
/// shaft carries: the coupling's stretch answers the scope's whole load, the canal's included, not the tip's alone.
double pressIndentationMm(const World& world, const PressPlan& plan, double faceOffsetMm);
/// A demonstration resection of pathology `pathology` (an index into scene().clinical.pathologies) with the
/// resectoscope's loop, planned in the cavity opened by the fluid: in through the canal with the inflow open, then
/// strip by strip from the pathology's free side towards its base, each strip the loop pushed out beyond the pathology
/// and drawn back with the cutting pedal down where the wire, as planned, passes through nothing but the pathology
/// and the fluid; out at the end. Only strokes whose wire, as planned, meets the pathology are made. InvalidInput for a
/// world whose exercise does not cut, a pathology out of range, or one that no stroke from the scope's pivot meets.
[[nodiscard]] Result<Script> resectionScript(const World& world, int pathology);
/// The built-in demonstration of the world's exercise (`hysteroscene-sim --demo`): the exploration for exploration
/// and diagnosis; for polypectomy the resection of the scene's first polyp, for myomectomy of its first myoma of FIGO
/// type 0-2 (resectionScript). InvalidInput naming the exercise when the scene has no such pathology.
[[nodiscard]] Result<Script> demonstrationScript(const World& world);

} // namespace hs::sim
