// Clinical descriptors measured from the geometry: FIGO type, size, base, topography, Lasmar score.
#include "Measure.h"
#include "Shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>

namespace hs::pathology {

clinical::FigoType classifyFigo(const WallFractions& f, double tol) {
    const bool cavity = f.cavity > 0.01;
    const bool serosal = f.outside > 0.02;
    const bool touchesEndometrium = cavity || f.bordersEndometrium.value_or(f.endometriumDistanceMm <= tol);
    if (cavity && serosal)
        return clinical::FigoType{f.cavity >= 0.5 ? 1 : 2, f.outside >= 0.5 ? 6 : 5};
    if (cavity)
        return clinical::FigoType{f.pedunculated ? 0 : (f.tissue < 0.5 ? 1 : 2), -1};
    if (serosal) {
        const int y = f.pedunculated ? 7 : (f.tissue < 0.5 ? 6 : 5);
        if (touchesEndometrium && y != 7)
            return clinical::FigoType{3, y};
        return clinical::FigoType{y, -1};
    }
    return clinical::FigoType{touchesEndometrium ? 3 : 4, -1};
}

namespace detail {

double tissueFraction(const SurfaceMesh& organ, const SurfaceMesh& pathology, double h) {
    const Grid g = Grid::covering(bounds(pathology), h, 1);
    const auto pm = insideMask(pathology, g);
    const auto om = insideMask(organ, g);
    std::size_t in = 0, total = 0;
    for (std::size_t i = 0; i < pm.size(); ++i)
        if (pm[i]) {
            ++total;
            in += om[i];
        }
    return total > 0 ? static_cast<double>(in) / static_cast<double>(total) : 0.0;
}

SurfaceMesh organPart(const OrganInfo& info, Side side) {
    SurfaceMesh part;
    part.points = info.mesh->points;
    for (std::size_t f = 0; f < info.mesh->triangles.size(); ++f)
        if (info.faceSide[f] == side)
            part.triangles.push_back(info.mesh->triangles[f]);
    return part;
}

namespace {

/// Splits the pathology's voxels outside the wall into connected pieces and labels each as cavity or outside by the
/// side of the organ vertex nearest to it.
void classifyFree(const OrganInfo& info, const Grid& g, const std::vector<std::uint8_t>& pm,
                  const std::vector<std::uint8_t>& om, std::size_t& cavity, std::size_t& outside) {
    std::vector<std::uint8_t> seen(pm.size(), 0);
    std::deque<std::array<int, 3>> queue;
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                const std::size_t id = g.index(i, j, k);
                if (!pm[id] || om[id] || seen[id])
                    continue;
                // Nearest organ vertex to the first voxel of the piece decides its side.
                const Vec3 p = g.center(i, j, k);
                double best = 1e300;
                Side side = Side::Serosa;
                for (std::size_t v = 0; v < info.mesh->points.size(); ++v) {
                    const double d2 = norm2(info.mesh->points[v] - p);
                    if (d2 < best) {
                        best = d2;
                        side = info.vertexSide[v];
                    }
                }
                std::size_t count = 0;
                seen[id] = 1;
                queue.push_back({i, j, k});
                while (!queue.empty()) {
                    const auto c = queue.front();
                    queue.pop_front();
                    ++count;
                    const int nb[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
                    for (const auto& d : nb) {
                        const int a = c[0] + d[0], b = c[1] + d[1], e = c[2] + d[2];
                        if (a < 0 || b < 0 || e < 0 || a >= g.nx || b >= g.ny || e >= g.nz)
                            continue;
                        const std::size_t nid = g.index(a, b, e);
                        if (pm[nid] && !om[nid] && !seen[nid]) {
                            seen[nid] = 1;
                            queue.push_back({a, b, e});
                        }
                    }
                }
                (side == Side::Cavity ? cavity : outside) += count;
            }
}

/// The base: organ vertices of `side` inside the pathology or within 1 mm of it, restricted to the pieces of that
/// surface (connected through near vertices) where the pathology passes through the wall. A head that merely comes
/// close to another part of the wall does not widen the base.
std::vector<Vec3> basePoints(const SurfaceMesh& organ, const OrganInfo& info, Side side, const Grid& g,
                             const std::vector<std::uint8_t>& pm) {
    const double h = g.h;
    const int reach = static_cast<int>(std::ceil(1.0 / h));
    const std::size_t nv = organ.points.size();
    std::vector<std::uint8_t> near(nv, 0), inside(nv, 0);
    for (std::size_t v = 0; v < nv; ++v) {
        if (info.vertexSide[v] != side)
            continue;
        const Vec3& p = organ.points[v];
        const int i = static_cast<int>(std::lround((p.x - g.origin.x) / h));
        const int j = static_cast<int>(std::lround((p.y - g.origin.y) / h));
        const int k = static_cast<int>(std::lround((p.z - g.origin.z) / h));
        for (int dk = -reach; dk <= reach && !near[v]; ++dk)
            for (int dj = -reach; dj <= reach && !near[v]; ++dj)
                for (int di = -reach; di <= reach && !near[v]; ++di) {
                    const int a = i + di, b = j + dj, c = k + dk;
                    near[v] = a >= 0 && b >= 0 && c >= 0 && a < g.nx && b < g.ny && c < g.nz && pm[g.index(a, b, c)];
                }
        inside[v] = near[v] && i >= 0 && j >= 0 && k >= 0 && i < g.nx && j < g.ny && k < g.nz && pm[g.index(i, j, k)];
    }
    // Flood the near vertices from those inside the pathology along the organ's edges.
    std::vector<std::vector<std::size_t>> nbr(nv);
    for (const Triangle& t : organ.triangles)
        for (std::size_t a = 0; a < 3; ++a) {
            const auto va = static_cast<std::size_t>(t[a]), vb = static_cast<std::size_t>(t[(a + 1) % 3]);
            if (near[va] && near[vb]) {
                nbr[va].push_back(vb);
                nbr[vb].push_back(va);
            }
        }
    std::vector<std::uint8_t> keep(nv, 0);
    std::deque<std::size_t> queue;
    for (std::size_t v = 0; v < nv; ++v)
        if (inside[v]) {
            keep[v] = 1;
            queue.push_back(v);
        }
    const bool anyInside = !queue.empty();
    while (!queue.empty()) {
        const std::size_t v = queue.front();
        queue.pop_front();
        for (std::size_t w : nbr[v])
            if (!keep[w]) {
                keep[w] = 1;
                queue.push_back(w);
            }
    }
    std::vector<Vec3> base;
    for (std::size_t v = 0; v < nv; ++v)
        if (anyInside ? keep[v] : near[v])
            base.push_back(organ.points[v]);
    return base;
}

} // namespace

/// The descriptors of a contact in `info`'s cavity frame: one home for the rules `measure` and `describeContact`
/// share.
Descriptors describe(const OrganInfo& info, const WallContact& c, clinical::PathologyKind kind, double tol) {
    WallFractions f = c.fractions;
    double sizeMm = c.sizeMm, stalkMm = c.stalkLengthMm;
    std::vector<Vec3> base = c.base;
    // Size: largest diameter; for a body that lies mostly outside the wall, of the head beyond a stalk, looked for
    // from where it grows (WallContact::root) or else from the base's centre. From its root, the base is then where
    // the stalk meets the wall: a head that rests on a wall beside it, or whose pocket's walls hug it, touches the
    // wall there too, and the centre of all those contacts lies nowhere near the stalk.
    if (f.tissue < 0.5 && !c.points.empty() && (c.root || !base.empty())) {
        double stalk = 0.0;
        const Vec3 origin = c.root ? *c.root : centroid(base);
        const Vec3 axis = normalized(c.centre - origin);
        const double head = headDiameter(c.points, origin, axis, &stalk);
        if (stalk > 0.0) {
            f.pedunculated = true;
            stalkMm = stalk;
            sizeMm = head;
            if (c.root) {
                std::vector<Vec3> foot;
                for (const Vec3& q : base)
                    if (dot(q - origin, axis) < 0.5 * stalk)
                        foot.push_back(q);
                base = foot.empty() ? std::vector<Vec3>{origin} : foot;
            }
        }
    }
    Descriptors d;
    d.kind = kind;
    d.volumeMm3 = c.volumeMm3;
    d.sizeMm = sizeMm;
    d.intramuralFraction = f.tissue;
    d.cavityFraction = f.cavity;
    d.outsideFraction = f.outside;
    d.endometriumDistanceMm = f.endometriumDistanceMm;
    d.serosaDistanceMm = f.serosaDistanceMm;
    d.pedunculated = f.pedunculated;
    d.stalkLengthMm = stalkMm;
    const Side baseSide = c.serosalBase ? Side::Serosa : Side::Cavity;
    Vec3 baseCentre;
    if (!base.empty()) {
        baseCentre = centroid(base);
        d.baseWidthMm = diameter(base);
    } else {
        const SurfaceMesh& organ = *info.mesh;
        const auto [face, dist] = info.nearestFace(c.centre, baseSide);
        (void)dist;
        const Triangle& t = organ.triangles[face];
        baseCentre = (organ.points[static_cast<std::size_t>(t[0])] + organ.points[static_cast<std::size_t>(t[1])] +
                      organ.points[static_cast<std::size_t>(t[2])]) /
                     3.0;
    }
    const Vec3 fromCentre = normalized(baseCentre - info.cavityCenter);
    const double wallLength = baseSide == Side::Serosa           ? info.corpusLengthMm
                              : dot(fromCentre, info.axis) > 0.8 ? info.cavityWidthMm
                                                                 : info.cavityLengthMm;
    d.baseExtension = wallLength > 0.0 ? d.baseWidthMm / wallLength : 0.0;
    const double along = dot(baseCentre - info.internalOs, info.axis) / std::max(info.cavityLengthMm, 1e-9);
    d.topography = along < 1.0 / 3.0 ? 0 : (along < 2.0 / 3.0 ? 1 : 2);
    const Vec3 radial = (baseCentre - info.internalOs) - info.axis * dot(baseCentre - info.internalOs, info.axis);
    d.lateralWall = norm(radial) > 0.25 * info.cavityWidthMm && std::fabs(dot(normalized(radial), info.lateral)) > 0.8;
    if (kind == clinical::PathologyKind::Myoma) {
        d.figo = classifyFigo(f, tol);
        d.lasmar = lasmarScore(d);
    } else {
        d.figo = clinical::FigoType{-1, -1};
    }
    return d;
}

} // namespace detail

clinical::LasmarScore lasmarScore(const Descriptors& d) {
    clinical::LasmarScore s;
    s.size = d.sizeMm <= 20.0 ? 0 : (d.sizeMm <= 50.0 ? 1 : 2);
    s.topography = d.topography;
    s.extension = d.baseExtension <= 1.0 / 3.0 ? 0 : (d.baseExtension <= 2.0 / 3.0 ? 1 : 2);
    s.penetration = (d.pedunculated || d.intramuralFraction < 0.05) ? 0 : (d.intramuralFraction < 0.5 ? 1 : 2);
    s.wall = d.lateralWall ? 1 : 0;
    return s;
}

Result<Descriptors> measure(const SurfaceMesh& organ, const SurfaceMesh& pathology, clinical::PathologyKind kind,
                            const PathologyParams& params, std::optional<Vec3> root) {
    using namespace detail;
    if (!analyzeTopology(pathology).isWatertight())
        return fail(ErrorCode::InvalidInput, "the pathology surface is not closed and manifold");
    auto infoResult = analyzeOrgan(organ);
    if (!infoResult.ok())
        return infoResult.failure();
    const OrganInfo& info = *infoResult;

    Descriptors d;
    d.kind = kind;
    d.volumeMm3 = std::fabs(enclosedVolume(pathology));
    const double extent = diameter(pathology.points);
    const double h = std::max(extent * params.measureVoxelFraction, 0.05);
    const Grid g = Grid::covering(bounds(pathology), h, 2);
    const auto pm = insideMask(pathology, g);
    const auto om = insideMask(organ, g);
    std::size_t total = 0, tissue = 0, cavity = 0, outside = 0;
    for (std::size_t i = 0; i < pm.size(); ++i)
        if (pm[i]) {
            ++total;
            tissue += om[i];
        }
    classifyFree(info, g, pm, om, cavity, outside);
    const double n = std::max<double>(1.0, static_cast<double>(total));
    Fractions f;
    f.tissue = static_cast<double>(tissue) / n;
    f.cavity = static_cast<double>(cavity) / n;
    f.outside = static_cast<double>(outside) / n;
    f.endometriumDistanceMm = f.cavity > 0.0 ? 0.0 : surfaceDistance(pathology, organPart(info, Side::Cavity), 30.0);
    f.serosaDistanceMm = f.outside > 0.0 ? 0.0 : surfaceDistance(pathology, organPart(info, Side::Serosa), 30.0);
    d.intramuralFraction = f.tissue;
    d.cavityFraction = f.cavity;
    d.outsideFraction = f.outside;
    d.endometriumDistanceMm = f.endometriumDistanceMm;
    d.serosaDistanceMm = f.serosaDistanceMm;

    // The base: organ vertices of the side it grows from that lie inside it or within 1 mm of it.
    WallContact c;
    c.serosalBase = !(f.cavity > 0.0 || (f.outside == 0.0 && f.endometriumDistanceMm <= f.serosaDistanceMm));
    c.base = basePoints(organ, info, c.serosalBase ? Side::Serosa : Side::Cavity, g, pm);
    c.centre = volumeCentroid(pathology);
    c.volumeMm3 = d.volumeMm3;
    c.points = pathology.points;
    c.sizeMm = extent;
    c.fractions = f;
    c.root = root;
    return detail::describe(info, c, kind, params.contactToleranceMm);
}

Result<Descriptors> describeContact(const SurfaceMesh& organ, const WallContact& contact, clinical::PathologyKind kind,
                                    double contactToleranceMm) {
    auto info = detail::analyzeOrgan(organ);
    if (!info.ok())
        return info.failure();
    return detail::describe(*info, contact, kind, contactToleranceMm);
}

} // namespace hs::pathology
