// The pathology stage: place, grow, fit the depth to the FIGO type, let the organ make room, measure.
#include "hs/pathology/Pathology.h"

#include "Geometry.h"
#include "Measure.h"
#include "PathologySteps.h"

#include "hs/core/RegionModel.h"
#include "hs/core/Rng.h"

#include <algorithm>
#include <cmath>
#include <sstream>

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
        HS_TRY(progress.check("pathology stage"));
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