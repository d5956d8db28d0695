// The pathology stage's checks: a request is valid and fits the organ; the planned pathologies keep apart.
#include "PathologySteps.h"

#include "Geometry.h"

#include "hs/core/RegionModel.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace hs::pathology::detail {

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
        if (r.sizeMm > kMaxMyomaToCorpus * smallest)
            return fail(ErrorCode::InvalidInput, who(r) + ": a " + fmt(r.sizeMm, 0) +
                                                     " mm myoma cannot grow in this uterus: its corpus measures " +
                                                     fmt(info.corpusWidthMm, 0) + " x " + fmt(info.corpusDepthMm, 0) +
                                                     " x " + fmt(info.corpusLengthMm, 0) +
                                                     " mm (width x depth x length), room for at most " +
                                                     fmt(kMaxMyomaToCorpus * smallest, 0) + " mm");
    } else {
        const double room = kMaxPolypToCavity * info.cavityLengthMm;
        const double length =
            r.sizeMm + (r.attachment == clinical::PolypAttachment::Pedunculated ? r.stalkLengthMm : 0.0);
        if (r.sizeMm > room || length > kMaxPolypReachToCavity * info.cavityLengthMm)
            return fail(ErrorCode::InvalidInput,
                        who(r) + ": a " + fmt(r.sizeMm, 0) + " mm polyp" +
                            (r.stalkLengthMm > 0.0 ? " on a " + fmt(r.stalkLengthMm, 0) + " mm stalk" : "") +
                            " does not fit a cavity " + fmt(info.cavityLengthMm, 0) + " mm long");
    }
    return {};
}
Status checkOverlap(const Planned& first, const Planned& second, double gap) {
    const SurfaceMesh& a = first.surface;
    const SurfaceMesh& b = second.surface;
    const double d = std::min(surfaceDistance(a, b, gap + 1.0), surfaceDistance(b, a, gap + 1.0));
    const bool nested = windingNumber(b, a.points.front()) > 0.5 || windingNumber(a, b.points.front()) > 0.5;
    if (d < gap || nested)
        return fail(ErrorCode::InvalidInput, who(*first.request) + " and " + who(*second.request) + " overlap" +
                                                 (nested ? " (one lies inside the other)"
                                                         : " (they come within " + fmt(d, 2) + " mm; at least " +
                                                               fmt(gap) + " mm of tissue must separate them)") +
                                                 ": move one or make them smaller");
    return {};
}

Status checkOverlaps(const std::vector<Planned>& all, double gap) {
    for (std::size_t i = 0; i < all.size(); ++i)
        for (std::size_t j = i + 1; j < all.size(); ++j)
            HS_TRY(checkOverlap(all[i], all[j], gap));
    return {};
}

} // namespace hs::pathology::detail
