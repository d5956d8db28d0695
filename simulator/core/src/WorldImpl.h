#pragma once
// The World's state, shared by its parts, one file each: World.cpp (loading, the step, what others read),
// WorldSurface.cpp (the contact surface's faces, zones, ostia and pathologies), WorldTissue.cpp (the tissue solver, its
// supports and the cavity's volume and load), WorldContact.cpp (the scope's virtual coupling and contacts, perforation,
// the haptics frame), WorldVisibility.cpp (what the optic sees, marking) and ExplorationScript.cpp.

#include "Bvh.h"
#include "Fluid.h"
#include "hs/core/TetEmbedding.h"
#include "hs/mechanics/CorotationalFem.h"
#include "hs/mechanics/UterusModel.h"
#include "hs/sim/Resection.h"
#include "hs/sim/Vessels.h"
#include "hs/sim/World.h"

#include <array>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace hs::sim {

namespace detail {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kMm = 1e-3;

/// The tip force at which the wall gives way, N (docs/simulator.md, "Perforation": an assumption of this project;
/// blunt-instrument puncture of soft tissue takes a few newtons).
constexpr double kPerforationForceN = 5.0;
/// ... held this long, s: the wall gives way under a sustained push, not a tap.
constexpr double kPerforationHoldS = 0.3;
/// The scripts plan the shaft's clearance from the walls only beyond this far past the internal os (along the canal),
/// mm: in the canal the sheath dilates a canal narrower than itself.
constexpr double kCanalContactFreeMm = 2.0;
/// The shaft is checked for contact from its tip back to this far behind the pivot, mm.
constexpr double kShaftCheckBehindPivotMm = 10.0;
/// Contact candidates are gathered this far beyond the scope's radius, mm; the physics' scope moves at most this far
/// in a step (300 mm/s, beyond a hand's speed), so no wall is passed between two steps.
constexpr double kContactMarginMm = 1.5;
/// A sphere of the shaft found inside the wall where the physics' scope is (it entered the part of the shaft that
/// collides while lying in the wall, or the wall moved onto it) is pushed out by at most this much a step, mm (50
/// mm/s): a contact asked to undo millimetres at once is solved far beyond the linearization it was built on (the
/// largest depenetration speed of game physics engines, e.g. PhysX's maxDepenetrationVelocity, and the error reduction
/// of Baumgarte's stabilization).
constexpr double kMaxDepenetrationMm = 0.25;
/// At most this many contact rows per step (the nearest), so a scope lying along the canal costs a bounded time.
constexpr std::size_t kMaxContacts = 48;
/// The virtual coupling between the device and the physics' scope (Colgate, Stanley & Brown 1995): stiffer than the
/// tissue under the tip (0.1-0.5 N/mm), so the device feels the tissue, and within what a 1 kHz device renders stably.
/// N/mm along the shaft; N mm per radian about the pivot (1 N/mm at the tip 60 mm beyond the pivot).
constexpr double kCouplingInsertionNPerMm = 1.0;
constexpr double kCouplingAngularNmmPerRad = 3600.0;
constexpr double kCouplingLeverMm = 60.0;
/// The exploration script: the tip's speed inside the cavity, mm/s of its plan (scaled to the duration asked for),
/// the clearance from the walls it looks for, mm, and how far beside the cavity's axis it looks for it, mm.
constexpr double kScriptSpeedMmPerS = 10.0;
constexpr double kScriptClearanceMm = 3.0;
constexpr double kMiddleSearchMm = 8.0;
constexpr double kMiddleStepMm = 1.0;
/// The clearance of a point is looked for this far, mm: more than half the wall's thickness, so a point inside the
/// wall finds the wall's surface and its side.
constexpr double kClearanceReachMm = 12.0;
/// Visibility is updated every kVisibilityPeriodS for a tenth of the faces (all of them every 50 ms), and the
/// series sampled every kSeriesPeriodS.
constexpr double kVisibilityPeriodS = 0.005;
constexpr std::size_t kVisibilitySlices = 10;
constexpr double kSeriesPeriodS = 0.1;
/// A contact ends after this long without touching (so a sliding scope counts once), s.
constexpr double kContactGapS = 0.05;
/// A pathology's faces: cavity faces this close to the visual faces over it, mm.
constexpr double kPathologyReachMm = 3.0;
/// The fundus zone: cavity faces this close to the fundus point, mm.
constexpr double kFundusZoneMm = 10.0;
/// The pressure at which the exploration script plans its path in the opened cavity, kPa (60 mmHg).
constexpr double kPlanningPressureKpa = 8.0;
/// Ostium faces spread wider than this across the cavity are two ostia, mm (the intercornual distance is 41-47 mm;
/// docs/references.md [FundusMRI]).
constexpr double kOstiumSeparationMm = 15.0;
/// The coarse simulation mesh rounds the cornual recess where an ostium opens: the ostium's centre may lie this far
/// behind the contact surface and still be seen, mm.
constexpr double kOstiumOcclusionSlackMm = 2.5;

/// The loop's wire (mm) on the scope in the pose of `body` (the scope's body: its camera head's roll is ignored, the
/// loop is fixed to the sheath), and its middle: the half circle hangs on the side of the image's bottom with the
/// camera upright, the working element's travel beyond the sheath's tip.
std::vector<Vec3> loopWireOf(const ScopeFrame& frame, const ScopeConfig& scope, const LoopElectrode& loop,
                             DeviceSample body, Vec3& middleMm);
/// The same loop as a LoopState (out, its middle, the sheath's axis and the side it hangs to; pedals unset).
LoopState loopStateOf(const ScopeFrame& frame, const ScopeConfig& scope, const LoopElectrode& loop, DeviceSample body);

struct Zone {
    std::string name;
    std::vector<std::int32_t> faces;
    double area = 0.0;
};

struct Ostium {
    std::string name;
    TetEmbedding at; ///< the centre of its faces on the visual surface, bound to the simulation mesh
    Vec3 normal;     ///< into the cavity, at rest
    int target = -1; ///< index in metrics.targets
};

Vec3 triangleNormal(const std::vector<Vec3>& pts, const Triangle& t);
Vec3 triangleCentre(const std::vector<Vec3>& pts, const Triangle& t);

} // namespace detail

/// mm: with the coagulating pedal down, the loop seals the cut faces that come this close to its wire (the
/// lateral thermal spread of bipolar electrosurgery, 1-2 mm, is the scale; this value is the project's choice).
inline constexpr double kCoagulationReachMm = 1.5;
/// mm/s, a chip sinking through the saline towards the patient's back (-y; she lies on it): tissue of 1050 kg/m^3
/// in saline of 1005 kg/m^3, a millimetre-sized piece at a drag-limited speed of millimetres to centimetres a
/// second: this project's estimate.
inline constexpr double kChipSinkMmPerS = 5.0;
/// mm: the loop drawn in (working element at most 1 mm) catches a chip whose surface lies this close to its middle;
/// the grasper's jaws shutting take hold of the nearest chip whose surface lies this close to theirs.
inline constexpr double kChipCatchMm = 2.0;

struct World::Impl {
    WorldOptions options;
    scene::Scene scene;
    std::string sha;
    scene::ScopeLandmarks landmarks;
    ScopeFrame frame;
    TetMesh simRest;
    SurfaceMesh contactSurface; ///< points: the simulation mesh's (mm, at rest); triangles in its point indices
    std::shared_ptr<const std::vector<Triangle>> triangles;
    std::vector<char> faceCavity;   ///< a cavity-side face (the scope sees it, the fluid presses on it)
    std::vector<char> faceInCavity; ///< beyond the internal os (the exploration's surface)
    std::vector<double> faceArea;   ///< mm^2 at rest
    std::vector<std::int32_t> faceRegion;
    std::vector<int> facePathology; ///< index into scene.clinical.pathologies, -1 none
    std::vector<char> faceHeld;     ///< a point of the face is held (the portio: the canal the sheath pivots in)
    std::vector<SurfaceSample> faceUnrolled;
    std::vector<std::int32_t> faceTet; ///< the simulation tet the face bounds
    std::vector<char> faceDead;        ///< a cut removed the face's tet: no contact, no sight (kept for its index)
    std::vector<char> faceCut;         ///< a face a cut opened (appended after the mesh's boundary)
    std::vector<char> faceSealed;      ///< a cut face the loop coagulated: its vessels are closed
    std::vector<detail::Zone> zones;
    std::vector<detail::Ostium> ostia;
    Vec3 cavityAxis, cavityAnterior, cavityLeft;
    double cavityArea = 0.0;

    // The tissue (WorldTissue.cpp): the scene's uterus model (shared with generate's hydrometra curve), its solver.
    mechanics::UterusModel uterus;
    mechanics::CorotationalFem& tissue = uterus.fem;
    detail::TriangleBvh bvh;
    detail::FluidModel fluid;
    /// The cavity's volume change per kPa over one step of the solver, mL/kPa (the fluid's coupling).
    double cavityComplianceMlPerKpa = 0.0;
    /// The points with the cavity opened at the planning pressure by a static solve (scripts plan with them).
    std::vector<Vec3> openPointsMm;

    // The resectoscope's loop (WorldCut.cpp): live in the operative exercises.
    std::unique_ptr<Resection> resection;
    LoopElectrode loop;
    std::vector<VesselDensity> tetVessels;  ///< per simulation tet (Vessels.h)
    std::shared_ptr<const CutView> cutView; ///< what the cuts did, for drawing (null before the first cut)
    std::size_t firstCutFace = 0;           ///< the contact surface's faces from here on are cuts'
    // The chips (WorldCut.cpp): the tissue a pedal press cuts gathers into one strip, let go when the pedal comes up.
    std::vector<Chip> chips;
    double stripMl = 0.0;
    std::array<double, 5> stripByTissue{}; ///< mL of the strip by clinical::Tissue
    bool lastPedal = false;
    /// Chips: the strip let go at `whereMm`; each step the chips sink and the drawn-in loop catches them.
    void releaseStrip(const Vec3& whereMm);
    void moveChips(const DeviceSample& device);
    std::vector<Vec3> lastWireMm; ///< the wire where the last step left it (empty: not out)
    Vec3 lastLoopMm;
    /// A cut event's tissue: pieces cut free float off as chips; the rest gathers on the loop's strip (`toStrip`) or,
    /// the scissors' kerf, is gone; the resection's metrics follow.
    void tookTissue(const CutEvent& event, bool toStrip);
    // The office scope's scissors and grasper (WorldCut.cpp): their jaws close while kButtonCut is held.
    JawInstrument jaws;
    double jawOpenDeg = JawInstrument{}.openDeg; ///< each jaw's angle off the shaft now (wide open at first)
    std::vector<Vec3> lastJawMm;                 ///< the jaws' wire where the last step left it (empty: not out)
    void moveJaws(const DeviceSample& device, bool squeezed);

    // The scope (WorldContact.cpp): the physics' scope's dofs (insertion m, pitch rad, yaw rad), coupled to the device.
    std::array<double, 3> scopeDofs{};
    bool scopePlaced = false;
    std::vector<HapticContact> hapticContacts;
    std::vector<double> hapticCompliance;
    double hapticTipGive = 0.0; ///< m/N, the tip's sub-element give in the last step (tipGive)
    double tipDimpleM = 0.0;    ///< m, how deep the tip's sub-element dimple was at the last step's end
    Vec3 tipDimpleOutMm;        ///< mm, from the physics' tip out of that dimple (its rows' net force times the give)

    std::vector<Vec3> pointsMm;
    WorldState state;
    TrialMetrics metrics;
    std::vector<SeriesPoint> series;
    std::vector<char> faceSeen;
    std::uint64_t samplesConsumed = 0;
    std::uint32_t lastButtons = 0;
    bool haveLastTip = false;
    Vec3 lastTip;
    double horizonSum = 0.0;
    double horizonTime = 0.0;
    double lastTouchS = -1.0;
    bool inContact = false;
    double seriesForceN = 0.0;
    double nextVisibilityS = 0.0;
    double nextSeriesS = 0.0;
    int perforationIndex = -1;
    double tipPushS = 0.0;
    std::size_t visibilityRound = 0;
    World::StepTimings timings;

    mutable std::mutex frameMutex;
    std::shared_ptr<const HapticFrame> hapticFrame;

    Status build(Progress& progress);
    void setupSurfaceData();
    [[nodiscard]] Status setupTissue();
    /// The cavity's one-step compliance (mL/kPa) from the solver's matrix, and the cavity opened at the planning
    /// pressure by a static solve of the same model.
    [[nodiscard]] Status measureCavity();
    /// One physics step: the scope coupled to `device`, the pressure on the cavity.
    void physics(const DeviceSample& device, double pressureKpa);
    void recordContact(const std::vector<mechanics::FemConstraint>& rows, const std::vector<char>& rowTip,
                       const std::vector<std::int32_t>& rowFace, const ScopePose& pose);
    /// Whether `point` (on `face`, -1: none) is in the view, in focus, facing the lens and not hidden (a hit within
    /// `slackMm` before it does not hide it).
    bool visible(const Vec3& point, const Vec3& normal, std::int32_t face, double slackMm = 0.5) const;
    bool visibleFrom(const ScopePose& pose, const Vec3& point, const Vec3& normal, std::int32_t face,
                     double slackMm) const;
    Vec3 ostiumPoint(const detail::Ostium& o) const;
    bool insideRestHull(const Vec3& p) const;
    /// Signed distance from `p` to the contact surface with the points `pts` (its tree `tree` refitted to them), mm:
    /// positive on the side its faces look to (the cavity, outside the body), negative inside the tissue; `reachMm`
    /// when no face is that close.
    double clearanceMm(const std::vector<Vec3>& pts, const detail::TriangleBvh& tree, const Vec3& p,
                       double reachMm) const;
    /// The least clearance of the scope in `pose` beyond its radius (its tip, and its shaft beyond the canal), mm;
    /// negative where it would press into the wall.
    double scopeClearanceMm(const std::vector<Vec3>& pts, const detail::TriangleBvh& tree, const ScopePose& pose) const;
    void updateVisibility();
    void mark();
    void publishFrame();
    /// The loop after the step's physics: with the cutting pedal down it cuts what its wire swept since the last
    /// step, and the contact surface follows the cut.
    void cut(const DeviceSample& device);
    /// The vessels of the cut faces that are live and not sealed (the fluid's exchange with them).
    detail::OpenVessels openVessels() const;
    /// The coagulating pedal: the cut faces within kCoagulationReachMm of the loop's wire (`wire`) are sealed.
    void coagulate(const std::vector<Vec3>& wire);
    /// The contact surface after `removed` left the tissue: their faces die, the faces they bared are appended.
    void surfaceAfterCut(const std::vector<std::size_t>& removed);
    /// The loop's wire for the device's working element on the physics' scope, and its middle.
    std::vector<Vec3> loopWireMm(const DeviceSample& device, Vec3& middleMm) const;
    Vec3 faceNormal(std::int32_t f) const;
    Vec3 faceCentre(std::int32_t f) const;
    /// m/N: the sub-element give of the tip pressing face `f` at the barycentric `weights`
    /// (mechanics::punchSubElementCompliance with the scope's radius, the face's mean edge at rest, its tet's
    /// material), softened by the material's stiffening at the last step's dimple (mechanics::punchDimpleStiffening).
    double tipCompliance(std::int32_t f, const std::array<double, 3>& weights) const;
    /// The device outside the external os (insertion -5 mm), aimed along the straight line from the external os that
    /// keeps farthest from the canal's walls in the cavity opened by the fluid (`open`: the tree of openPointsMm).
    DeviceSample canalEntry(const detail::TriangleBvh& open) const;
    /// The device sample with the physics' scope's dofs in place of the device's.
    DeviceSample physicsSample(const DeviceSample& device) const;
};

} // namespace hs::sim
