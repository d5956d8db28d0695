// The pathology stage: place, grow, fit the depth to the FIGO type, let the organ make room, measure.
#include "hs/pathology/Pathology.h"

#include "Geometry.h"
#include "Measure.h"
#include "Organ.h"
#include "Shapes.h"

#include "hs/anatomy/OrganChecks.h"
#include "hs/clinical/Tissue.h"
#include "hs/core/RegionModel.h"
#include "hs/core/Rng.h"
#include "hs/core/Units.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hs::pathology {

namespace {
using namespace detail;

constexpr double kSinkMm = 1.5;           ///< a stalk's root lies this deep in the wall
constexpr double kOpenKeep = 0.5;         ///< the far wall's serosa moves by this fraction less than its endometrium
constexpr double kOpenStretch = 1.0;      ///< the far wall's window ramp widens by this fraction of its push
constexpr double kOpenWiden = 1.0;        ///< the far wall's outside moves over a profile this much wider
constexpr double kMaxSizeToCorpus = 1.25; ///< largest myoma against the smallest corpus dimension
constexpr double kMaxPolypToCavity = 0.8; ///< largest polyp head against the cavity length
constexpr double kHybridPlay = 0.15;      ///< a hybrid's seat: play for the centre across the wall, of the radius
constexpr double kHybridSlide = 0.4;      ///< a hybrid's seat slides at most this fraction of the cavity length
constexpr double kHybridTurnDeg = 30.0;   ///< and faces within this angle of the nominal seat
constexpr int kPocketRounds = 30;         ///< rounds of averaging that round the pockets the pushes open
constexpr double kPocketSlackMm = 1.0;    ///< a rounded pocket keeps this much more than the clearance

std::string fmt(double v, int digits = 1) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(digits);
    s << v;
    return s.str();
}
std::string fmt(const Vec3& v) {
    return "(" + fmt(v.x) + ", " + fmt(v.y) + ", " + fmt(v.z) + ")";
}

/// The wall chord through the placement: endometrium point, serosa point, direction from cavity into the wall.
struct Seat {
    Vec3 endometrium, serosa, intoWall;
    double wallMm = 0.0;
};

struct Planned {
    const PathologyRequest* request = nullptr;
    ShapeSpec spec;
    Seat seat;
    bool fromSerosa = false; ///< types 5-7: grows from the serosa side
    SurfaceMesh surface;
};

std::string who(const PathologyRequest& r) {
    return std::string(toString(r.kind)) + " '" + r.id + "'";
}

Status checkRequest(const PathologyRequest& r) {
    if (!std::isfinite(r.sizeMm) || r.sizeMm <= 0.0)
        return fail(ErrorCode::InvalidInput, who(r) + ": size " + fmt(r.sizeMm) + " mm must be positive");
    if (r.kind == clinical::PathologyKind::Myoma) {
        const clinical::FigoType& f = r.figo;
        if (f.isHybrid()) {
            if (f.type < 1 || f.type > 3 || f.serosal < 5 || f.serosal > 6)
                return fail(ErrorCode::InvalidInput, who(r) + ": FIGO hybrid " + f.toString() +
                                                         " does not exist (hybrids are X-Y with X 1-3, Y 5-6)");
        } else if (f.type < 0 || f.type > 8) {
            return fail(ErrorCode::InvalidInput, who(r) + ": FIGO type " + std::to_string(f.type) +
                                                     " does not exist (types are 0-8 and hybrids X-Y)");
        } else if (f.type == 8) {
            return fail(ErrorCode::Unsupported,
                        who(r) + ": FIGO type 8 (cervical, parasitic) is not modelled; use types 0-7 or a hybrid");
        }
    } else {
        if (r.model == clinical::GrowthModel::CellularAutomaton)
            return fail(ErrorCode::InvalidInput,
                        who(r) + ": the cellular automaton grows myomas only; use skeleton or particles for polyps");
        if (r.attachment == clinical::PolypAttachment::Pedunculated &&
            (!std::isfinite(r.stalkLengthMm) || r.stalkLengthMm < 0.0))
            return fail(ErrorCode::InvalidInput, who(r) + ": stalk length must be >= 0 mm");
    }
    if (const auto* c = std::get_if<clinical::ClinicalPlacement>(&r.placement);
        c && c->location == clinical::UterineLocation::Cervical)
        return fail(ErrorCode::Unsupported, who(r) + ": cervical pathologies are not modelled");
    if (const auto* s = std::get_if<clinical::SurfacePlacement>(&r.placement);
        s && (!isFinite(s->pointMm) || !isFinite(s->normal) || norm(s->normal) == 0.0))
        return fail(ErrorCode::InvalidInput,
                    who(r) + ": the surface point and normal must be finite, the normal non-zero");
    return {};
}

Status checkSize(const PathologyRequest& r, const OrganInfo& info) {
    if (r.kind == clinical::PathologyKind::Myoma) {
        const double smallest = std::min({info.corpusWidthMm, info.corpusDepthMm, info.corpusLengthMm});
        if (r.sizeMm > kMaxSizeToCorpus * smallest)
            return fail(ErrorCode::InvalidInput, who(r) + ": a " + fmt(r.sizeMm, 0) +
                                                     " mm myoma cannot grow in this uterus: its corpus measures " +
                                                     fmt(info.corpusWidthMm, 0) + " x " + fmt(info.corpusDepthMm, 0) +
                                                     " x " + fmt(info.corpusLengthMm, 0) +
                                                     " mm (width x depth x length), room for at most " +
                                                     fmt(kMaxSizeToCorpus * smallest, 0) + " mm");
    } else {
        const double room = kMaxPolypToCavity * info.cavityLengthMm;
        const double length =
            r.sizeMm + (r.attachment == clinical::PolypAttachment::Pedunculated ? r.stalkLengthMm : 0.0);
        if (r.sizeMm > room || length > 1.2 * info.cavityLengthMm)
            return fail(ErrorCode::InvalidInput,
                        who(r) + ": a " + fmt(r.sizeMm, 0) + " mm polyp" +
                            (r.stalkLengthMm > 0.0 ? " on a " + fmt(r.stalkLengthMm, 0) + " mm stalk" : "") +
                            " does not fit a cavity " + fmt(info.cavityLengthMm, 0) + " mm long");
    }
    return {};
}

Vec3 faceNormalOf(const OrganInfo& info, std::size_t face) {
    return faceNormal(*info.mesh, face);
}

Vec3 faceCentroid(const SurfaceMesh& mesh, std::size_t face) {
    const Triangle& t = mesh.triangles[face];
    return (mesh.points[static_cast<std::size_t>(t[0])] + mesh.points[static_cast<std::size_t>(t[1])] +
            mesh.points[static_cast<std::size_t>(t[2])]) /
           3.0;
}

/// Completes a seat from its endometrium point and direction: the serosa where the chord leaves the wall. False
/// when the chord leaves through the cavity side (near the cervix).
bool reachSerosa(const OrganInfo& info, Seat& seat) {
    auto out = info.ray(seat.endometrium + seat.intoWall * 0.01, seat.intoWall, std::nullopt);
    if (!out || info.faceSide[out->face] != Side::Serosa)
        return false;
    seat.serosa = out->point;
    seat.wallMm = out->t + 0.01;
    return true;
}

double capFraction(double depth, double radius) {
    const double h = std::clamp(depth, 0.0, 2.0 * radius);
    return h * h * (3.0 * radius - h) / (4.0 * radius * radius * radius);
}

/// The centre depths along the wall chord (0 at the endometrium) at which an ideal sphere in a slab `wallMm` thick
/// classifies as `want`: the start and length (mm) of the longest such interval, length <= 0 when there is none.
/// Surfaces the type must not reach are left out of the slab: the organ will make room there.
std::pair<double, double> figoRun(const clinical::FigoType& want, double wallMm, double radius, double tol) {
    const bool useCavity = want.isHybrid() || want.type <= 3;
    const bool useSerosa = want.isHybrid() || want.type >= 5;
    double bestStart = 0.0, bestLength = -1.0, runStart = 0.0;
    bool inRun = false;
    const double step = 0.02;
    const double lo = -radius - 2.0, hi = wallMm + radius + 2.0;
    for (double s = lo; s <= hi + step; s += step) {
        Fractions f;
        f.cavity = useCavity ? capFraction(radius - s, radius) : 0.0;
        f.outside = useSerosa ? capFraction(s + radius - wallMm, radius) : 0.0;
        f.tissue = 1.0 - f.cavity - f.outside;
        f.endometriumDistanceMm = useCavity ? std::max(0.0, s - radius) : 1e9;
        f.serosaDistanceMm = useSerosa ? std::max(0.0, wallMm - s - radius) : 1e9;
        const bool match = s <= hi && classifyFigo(f, tol) == want;
        if (match && !inRun) {
            inRun = true;
            runStart = s;
        }
        if (!match && inRun) {
            inRun = false;
            if (s - runStart > bestLength) {
                bestLength = s - runStart;
                bestStart = runStart;
            }
        }
    }
    return {bestStart, bestLength};
}

/// A hybrid (X-Y) must span the wall, and a clinical location names a wall, not a point on it. Where the wall at the
/// nominal seat is too thick for the requested size to span it with room to spare (an ideal sphere's centre must
/// have kHybridPlay of its radius of play), the seat slides to the nearest endometrium point within kHybridSlide of
/// the cavity's length that faces the same way (within kHybridTurnDeg) and where the wall is thin enough; to the
/// one with the most play when there is none (the measured type then tells). A point placement stays where it was
/// put. A slide is reported in `notes`.
Seat slideHybridSeat(const PathologyRequest& r, const OrganInfo& info, const Seat& nominal, double tol,
                     std::vector<std::string>& notes) {
    const double radius = 0.5 * r.sizeMm;
    const double enough = kHybridPlay * radius;
    auto play = [&](const Seat& s) { return figoRun(r.figo, s.wallMm, radius, tol).second; };
    Seat best = nominal;
    double bestPlay = play(nominal);
    if (bestPlay >= enough)
        return nominal;
    const SurfaceMesh& organ = *info.mesh;
    const auto& tissue = organ.faceLabels.at(clinical::kSurfaceTissueLabel);
    const double reach = std::max(5.0, kHybridSlide * info.cavityLengthMm);
    const double minCos = std::cos(units::degToRad(kHybridTurnDeg));
    std::vector<std::pair<double, std::size_t>> candidates;
    for (std::size_t f = 0; f < organ.triangles.size(); ++f) {
        if (static_cast<clinical::SurfaceTissue>(tissue[f]) != clinical::SurfaceTissue::Endometrium)
            continue;
        const double d = distance(faceCentroid(organ, f), nominal.endometrium);
        if (d <= reach && dot(-faceNormalOf(info, f), nominal.intoWall) >= minCos)
            candidates.emplace_back(d, f);
    }
    std::sort(candidates.begin(), candidates.end());
    auto slid = [&](const Seat& s) {
        notes.push_back(who(r) + ": the wall at the nominal seat is " + fmt(nominal.wallMm) +
                        " mm thick, too thick for a " + fmt(r.sizeMm, 0) + " mm FIGO " + r.figo.toString() +
                        " myoma to span; seated " + fmt(distance(s.endometrium, nominal.endometrium)) +
                        " mm away, where it is " + fmt(s.wallMm) + " mm");
        return s;
    };
    for (const auto& [d, f] : candidates) {
        Seat s;
        s.endometrium = faceCentroid(organ, f);
        s.intoWall = -faceNormalOf(info, f);
        if (!reachSerosa(info, s))
            continue;
        const double p = play(s);
        if (p >= enough)
            return slid(s);
        if (p > bestPlay) {
            bestPlay = p;
            best = s;
        }
    }
    return bestPlay > play(nominal) ? slid(best) : nominal;
}

Result<Seat> seatFrom(const PathologyRequest& r, const OrganInfo& info, double tol, std::vector<std::string>& notes) {
    Seat seat;
    const auto& tissue = info.mesh->faceLabels.at(clinical::kSurfaceTissueLabel);
    if (const auto* c = std::get_if<clinical::ClinicalPlacement>(&r.placement)) {
        Vec3 origin = info.cavityCenter, dir;
        switch (c->location) {
        case clinical::UterineLocation::Fundal:
            dir = info.axis;
            break;
        case clinical::UterineLocation::Anterior:
            dir = info.anterior;
            break;
        case clinical::UterineLocation::Posterior:
            dir = -info.anterior;
            break;
        case clinical::UterineLocation::RightLateral:
            dir = info.lateral;
            break;
        case clinical::UterineLocation::LeftLateral:
            dir = -info.lateral;
            break;
        case clinical::UterineLocation::CornualRight:
            dir = normalized(info.cornuRight - info.cavityCenter);
            break;
        case clinical::UterineLocation::CornualLeft:
            dir = normalized(info.cornuLeft - info.cavityCenter);
            break;
        case clinical::UterineLocation::Isthmic:
            origin = info.internalOs + info.axis * (0.2 * info.cavityLengthMm);
            dir = info.anterior;
            break;
        case clinical::UterineLocation::Cervical:
            break;
        }
        auto hit = info.ray(origin, dir, Side::Cavity);
        if (!hit)
            return fail(ErrorCode::InvalidInput,
                        who(r) + ": no endometrium found towards the " + std::string(toString(c->location)) + " wall");
        seat.endometrium = hit->point;
        seat.intoWall = -faceNormalOf(info, hit->face);
    } else {
        const auto& s = std::get<clinical::SurfacePlacement>(r.placement);
        const auto [face, dist] = info.nearestFace(s.pointMm);
        if (dist > 5.0)
            return fail(ErrorCode::InvalidInput, who(r) + ": the point " + fmt(s.pointMm) + " lies " + fmt(dist) +
                                                     " mm from the organ surface (at most 5 mm)");
        const Vec3 n = faceNormalOf(info, face);
        const Triangle& t = info.mesh->triangles[face];
        const Vec3 onFace = s.pointMm - n * dot(s.pointMm - info.mesh->points[static_cast<std::size_t>(t[0])], n);
        const auto label = static_cast<clinical::SurfaceTissue>(tissue[face]);
        if (label == clinical::SurfaceTissue::CervicalCanal || label == clinical::SurfaceTissue::Ectocervix)
            return fail(ErrorCode::Unsupported, who(r) + ": the point " + fmt(s.pointMm) +
                                                    " lies on the cervix; cervical pathologies are not modelled");
        if (info.faceSide[face] == Side::Cavity) {
            seat.endometrium = onFace;
            seat.intoWall = -n;
        } else {
            if (r.kind == clinical::PathologyKind::Polyp)
                return fail(ErrorCode::InvalidInput,
                            who(r) + ": a polyp grows from the endometrium into the cavity, but the point " +
                                fmt(s.pointMm) + " lies on the serosa, outside the cavity");
            auto back = info.ray(onFace - n * 0.01, -n, Side::Cavity);
            if (!back || back->t > 60.0)
                return fail(ErrorCode::InvalidInput, who(r) + ": there is no uterine cavity behind the point " +
                                                         fmt(s.pointMm) +
                                                         " (the wall must separate it from the serosa)");
            seat.endometrium = back->point;
            seat.intoWall = normalized(onFace - back->point);
        }
    }
    if (!reachSerosa(info, seat))
        return fail(ErrorCode::InvalidInput, who(r) + ": the wall at " + fmt(seat.endometrium) +
                                                 " does not reach the serosa (placement too close to the cervix?)");
    if (r.kind == clinical::PathologyKind::Myoma && r.figo.isHybrid() &&
        std::holds_alternative<clinical::ClinicalPlacement>(r.placement))
        return slideHybridSeat(r, info, seat, tol, notes);
    return seat;
}

/// Depth of a sphere's centre along the wall chord (0 at the endometrium, W at the serosa) for the requested FIGO
/// type: the middle of the longest interval in which an ideal sphere in a slab classifies as requested.
Result<double> centreDepth(const PathologyRequest& r, const Seat& seat, double radius, double tol) {
    const clinical::FigoType want = r.figo;
    if (want.type == 4 && !want.isHybrid())
        return 0.5 * seat.wallMm;
    const auto [start, length] = figoRun(want, seat.wallMm, radius, tol);
    if (length <= 0.0)
        return fail(ErrorCode::InvalidInput, who(r) + ": FIGO " + want.toString() + " is impossible for a " +
                                                 fmt(r.sizeMm, 0) + " mm myoma in a wall " + fmt(seat.wallMm) +
                                                 " mm thick (a hybrid must span the wall)");
    return start + 0.5 * length;
}

/// Signed distance from p to a closed surface (negative inside), capped at `cutoff`.
double signedDistance(const SurfaceMesh& s, const Bounds& box, const Vec3& p, double cutoff) {
    if (p.x < box.min.x - cutoff || p.y < box.min.y - cutoff || p.z < box.min.z - cutoff || p.x > box.max.x + cutoff ||
        p.y > box.max.y + cutoff || p.z > box.max.z + cutoff)
        return cutoff;
    double best = cutoff * cutoff;
    for (const Triangle& t : s.triangles)
        best = std::min(best, pointTriangleDistance2(p, s.points[static_cast<std::size_t>(t[0])],
                                                     s.points[static_cast<std::size_t>(t[1])],
                                                     s.points[static_cast<std::size_t>(t[2])]));
    const double d = std::sqrt(best);
    return windingNumber(s, p) > 0.5 ? -d : d;
}

/// The growth direction of a stalk into the cavity: away from the wall and down towards the internal os, the way
/// a pedunculated polyp hangs in the cavity.
Vec3 stalkDirection(const OrganInfo& info, const Vec3& intoWall) {
    const Vec3 down = -info.axis - intoWall * dot(-info.axis, intoWall);
    if (norm(down) < 0.3)
        return -intoWall;
    return normalized(-intoWall * 0.85 + normalized(down) * 0.5);
}

/// How far a head of `radius` at the end of a stalk from `root` along `dir` stays from the pathologies planned
/// before it (mm; large when there are none).
double stalkClearance(const Vec3& root, const Vec3& dir, double reach, double radius, double stalkRadius,
                      const std::vector<const SurfaceMesh*>& earlier) {
    double worst = 1e9;
    for (const SurfaceMesh* other : earlier) {
        const Bounds box = bounds(*other);
        const double cutoff = 2.0 * radius + 10.0;
        worst = std::min(worst, signedDistance(*other, box, root + dir * reach, cutoff) - radius);
        for (double t = 0.25; t < 0.8; t += 0.25)
            worst = std::min(worst, signedDistance(*other, box, root + dir * (t * reach), cutoff) - stalkRadius);
    }
    return worst;
}

/// The stalk's direction: the way it hangs (stalkDirection), or, when that runs into a pathology planned before
/// it, the nearest direction (tilted in 15 degree steps, still leaving the wall) whose head keeps `gap` from it.
/// Among the clear directions of a tilt, the one that stays closest to the cavity's plane (least anteroposterior):
/// the cavity is flat, so a head tilted towards the anterior or posterior wall would stand in it.
Vec3 freeStalkDirection(const OrganInfo& info, const Seat& seat, double reach, double radius, double stalkRadius,
                        double gap, const std::vector<const SurfaceMesh*>& earlier) {
    const Vec3 hang = stalkDirection(info, seat.intoWall);
    double best = stalkClearance(seat.endometrium, hang, reach, radius, stalkRadius, earlier);
    if (best >= gap)
        return hang;
    Vec3 bestDir = hang, e1, e2;
    orthonormalFrame(hang, e1, e2);
    constexpr double kDegree = 3.14159265358979323846 / 180.0;
    for (int tilt = 15; tilt <= 60; tilt += 15) {
        double flattest = 2.0;
        for (int azimuth = 0; azimuth < 360; azimuth += 30) {
            const double a = azimuth * kDegree, t = tilt * kDegree;
            const Vec3 dir = normalized(hang * std::cos(t) + (e1 * std::cos(a) + e2 * std::sin(a)) * std::sin(t));
            if (dot(dir, -seat.intoWall) < 0.35)
                continue;
            const double clear = stalkClearance(seat.endometrium, dir, reach, radius, stalkRadius, earlier);
            const double ap = std::fabs(dot(dir, info.anterior));
            if (clear >= gap ? ap < flattest : (flattest > 1.0 && clear > best)) {
                if (clear >= gap)
                    flattest = ap;
                best = std::max(best, clear);
                bestDir = dir;
            }
        }
        if (flattest <= 1.0)
            break;
    }
    return bestDir;
}

Result<ShapeSpec> planShape(const PathologyRequest& r, const OrganInfo& info, const Seat& seat,
                            const PathologyParams& params, const std::vector<const SurfaceMesh*>& earlier,
                            bool& fromSerosa) {
    ShapeSpec spec;
    const double radius = 0.5 * r.sizeMm;
    spec.radius = radius;
    spec.intoWall = seat.intoWall;
    fromSerosa = false;
    if (r.kind == clinical::PathologyKind::Polyp) {
        spec.polyp = true;
        spec.base = seat.endometrium + seat.intoWall * kSinkMm;
        if (r.attachment == clinical::PolypAttachment::Pedunculated) {
            spec.pedunculated = true;
            const double stalk = r.stalkLengthMm > 0.0 ? r.stalkLengthMm : 0.5 * r.sizeMm;
            spec.stalkRadius = std::clamp(0.18 * radius, 0.8, 3.0);
            const double gap = params.minimumGapMm + params.clearanceMm;
            spec.center = seat.endometrium +
                          freeStalkDirection(info, seat, stalk + radius, radius, spec.stalkRadius, gap, earlier) *
                              (stalk + radius);
        } else {
            spec.stalkRadius = 0.65 * radius;
            spec.center = seat.endometrium - seat.intoWall * (0.85 * radius);
        }
        return spec;
    }
    const clinical::FigoType& f = r.figo;
    if (!f.isHybrid() && (f.type == 0 || f.type == 7)) {
        spec.pedunculated = true;
        spec.stalkRadius = std::clamp(0.3 * radius, 1.5, 5.0);
        const double stalk = std::max(4.0, 0.35 * r.sizeMm);
        if (f.type == 0) {
            spec.base = seat.endometrium + seat.intoWall * kSinkMm;
            spec.center = seat.endometrium - seat.intoWall * (stalk + radius);
        } else {
            fromSerosa = true;
            spec.base = seat.serosa - seat.intoWall * kSinkMm;
            spec.center = seat.serosa + seat.intoWall * (stalk + radius);
        }
        return spec;
    }
    auto depth = centreDepth(r, seat, radius, params.contactToleranceMm);
    if (!depth.ok())
        return depth.failure();
    fromSerosa = !f.isHybrid() && f.type >= 5;
    spec.transmural = f.isHybrid();
    spec.center = seat.endometrium + seat.intoWall * *depth;
    spec.base = spec.center;
    return spec;
}

Result<SurfaceMesh> grow(const PathologyRequest& r, const ShapeSpec& spec, const SurfaceMesh& organ, Rng& rng,
                         Progress& progress) {
    GrowthTuning tuning;
    switch (r.model) {
    case clinical::GrowthModel::Skeleton:
        return skeletonShape(spec, rng);
    case clinical::GrowthModel::CellularAutomaton:
        return cellularAutomatonShape(spec, organ, tuning, rng, progress);
    case clinical::GrowthModel::Particles:
        return particleShape(spec, organ, tuning, rng, progress);
    }
    return fail(ErrorCode::Internal, "unknown growth model");
}

/// Scales so the measured size equals the request: about the centroid, or, for stalked shapes, about the planned
/// centre of the head when it grows (a head grown smaller than planned has its foot further out by the difference,
/// and growing about its centre brings the foot back to the planned stalk length; its root sinks deeper into the
/// wall; scaled about the planned foot, the particle model's stalks measured 9.4-10.7 mm where 7-8 mm were asked)
/// and about the stalk's root when it shrinks (the root stays in the wall); a sessile polyp about the endometrium
/// point it sits on (about its sunk root, a shrinking head sank into the wall: 22-39 % of it measured intramural).
void scaleToSize(SurfaceMesh& mesh, const ShapeSpec& spec, double sizeMm) {
    const bool stalked = spec.polyp || spec.pedunculated;
    const Vec3 axis = normalized(spec.center - spec.base);
    for (int it = 0; it < 3; ++it) {
        const double now = stalked ? headDiameter(mesh.points, spec.base, axis) : diameter(mesh.points);
        if (now <= 0.0)
            return;
        const double factor = sizeMm / now;
        const Vec3 pivot = !stalked                           ? volumeCentroid(mesh)
                           : spec.polyp && !spec.pedunculated ? spec.base - spec.intoWall * kSinkMm
                           : factor > 1.0                     ? spec.center
                                                              : spec.base;
        scaleAbout(mesh, pivot, factor);
    }
}

/// Depths along the wall chord (0 at the endometrium) of the shape's inside voxels (edge size / 40), sorted.
std::vector<double> voxelDepths(const SurfaceMesh& mesh, const PathologyRequest& r, const Seat& seat) {
    const double h = r.sizeMm / 40.0;
    const Grid g = Grid::covering(bounds(mesh), h, 1);
    const auto inside = insideMask(mesh, g);
    std::vector<double> depth;
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
                if (inside[g.index(i, j, k)])
                    depth.push_back(dot(g.center(i, j, k) - seat.endometrium, seat.intoWall));
    std::sort(depth.begin(), depth.end());
    return depth;
}

/// The shift along the chord that centres a 2-5 hybrid in the wall slab: the fractions beyond the endometrium and
/// beyond the serosa, each over the threshold that makes it count (classifyFigo: 0.01 and 0.02), are made equal,
/// keeping at least half of the volume in the wall.
double hybridShift(const SurfaceMesh& mesh, const PathologyRequest& r, const Seat& seat) {
    const std::vector<double> depth = voxelDepths(mesh, r, seat);
    if (depth.empty())
        return 0.0;
    const auto n = static_cast<double>(depth.size());
    auto fractions = [&](double shift, double& cavity, double& outside) {
        cavity = static_cast<double>(std::lower_bound(depth.begin(), depth.end(), -shift) - depth.begin()) / n;
        outside =
            static_cast<double>(depth.end() - std::upper_bound(depth.begin(), depth.end(), seat.wallMm - shift)) / n;
    };
    double best = 0.0, bestScore = -1e300;
    const double span = depth.back() - depth.front() + seat.wallMm;
    for (double shift = -span; shift <= span; shift += 0.05) {
        double cavity = 0.0, outside = 0.0;
        fractions(shift, cavity, outside);
        const double score = std::min(cavity / 0.01, outside / 0.02) - (cavity + outside > 0.5 ? 1e6 : 0.0);
        if (score > bestScore) {
            bestScore = score;
            best = shift;
        }
    }
    return best;
}

/// The slab is flat, the organ is not: where the curved cavity leaves less of the shape beyond the endometrium (or
/// the serosa) than the slab promised, the shape moves along the chord in 0.25 mm steps towards the side that falls
/// short of its threshold, measured on the organ, as long as the other side keeps its own.
void refineHybrid(SurfaceMesh& mesh, const SurfaceMesh& organ, const PathologyRequest& r, const Seat& seat,
                  const PathologyParams& params) {
    for (int it = 0; it < 8; ++it) {
        auto d = measure(organ, mesh, clinical::PathologyKind::Myoma, params);
        if (!d.ok() || d->figo == r.figo)
            return;
        const double cavity = d->cavityFraction / 0.01, outside = d->outsideFraction / 0.02;
        const double step = cavity < 1.0 && outside > 1.0 ? -0.25 : (outside < 1.0 && cavity > 1.0 ? 0.25 : 0.0);
        if (step == 0.0)
            return;
        translate(mesh, seat.intoWall * step);
        auto after = measure(organ, mesh, clinical::PathologyKind::Myoma, params);
        if (!after.ok() || (step < 0.0 ? after->outsideFraction < 0.02 : after->cavityFraction < 0.01)) {
            translate(mesh, seat.intoWall * -step); // the other side would fall short: keep the balance
            return;
        }
    }
}

/// Moves the shape along the wall chord until its depth matches the FIGO type, measured against the planes of
/// the wall at the seat (the local slab, so the far wall of a narrow cavity does not count): intramural fraction
/// 0.25 (types 1, 6) or 0.75 (types 2, 5), or a gap of half the contact tolerance to the endometrium (type 3).
void fitDepth(SurfaceMesh& mesh, const SurfaceMesh& organ, const PathologyRequest& r, const Seat& seat,
              const PathologyParams& params) {
    if (r.kind != clinical::PathologyKind::Myoma)
        return;
    const int type = r.figo.type;
    if (r.figo.isHybrid()) {
        if (r.figo == clinical::FigoType{2, 5}) { // other hybrids keep the depth of the ideal sphere
            translate(mesh, seat.intoWall * hybridShift(mesh, r, seat));
            refineHybrid(mesh, organ, r, seat, params);
        }
        return;
    }
    if (type != 1 && type != 2 && type != 3 && type != 5 && type != 6)
        return;
    double shift = 0.0;
    if (type == 3) {
        double shallowest = 1e300;
        for (const Vec3& q : mesh.points)
            shallowest = std::min(shallowest, dot(q - seat.endometrium, seat.intoWall));
        shift = 0.5 * params.contactToleranceMm - shallowest;
    } else {
        const std::vector<double> depth = voxelDepths(mesh, r, seat);
        if (depth.empty())
            return;
        const double target = type == 1 ? 0.05 : (type == 6 ? 0.25 : 0.75);
        // Types 1-2: the fraction deeper than the endometrium plane; 5-6: shallower than the serosa plane.
        const auto n = static_cast<double>(depth.size());
        if (type <= 2) {
            const double q = depth[static_cast<std::size_t>(std::clamp((1.0 - target) * n, 0.0, n - 1.0))];
            shift = -q;
        } else {
            const double q = depth[static_cast<std::size_t>(std::clamp(target * n, 0.0, n - 1.0))];
            shift = seat.wallMm - q;
        }
    }
    translate(mesh, seat.intoWall * shift);
}

/// An injective deformation that opens room: points move along `n` by amount * s(h) * (1 - s(rho)), h the height
/// along `up` (n unless set; up . n > 0) from `origin`, rho the distance from the axis through origin along n. Every
/// line along n maps to itself monotonically (s(h) only grows along it), so the organ can never fold over itself,
/// however steep the ramps.
///
/// The radial variant moves points away from that axis instead, by amount * g * (1 - s(rho)), g rising with the
/// height and falling beyond the pathology's top along n. Each half-plane bounded by the axis maps to itself, and
/// rho -> rho + amount * weight is strictly increasing when the ramps that fall along rho are wide enough: the fall
/// over rho is 2.5 amount and the height ramp amount (0.5 + 4 sin(up, n)) (the height changes along rho when up is
/// tilted from n), so the weight's slope along rho stays below 0.6 / amount + 0.375 / amount. The walls around a
/// pathology that stands in the cavity then move away from it in every direction across the axis.
struct Push {
    Vec3 origin, n;
    double rampLo = 0.0, rampHi = 1.0;     ///< mm of height: no motion below, full motion above
    double window = 0.0, windowRamp = 5.0; ///< mm from the axis: full motion inside, none beyond window + ramp
    double amount = 0.0;
    double stretch = 0.0; ///< the window ramp widens by this fraction of the amount (a mesh follows a smooth map)
    bool radial = false;
    Vec3 up{};                       ///< height direction; zero: n
    double topLo = 0.0, topHi = 0.0; ///< radial: mm along n where the motion falls back to 0 (beyond the pathology)
    /// Axial solve: only points this close to the axis drive the amount (0: all); the far wall in front of the
    /// pathology, not the side walls that the radial push moves.
    double solveWithin = 0.0;
    /// Axial: a dome instead of a plateau across the axis, the motion falling off smoothly from the axis itself
    /// (so the pocket it opens is rounded, not a box with flat faces and sharp corners). Any profile across the
    /// axis keeps the map injective: it is constant along each line along n.
    bool dome = false;
    /// Axial: beyond this height (mm, 0: never) the motion falls back to 1 - keep, over a ramp of at least 2 keep
    /// amount (so the slope along n stays below 0.75 / amount and lines along n still map monotonically): the far
    /// wall moves away with the cavity, its serosa less.
    double keepFrom = 0.0, keep = 0.0;
    /// Axial, with keep: over the same ramp the profile across the axis widens by this factor more (so the far wall's
    /// outside rises as a wide, low swelling rather than a bump). Widening with the height only adds motion further
    /// along each line along n, so it keeps the map injective.
    double widen = 0.0;
    Vec3 upDir() const { return norm(up) > 0.0 ? up : n; }
    double keepRamp(double height) const {
        return smoothstep(keepFrom, keepFrom + std::max(windowRamp, 2.0 * keep * amount), height);
    }
    double beyond(double height) const {
        if (keepFrom <= 0.0 || keep <= 0.0)
            return 1.0;
        return 1.0 - keep * keepRamp(height);
    }
    double widthAt(double height) const {
        if (keepFrom <= 0.0 || keep <= 0.0 || widen <= 0.0)
            return 1.0;
        return 1.0 + widen * keepRamp(height);
    }
    double fall() const { return radial ? std::max(windowRamp, 2.5 * amount) : std::max(windowRamp, stretch * amount); }
    double weight(const Vec3& x) const {
        const Vec3 d = x - origin;
        const double tau = dot(d, n);
        const double rho = norm(d - n * tau);
        const double height = dot(d, upDir());
        const double across = 1.0 - smoothstep(dome ? 0.0 : window, (window + fall()) * widthAt(height), rho);
        if (radial) {
            const double tilt = norm(cross(upDir(), n));
            const double hi = std::max(rampHi, rampLo + amount * (0.5 + 4.0 * tilt));
            // Rising from the axis over half the window: no wall lies there (the far wall's push cleared it), but
            // another pathology may, and it moves with the tissue.
            return smoothstep(rampLo, hi, height) * (1.0 - smoothstep(topLo, topHi, tau)) *
                   smoothstep(0.0, std::max(0.5, 0.5 * window), rho) * across;
        }
        return smoothstep(rampLo, rampHi, height) * beyond(height) * across;
    }
    Vec3 direction(const Vec3& x) const {
        if (!radial)
            return n;
        const Vec3 d = x - origin;
        const Vec3 r = d - n * dot(d, n);
        const double len = norm(r);
        return len > 1e-12 ? r / len : Vec3{};
    }
    Vec3 apply(const Vec3& x) const { return x + direction(x) * (amount * weight(x)); }
};

/// Increases the push until the organ points it moves keep `clearance` from the pathology (at most `cap`).
void solvePush(Push& push, const SurfaceMesh& organ, const SurfaceMesh& pathology, double clearance, double cap) {
    const Bounds box = bounds(pathology);
    for (int it = 0; it < 12 && push.amount < cap; ++it) {
        double deficit = 0.0;
        for (const Vec3& x0 : organ.points) {
            const double w = push.weight(x0);
            if (w < 0.3)
                continue;
            if (push.solveWithin > 0.0) {
                const Vec3 d = x0 - push.origin;
                if (norm(d - push.n * dot(d, push.n)) > push.solveWithin)
                    continue;
            }
            const double sd = signedDistance(pathology, box, push.apply(x0), clearance + 1.0);
            if (sd < clearance)
                deficit = std::max(deficit, (clearance - sd) / w);
        }
        if (deficit < 0.05)
            break;
        push.amount = std::min(cap, push.amount + deficit);
    }
}

/// The direction a pathology stands into the cavity: its stalk (pedunculated) or straight out of the wall.
Vec3 protrusionDirection(const Planned& p) {
    if (p.spec.pedunculated && !p.fromSerosa)
        return normalized(p.spec.center - p.seat.endometrium);
    return -p.seat.intoWall;
}

/// The pushes a pathology needs, by where it must and must not reach (UTERUS.md: types 0-2 bulge into the cavity,
/// 3 touches the endometrium, 4 stays in the wall, 5-7 bulge outwards).
std::vector<Push> planPushes(const Planned& p, const OrganInfo& info, const PathologyParams& params) {
    const SurfaceMesh& mesh = p.surface;
    const Vec3 e = p.seat.endometrium, u = p.seat.intoWall;
    double shallowest = 1e300, deepest = -1e300, lateral = 0.0;
    for (const Vec3& q : mesh.points) {
        const double t = dot(q - e, u);
        shallowest = std::min(shallowest, t);
        deepest = std::max(deepest, t);
        lateral = std::max(lateral, norm((q - e) - u * t));
    }
    const clinical::FigoType& f = p.request->figo;
    const bool polyp = p.request->kind == clinical::PathologyKind::Polyp;
    const bool intoCavity = polyp || f.isHybrid() || f.type <= 2;
    const bool clearOfCavity = !polyp && !f.isHybrid() && f.type >= 4;
    const bool clearOfSerosa = !polyp && !f.isHybrid() && f.type <= 4;
    const double windowRamp = std::max(5.0, 0.5 * p.spec.radius);
    const double c = params.clearanceMm;
    std::vector<Push> pushes;
    const double w = p.seat.wallMm;
    if (intoCavity) {
        // Open the cavity around the part that stands in it: first the far wall moves away along the protrusion
        // (driven by the wall in front of it), then, around a head on a stalk, the walls move away across it.
        const Vec3 d = protrusionDirection(p);
        double top = 0.0, across = 0.0;
        for (const Vec3& q : mesh.points) {
            const double t = dot(q - e, d);
            top = std::max(top, t);
            if (t > 0.5)
                across = std::max(across, norm((q - e) - d * t));
        }
        // Heights are measured from the seat's endometrium plane, so a slanting stalk does not drag the wall it
        // grows from.
        const auto far = info.ray(e + d * 0.5, d, Side::Cavity);
        const double farMm = (far ? far->t + 0.5 : top) * dot(d, -u);
        Push open{e, d, 1.5, std::max(3.0, 0.6 * farMm), across + c, windowRamp, 0.0, kOpenStretch};
        open.up = -u;
        open.solveWithin = std::max(1.0, 0.5 * across);
        open.dome = true;
        open.keepFrom = far ? farMm + c : 0.0;
        open.keep = kOpenKeep;
        open.widen = kOpenWiden;
        pushes.push_back(open);
        Push around{e, d, 0.5, 2.0, across + c, windowRamp, 0.0, 0.0};
        around.radial = true;
        around.up = -u;
        around.topLo = top;
        around.topHi = top + c + 0.5 * across; // a wide fall over the head rounds the pocket's corners; any fall
                                               // along n keeps the radial map injective
        if (p.spec.pedunculated) // a head on a stalk; a dome on the wall keeps its corners (they would fold)
            pushes.push_back(around);
    }
    if (clearOfCavity) { // the endometrium (and the cavity with it) moves away from the myoma; the ramp lies in the
                         // wall between the myoma's top and the endometrium, or just under the endometrium
        const double hi = std::min(-0.3, -shallowest + 0.2 + std::clamp(0.5 * std::max(shallowest, 0.0), 0.3, 3.0));
        const double lo = std::max(-0.6 * w, std::min(-shallowest + 0.2, hi - 0.3));
        pushes.push_back(Push{e, -u, lo, std::max(hi, lo + 0.3), lateral + c, windowRamp, 0.0});
    }
    if (clearOfSerosa) { // the serosa bulges over the myoma; the ramp lies in the wall below the serosa
        const double lo = std::max(1.0, std::min(deepest + 0.2, 0.5 * w));
        const double hi = std::max(
            lo + 0.3, std::min(deepest + 0.2 + std::clamp(0.5 * std::max(w - deepest, 0.0), 0.3, 3.0), 0.85 * w));
        pushes.push_back(Push{e, u, lo, hi, lateral + c, windowRamp, 0.0});
    }
    return pushes;
}

/// Applies pathology `which`'s pushes to the organ and to every other pathology (they sit in the moving tissue).
Status adaptOrgan(SurfaceMesh& organ, std::vector<Planned>& all, std::size_t which, const PathologyParams& params) {
    const SurfaceMesh& mesh = all[which].surface;
    const double cap = 2.0 * all[which].spec.radius + 2.0 * params.clearanceMm;
    auto info = analyzeOrgan(organ); // the organ as earlier pathologies left it
    if (!info.ok())
        return info.failure();
    for (Push& push : planPushes(all[which], *info, params)) {
        solvePush(push, organ, mesh, params.clearanceMm, cap);
        if (push.amount <= 0.0)
            continue;
        for (Vec3& x : organ.points)
            x = push.apply(x);
        // Other pathologies move with the tissue, rigidly: a myoma in the wall by its mean motion (it is stiffer than
        // the myometrium, UTERUS.md), a polyp or a stalked myoma with the root of its stalk, which the wall carries
        // (the head hangs in the free cavity). A push's ramps would stretch whatever stands in them: a far-wall push
        // once stretched a 25 mm myoma to 31 mm and a 10 mm polyp to 20 mm.
        for (std::size_t j = 0; j < all.size(); ++j) {
            if (j == which)
                continue;
            Planned& other = all[j];
            Vec3 motion;
            if (other.spec.polyp || other.spec.pedunculated) {
                motion = push.apply(other.spec.base) - other.spec.base;
            } else {
                for (const Vec3& q : other.surface.points)
                    motion += push.apply(q) - q;
                motion = motion / static_cast<double>(std::max<std::size_t>(1, other.surface.points.size()));
            }
            translate(other.surface, motion);
            other.seat.endometrium = push.apply(other.seat.endometrium); // still on the organ's surfaces
            other.seat.serosa = push.apply(other.seat.serosa);
            other.spec.center += motion;
            other.spec.base += motion;
        }
    }
    return {};
}

/// The pushes leave a pocket with flat faces and square corners around a head on a stalk, where it meets the wall it
/// opens from (each push is a smooth map of space, but the walls they move by different amounts meet at a crease).
/// The cavity's walls collapse onto a mass instead: the displacement of the moved cavity-side vertices near such a
/// head (within 3 radii + 10 mm of its centre), and two rings around them, is averaged with their neighbours'
/// (Jacobi, kPocketRounds rounds, half weight), each vertex held where its next step would bring it closer than the
/// clearance + kPocketSlackMm to a pathology (tracked with a slack, so distances are only recomputed when a vertex
/// may have used its slack up; steps are shorter than that distance, so none jumps through a surface), and vertices
/// inside a pathology or already that close to one (the wall it stands in) held throughout. Kept only when the organ
/// still does not intersect itself.
void roundPockets(SurfaceMesh& adapted, const SurfaceMesh& original, const OrganInfo& info,
                  const std::vector<Planned>& plans, const PathologyParams& params) {
    // Only around a head on a stalk in the cavity (FIGO 0, pedunculated polyps): its pocket is opened by the far
    // wall's and the radial push together. A dome on the wall keeps the pocket of its far wall's push, which is
    // rounded (and collapsing the walls onto it narrows the cavity beside it below a mesh edge).
    std::vector<std::pair<Vec3, double>> heads; // centre, reach
    for (const Planned& p : plans)
        if (p.spec.pedunculated && !p.fromSerosa)
            heads.emplace_back(p.spec.center, 3.0 * p.spec.radius + 10.0);
    if (heads.empty())
        return;
    const std::size_t n = adapted.points.size();
    std::vector<Vec3> disp(n);
    std::vector<std::uint8_t> active(n, 0);
    for (std::size_t v = 0; v < n; ++v) {
        disp[v] = adapted.points[v] - original.points[v];
        const bool nearHead = std::any_of(heads.begin(), heads.end(), [&](const std::pair<Vec3, double>& h) {
            return distance(adapted.points[v], h.first) < h.second;
        });
        active[v] = nearHead && info.vertexSide[v] == Side::Cavity && norm(disp[v]) > 0.05 ? 1 : 0;
    }
    std::vector<std::vector<std::size_t>> ring(n);
    for (const Triangle& t : adapted.triangles)
        for (int k = 0; k < 3; ++k) {
            const auto a = static_cast<std::size_t>(t[static_cast<std::size_t>(k)]);
            const auto b = static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)]);
            ring[a].push_back(b);
            ring[b].push_back(a);
        }
    for (auto& r : ring) {
        std::sort(r.begin(), r.end());
        r.erase(std::unique(r.begin(), r.end()), r.end());
    }
    for (int grow = 0; grow < 2; ++grow) {
        const std::vector<std::uint8_t> before = active;
        for (std::size_t v = 0; v < n; ++v)
            if (before[v])
                for (std::size_t w : ring[v])
                    if (info.vertexSide[w] == Side::Cavity)
                        active[w] = 1;
    }
    std::vector<std::size_t> movable;
    for (std::size_t v = 0; v < n; ++v)
        if (active[v])
            movable.push_back(v);
    if (movable.empty())
        return;
    const double clearance = params.clearanceMm + kPocketSlackMm;
    const double reach = clearance + 1.0;
    std::vector<TriangleGrid> grids;
    for (const Planned& p : plans)
        grids.emplace_back(p.surface, 2.0);
    auto nearest = [&](const Vec3& x) {
        double d = reach;
        for (const TriangleGrid& g : grids)
            d = std::min(d, g.distance(x, reach));
        return d;
    };
    // Inside a pathology, for points at least the clearance from it: voxels of 1 mm (half a diagonal, 0.87 mm, below
    // the clearance) classify them exactly.
    std::vector<Grid> voxelGrids;
    std::vector<std::vector<std::uint8_t>> masks;
    for (const Planned& p : plans) {
        voxelGrids.push_back(Grid::covering(bounds(p.surface), 1.0, 1));
        masks.push_back(insideMask(p.surface, voxelGrids.back()));
    }
    auto inside = [&](const Vec3& x) {
        for (std::size_t j = 0; j < plans.size(); ++j) {
            const Grid& g = voxelGrids[j];
            const Vec3 c = (x - g.origin) / g.h;
            const int i = static_cast<int>(std::lround(c.x)), jj = static_cast<int>(std::lround(c.y)),
                      k = static_cast<int>(std::lround(c.z));
            if (i >= 0 && jj >= 0 && k >= 0 && i < g.nx && jj < g.ny && k < g.nz && masks[j][g.index(i, jj, k)])
                return true;
        }
        return false;
    };
    std::vector<double> slack(n, 0.0);
    std::vector<std::uint8_t> held(n, 0);
    for (std::size_t v : movable) {
        const double d = nearest(adapted.points[v]);
        held[v] = d < clearance || inside(adapted.points[v]) ? 1 : 0; // a wall a pathology stands in stays
        slack[v] = d - clearance;
    }
    std::vector<Vec3> next = disp;
    for (int round = 0; round < kPocketRounds; ++round) {
        for (std::size_t v : movable) {
            if (held[v])
                continue;
            Vec3 mean;
            for (std::size_t w : ring[v])
                mean += disp[w];
            const Vec3 target = disp[v] * 0.5 + mean / static_cast<double>(ring[v].size()) * 0.5;
            const double step = norm(target - disp[v]);
            if (step < 1e-9 || step >= clearance) // shorter than the clearance: it cannot jump through a surface
                continue;
            if (slack[v] < step) {
                const double d = nearest(original.points[v] + target);
                if (d < clearance)
                    continue; // it would come too close: it stays this round
                slack[v] = d - clearance;
            } else {
                slack[v] -= step;
            }
            next[v] = target;
        }
        disp = next;
    }
    SurfaceMesh rounded = adapted;
    for (std::size_t v : movable)
        rounded.points[v] = original.points[v] + disp[v];
    if (!anatomy::hasSelfIntersections(rounded))
        adapted.points = std::move(rounded.points);
}

Status checkOverlaps(const std::vector<Planned>& all, double gap) {
    for (std::size_t i = 0; i < all.size(); ++i)
        for (std::size_t j = i + 1; j < all.size(); ++j) {
            const SurfaceMesh& a = all[i].surface;
            const SurfaceMesh& b = all[j].surface;
            const double d = std::min(surfaceDistance(a, b, gap + 1.0), surfaceDistance(b, a, gap + 1.0));
            const bool nested = windingNumber(b, a.points.front()) > 0.5 || windingNumber(a, b.points.front()) > 0.5;
            if (d < gap || nested)
                return fail(ErrorCode::InvalidInput,
                            who(*all[i].request) + " and " + who(*all[j].request) + " overlap" +
                                (nested ? " (one lies inside the other)"
                                        : " (they come within " + fmt(d, 2) + " mm; at least " + fmt(gap) +
                                              " mm of tissue must separate them)") +
                                ": move one or make them smaller");
        }
    return {};
}

} // namespace

Result<PathologyResult> growPathologies(const SurfaceMesh& organ, const PathologyParams& params, Progress& progress) {
    PathologyResult result;
    auto organInfo = analyzeOrgan(organ);
    if (!organInfo.ok())
        return organInfo.failure();
    const OrganInfo& info = *organInfo;
    if (!analyzeTopology(organ).isWatertight())
        return fail(ErrorCode::InvalidInput, "the organ surface is not closed and manifold");
    const Rng root(params.seed);
    std::vector<Planned> plans(params.pathologies.size());
    const double n = static_cast<double>(std::max<std::size_t>(1, plans.size()));
    for (std::size_t i = 0; i < plans.size(); ++i) {
        if (progress.cancelled())
            return fail(ErrorCode::Cancelled, "pathology stage cancelled");
        const PathologyRequest& r = params.pathologies[i];
        Planned& p = plans[i];
        p.request = &r;
        {
            ScopedStepTimer timer(result.timings, "place");
            HS_TRY(checkRequest(r));
            HS_TRY(checkSize(r, info));
            auto seat = seatFrom(r, info, params.contactToleranceMm, result.warnings);
            if (!seat.ok())
                return seat.failure();
            p.seat = *seat;
            std::vector<const SurfaceMesh*> earlier;
            for (std::size_t j = 0; j < i; ++j)
                earlier.push_back(&plans[j].surface);
            auto spec = planShape(r, info, p.seat, params, earlier, p.fromSerosa);
            if (!spec.ok())
                return spec.failure();
            p.spec = *spec;
        }
        {
            ScopedStepTimer timer(result.timings, "grow");
            Rng rng = root.derive(i);
            const double di = static_cast<double>(i);
            auto sub = progress.sub(di / n * 0.8, (di + 1.0) / n * 0.8);
            auto shape = grow(r, p.spec, organ, rng, sub);
            if (!shape.ok())
                return shape.failure();
            p.surface = std::move(*shape);
            scaleToSize(p.surface, p.spec, r.sizeMm);
            result.timings.step("grow").counts.emplace_back(r.id + ".triangles",
                                                            static_cast<std::int64_t>(p.surface.triangles.size()));
        }
        {
            ScopedStepTimer timer(result.timings, "fit");
            const Vec3 before = volumeCentroid(p.surface);
            fitDepth(p.surface, organ, r, p.seat, params);
            const Vec3 moved = volumeCentroid(p.surface) - before;
            p.spec.center += moved;
            p.spec.base += moved;
        }
        progress.report("pathology.grow", (static_cast<double>(i) + 1.0) / n * 0.8);
    }
    {
        ScopedStepTimer timer(result.timings, "overlap");
        HS_TRY(checkOverlaps(plans, params.minimumGapMm));
    }
    {
        ScopedStepTimer timer(result.timings, "adapt");
        result.organ = organ;
        for (std::size_t i = 0; i < plans.size(); ++i)
            HS_TRY(adaptOrgan(result.organ, plans, i, params));
        roundPockets(result.organ, organ, info, plans, params);
    }
    ScopedStepTimer timer(result.timings, "measure");
    for (std::size_t i = 0; i < plans.size(); ++i) {
        const PathologyRequest& r = *plans[i].request;
        GrownPathology g;
        g.id = r.id;
        g.kind = r.kind;
        g.model = r.model;
        g.surface = std::move(plans[i].surface);
        g.anchor = plans[i].fromSerosa ? plans[i].seat.serosa : plans[i].seat.endometrium;
        g.intoWall = plans[i].seat.intoWall;
        auto d = measure(result.organ, g.surface, r.kind, params);
        if (!d.ok())
            return fail(ErrorCode::Internal, who(r) + ": " + d.error().detail);
        g.descriptors = *d;
        if (r.kind == clinical::PathologyKind::Myoma && g.descriptors.figo != r.figo)
            result.warnings.push_back(who(r) + ": requested FIGO " + r.figo.toString() + ", measured " +
                                      g.descriptors.figo.toString());
        if (std::fabs(g.descriptors.sizeMm - r.sizeMm) > 0.1 * r.sizeMm)
            result.warnings.push_back(who(r) + ": requested " + fmt(r.sizeMm) + " mm, measured " +
                                      fmt(g.descriptors.sizeMm) + " mm");
        result.pathologies.push_back(std::move(g));
    }
    progress.report("pathology.measure", 1.0);
    return result;
}

} // namespace hs::pathology
