// The mass effect: the organ makes room for its pathologies, and its walls collapse onto them.
#include "PathologySteps.h"

#include "Geometry.h"

#include "hs/anatomy/OrganChecks.h"
#include "hs/clinical/Tissue.h"
#include "hs/core/TriangleGrid.h"

#include <algorithm>
#include <cmath>

namespace hs::pathology::detail {

namespace {

constexpr double kOpenKeep = 0.5;           ///< the far wall's serosa moves by this fraction less than its endometrium
constexpr double kOpenStretch = 1.0;        ///< the far wall's window ramp widens by this fraction of its push
constexpr double kOpenWiden = 1.0;          ///< the far wall's outside moves over a profile this much wider
constexpr double kPartRampPerAmount = 0.25; ///< the parting's ramp across the midplane widens with its amount
constexpr double kPartKeep = 0.5;           ///< the serosa across a dome moves by this fraction less than its lining
constexpr int kPocketRounds = 30;           ///< rounds of averaging that round the pockets the pushes open
constexpr double kPocketSlackMm = 1.0;      ///< a rounded pocket keeps this much more than the clearance

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
    double clearance = 0.0; ///< mm the points it moves keep from the pathology (0: the stage's clearanceMm)
    /// Axial, parting: points move along n by amount * a(tau) * (1 - s(rho)), a(tau) rising from -1 to 1 over
    /// |tau| < partRamp (odd, monotone), tau the signed distance from the plane through origin across n: the two
    /// sides of that plane move apart. Each line along n maps onto itself monotonically, so it is injective too.
    bool parting = false;
    double partRamp = 1.5;
    /// Parting solve: only points at least this far along `solveAlong` from `solveFrom` drive the amount (the walls
    /// across the pathology, not the wall it stands in).
    Vec3 solveFrom{}, solveAlong{};
    double solveAbove = 0.0;
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
        if (parting) // beyond the cavity's lining (keepFrom) the motion falls back to 1 - keep: the serosa moves less
        {
            const double ramp = std::max(partRamp, kPartRampPerAmount * amount);
            return (2.0 * smoothstep(-ramp, ramp, tau) - 1.0) * beyond(std::fabs(tau)) * across;
        }
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

/// Increases the push until the organ points it moves keep its clearance (`clearance` unless the push sets its own)
/// from the pathology (at most `cap`).
void solvePush(Push& push, const SurfaceMesh& organ, const SurfaceMesh& pathology, double clearance, double cap) {
    if (push.clearance > 0.0)
        clearance = push.clearance;
    const Bounds box = bounds(pathology);
    for (int it = 0; it < 12 && push.amount < cap; ++it) {
        double deficit = 0.0;
        for (const Vec3& x0 : organ.points) {
            const double w = std::fabs(push.weight(x0)); // a parting push moves either side away from the pathology
            if (w < 0.3)
                continue;
            if (push.parting && (w < 0.9 || dot(x0 - push.solveFrom, push.solveAlong) < push.solveAbove))
                continue; // on the midplane (the cavity's rim) or the wall it stands in: parting cannot clear them
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

/// A submucosal myoma (types 1, 2) on a wall beside the cavity's flat plane (lateral, fundal, cornual) stands across
/// the cavity's depth: a lateral myoma wider than the 5 mm of an atrophic cavity lies in its anterior and posterior
/// walls, which then close the cavity to a scope and count it as intramural. Those walls part as the distension medium
/// holds them off it (45-75 mmHg, docs/references.md [Vulgaropulos1992]): everything on either side of the cavity's
/// midplane through the myoma's centre moves away from that plane over its footprint until the walls keep the distended
/// gap, and the uterus thickens there. The sides do not fold: each line across the plane maps onto itself
/// monotonically. Nothing when the myoma stands out of the anterior or posterior wall (its far wall moves instead).
/// Polyps and hybrids do not part the walls: with them too the default organ intersected itself and two sweep myomas
/// nearby changed type.
std::optional<Push> partingPush(const Planned& p, const Vec3& d, const OrganInfo& info, const PathologyParams& params,
                                double windowRamp) {
    Vec3 m = info.anterior - d * dot(info.anterior, d);
    if (norm(m) < 0.5)
        return std::nullopt;
    m = normalized(m);
    const Vec3 c = volumeCentroid(p.surface);
    double footprint = 0.0;
    for (const Vec3& q : p.surface.points) {
        const Vec3 r = q - c;
        footprint = std::max(footprint, norm(r - m * dot(r, m)));
    }
    Push part{c, m, 0.0, 1.0, footprint + params.clearanceMm, windowRamp, 0.0, kOpenStretch};
    part.parting = true;
    // The lining across the dome: the farthest cavity-side hit from the midplane, on rays across it from the dome's
    // axis into the cavity. Beyond it the wall moves less, so it thins rather than the whole uterus growing.
    double lining = part.partRamp;
    for (double t : {1.0, 3.0, 6.0})
        for (double sign : {-1.0, 1.0})
            if (auto hit = info.ray(p.seat.endometrium + d * t, m * sign, Side::Cavity))
                lining = std::max(lining, std::fabs(dot(hit->point - c, m)));
    part.keepFrom = std::min(lining, 0.25 * info.corpusDepthMm) + 1.0;
    part.keep = kPartKeep;
    part.solveFrom = p.seat.endometrium;
    part.solveAlong = d;
    part.solveAbove = 1.5;
    part.clearance = std::max(params.clearanceMm, params.distendedGapMm);
    return part;
}

/// The pushes a pathology needs, by where it must and must not reach (FIGO, docs/references.md [Munro2011]: types
/// 0-2 bulge into the cavity, 3 touches the endometrium, 4 stays in the wall, 5-7 bulge outwards).
std::vector<Push> planPushes(const Planned& p, const OrganInfo& info, const PathologyParams& params, AdaptRound round) {
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
    // Once all are placed, only the walls a myoma must keep clear of are looked at again: opening the cavity anew
    // around a head, on walls the later pushes moved, made the organ intersect itself in 3 more of the 36 crowded
    // cases.
    if (intoCavity && round == AdaptRound::First) {
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
        // The far wall stands off as the distension medium holds it: a scope passes in front of the mass.
        open.clearance = std::max(c, params.distendedGapMm);
        const bool dome = !polyp && !f.isHybrid() && f.type <= 1;
        if (dome) // first the walls across the dome part, so the far wall's push is solved on the far wall alone
            if (auto part = partingPush(p, d, info, params, windowRamp))
                pushes.push_back(*part);
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
        // The lining the scene lays over the cavity after placement belongs to the cavity's side: the myoma keeps
        // the clearance from its inner face, so the layer ends in myometrium before it (FIGO 4, not 3).
        const double keep = c + params.endometriumThicknessMm;
        // A later pathology's push can bend the endometrium over the myoma out into the wall, past the seat's plane
        // (AdaptRound::Again). Then the push is aimed at the cavity-side points that miss their clearance: its axis
        // through their centroid (projected onto the seat's plane, so heights stay the seat's), its window as wide as
        // they lie from it, its ramp below the deepest of them, so all of them move fully. Aimed through the seat
        // with the myoma's whole width, a seat low on the wall took the cervical canal into the push and sheared it.
        double sunk = 0.0, reach = lateral;
        Vec3 origin = e;
        if (round == AdaptRound::Again) {
            const Bounds box = bounds(mesh);
            std::vector<Vec3> missing;
            for (std::size_t v = 0; v < info.mesh->points.size(); ++v) {
                const Vec3 r = info.mesh->points[v] - e;
                const double t = dot(r, u), rho = norm(r - u * t);
                if (info.vertexSide[v] == Side::Cavity && rho < lateral + keep &&
                    signedDistance(mesh, box, info.mesh->points[v], keep + 1.0) < keep) {
                    sunk = std::max(sunk, t);
                    missing.push_back(info.mesh->points[v]);
                }
            }
            reach = 0.0;
            if (!missing.empty()) {
                Vec3 mean;
                for (const Vec3& q : missing)
                    mean += q;
                mean = mean / static_cast<double>(missing.size());
                origin = e + (mean - e) - u * dot(mean - e, u);
                for (const Vec3& q : missing) {
                    const Vec3 r = q - origin;
                    reach = std::max(reach, norm(r - u * dot(r, u)));
                }
            }
        }
        double hi = std::min(-0.3, -shallowest + 0.2 + std::clamp(0.5 * std::max(shallowest, 0.0), 0.3, 3.0));
        if (sunk > 0.0)
            hi = std::min(hi, -sunk - 0.2);
        const double lo = std::max(-0.6 * w, std::min(-shallowest + 0.2, hi - 0.3));
        Push clear{origin, -u, lo, std::max(hi, lo + 0.3), reach + keep, windowRamp, 0.0};
        clear.clearance = keep;
        clear.stretch = kOpenStretch; // a larger push over a wider ramp: the mesh follows a smooth map
        pushes.push_back(clear);
    }
    if (clearOfSerosa) { // the serosa bulges over the myoma; the ramp lies in the wall below the serosa
        const double lo = std::max(1.0, std::min(deepest + 0.2, 0.5 * w));
        const double hi = std::max(
            lo + 0.3, std::min(deepest + 0.2 + std::clamp(0.5 * std::max(w - deepest, 0.0), 0.3, 3.0), 0.85 * w));
        pushes.push_back(Push{e, u, lo, hi, lateral + c, windowRamp, 0.0});
    }
    return pushes;
}

/// A head on a stalk hangs in the free cavity, wherever there is room: the pushes of the pathologies before it move
/// its root with the wall, and the head with it, rigidly, which can leave it in a wall that moved less (a cornual
/// polyp beside the far wall of a posterior myoma: 56 % in tissue). When the head's centre lies closer to the organ's
/// wall than its radius, the pathology turns about its root to the direction the stalk would take on the organ as it
/// now is (freeStalkDirection), if the head keeps more room from the wall there.
void reaimStalk(std::vector<Planned>& all, std::size_t which, const OrganInfo& info, const PathologyParams& params) {
    Planned& p = all[which];
    if (!p.spec.pedunculated || p.fromSerosa)
        return;
    const Vec3 root = p.seat.endometrium;
    const double reach = distance(p.spec.center, root);
    if (reach < 1e-6)
        return;
    const Bounds box = bounds(*info.mesh);
    const double cutoff = 2.0 * p.spec.radius + 10.0;
    const double room = signedDistance(*info.mesh, box, p.spec.center, cutoff);
    if (room >= p.spec.radius)
        return;
    std::vector<const SurfaceMesh*> others;
    for (std::size_t j = 0; j < all.size(); ++j)
        if (j != which)
            others.push_back(&all[j].surface);
    const Vec3 from = (p.spec.center - root) / reach;
    const Vec3 to = freeStalkDirection(info, p.seat, reach, p.spec.radius, p.spec.stalkRadius,
                                       params.minimumGapMm + params.clearanceMm, others);
    if (signedDistance(*info.mesh, box, root + to * reach, cutoff) <= room)
        return;
    // The rotation about the root that takes `from` to `to` (Rodrigues).
    const Vec3 k = cross(from, to);
    const double sinA = norm(k), cosA = dot(from, to);
    if (sinA < 1e-9)
        return;
    const Vec3 axis = k / sinA;
    auto turn = [&](const Vec3& x) {
        const Vec3 v = x - root;
        return root + v * cosA + cross(axis, v) * sinA + axis * (dot(axis, v) * (1.0 - cosA));
    };
    Planned turned = p;
    for (Vec3& x : turned.surface.points)
        x = turn(x);
    turned.spec.center = turn(p.spec.center);
    turned.spec.base = turn(p.spec.base);
    for (std::size_t j = 0; j < all.size(); ++j) // it stays clear of the others, or it stays where it is
        if (j != which &&
            !checkOverlap(j < which ? all[j] : turned, j < which ? turned : all[j], params.minimumGapMm).ok())
            return;
    p = std::move(turned);
}

} // namespace

/// Applies pathology `which`'s pushes to the organ and to every other pathology (they sit in the moving tissue).
Status adaptOrgan(SurfaceMesh& organ, std::vector<Planned>& all, std::size_t which, const PathologyParams& params,
                  AdaptRound round) {
    const SurfaceMesh& mesh = all[which].surface;
    const double cap = 2.0 * all[which].spec.radius + 2.0 * params.clearanceMm;
    auto info = analyzeOrgan(organ); // the organ as earlier pathologies left it
    if (!info.ok())
        return info.failure();
    if (which > 0 && round == AdaptRound::First)
        reaimStalk(all, which, *info, params);
    for (Push& push : planPushes(all[which], *info, params, round)) {
        solvePush(push, organ, mesh, params.clearanceMm, cap);
        if (push.amount <= 0.0)
            continue;
        for (Vec3& x : organ.points)
            x = push.apply(x);
        // Other pathologies move with the tissue, rigidly: a myoma in the wall by its mean motion (it is stiffer than
        // the myometrium, docs/references.md [Omari2015]), a polyp or a stalked myoma with the root of its stalk, which
        // the wall carries (the head hangs in the free cavity). A push's ramps would stretch whatever stands in them: a
        // far-wall push once stretched a 25 mm myoma to 31 mm and a 10 mm polyp to 20 mm.
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
        grids.emplace_back(p.surface, 2.0, /*insideTests=*/false);
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

} // namespace hs::pathology::detail
