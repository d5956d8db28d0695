// Fitting a grown shape: its size to the request, its depth in the wall to the FIGO type.
#include "PathologySteps.h"

#include "Geometry.h"
#include "Measure.h"

#include <algorithm>

namespace hs::pathology::detail {

namespace {

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

} // namespace

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

} // namespace hs::pathology::detail
