#pragma once
/// Resection with a loop electrode (docs/simulator.md, "Cutting"): the loop's wire, the tets it passes through while
/// the cut pedal is on, and what each cut took: the pathology's volume, healthy tissue and how deep into the
/// myometrium, a perforation of the serosa, the chips cut free.
///
/// The tissue is the solver's (hs::mechanics::CorotationalFem): a cut removes whole tets from it, which keeps the
/// tissue a valid solid (no piece hanging by an edge or a point, a manifold boundary; Forest, Delingette & Ayache,
/// Med Image Anal 9(2):113-122, 2005) and needs no new points, so the solver's factor follows it by downdates
/// (CorotationalFem::Refactor::Downdate). Lengths mm, volumes mL (cm^3), time ms.

#include "hs/clinical/Tissue.h"
#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/TetMesh.h"
#include "hs/core/Vec3.h"
#include "hs/mechanics/CorotationalFem.h"
#include "hs/mechanics/UterusModel.h"
#include "hs/scene/Scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace hs::sim {

/// A resectoscope's cutting loop: a half circle of wire across the sheath's axis, hanging from two arms on the side
/// away from the optic, moved along the axis by the working element (docs/simulator.md, "Cutting").
struct LoopElectrode {
    double widthMm = 4.5;  ///< the half circle's span (26 Fr bipolar loops: about 4-5 mm)
    double sampleMm = 0.2; ///< the wire and its motion are followed at this spacing (thinner slivers are missed)
};

/// The wire's points, mm: the half circle of `loop.widthMm` in the plane through `centreMm` normal to `axis` (unit,
/// the sheath's forward), its middle `widthMm / 2` from the centre along `down` (unit, normal to the axis), its ends
/// on the line through the centre normal to both, at most loop.sampleMm apart.
std::vector<Vec3> loopWire(const LoopElectrode& loop, const Vec3& centreMm, const Vec3& axis, const Vec3& down);

/// The office hysteroscope's 5 Fr mechanical instruments, scissors and grasping forceps, through its working channel
/// (Bettocchi et al. 2004): two jaws hinged at the instrument's end, in the plane of the shaft and `down`, opening
/// symmetrically about the shaft (docs/simulator.md, "The office scope's scissors and grasper").
struct JawInstrument {
    double shaftMm = 5.0 / 3.0; ///< mm, 5 Fr (the French gauge is the outer diameter in mm times 3)
    double jawLengthMm = 3.0;   ///< hinge to tip (the project's choice: about twice the shaft)
    double openDeg = 25.0;      ///< each jaw's angle off the shaft wide open (the project's choice)
    double closeS = 0.25;       ///< s, wide open to shut (the project's choice: a squeeze of the handle)
    /// mm, the working channel's axis from the optic's, towards the image's bottom (the project's choice: side by side
    /// in the 4-5 mm sheath of an office scope); the instrument comes out of the tip there.
    double channelOffsetMm = 1.5;
    double sampleMm = 0.2; ///< the jaws and their motion are followed at this spacing
};

/// The jaws' edges as one wire, mm: from one jaw's tip (on the side away from `down`) through the hinge at `hingeMm`
/// to the other's, each jaw `openDeg` off `axis` (unit, the shaft's forward; 0: shut) in the plane of `axis` and
/// `down` (unit, normal to it), at most jaws.sampleMm apart; the same number of points at every opening, so a closing
/// is a sweep (Resection::sweptTets).
std::vector<Vec3> jawWire(const JawInstrument& jaws, const Vec3& hingeMm, const Vec3& axis, const Vec3& down,
                          double openDeg);

/// What one cut event (a step with the pedal on and the loop moved) took.
struct CutEvent {
    std::vector<std::size_t> removed;            ///< every tet removed, ascending (with chips and manifold repair)
    std::vector<std::vector<std::size_t>> chips; ///< the pieces cut free (CorotationalFem::Removal::chips)
    std::size_t sweptTets = 0;                   ///< of `removed`, the tets the wire passed through
    double pathologyMl = 0.0;                    ///< the pathologies' tets removed (chips included)
    double healthyMl = 0.0;                      ///< every other tet removed
    double deepestMyometriumMm = 0.0;            ///< how far below the cavity's surface (at rest) a removed
                                                 ///< myometrium or cervix tet reached (0: none)
    bool perforation = false;                    ///< a removed tet had a face on the serosa: the wall is open
    double topologyMs = 0.0;                     ///< wall clock of the event (finding, removing, accounting)
};

/// The running totals of a resection.
struct ResectionTotals {
    std::size_t events = 0; ///< cut events that removed a tet
    std::size_t removedTets = 0;
    std::size_t chips = 0;
    std::vector<double> pathologyRemovedMl; ///< per scene pathology (Scene::clinical.pathologies)
    std::vector<double> pathologyMl;        ///< their volume on the simulation mesh
    double healthyMl = 0.0;
    double deepestMyometriumMm = 0.0;
    int perforations = 0; ///< cut events that opened the serosa
};

/// The cutting of one scene's simulation mesh.
class Resection {
public:
    /// `restMm` the simulation mesh at rest (scene region ids), `boundary` its boundary faces in its point indices
    /// with `faceCavity` marking the cavity's and the canal's (UterusModel). InvalidInput for arrays that do not match.
    [[nodiscard]] static Result<Resection> make(const scene::Scene& scene, const TetMesh& restMm,
                                                const std::vector<Triangle>& boundary,
                                                const std::vector<char>& faceCavity);

    /// The live tets of `fem` (positions as they are now) the wire passes through moving from `wireFromMm` to
    /// `wireToMm` (the same number of points; a point moving farther than `sampleMm` is followed in between),
    /// ascending; none for wires of no points or not finite. The loop's wire, or the jaws' (jawWire).
    std::vector<std::size_t> sweptTets(const mechanics::CorotationalFem& fem, double sampleMm,
                                       const std::vector<Vec3>& wireFromMm, const std::vector<Vec3>& wireToMm) const;
    /// Those tets removed from `model`'s solver (UterusModel::cutTets with Refactor::Downdate: the factor follows the
    /// cut, the fluid's volume stays continuous) and accounted. An event with no tet swept changes nothing.
    CutEvent cut(mechanics::UterusModel& model, double sampleMm, const std::vector<Vec3>& wireFromMm,
                 const std::vector<Vec3>& wireToMm);

    const ResectionTotals& totals() const { return m_totals; }
    /// Per simulation tet, the index of its pathology in Scene::clinical.pathologies (-1: healthy tissue).
    const std::vector<std::int32_t>& tetPathology() const { return m_tetPathology; }
    /// Per simulation tet, its tissue.
    const std::vector<clinical::Tissue>& tetTissue() const { return m_tetTissue; }

private:
    std::vector<std::int32_t> m_tetPathology;
    std::vector<clinical::Tissue> m_tetTissue;
    std::vector<double> m_tetVolumeMl;
    std::vector<double> m_tetDepthMm; ///< deepest point below the cavity's surface at rest
    std::vector<char> m_tetOnSerosa;  ///< a face of the tet lies on the outer boundary
    std::vector<Vec3> m_restMm;
    ResectionTotals m_totals;
};

} // namespace hs::sim
