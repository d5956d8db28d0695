// Placement: the seat (the wall chord a pathology grows at) and the shape planned there.
#include "PathologySteps.h"

#include "Geometry.h"
#include "Measure.h"

#include "hs/clinical/Tissue.h"
#include "hs/core/Units.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <variant>

namespace hs::pathology::detail {

namespace {

constexpr double kHybridPlay = 0.15;    ///< a hybrid's seat: play for the centre across the wall, of the radius
constexpr double kHybridSlide = 0.4;    ///< a hybrid's seat slides at most this fraction of the cavity length
constexpr double kHybridTurnDeg = 30.0; ///< and faces within this angle of the nominal seat
/// A pathology placed by location keeps its head and foot this far beyond their radii from a tubal ostium's centre,
/// and its head this far from the sight line to the ostium from the cavity's middle: the tube's lumen is about 1 mm
/// [ElMowafi2008] and the model's ostium funnel 1-3 mm across, so a millimetre is left between its rim and the mass.
constexpr double kOstiumClearMm = 3.0;
constexpr double kOstiumSlide = 1.0; ///< a pathology moved off an ostium slides at most this fraction of the
                                     ///< cavity length
/// A grown shape on a lateral or cornual wall keeps this far from the sight line to that side's ostium: the organ's
/// adaptation to the masses still moves the walls and the pathologies on them by about a millimetre.
constexpr double kOstiumSightClearMm = 1.5;
constexpr double kOstiumTurnDeg = 80.0; ///< and on a wall facing within this angle of the nominal seat

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

} // namespace

std::vector<Seat> nearbySeats(const OrganInfo& info, const Seat& nominal, double reachMm, double turnDeg) {
    const SurfaceMesh& organ = *info.mesh;
    const auto& tissue = organ.faceLabels.at(clinical::kSurfaceTissueLabel);
    const double minCos = std::cos(units::degToRad(turnDeg));
    std::vector<std::pair<double, std::size_t>> candidates;
    for (std::size_t f = 0; f < organ.triangles.size(); ++f) {
        if (static_cast<clinical::SurfaceTissue>(tissue[f]) != clinical::SurfaceTissue::Endometrium)
            continue;
        const double d = distance(faceCentroid(organ, f), nominal.endometrium);
        if (d <= reachMm && dot(-faceNormalOf(info, f), nominal.intoWall) >= minCos)
            candidates.emplace_back(d, f);
    }
    std::sort(candidates.begin(), candidates.end());
    std::vector<Seat> seats;
    for (const auto& [d, f] : candidates) {
        Seat s;
        s.endometrium = faceCentroid(organ, f);
        s.intoWall = -faceNormalOf(info, f);
        if (reachSerosa(info, s))
            seats.push_back(s);
    }
    return seats;
}

namespace {

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
    const std::vector<Seat> candidates =
        nearbySeats(info, nominal, std::max(5.0, kHybridSlide * info.cavityLengthMm), kHybridTurnDeg);
    auto slid = [&](const Seat& s) {
        notes.push_back(who(r) + ": the wall at the nominal seat is " + fmt(nominal.wallMm) +
                        " mm thick, too thick for a " + fmt(r.sizeMm, 0) + " mm FIGO " + r.figo.toString() +
                        " myoma to span; seated " + fmt(distance(s.endometrium, nominal.endometrium)) +
                        " mm away, where it is " + fmt(s.wallMm) + " mm");
        return s;
    };
    for (const Seat& s : candidates) {
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

} // namespace

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

namespace {

double segmentDistance(const Vec3& a, const Vec3& b, const Vec3& p) {
    const Vec3 ab = b - a;
    const double len2 = dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return distance(a + ab * t, p);
}

} // namespace

namespace {

/// The side whose wall a clinical location names ("left", "right"; empty for the others): a mass on it stands between
/// the cavity's middle and that side's ostium.
std::string_view sideOfWall(const PathologyRequest& r) {
    if (const auto* c = std::get_if<clinical::ClinicalPlacement>(&r.placement)) {
        if (c->location == clinical::UterineLocation::LeftLateral ||
            c->location == clinical::UterineLocation::CornualLeft)
            return "left";
        if (c->location == clinical::UterineLocation::RightLateral ||
            c->location == clinical::UterineLocation::CornualRight)
            return "right";
    }
    return {};
}

struct OstiumPoint {
    Vec3 centre;
    const char* side;
};

/// The organ's labelled ostia.
std::vector<OstiumPoint> labelledOstia(const OrganInfo& info) {
    std::vector<OstiumPoint> ostia;
    if (info.ostiumRight)
        ostia.push_back({info.cornuRight, "right"});
    if (info.ostiumLeft)
        ostia.push_back({info.cornuLeft, "left"});
    return ostia;
}

/// The scope's eye in the middle of the cavity, as the scene's validation places it: halfway from the internal os to
/// the midpoint of the ostia.
Vec3 sightEye(const OrganInfo& info) {
    return (info.internalOs + (info.cornuRight + info.cornuLeft) * 0.5) * 0.5;
}

} // namespace

std::string ostiumCoveredBy(const PathologyRequest& r, const OrganInfo& info, const ShapeSpec& spec) {
    const std::string_view wall = sideOfWall(r);
    const Vec3 eye = sightEye(info);
    for (const auto& [centre, side] : labelledOstia(info))
        if (distance(spec.center, centre) < spec.radius + kOstiumClearMm ||
            distance(spec.base, centre) < spec.stalkRadius + kOstiumClearMm ||
            (wall == side && segmentDistance(eye, centre, spec.center) < spec.radius + kOstiumClearMm))
            return side;
    return {};
}

std::string ostiumHiddenByShape(const PathologyRequest& r, const OrganInfo& info, const SurfaceMesh& shape) {
    const std::string_view wall = sideOfWall(r);
    const Vec3 eye = sightEye(info);
    for (const auto& [centre, side] : labelledOstia(info)) {
        for (const Vec3& q : shape.points)
            if (distance(q, centre) < kOstiumClearMm ||
                (wall == side && segmentDistance(eye, centre, q) < kOstiumSightClearMm))
                return side;
        if (wall != side)
            continue;
        const double length = distance(eye, centre);
        const Vec3 dir = (centre - eye) / std::max(length, 1e-12);
        for (const Triangle& t : shape.triangles) {
            double at = 0.0;
            if (rayTriangle(eye, dir, shape.points[static_cast<std::size_t>(t[0])],
                            shape.points[static_cast<std::size_t>(t[1])], shape.points[static_cast<std::size_t>(t[2])],
                            0.0, at) &&
                at < length)
                return side;
        }
    }
    return {};
}

double ostiumSlideReachMm(const OrganInfo& info) {
    return std::max(5.0, kOstiumSlide * info.cavityLengthMm);
}

std::vector<Seat> seatsOffOstia(const OrganInfo& info, const Seat& nominal) {
    return nearbySeats(info, nominal, ostiumSlideReachMm(info), kOstiumTurnDeg);
}

Seat plannedOffOstia(const PathologyRequest& r, const OrganInfo& info, const Seat& nominal,
                     const PathologyParams& params, const std::vector<const SurfaceMesh*>& earlier) {
    if (!std::holds_alternative<clinical::ClinicalPlacement>(r.placement))
        return nominal;
    bool fromSerosa = false;
    auto planned = planShape(r, info, nominal, params, earlier, fromSerosa);
    if (!planned.ok() || ostiumCoveredBy(r, info, *planned).empty())
        return nominal; // clear, or the grow step reports why it cannot be planned
    for (const Seat& seat : seatsOffOstia(info, nominal)) {
        auto spec = planShape(r, info, seat, params, earlier, fromSerosa);
        if (spec.ok() && ostiumCoveredBy(r, info, *spec).empty())
            return seat;
    }
    return nominal;
}

} // namespace hs::pathology::detail
