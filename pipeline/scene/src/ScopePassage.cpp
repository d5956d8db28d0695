// The scope passage check: clearance grid, widest route, its narrowest point and the straight stretch ahead.

#include "hs/scene/ScopePassage.h"

#include "ClearanceGrid.h"
#include "Format.h"
#include "hs/core/TriangleGeometry.h"
#include "hs/core/TriangleGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <queue>
#include <utility>

namespace hs::scene {

namespace {

using detail::ClearanceGrid;
using detail::formatNumber;

/// Half-width of each os zone along the canal axis, mm: an os is a short funnel, not a plane.
constexpr double kOsBandMm = 2.0;
/// Depth of the organ's outer tissue that the route may not cross, mm: a closure thinner than twice this is found
/// where it is. The organ's walls are thicker (the generator keeps 6 mm, the organ checks 5 mm).
constexpr double kSkinMm = 3.0;
constexpr std::uint8_t kNoParent = 255;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Step {
    Index3 offset;
    double lengthVoxels;
};

/// The 26 neighbours of a voxel, in a fixed order (so ties are broken the same way every run).
std::array<Step, 26> neighbourSteps() {
    std::array<Step, 26> steps{};
    std::size_t k = 0;
    for (std::int64_t z = -1; z <= 1; ++z)
        for (std::int64_t y = -1; y <= 1; ++y)
            for (std::int64_t x = -1; x <= 1; ++x)
                if (x || y || z)
                    steps[k++] = {{x, y, z}, std::sqrt(double(x * x + y * y + z * z))};
    return steps;
}

Status checkRange(const char* name, double value, double lo, double hi, const char* unit) {
    if (std::isfinite(value) && value >= lo && value <= hi)
        return {};
    return fail(ErrorCode::InvalidInput, std::string("scope passage: ") + name + " " + formatNumber(value) + unit +
                                             " is outside " + formatNumber(lo) + ".." + formatNumber(hi) + unit);
}

Status checkParams(const ScopePassageParams& p) {
    HS_TRY(checkRange("scopeDiameterMm", p.scopeDiameterMm, 1.0, 10.0, " mm"));
    HS_TRY(checkRange("voxelFraction", p.voxelFraction, 0.05, 0.5, ""));
    HS_TRY(checkRange("straightLengthMm", p.straightLengthMm, 0.0, 100.0, " mm"));
    HS_TRY(checkRange("startOffsetMm", p.startOffsetMm, 1.0, 50.0, " mm"));
    HS_TRY(checkRange("fundusReachMm", p.fundusReachMm, 0.5, 30.0, " mm"));
    if (p.maxVoxels < 1 || p.maxVoxels > VoxelGrid<float>::kMaxVoxels)
        return fail(ErrorCode::InvalidInput,
                    "scope passage: maxVoxels " + std::to_string(p.maxVoxels) + " is outside 1..2^31");
    return {};
}

Status checkLandmarks(const ScopeLandmarks& l, const Bounds& meshBox, double slackMm) {
    const std::array<std::pair<const char*, Vec3>, 3> points{
        {{"externalOsMm", l.externalOsMm}, {"internalOsMm", l.internalOsMm}, {"fundusMm", l.fundusMm}}};
    for (const auto& [name, p] : points) {
        if (!isFinite(p))
            return fail(ErrorCode::InvalidInput, std::string("scope passage: landmark ") + name + " is not finite");
        for (int k = 0; k < 3; ++k)
            if (p[k] < meshBox.min[k] - slackMm || p[k] > meshBox.max[k] + slackMm)
                return fail(ErrorCode::InvalidInput, std::string("scope passage: landmark ") + name +
                                                         " lies outside the mesh's bounding box (+" +
                                                         formatNumber(slackMm) + " mm)");
    }
    if (distance(l.externalOsMm, l.internalOsMm) < 1e-6)
        return fail(ErrorCode::InvalidInput, "scope passage: the external and internal os coincide; no canal axis");
    return {};
}

/// Voxels whose centre lies within `radiusMm` of p, ascending.
std::vector<std::int64_t> voxelsNear(const VoxelGrid<float>& grid, const Vec3& p, double radiusMm) {
    std::vector<std::int64_t> found;
    const Index3 lo = grid.voxelOf(p - Vec3(radiusMm, radiusMm, radiusMm));
    const Index3 hi = grid.voxelOf(p + Vec3(radiusMm, radiusMm, radiusMm));
    for (std::int64_t z = lo[2]; z <= hi[2]; ++z)
        for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
            for (std::int64_t x = lo[0]; x <= hi[0]; ++x) {
                const Index3 ijk{x, y, z};
                if (grid.contains(ijk) && distance(grid.center(ijk), p) <= radiusMm)
                    found.push_back(static_cast<std::int64_t>(grid.linear(ijk)));
            }
    return found;
}

bool isIn(const std::vector<std::int64_t>& sorted, std::int64_t v) {
    return std::binary_search(sorted.begin(), sorted.end(), v);
}

/// Calls f(neighbour, step) for every in-grid neighbour of voxel v.
template <class F>
void forEachNeighbour(const VoxelGrid<float>& grid, const std::array<Step, 26>& steps, std::int64_t v, F&& f) {
    const Index3 ijk = grid.unlinear(std::size_t(v));
    for (std::size_t k = 0; k < steps.size(); ++k) {
        const Index3 n{ijk[0] + steps[k].offset[0], ijk[1] + steps[k].offset[1], ijk[2] + steps[k].offset[2]};
        if (grid.contains(n))
            f(static_cast<std::int64_t>(grid.linear(n)), k);
    }
}

/// Where the route may not go: the free space outside the organ (free voxels connected, by 26 neighbours, to the
/// grid's border without passing within `radiusMm` of the external os) and the tissue within kSkinMm of it.
/// Without this a closed canal would let the widest route go round the organ, or creep along just under its
/// serosa, and enter the cavity through its thinnest wall instead of crossing the closure.
Result<std::vector<std::uint8_t>> blockedVoxels(const ClearanceGrid& grid, const Vec3& externalOs, double radiusMm,
                                                Progress& progress) {
    const auto& g = grid.clearanceMm;
    std::vector<std::uint8_t> exterior(g.size(), 0);
    const auto open = [&](std::size_t v) {
        return !exterior[v] && !grid.tissue[v] && distance(g.center(g.unlinear(v)), externalOs) > radiusMm;
    };
    std::vector<std::int64_t> queue;
    const Index3& n = g.dims();
    for (std::size_t v = 0; v < g.size(); ++v) {
        const Index3 ijk = g.unlinear(v);
        const bool border =
            ijk[0] == 0 || ijk[1] == 0 || ijk[2] == 0 || ijk[0] == n[0] - 1 || ijk[1] == n[1] - 1 || ijk[2] == n[2] - 1;
        if (border && open(v)) {
            exterior[v] = 1;
            queue.push_back(std::int64_t(v));
        }
    }
    const auto steps = neighbourSteps();
    for (std::size_t head = 0; head < queue.size(); ++head)
        forEachNeighbour(g, steps, queue[head], [&](std::int64_t m, std::size_t) {
            if (open(std::size_t(m))) {
                exterior[std::size_t(m)] = 1;
                queue.push_back(m);
            }
        });
    auto toExterior = detail::squaredVoxelDistance(n, exterior, 1, progress);
    if (!toExterior.ok())
        return toExterior.failure();
    const double skinVoxels2 = (kSkinMm / g.spacing()) * (kSkinMm / g.spacing());
    for (std::size_t v = 0; v < g.size(); ++v)
        if (grid.tissue[v] && (*toExterior)[v] <= skinVoxels2)
            exterior[v] = 1;
    return exterior;
}

/// The largest clearance c such that some voxel path from a start to a target keeps clearance >= c everywhere: the
/// maximin (bottleneck) path problem, solved by Dijkstra's algorithm with min() in place of + (Pollack, "The
/// maximum capacity through a network", Operations Research 8, 1960).
Result<float> widestBottleneck(const VoxelGrid<float>& clearance, const std::vector<std::uint8_t>& exterior,
                               const std::vector<std::int64_t>& starts, const std::vector<std::int64_t>& targets,
                               Progress& progress) {
    const auto steps = neighbourSteps();
    std::vector<float> best(clearance.size(), -std::numeric_limits<float>::infinity());
    std::priority_queue<std::pair<float, std::int64_t>> heap;
    for (std::int64_t s : starts) {
        best[std::size_t(s)] = clearance[std::size_t(s)];
        heap.push({best[std::size_t(s)], s});
    }
    std::size_t pops = 0;
    while (!heap.empty()) {
        // Plain variables, not a structured binding: a C++17 lambda may not capture a binding (clang refuses).
        const float value = heap.top().first;
        const std::int64_t v = heap.top().second;
        heap.pop();
        if (value < best[std::size_t(v)])
            continue;
        if (isIn(targets, v))
            return value;
        if ((++pops & 65535) == 0 && progress.cancelled())
            return fail(ErrorCode::Cancelled, "scope passage cancelled while searching the widest route");
        forEachNeighbour(clearance, steps, v, [&](std::int64_t n, std::size_t) {
            if (exterior[std::size_t(n)])
                return;
            const float through = std::min(value, clearance[std::size_t(n)]);
            if (through > best[std::size_t(n)]) {
                best[std::size_t(n)] = through;
                heap.push({through, n});
            }
        });
    }
    return fail(ErrorCode::InvalidInput, "scope passage: no route from outside the external os to the fundus "
                                         "inside the organ; the landmarks may not belong to this mesh");
}

/// Of all the widest routes, the one that keeps to the middle of the free space: the path through voxels of
/// clearance >= bottleneck that minimises the integral of 1 / (clearance - bottleneck + one voxel) along its length
/// (Dijkstra). Centrelines are extracted the same way in VMTK, as paths minimising the integral of the inverse
/// inscribed-sphere radius (Antiga et al., "Robust and objective decomposition and mapping of bifurcating vessels",
/// IEEE TMI 27(6), 2008). A merely shortest route would hug the walls, and every point of it would look narrow.
Result<std::vector<std::int64_t>> centredWideRoute(const VoxelGrid<float>& clearance,
                                                   const std::vector<std::uint8_t>& exterior,
                                                   const std::vector<std::int64_t>& starts,
                                                   const std::vector<std::int64_t>& targets, float bottleneck,
                                                   Progress& progress) {
    const auto steps = neighbourSteps();
    const double h = clearance.spacing();
    std::vector<double> dist(clearance.size(), kInf);
    std::vector<std::uint8_t> parent(clearance.size(), kNoParent);
    using Entry = std::pair<double, std::int64_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
    for (std::int64_t s : starts)
        if (clearance[std::size_t(s)] >= bottleneck) {
            dist[std::size_t(s)] = 0.0;
            heap.push({0.0, s});
        }
    std::size_t pops = 0;
    while (!heap.empty()) {
        const double d = heap.top().first;
        const std::int64_t v = heap.top().second;
        heap.pop();
        if (d > dist[std::size_t(v)])
            continue;
        if (isIn(targets, v)) {
            std::vector<std::int64_t> route{v};
            for (std::int64_t at = v; parent[std::size_t(at)] != kNoParent;) {
                const Index3 ijk = clearance.unlinear(std::size_t(at));
                const Index3& o = steps[parent[std::size_t(at)]].offset;
                at = static_cast<std::int64_t>(clearance.linear({ijk[0] - o[0], ijk[1] - o[1], ijk[2] - o[2]}));
                route.push_back(at);
            }
            std::reverse(route.begin(), route.end());
            return route;
        }
        if ((++pops & 65535) == 0 && progress.cancelled())
            return fail(ErrorCode::Cancelled, "scope passage cancelled while tracing the route");
        forEachNeighbour(clearance, steps, v, [&](std::int64_t n, std::size_t k) {
            if (exterior[std::size_t(n)] || clearance[std::size_t(n)] < bottleneck)
                return;
            const double room = double(clearance[std::size_t(n)]) - double(bottleneck) + h;
            const double through = d + steps[k].lengthVoxels * h / room;
            if (through < dist[std::size_t(n)]) {
                dist[std::size_t(n)] = through;
                parent[std::size_t(n)] = static_cast<std::uint8_t>(k);
                heap.push({through, n});
            }
        });
    }
    return fail(ErrorCode::Internal, "scope passage: the widest route's bottleneck has no path");
}

/// Free, unblocked voxels reachable from the free ones of `seeds` (26 neighbours), as a mask.
std::vector<std::uint8_t> reachableFree(const ClearanceGrid& grid, const std::vector<std::uint8_t>& blocked,
                                        const std::vector<std::int64_t>& seeds) {
    const auto& g = grid.clearanceMm;
    std::vector<std::uint8_t> reached(g.size(), 0);
    const auto open = [&](std::size_t v) { return !reached[v] && !grid.tissue[v] && !blocked[v]; };
    std::vector<std::int64_t> queue;
    for (std::int64_t s : seeds)
        if (open(std::size_t(s))) {
            reached[std::size_t(s)] = 1;
            queue.push_back(s);
        }
    const auto steps = neighbourSteps();
    for (std::size_t head = 0; head < queue.size(); ++head)
        forEachNeighbour(g, steps, queue[head], [&](std::int64_t m, std::size_t) {
            if (open(std::size_t(m))) {
                reached[std::size_t(m)] = 1;
                queue.push_back(m);
            }
        });
    return reached;
}

/// Where a closed passage ends: the point of the free space reachable from the start that comes nearest to the free
/// space around the fundus (or to the fundus voxels, when they have none), and the gap between the two, mm: the
/// thinnest closure. Measuring the closure by its thickness rather than by how deep a route through it runs keeps
/// a thick closure (a myoma filling the cavity) from being found along a thin outer wall instead.
struct Closure {
    std::int64_t deadEnd = -1; ///< -1: no free voxel at the start
    double gapMm = 0.0;
};

Result<Closure> closureOf(const ClearanceGrid& grid, const std::vector<std::uint8_t>& blocked,
                          const std::vector<std::int64_t>& starts, const std::vector<std::int64_t>& targets,
                          Progress& progress) {
    const auto fromStart = reachableFree(grid, blocked, starts);
    auto nearFundus = reachableFree(grid, blocked, targets);
    if (std::none_of(nearFundus.begin(), nearFundus.end(), [](std::uint8_t r) { return r != 0; }))
        for (std::int64_t t : targets)
            nearFundus[std::size_t(t)] = 1;
    auto toFundus = detail::squaredVoxelDistance(grid.clearanceMm.dims(), nearFundus, 1, progress);
    if (!toFundus.ok())
        return toFundus.failure();
    Closure closure;
    double best = kInf;
    for (std::size_t v = 0; v < fromStart.size(); ++v)
        if (fromStart[v] && (*toFundus)[v] < best) {
            best = (*toFundus)[v];
            closure.deadEnd = std::int64_t(v);
        }
    // Centre to centre, less the voxel the two free points stand in: the tissue between them.
    const double h = grid.clearanceMm.spacing();
    closure.gapMm = closure.deadEnd < 0 ? 0.0 : std::max(0.0, (std::sqrt(best) - 1.0) * h);
    return closure;
}

/// The tissue boundary and its triangle index, for exact distances along the route.
struct BoundaryTriangles {
    SurfaceMesh surface;
    TriangleGrid index;
    explicit BoundaryTriangles(SurfaceMesh boundary) : surface(std::move(boundary)), index(surface, 0.0, false) {}
    BoundaryTriangles(const BoundaryTriangles&) = delete;
    BoundaryTriangles& operator=(const BoundaryTriangles&) = delete;
};

/// Exact distance from p to the tissue boundary, signed like the grid's (negative in tissue).
double exactClearance(const Vec3& p, bool inTissue, const BoundaryTriangles& b) {
    const double d = std::sqrt(b.index.closest(p).closest.distance2);
    return inTissue ? -d : d;
}

/// Moves a route point within a voxel across the route (pattern search in the plane normal to `along`, steps
/// halved from half a voxel) to where the exact clearance is largest: a voxel centre can lie half a voxel off the
/// middle of a channel, which would understate its width by up to a voxel. Returns the clearance at the new point.
double centreAcross(Vec3& p, const Vec3& along, bool inTissue, const BoundaryTriangles& b, double voxelMm) {
    Vec3 u = cross(along, std::fabs(along.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0));
    u = normalized(u);
    const Vec3 v = cross(along, u);
    double best = exactClearance(p, inTissue, b);
    if (norm2(u) == 0.0)
        return best;
    const Vec3 centre = p;
    for (double step = 0.5 * voxelMm; step > voxelMm / 40.0; step *= 0.5) {
        const Vec3 from = p;
        for (int du = -1; du <= 1; ++du)
            for (int dv = -1; dv <= 1; ++dv) {
                const Vec3 q = from + (u * double(du) + v * double(dv)) * step;
                if ((du || dv) && distance(q, centre) <= voxelMm) {
                    const double c = exactClearance(q, inTissue, b);
                    if (c > best) {
                        best = c;
                        p = q;
                    }
                }
            }
    }
    return best;
}

PassagePart partOf(const Vec3& p, const ScopeLandmarks& l) {
    const Vec3 axis = l.internalOsMm - l.externalOsMm;
    const double canalMm = norm(axis);
    const double s = dot(p - l.externalOsMm, axis / canalMm);
    if (s < -kOsBandMm)
        return PassagePart::Outside;
    if (s <= kOsBandMm)
        return PassagePart::ExternalOs;
    if (s < canalMm - kOsBandMm)
        return PassagePart::Canal;
    if (s <= canalMm + kOsBandMm)
        return PassagePart::InternalOs;
    return PassagePart::Cavity;
}

/// Route points with exact clearances, arc lengths and parts.
Result<std::vector<PassagePoint>> describeRoute(const std::vector<std::int64_t>& voxels, const ClearanceGrid& grid,
                                                const BoundaryTriangles& boundary, const ScopeLandmarks& landmarks,
                                                std::vector<double>& clearanceMm, Progress& progress) {
    std::vector<PassagePoint> route;
    route.reserve(voxels.size());
    clearanceMm.clear();
    const double h = grid.clearanceMm.spacing();
    for (std::size_t i = 0; i < voxels.size(); ++i) {
        if ((i & 63) == 0 && progress.cancelled())
            return fail(ErrorCode::Cancelled, "scope passage cancelled while measuring the route");
        const auto v = std::size_t(voxels[i]);
        const auto centreOf = [&](std::size_t k) {
            return grid.clearanceMm.center(grid.clearanceMm.unlinear(std::size_t(voxels[k])));
        };
        PassagePoint p;
        p.positionMm = centreOf(i);
        const Vec3 along = normalized(centreOf(std::min(i + 1, voxels.size() - 1)) - centreOf(i > 0 ? i - 1 : 0));
        // Points in tissue stay at their centre: the route crosses the closure, it does not need room there.
        const bool inTissue = grid.tissue[v] != 0;
        const double c = boundary.surface.triangles.empty() ? double(grid.clearanceMm[v])
                         : inTissue                         ? exactClearance(p.positionMm, true, boundary)
                                                            : centreAcross(p.positionMm, along, false, boundary, h);
        p.freeWidthMm = 2.0 * std::max(0.0, c);
        p.arcLengthMm =
            route.empty() ? 0.0 : route.back().arcLengthMm + distance(route.back().positionMm, p.positionMm);
        p.part = partOf(p.positionMm, landmarks);
        route.push_back(p);
        clearanceMm.push_back(c);
    }
    return route;
}

/// The least exact clearance of the straight stretch from route point i to the route point `lengthMm` further on
/// (interpolated; the route's end when it is nearer), sampled every half voxel: a rigid scope cannot follow a bend
/// of the route. A sample whose voxel centre is tissue counts as in tissue.
double straightClearance(const std::vector<PassagePoint>& route, const std::vector<double>& clearanceMm, std::size_t i,
                         double lengthMm, const ClearanceGrid& grid, const BoundaryTriangles& boundary) {
    const Vec3 tip = route[i].positionMm;
    const double endArc = route[i].arcLengthMm + lengthMm;
    std::size_t j = i;
    while (j + 1 < route.size() && route[j + 1].arcLengthMm <= endArc)
        ++j;
    Vec3 end = route[j].positionMm;
    if (j + 1 < route.size() && route[j + 1].arcLengthMm > route[j].arcLengthMm) {
        const double t = (endArc - route[j].arcLengthMm) / (route[j + 1].arcLengthMm - route[j].arcLengthMm);
        end = route[j].positionMm + (route[j + 1].positionMm - route[j].positionMm) * t;
    }
    const double h = grid.clearanceMm.spacing();
    const auto samples = static_cast<int>(std::ceil(distance(tip, end) / (0.5 * h)));
    if (samples == 0)
        return clearanceMm[i];
    double least = clearanceMm[i];
    if (boundary.surface.triangles.empty())
        return least;
    for (int s = 1; s <= samples; ++s) {
        const Vec3 q = tip + (end - tip) * (double(s) / double(samples));
        const Index3 v = grid.tissue.voxelOf(q);
        const bool inTissue = grid.tissue.contains(v) && grid.tissue.at(v) != 0;
        least = std::min(least, exactClearance(q, inTissue, boundary));
    }
    return least;
}

/// Narrowest points and verdicts. `closure`: the passage is closed at the route's last point (its dead end).
void summarise(ScopePassage& out, std::vector<double> clearanceMm, const ScopePassageParams& params,
               const ClearanceGrid& grid, const BoundaryTriangles& boundary, const std::optional<Closure>& closure) {
    if (closure) {
        clearanceMm.back() = 0.0;
        out.route.back().freeWidthMm = 0.0;
    }
    std::size_t narrowest = 0;
    for (std::size_t i = 1; i < clearanceMm.size(); ++i)
        if (clearanceMm[i] < clearanceMm[narrowest])
            narrowest = i;
    if (closure)
        narrowest = clearanceMm.size() - 1;
    out.narrowest = out.route[narrowest];
    out.open = !closure;
    out.closedGapMm = closure ? closure->gapMm : 0.0;
    out.ballPasses = out.open && out.narrowest.freeWidthMm >= params.scopeDiameterMm;
    std::size_t canal = 0;
    for (std::size_t i = 1; i < clearanceMm.size() && out.route[i].part != PassagePart::Cavity; ++i)
        if (clearanceMm[i] < clearanceMm[canal])
            canal = i;
    const bool closedInCanal = closure && out.route.back().part != PassagePart::Cavity;
    if (closedInCanal)
        canal = clearanceMm.size() - 1;
    out.narrowestCanal = out.route[canal];
    out.canalOpen = !closedInCanal;
    out.canalClosedGapMm = closedInCanal ? closure->gapMm : 0.0;
    out.canalPasses = out.canalOpen && out.narrowestCanal.freeWidthMm >= params.scopeDiameterMm;

    std::size_t tightest = 0;
    double tightestClearance = kInf;
    for (std::size_t i = 0; i < out.route.size(); ++i) {
        const double c = straightClearance(out.route, clearanceMm, i, params.straightLengthMm, grid, boundary);
        if (c < tightestClearance) {
            tightestClearance = c;
            tightest = i;
        }
    }
    out.narrowestStraight = out.route[tightest];
    out.straightWidthMm = 2.0 * std::max(0.0, tightestClearance);
    out.straightPasses = out.ballPasses && out.straightWidthMm >= params.scopeDiameterMm;
}

} // namespace

std::string_view toString(PassagePart part) {
    switch (part) {
    case PassagePart::Outside:
        return "outside";
    case PassagePart::ExternalOs:
        return "external-os";
    case PassagePart::Canal:
        return "canal";
    case PassagePart::InternalOs:
        return "internal-os";
    case PassagePart::Cavity:
        return "cavity";
    }
    return "outside";
}

Result<ScopePassage> checkScopePassage(const TetMesh& tets, const ScopeLandmarks& landmarks,
                                       const ScopePassageParams& params, Progress& progress) {
    HS_TRY(checkParams(params));
    if (auto valid = validate(tets); !valid.ok())
        return fail(ErrorCode::InvalidInput, "scope passage: invalid tet mesh: " + valid.error().detail);
    if (tets.tetCount() == 0)
        return fail(ErrorCode::InvalidInput, "scope passage: the tet mesh has no tetrahedra");
    const double h = params.voxelFraction * params.scopeDiameterMm;
    const Bounds meshBox = bounds(tets);
    HS_TRY(checkLandmarks(landmarks, meshBox, h));

    // The grid holds the mesh and the start ball outside the external os, with two voxels of free border.
    const Vec3 axis = normalized(landmarks.internalOsMm - landmarks.externalOsMm);
    const Vec3 start = landmarks.externalOsMm - axis * params.startOffsetMm;
    const double startRadiusMm = std::max(params.scopeDiameterMm, 2.0 * h);
    Bounds box = meshBox;
    const Vec3 pad(startRadiusMm, startRadiusMm, startRadiusMm);
    box.add(start - pad);
    box.add(start + pad);
    box.min -= Vec3(2 * h, 2 * h, 2 * h);
    box.max += Vec3(2 * h, 2 * h, 2 * h);

    Progress::Sub gridProgress = progress.sub(0.0, 0.6);
    auto grid = detail::buildClearanceGrid(tets, box, h, params.maxVoxels, gridProgress);
    if (!grid.ok())
        return grid.failure();
    const VoxelGrid<float>& clearance = grid->clearanceMm;

    ScopePassage out;
    out.scopeDiameterMm = params.scopeDiameterMm;
    out.landmarks = landmarks;
    out.voxelSizeMm = h;
    out.gridDims = clearance.dims();
    const auto starts = voxelsNear(clearance, start, startRadiusMm);
    auto blocked = blockedVoxels(*grid, landmarks.externalOsMm, params.startOffsetMm + startRadiusMm + h, progress);
    if (!blocked.ok())
        return blocked.failure();
    const std::vector<std::uint8_t>& exterior = *blocked;
    // The route ends in the cavity: fundus voxels beyond the internal os, not the top of the canal.
    auto targets = voxelsNear(clearance, landmarks.fundusMm, std::max(params.fundusReachMm, h));
    targets.erase(std::remove_if(targets.begin(), targets.end(),
                                 [&](std::int64_t v) {
                                     return exterior[std::size_t(v)] ||
                                            partOf(clearance.center(clearance.unlinear(std::size_t(v))), landmarks) !=
                                                PassagePart::Cavity;
                                 }),
                  targets.end());
    if (targets.empty())
        return fail(ErrorCode::InvalidInput,
                    "scope passage: no point within " + formatNumber(params.fundusReachMm) +
                        " mm of the fundus landmark lies beyond the internal os and inside the organ");
    if (std::all_of(starts.begin(), starts.end(), [&](std::int64_t v) { return grid->tissue[std::size_t(v)]; }))
        out.warnings.push_back("the start outside the external os lies in tissue; check the landmarks");
    if (std::all_of(targets.begin(), targets.end(), [&](std::int64_t v) { return grid->tissue[std::size_t(v)]; }))
        out.warnings.push_back("no free space within " + formatNumber(params.fundusReachMm) +
                               " mm of the fundus point; a pathology may fill the fundus");

    progress.report("scope.route", 0.6);
    auto bottleneck = widestBottleneck(clearance, exterior, starts, targets, progress);
    if (!bottleneck.ok())
        return bottleneck.failure();
    // No free route: the route goes as far as the free space from the start allows, to where it ends.
    std::optional<Closure> closure;
    std::vector<std::int64_t> routeEnds = targets;
    if (!(*bottleneck > 0.0f)) {
        auto c = closureOf(*grid, exterior, starts, targets, progress);
        if (!c.ok())
            return c.failure();
        closure = *c;
        routeEnds = {closure->deadEnd >= 0 ? closure->deadEnd : starts.front()};
        bottleneck = widestBottleneck(clearance, exterior, starts, routeEnds, progress);
        if (!bottleneck.ok())
            return bottleneck.failure();
    }
    progress.report("scope.route", 0.75);
    auto voxels = centredWideRoute(clearance, exterior, starts, routeEnds, *bottleneck, progress);
    if (!voxels.ok())
        return voxels.failure();
    progress.report("scope.route", 0.9);

    std::vector<double> clearanceMm;
    const BoundaryTriangles boundary(extractBoundary(tets));
    auto route = describeRoute(*voxels, *grid, boundary, landmarks, clearanceMm, progress);
    if (!route.ok())
        return route.failure();
    out.route = std::move(route).value();
    summarise(out, std::move(clearanceMm), params, *grid, boundary, closure);
    progress.report("scope.route", 1.0);
    return out;
}

} // namespace hs::scene
