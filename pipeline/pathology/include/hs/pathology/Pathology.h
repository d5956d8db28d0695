#pragma once
/// Pathologies grown inside a healthy organ (Sierra et al., "Coherent Scene Generation for Surgical Simulators",
/// 2004, sec. 2.1): placement, three growth models, the organ's adaptation and the clinical descriptors measured
/// from the resulting geometry.
///
/// The organ is a surface of the uterus template (hs/anatomy/UterusGenerator.h): one closed surface with the face
/// label "tissue" (clinical::SurfaceTissue: serosa, endometrium, cervical canal, tubal ostia, ectocervix); the
/// cavity lies outside it.

#include "hs/clinical/Clinical.h"
#include "hs/clinical/Figo.h"
#include "hs/clinical/Placement.h"
#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/Timings.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace hs::pathology {

/// How large a pathology may be against its organ (the stage refuses larger ones, InvalidInput): a myoma's diameter
/// at most this times the smallest of the corpus's width, depth and length (internal os to fundal serosa) ...
constexpr double kMaxMyomaToCorpus = 1.25;
/// ... and a polyp's head at most this times the cavity's length (head and stalk together at most 1.2 times).
constexpr double kMaxPolypToCavity = 0.8;
constexpr double kMaxPolypReachToCavity = 1.2;

struct PathologyRequest {
    std::string id; ///< names the region and the messages
    clinical::PathologyKind kind = clinical::PathologyKind::Myoma;
    clinical::GrowthModel model = clinical::GrowthModel::Skeleton;
    double sizeMm = 20.0;    ///< mm, largest diameter (pedunculated: of the head)
    clinical::FigoType figo; ///< myomas only
    clinical::PolypAttachment attachment = clinical::PolypAttachment::Sessile; ///< polyps only
    double stalkLengthMm = 0.0; ///< mm, pedunculated polyps; 0 = derived from the size
    clinical::Placement placement = clinical::ClinicalPlacement{};
};

struct PathologyParams {
    std::vector<PathologyRequest> pathologies;
    std::uint64_t seed = 1;   ///< every random choice derives from it (one stream per pathology)
    double clearanceMm = 2.0; ///< mm of wall the organ keeps between a pathology and a surface it must
                              ///< not reach (it is displaced to make room)
    /// mm the cavity keeps open in front of a pathology that stands in it (FIGO 0-2, hybrids reaching it, polyps):
    /// the far wall moves away until it is this far from the pathology. Hysteroscopy distends the cavity with fluid
    /// (45-75 mmHg, docs/references.md [Vulgaropulos1992]), which holds the walls off a mass as it does elsewhere:
    /// the model's cavity has its distended depth (8 mm, docs/anatomy.md), 4 mm on either side of its midplane, and
    /// a 2.9 mm office scope passes in front of the mass (docs/pathology.md, "The organ adapts").
    double distendedGapMm = 4.0;
    /// mm, the endometrium the scene lays over the cavity's surface after placement (one layer, generate's tissue
    /// layers): a myoma that must not reach it (FIGO 4) keeps clearanceMm from its inner face. 0: a surface only.
    double endometriumThicknessMm = 0.0;
    double contactToleranceMm = 1.0;          ///< mm; closer than this to the endometrium counts as contact (FIGO 3)
    double minimumGapMm = 1.0;                ///< mm; two pathologies closer than this overlap (an error)
    double measureVoxelFraction = 1.0 / 40.0; ///< voxel edge for volume fractions, fraction of the size
};

/// Clinical descriptors measured from the geometry (never echoed from the request).
struct Descriptors {
    clinical::PathologyKind kind = clinical::PathologyKind::Myoma;
    clinical::FigoType figo; ///< myomas: from the fractions and contacts below; polyps: not classified (-1)
    double sizeMm = 0.0;     ///< largest diameter (pedunculated: of the head, stalk excluded)
    double volumeMm3 = 0.0;
    double intramuralFraction = 0.0;    ///< volume fraction inside the wall
    double cavityFraction = 0.0;        ///< volume fraction inside the cavity
    double outsideFraction = 0.0;       ///< volume fraction outside the serosa
    double endometriumDistanceMm = 0.0; ///< 0 when it crosses the endometrium
    double serosaDistanceMm = 0.0;      ///< 0 when it crosses the serosa
    bool pedunculated = false;          ///< a stalk narrower than half the head
    double stalkLengthMm = 0.0;         ///< mm, wall to the head (0 when sessile)
    double baseWidthMm = 0.0;           ///< mm, widest extent of the contact with the wall surface it grows from
    double baseExtension = 0.0;         ///< base width / length of that wall
    int topography = 0;                 ///< third of the cavity: 0 lower, 1 middle, 2 upper
    bool lateralWall = false;
    clinical::LasmarScore lasmar; ///< myomas (meaningful for types 0-2); polyps: not computed (-1)
};

/// One grown pathology, in the organ frame.
struct GrownPathology {
    std::string id;
    clinical::PathologyKind kind = clinical::PathologyKind::Myoma;
    clinical::GrowthModel model = clinical::GrowthModel::Skeleton;
    SurfaceMesh surface; ///< closed, manifold, outward-oriented
    Vec3 anchor;         ///< where it meets the wall surface it grows from
    Vec3 intoWall;       ///< unit direction from that surface into the wall
    Descriptors descriptors;
};

struct PathologyResult {
    SurfaceMesh organ; ///< the organ displaced where the pathologies push it (labels kept)
    std::vector<GrownPathology> pathologies;
    StageTimings timings; ///< place, grow, fit, adapt, measure
    std::vector<std::string> warnings;
};

/// One step of a pathology's growth as it happens, for a viewer (the workstation's Grow): the points the model grows
/// at that step, in the organ frame (mm), before the shape is scaled to its size and fitted to its depth. Cellular
/// automaton: the centres of its cells every few sweeps; particles: the cells after each division; skeleton: the
/// revolved contour swept along the skeleton from its root, in four steps. A pathology moved to another seat grows
/// again there, so its frames start over.
struct GrowthFrame {
    std::size_t pathology = 0; ///< index in PathologyParams::pathologies
    clinical::GrowthModel model = clinical::GrowthModel::Skeleton;
    int step = 0;
    bool last = false; ///< the model's final state at this seat
    std::vector<Vec3> points;
};
/// Called on the stage's thread; it must be quick (copy what it keeps) and never changes the result.
using GrowthObserver = std::function<void(const GrowthFrame&)>;

/// Places, grows and measures every requested pathology in `organ` (a uterus-template surface with the "tissue"
/// label). The organ yields where a pathology pushes (mass effect: tissue displaced radially, the surface a
/// pathology is meant to break through stays). Fails with InvalidInput on a request that is impossible (FIGO 9, a
/// myoma larger than the corpus, a polyp outside the cavity, overlapping pathologies, CA polyps) saying why,
/// Unsupported for FIGO 8 and cervical sites, Cancelled on request.
[[nodiscard]] Result<PathologyResult> growPathologies(const SurfaceMesh& organ, const PathologyParams& params,
                                                      Progress& progress = Progress::none(),
                                                      const GrowthObserver& observe = {});

/// Where a click at `pointMm` on `organ` (the organ the case's patient, anatomy and seed give, as a 3-D view shows
/// it) seats a pathology of `kind`: the point and the outward normal of the organ's face under it (the closest face
/// within `toleranceMm`). Refuses, naming the tissue, the cervix (Unsupported: cervical pathologies are not
/// modelled) and, for a polyp, the serosa (a polyp grows from the endometrium); InvalidInput for a point off the
/// organ or not finite.
[[nodiscard]] Result<clinical::SurfacePlacement> seatAt(const SurfaceMesh& organ, const Vec3& pointMm,
                                                        clinical::PathologyKind kind, double toleranceMm = 0.5);

/// Measures one pathology against an organ (the displaced organ of a PathologyResult). `root`: where it grows from
/// when known (GrownPathology::anchor), so a head that also rests on a wall is measured from its stalk's root
/// (WallContact::root). Fails with InvalidInput for an open surface.
[[nodiscard]] Result<Descriptors> measure(const SurfaceMesh& organ, const SurfaceMesh& pathology,
                                          clinical::PathologyKind kind, const PathologyParams& params = {},
                                          std::optional<Vec3> root = std::nullopt);

/// Lasmar score of a myoma from its measured descriptors.
clinical::LasmarScore lasmarScore(const Descriptors& d);

/// Where a pathology lies against the wall, however it was measured: voxels of the grown shape against the displaced
/// organ (`measure`), or the tets of a meshed region against a scene's boundary.
struct WallFractions {
    double tissue = 0.0;  ///< volume fraction inside the wall
    double cavity = 0.0;  ///< inside the cavity
    double outside = 0.0; ///< outside the serosa
    double endometriumDistanceMm = 1e9;
    double serosaDistanceMm = 1e9;
    bool pedunculated = false;
    /// Whether it borders the endometrium, where a measurement sees the layer itself (a scene's tets, whose lining is
    /// a region of its own); unset, contact is closer than the tolerance to the cavity's surface.
    std::optional<bool> bordersEndometrium;
};

/// FIGO type from fractions and contacts (docs/references.md [Munro2011]: 0 pedunculated intracavitary,
/// 1 < 50 % intramural, 2 >= 50 %, 3 contacts the endometrium, 4 intramural, 5 subserosal >= 50 % intramural,
/// 6 < 50 %, 7 pedunculated subserosal; hybrids X-Y when it reaches both sides). In the cavity means more than 0.01
/// of the volume, outside more than 0.02. Contact with the endometrium (3 against 4, 3-5 against 5) is
/// `bordersEndometrium` where set, else a distance to the cavity's surface within `contactToleranceMm`.
clinical::FigoType classifyFigo(const WallFractions& f, double contactToleranceMm);

/// A pathology against the wall it grows from, as some measurement found it.
struct WallContact {
    WallFractions fractions;
    double sizeMm = 0.0; ///< largest diameter; replaced by the head's when a stalk is found in `points`
    double volumeMm3 = 0.0;
    double stalkLengthMm = 0.0; ///< replaced when a stalk is found in `points`
    std::vector<Vec3> points;   ///< its surface's points: a stalk is looked for in them (empty: not looked for)
    Vec3 centre;                ///< its volume centroid
    std::vector<Vec3> base;     ///< points of the wall surface it grows from where it meets it (may be empty)
    bool serosalBase = false;   ///< the base lies on the serosa (else on the cavity side)
    /// Where it grows from, when known (its seat, a stalk's root): a stalk is looked for from there rather than from
    /// the base's centre, and when one is found the base is where it meets the wall. A head on a stalk that also
    /// rests on a wall, or whose pocket's walls hug it, touches the wall away from its root too.
    std::optional<Vec3> root;
};

/// The descriptors of `contact` read in the cavity frame of `organ` (a surface with the "tissue" face label: an organ,
/// or the boundary of a scene's mesh): base width and extension, topography, lateral wall, and for myomas the FIGO
/// type and Lasmar score. `measure` ends with it, so a grown shape and a meshed region are described by the same
/// rules. Fails with InvalidInput when `organ` lacks the labels `measure` needs.
[[nodiscard]] Result<Descriptors> describeContact(const SurfaceMesh& organ, const WallContact& contact,
                                                  clinical::PathologyKind kind, double contactToleranceMm);

} // namespace hs::pathology
