// The pathology stage: place, grow, fit the depth to the FIGO type, let the organ make room, measure.
#include "hs/pathology/Pathology.h"

#include "Geometry.h"
#include "Measure.h"
#include "PathologySteps.h"

#include "hs/clinical/Tissue.h"
#include "hs/core/RegionModel.h"
#include "hs/core/Rng.h"
#include "hs/core/TriangleGeometry.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <variant>

namespace hs::pathology {

namespace detail {

std::string fmt(double v, int digits) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(digits);
    s << v;
    return s.str();
}
std::string fmt(const Vec3& v) {
    return "(" + fmt(v.x) + ", " + fmt(v.y) + ", " + fmt(v.z) + ")";
}

std::string who(const PathologyRequest& r) {
    return std::string(toString(r.kind)) + " '" + r.id + "'";
}

} // namespace detail

namespace {
using namespace detail;

constexpr double kResiteSlide = 0.5;    ///< a pathology moved off another slides at most this fraction of the
                                        ///< cavity length
constexpr double kResiteTurnDeg = 45.0; ///< and stays on a wall facing within this angle of the nominal seat
constexpr double kResiteMarginMm = 1.0; ///< planned room beyond the minimum gap (the grown shape is lobulated)
constexpr int kResiteGrowths = 8;       ///< seats grown at most before the case is refused
constexpr int kOstiumGrowths = 8;       ///< seats grown at most off an ostium before it stays, with a warning

/// The pathologies placed before pathology i: those it keeps clear of when it is placed.
std::vector<std::size_t> othersOf(std::size_t i) {
    std::vector<std::size_t> others;
    for (std::size_t j = 0; j < i; ++j)
        others.push_back(j);
    return others;
}

std::vector<const SurfaceMesh*> surfacesOf(const std::vector<Planned>& plans, const std::vector<std::size_t>& which) {
    std::vector<const SurfaceMesh*> surfaces;
    for (std::size_t j : which)
        surfaces.push_back(&plans[j].surface);
    return surfaces;
}

Result<SurfaceMesh> grow(const PathologyRequest& r, const ShapeSpec& spec, const SurfaceMesh& organ, Rng& rng,
                         Progress& progress, const GrowthObserver& observe, std::size_t index) {
    GrowthTuning tuning;
    tuning.observe = observe ? &observe : nullptr;
    tuning.pathology = index;
    switch (r.model) {
    case clinical::GrowthModel::Skeleton: {
        SurfaceMesh shape = skeletonShape(spec, rng);
        emitSweptFrames(tuning, shape, spec);
        return shape;
    }
    case clinical::GrowthModel::CellularAutomaton:
        return cellularAutomatonShape(spec, organ, tuning, rng, progress);
    case clinical::GrowthModel::Particles:
        return particleShape(spec, organ, tuning, rng, progress);
    }
    return fail(ErrorCode::Internal, "unknown growth model");
}

/// Room a planned shape needs among the pathologies placed before it: its centre keeps radius + gap (+ margin, the
/// grown shape is lobulated) from every one of them, and so does its foot (a stalk's root or a dome's base) within its
/// own reach.
class Room {
public:
    Room(const std::vector<Planned>& plans, const std::vector<std::size_t>& others, double gapMm) : m_gapMm(gapMm) {
        for (std::size_t j : others)
            m_earlier.emplace_back(&plans[j].surface, bounds(plans[j].surface));
    }
    bool operator()(const ShapeSpec& spec) const {
        const double need = spec.radius + m_gapMm + kResiteMarginMm;
        const double footNeed = spec.stalkRadius + m_gapMm + kResiteMarginMm;
        for (const auto& [mesh, box] : m_earlier) {
            if (signedDistance(*mesh, box, spec.center, need + 1.0) < need)
                return false;
            if (signedDistance(*mesh, box, spec.base, footNeed + 1.0) < footNeed)
                return false;
        }
        return true;
    }

private:
    double m_gapMm;
    std::vector<std::pair<const SurfaceMesh*, Bounds>> m_earlier;
};

/// Plans pathology i at `seat`, grows it (its own random stream, so a second seat grows it the same way), scales it
/// to the requested size and fits its depth to the FIGO type.
Status growAt(std::vector<Planned>& plans, std::size_t i, const std::vector<std::size_t>& others, const Seat& seat,
              const SurfaceMesh& organ, const OrganInfo& info, const PathologyParams& params, const Rng& root,
              StageTimings& timings, Progress& progress, const GrowthObserver& observe) {
    Planned& p = plans[i];
    const PathologyRequest& r = *p.request;
    {
        ScopedStepTimer timer(timings, "place");
        p.seat = seat;
        auto spec = planShape(r, info, p.seat, params, surfacesOf(plans, others), p.fromSerosa);
        if (!spec.ok())
            return spec.failure();
        p.spec = *spec;
    }
    {
        ScopedStepTimer timer(timings, "grow");
        Rng rng = root.derive(i);
        auto shape = grow(r, p.spec, organ, rng, progress, observe, i);
        if (!shape.ok())
            return shape.failure();
        p.surface = std::move(*shape);
        scaleToSize(p.surface, p.spec, r.sizeMm);
    }
    ScopedStepTimer timer(timings, "fit");
    const Vec3 before = volumeCentroid(p.surface);
    fitDepth(p.surface, organ, r, p.seat, params);
    const Vec3 moved = volumeCentroid(p.surface) - before;
    p.spec.center += moved;
    p.spec.base += moved;
    return {};
}

/// The pathology of `others` that pathology i overlaps (comes within `gap` of, or nests in), if any.
std::optional<std::size_t> overlapsAny(const std::vector<Planned>& plans, std::size_t i,
                                       const std::vector<std::size_t>& others, double gap) {
    for (std::size_t j : others)
        if (!checkOverlap(plans[std::min(i, j)], plans[std::max(i, j)], gap).ok())
            return j;
    return std::nullopt;
}

/// A clinical location names a wall, not a point on it: when pathology i, grown at its seat, overlaps one of
/// `others` (the pathologies already placed), it moves to the nearest seat on the same wall (within kResiteSlide of
/// the cavity's length, facing within kResiteTurnDeg) where it keeps the minimum gap, with a warning that says so.
/// Seats whose planned centre already lies too close to one of them are skipped without growing; at most
/// kResiteGrowths are grown. When none is clear the pathology stays where it was (false). A point placement (a
/// click) is never moved: it stays where it was put, and the overlap check refuses the case.
Result<bool> resiteClearOf(std::vector<Planned>& plans, std::size_t i, const std::vector<std::size_t>& others,
                           const SurfaceMesh& organ, const OrganInfo& info, const PathologyParams& params,
                           const Rng& root, PathologyResult& result, Progress& progress,
                           const GrowthObserver& observe) {
    const auto blocker = overlapsAny(plans, i, others, params.minimumGapMm);
    if (!blocker)
        return true;
    const PathologyRequest& r = *plans[i].request;
    const Seat nominal = plans[i].seat;
    const Planned kept = plans[i];
    const Room roomy(plans, others, params.minimumGapMm);
    int grown = 0;
    for (const Seat& seat :
         nearbySeats(info, nominal, std::max(5.0, kResiteSlide * info.cavityLengthMm), kResiteTurnDeg)) {
        if (grown >= kResiteGrowths)
            break;
        bool fromSerosa = false;
        auto spec = planShape(r, info, seat, params, surfacesOf(plans, others), fromSerosa);
        if (!spec.ok() || !roomy(*spec) || !ostiumCoveredBy(r, info, *spec).empty())
            continue;
        ++grown;
        HS_TRY(progress.check("pathology stage"));
        HS_TRY(growAt(plans, i, others, seat, organ, info, params, root, result.timings, progress, observe));
        if (!overlapsAny(plans, i, others, params.minimumGapMm)) {
            result.warnings.push_back(who(r) + ": at its nominal seat it overlaps " + who(*plans[*blocker].request) +
                                      "; seated " + fmt(distance(seat.endometrium, nominal.endometrium)) +
                                      " mm away on the same wall");
            return true;
        }
    }
    plans[i] = kept; // nothing clear nearby: the overlap check names both
    return false;
}

/// Pathology i, placed by a clinical location, overlaps one placed before it: i slides along its wall
/// (resiteClearOf); when no seat there is clear, the earlier one slides along its own wall instead, clear of i and
/// of those before it, if it was placed by a clinical location too (a big head on a stalk can fill the room a later,
/// smaller pathology's wall has, while its own wall has more). Otherwise both stay and the overlap check names them.
Status resiteClearOfEarlier(std::vector<Planned>& plans, std::size_t i, const SurfaceMesh& organ, const OrganInfo& info,
                            const PathologyParams& params, const Rng& root, PathologyResult& result, Progress& progress,
                            const GrowthObserver& observe) {
    auto cleared = resiteClearOf(plans, i, othersOf(i), organ, info, params, root, result, progress, observe);
    if (!cleared.ok())
        return cleared.failure();
    if (*cleared)
        return {};
    const auto blocker = overlapsAny(plans, i, othersOf(i), params.minimumGapMm);
    if (!blocker || !std::holds_alternative<clinical::ClinicalPlacement>(plans[*blocker].request->placement))
        return {};
    const std::size_t j = *blocker;
    std::vector<std::size_t> others;
    for (std::size_t k = 0; k <= i; ++k)
        if (k != j)
            others.push_back(k);
    auto moved = resiteClearOf(plans, j, others, organ, info, params, root, result, progress, observe);
    if (!moved.ok())
        return moved.failure();
    return {};
}

/// A clinical location names a wall, not a point on it, and the scope must find both tubal ostia: where pathology i,
/// grown at its seat, covers an ostium or, on a lateral or cornual wall, hides that side's ostium from the cavity's
/// middle (ostiumHiddenByShape), it is grown again at the seats of seatsOffOstia around its nominal seat whose planned
/// shape keeps both ostia free and has room among the pathologies before it, at most kOstiumGrowths, and stays at the
/// first whose grown shape keeps the ostia free and overlaps none of them. Either way a warning says what happened:
/// the slide from `nominal` (also when the first seat, plannedOffOstia, already slid), or the ostium it covers when
/// no seat keeps it free (it then goes back where it was grown first). A point placement is never moved.
Status keepOstiaFree(std::vector<Planned>& plans, std::size_t i, const Seat& nominal, const SurfaceMesh& organ,
                     const OrganInfo& info, const PathologyParams& params, const Rng& root, PathologyResult& result,
                     Progress& progress, const GrowthObserver& observe) {
    const PathologyRequest& r = *plans[i].request;
    if (!std::holds_alternative<clinical::ClinicalPlacement>(r.placement))
        return {};
    auto slid = [&](const std::string& ostium) {
        const double d = distance(plans[i].seat.endometrium, nominal.endometrium);
        if (d > 1e-9)
            result.warnings.push_back(who(r) + ": at its nominal seat it would cover or hide the " + ostium +
                                      " tubal ostium; seated " + fmt(d) + " mm away on the same wall");
    };
    std::string hidden = ostiumHiddenByShape(r, info, plans[i].surface);
    if (hidden.empty()) {
        // Clear where it grew: say so when the planned seat already slid off an ostium.
        bool fromSerosa = false;
        auto atNominal = planShape(r, info, nominal, params, surfacesOf(plans, othersOf(i)), fromSerosa);
        if (atNominal.ok()) {
            const std::string planned = ostiumCoveredBy(r, info, *atNominal);
            if (!planned.empty())
                slid(planned);
        }
        return {};
    }
    const Planned kept = plans[i];
    const Room roomy(plans, othersOf(i), params.minimumGapMm);
    int grown = 0;
    for (const Seat& seat : seatsOffOstia(info, nominal)) {
        if (grown >= kOstiumGrowths)
            break;
        bool fromSerosa = false;
        auto spec = planShape(r, info, seat, params, surfacesOf(plans, othersOf(i)), fromSerosa);
        if (!spec.ok() || !roomy(*spec) || !ostiumCoveredBy(r, info, *spec).empty())
            continue;
        ++grown;
        HS_TRY(progress.check("pathology stage"));
        HS_TRY(growAt(plans, i, othersOf(i), seat, organ, info, params, root, result.timings, progress, observe));
        if (ostiumHiddenByShape(r, info, plans[i].surface).empty() &&
            !overlapsAny(plans, i, othersOf(i), params.minimumGapMm)) {
            slid(hidden);
            return {};
        }
    }
    plans[i] = kept;
    result.warnings.push_back(who(r) + ": covers or hides the " + hidden +
                              " tubal ostium: no seat on the same wall within " + fmt(ostiumSlideReachMm(info)) +
                              " mm keeps both ostia free");
    return {};
}

} // namespace

Result<PathologyResult> growPathologies(const SurfaceMesh& organ, const PathologyParams& params, Progress& progress,
                                        const GrowthObserver& observe) {
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
        HS_TRY(progress.check("pathology stage"));
        const PathologyRequest& r = params.pathologies[i];
        Planned& p = plans[i];
        p.request = &r;
        Seat seat, nominalSeat;
        {
            ScopedStepTimer timer(result.timings, "place");
            HS_TRY(checkRequest(r));
            HS_TRY(checkSize(r, info));
            auto nominal = seatFrom(r, info, params.contactToleranceMm, result.warnings);
            if (!nominal.ok())
                return nominal.failure();
            nominalSeat = *nominal;
            seat = plannedOffOstia(r, info, *nominal, params, surfacesOf(plans, othersOf(i)));
        }
        const double di = static_cast<double>(i);
        auto sub = progress.sub(di / n * 0.8, (di + 1.0) / n * 0.8);
        HS_TRY(growAt(plans, i, othersOf(i), seat, organ, info, params, root, result.timings, sub, observe));
        if (std::holds_alternative<clinical::ClinicalPlacement>(r.placement)) {
            HS_TRY(resiteClearOfEarlier(plans, i, organ, info, params, root, result, sub, observe));
            HS_TRY(keepOstiaFree(plans, i, nominalSeat, organ, info, params, root, result, sub, observe));
        }
        result.timings.step("grow").counts.emplace_back(r.id + ".triangles",
                                                        static_cast<std::int64_t>(p.surface.triangles.size()));
        progress.report("pathology.grow", (di + 1.0) / n * 0.8);
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
        // A later pathology's pushes move the walls an earlier one stands in: a cornual polyp's radial push once moved
        // a lateral wall 6 mm onto a FIGO 5 myoma, which moved 0.8 mm (its mean motion) and then touched the
        // endometrium. So each earlier myoma's pushes that keep it clear of the endometrium (types 4-7) and of the
        // serosa (types 0-4) are solved once more on the organ as the later ones left it; where the clearance still
        // holds they have nothing to make up and move nothing.
        for (std::size_t i = 0; i + 1 < plans.size(); ++i)
            HS_TRY(adaptOrgan(result.organ, plans, i, params, AdaptRound::Again));
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
        auto d = measure(result.organ, g.surface, r.kind, params, g.anchor);
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

Result<clinical::SurfacePlacement> seatAt(const SurfaceMesh& organ, const Vec3& pointMm, clinical::PathologyKind kind,
                                          double toleranceMm) {
    if (!std::isfinite(pointMm.x) || !std::isfinite(pointMm.y) || !std::isfinite(pointMm.z))
        return fail(ErrorCode::InvalidInput, "the picked point is not finite");
    // The face under the point: the closest one (a pick lies on a face up to rounding, and the view may show the
    // surface cut or re-triangulated, so its cell ids are not the organ's).
    std::size_t face = organ.triangles.size();
    double best = toleranceMm * toleranceMm;
    for (std::size_t f = 0; f < organ.triangles.size(); ++f) {
        const Triangle& t = organ.triangles[f];
        const ClosestPoint c = closestPointOnTriangle(pointMm, organ.points[static_cast<std::size_t>(t[0])],
                                                      organ.points[static_cast<std::size_t>(t[1])],
                                                      organ.points[static_cast<std::size_t>(t[2])]);
        if (c.distance2 <= best) {
            best = c.distance2;
            face = f;
        }
    }
    if (face == organ.triangles.size())
        return fail(ErrorCode::InvalidInput,
                    "the point lies more than " + std::to_string(toleranceMm) + " mm from the organ's surface");
    const Vec3 normal = faceNormal(organ, face);
    if (norm(normal) == 0.0)
        return fail(ErrorCode::InvalidInput, "face " + std::to_string(face) + " of the organ has no area");
    const auto labels = organ.faceLabels.find(clinical::kSurfaceTissueLabel);
    if (labels != organ.faceLabels.end() && face < labels->second.size()) {
        const auto tissue = static_cast<clinical::SurfaceTissue>(labels->second[face]);
        if (tissue == clinical::SurfaceTissue::CervicalCanal || tissue == clinical::SurfaceTissue::Ectocervix)
            return fail(ErrorCode::Unsupported, "the point lies on the " + std::string(clinical::toString(tissue)) +
                                                    ": cervical pathologies are not modelled");
        if (kind == clinical::PathologyKind::Polyp && tissue == clinical::SurfaceTissue::Serosa)
            return fail(ErrorCode::InvalidInput, "the point lies on the serosa: a polyp grows from the endometrium "
                                                 "into the cavity");
    }
    return clinical::SurfacePlacement{pointMm, normal};
}

} // namespace hs::pathology