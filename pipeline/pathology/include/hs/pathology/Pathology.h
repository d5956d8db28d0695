#pragma once
/// Pathologies grown inside a healthy organ (Sierra et al., "Coherent Scene Generation for Surgical Simulators",
/// 2004, sec. 2.1): placement, three growth models, the organ's adaptation and the clinical descriptors measured
/// from the resulting geometry.
///
/// The organ is a surface of the uterus template (hs/anatomy/UterusGenerator.h): one closed surface with the face
/// label "tissue" (serosa, endometrium, cervical canal, tubal ostia, ectocervix); the cavity lies outside it.

#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/Timings.h"

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace hs::pathology {

enum class Kind { Myoma, Polyp };
enum class GrowthModel {
    CellularAutomaton, ///< voxel automaton; myomas only
    Skeleton,          ///< object skeleton + revolved contours; myomas and polyps
    Particles,         ///< dividing cells that push each other; myomas and polyps
};
enum class Location {
    Fundal,
    Anterior,
    Posterior,
    LeftLateral,
    RightLateral,
    CornualLeft,
    CornualRight,
    Isthmic,
    Cervical
};
enum class Attachment { Sessile, Pedunculated };

const char* toString(Kind value);
const char* toString(GrowthModel value); ///< "ca", "skeleton", "particles"
const char* toString(Location value);
const char* toString(Attachment value);

/// FIGO leiomyoma type (PALM-COEIN): 0..8, or a hybrid X-Y (X 1..3 towards the endometrium, Y 5..6 towards the
/// serosa).
struct Figo {
    int type = 0;
    int serosal = -1; ///< hybrid only, else -1
    bool isHybrid() const { return serosal >= 0; }
    std::string toString() const;
};
bool operator==(const Figo& a, const Figo& b);
bool operator!=(const Figo& a, const Figo& b);

/// Where a pathology sits, by clinical description (the depth follows from the FIGO type).
struct ClinicalPlacement {
    Location location = Location::Fundal;
};
/// A point on the organ surface with its outward normal (a click in the 3-D view), organ frame, mm.
struct SurfacePlacement {
    Vec3 pointMm;
    Vec3 normal{0.0, 0.0, 1.0};
};
using Placement = std::variant<ClinicalPlacement, SurfacePlacement>;

struct PathologyRequest {
    std::string id; ///< names the region and the messages
    Kind kind = Kind::Myoma;
    GrowthModel model = GrowthModel::Skeleton;
    double sizeMm = 20.0;                        ///< mm, largest diameter (pedunculated: of the head)
    Figo figo;                                   ///< myomas only
    Attachment attachment = Attachment::Sessile; ///< polyps only
    double stalkLengthMm = 0.0;                  ///< mm, pedunculated polyps; 0 = derived from the size
    Placement placement = ClinicalPlacement{};
};

struct PathologyParams {
    std::vector<PathologyRequest> pathologies;
    std::uint64_t seed = 1;                   ///< every random choice derives from it (one stream per pathology)
    double clearanceMm = 2.0;                 ///< mm of wall the organ keeps between a pathology and a surface it must
                                              ///< not reach (it is displaced to make room)
    double contactToleranceMm = 1.0;          ///< mm; closer than this to the endometrium counts as contact (FIGO 3)
    double minimumGapMm = 1.0;                ///< mm; two pathologies closer than this overlap (an error)
    double measureVoxelFraction = 1.0 / 40.0; ///< voxel edge for volume fractions, fraction of the size
};

/// Lasmar (STEPW) score for hysteroscopic myomectomy (Lasmar et al. 2005).
struct LasmarScore {
    int size = 0;        ///< <= 20 mm 0, 20-50 mm 1, > 50 mm 2
    int topography = 0;  ///< lower 0, middle 1, upper third 2
    int extension = 0;   ///< base <= 1/3 of the wall 0, 1/3-2/3 1, > 2/3 2
    int penetration = 0; ///< intramural 0 % 0, < 50 % 1, >= 50 % 2
    int wall = 0;        ///< lateral wall 1
    int total() const { return size + topography + extension + penetration + wall; }
};

/// Clinical descriptors measured from the geometry (never echoed from the request).
struct Descriptors {
    Kind kind = Kind::Myoma;
    Figo figo;           ///< myomas: from the fractions and contacts below
    double sizeMm = 0.0; ///< largest diameter (pedunculated: of the head, stalk excluded)
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
    LasmarScore lasmar; ///< myomas (meaningful for types 0-2)
};

/// One grown pathology, in the organ frame.
struct GrownPathology {
    std::string id;
    Kind kind = Kind::Myoma;
    GrowthModel model = GrowthModel::Skeleton;
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

/// Places, grows and measures every requested pathology in `organ` (a uterus-template surface with the "tissue"
/// label). The organ yields where a pathology pushes (mass effect: tissue displaced radially, the surface a
/// pathology is meant to break through stays). Fails with InvalidInput on a request that is impossible (FIGO 9, a
/// myoma larger than the corpus, a polyp outside the cavity, overlapping pathologies, CA polyps) saying why,
/// Unsupported for FIGO 8 and cervical sites, Cancelled on request.
[[nodiscard]] Result<PathologyResult> growPathologies(const SurfaceMesh& organ, const PathologyParams& params,
                                                      Progress& progress = Progress::none());

/// Measures one pathology against an organ (the displaced organ of a PathologyResult). Fails with InvalidInput
/// for an open surface.
[[nodiscard]] Result<Descriptors> measure(const SurfaceMesh& organ, const SurfaceMesh& pathology, Kind kind,
                                          const PathologyParams& params = {});

/// Lasmar score of a myoma from its measured descriptors.
LasmarScore lasmarScore(const Descriptors& d);

} // namespace hs::pathology
