#include "Shapes.h"

#include "Geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace hs::pathology::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kAround = 48; ///< vertices per ring of a revolved contour

double smin(double a, double b, double k) {
    const double h = std::max(k - std::fabs(a - b), 0.0) / k;
    return std::min(a, b) - h * h * k * 0.25;
}

Vec3 randomUnit(Rng& rng) {
    for (;;) {
        const Vec3 v{rng.normal(), rng.normal(), rng.normal()};
        if (norm(v) > 1e-6)
            return normalized(v);
    }
}

/// The 2-D contour of a revolved shape: signed distance in the (s, r) half plane.
struct Profile {
    bool stalked = false;
    double length = 0.0; ///< s of the head centre (stalked) or half-length (ellipsoid)
    double radius = 0.0; ///< head / equatorial radius
    double stalkRadius = 0.0;
    double eval(double s, double r) const {
        if (!stalked) {
            const double q = std::sqrt((s / length) * (s / length) + (r / radius) * (r / radius));
            return (q - 1.0) * std::min(length, radius);
        }
        const double sc = std::clamp(s, 0.0, length);
        const double capsule = std::sqrt((s - sc) * (s - sc) + r * r) - stalkRadius;
        const double head = std::sqrt((s - length) * (s - length) + r * r) - radius;
        return smin(capsule, head, 0.6 * stalkRadius + 0.15 * radius);
    }
    /// Radius of the contour at s (0 outside).
    double radiusAt(double s) const {
        if (eval(s, 0.0) >= 0.0)
            return 0.0;
        double lo = 0.0, hi = 3.0 * (radius + stalkRadius);
        for (int it = 0; it < 50; ++it) {
            const double mid = 0.5 * (lo + hi);
            (eval(s, mid) < 0.0 ? lo : hi) = mid;
        }
        return 0.5 * (lo + hi);
    }
};

/// Contour points (s, r) from pole to pole, resampled uniformly by arc length.
std::vector<std::pair<double, double>> contour(const Profile& p, double sLo, double sHi, double spacing) {
    const int n = 800;
    std::vector<std::pair<double, double>> dense;
    double first = 0.0, last = 0.0;
    bool inside = false;
    double prevS = sLo;
    for (int i = 0; i <= n; ++i) {
        const double s = sLo + (sHi - sLo) * i / n;
        const bool in = p.eval(s, 0.0) < 0.0;
        if (in && !inside) { // refine the entry pole
            double lo = prevS, hi = s;
            for (int it = 0; it < 50; ++it) {
                const double mid = 0.5 * (lo + hi);
                (p.eval(mid, 0.0) < 0.0 ? hi : lo) = mid;
            }
            first = hi;
            dense.emplace_back(first, 0.0);
        }
        if (in)
            dense.emplace_back(s, p.radiusAt(s));
        if (!in && inside) {
            double lo = prevS, hi = s;
            for (int it = 0; it < 50; ++it) {
                const double mid = 0.5 * (lo + hi);
                (p.eval(mid, 0.0) < 0.0 ? lo : hi) = mid;
            }
            last = lo;
            dense.emplace_back(last, 0.0);
            break;
        }
        inside = in;
        prevS = s;
    }
    std::vector<double> arc(dense.size(), 0.0);
    for (std::size_t i = 1; i < dense.size(); ++i)
        arc[i] = arc[i - 1] + std::hypot(dense[i].first - dense[i - 1].first, dense[i].second - dense[i - 1].second);
    const double total = arc.back();
    const int stations = std::max(10, static_cast<int>(std::lround(total / spacing)));
    std::vector<std::pair<double, double>> out;
    out.push_back(dense.front());
    std::size_t seg = 1;
    for (int k = 1; k < stations; ++k) {
        const double a = total * k / stations;
        while (seg + 1 < arc.size() && arc[seg] < a)
            ++seg;
        const double t = (a - arc[seg - 1]) / std::max(arc[seg] - arc[seg - 1], 1e-12);
        out.emplace_back(dense[seg - 1].first + t * (dense[seg].first - dense[seg - 1].first),
                         dense[seg - 1].second + t * (dense[seg].second - dense[seg - 1].second));
    }
    out.push_back(dense.back());
    return out;
}

/// Box blur [1 2 1]/4 along each axis.
std::vector<float> blur(const std::vector<float>& in, const Grid& g) {
    std::vector<float> a = in, b(in.size());
    const std::array<std::size_t, 3> strides{1, static_cast<std::size_t>(g.nx),
                                             static_cast<std::size_t>(g.nx) * static_cast<std::size_t>(g.ny)};
    const std::array<int, 3> dims{g.nx, g.ny, g.nz};
    for (int axis = 0; axis < 3; ++axis) {
        for (int k = 0; k < g.nz; ++k)
            for (int j = 0; j < g.ny; ++j)
                for (int i = 0; i < g.nx; ++i) {
                    const std::array<int, 3> c{i, j, k};
                    const std::size_t id = g.index(i, j, k);
                    const std::size_t st = strides[static_cast<std::size_t>(axis)];
                    const bool lo = c[static_cast<std::size_t>(axis)] > 0;
                    const bool hi = c[static_cast<std::size_t>(axis)] + 1 < dims[static_cast<std::size_t>(axis)];
                    b[id] = 0.5f * a[id] + 0.25f * (lo ? a[id - st] : 0.0f) + 0.25f * (hi ? a[id + st] : 0.0f);
                }
        a.swap(b);
    }
    return a;
}

Grid growthGrid(const ShapeSpec& spec, double h, double reach) {
    Bounds box;
    box.add(spec.center - Vec3{reach, reach, reach});
    box.add(spec.center + Vec3{reach, reach, reach});
    if (spec.pedunculated || spec.polyp) {
        box.add(spec.base - Vec3{spec.stalkRadius, spec.stalkRadius, spec.stalkRadius} * 2.0);
        box.add(spec.base + Vec3{spec.stalkRadius, spec.stalkRadius, spec.stalkRadius} * 2.0);
    }
    return Grid::covering(box, h, 3);
}

void addCapsule(std::vector<float>& occ, const Grid& g, const Vec3& a, const Vec3& b, double radius) {
    const Vec3 ab = b - a;
    const double len2 = std::max(norm2(ab), 1e-12);
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                const Vec3 p = g.center(i, j, k);
                const double t = std::clamp(dot(p - a, ab) / len2, 0.0, 1.0);
                if (norm2(p - (a + ab * t)) <= radius * radius)
                    occ[g.index(i, j, k)] = 1.0f;
            }
}

/// Moves each vertex towards the centroid of its neighbours within its tangent plane: evens out the slivers of
/// marching tetrahedra without changing the shape.
void relaxTangentially(SurfaceMesh& mesh, int iterations) {
    std::vector<std::vector<std::int32_t>> nbr(mesh.points.size());
    for (const Triangle& t : mesh.triangles)
        for (std::size_t k = 0; k < 3; ++k)
            nbr[static_cast<std::size_t>(t[k])].push_back(t[(k + 1) % 3]);
    for (int it = 0; it < iterations; ++it) {
        const std::vector<Vec3> normals = vertexNormals(mesh);
        std::vector<Vec3> next = mesh.points;
        for (std::size_t i = 0; i < mesh.points.size(); ++i) {
            if (nbr[i].empty())
                continue;
            Vec3 c;
            for (std::int32_t j : nbr[i])
                c += mesh.points[static_cast<std::size_t>(j)];
            const Vec3 d = c / static_cast<double>(nbr[i].size()) - mesh.points[i];
            next[i] = mesh.points[i] + (d - normals[i] * dot(d, normals[i])) * 0.5;
        }
        mesh.points.swap(next);
    }
}

SurfaceMesh surfaceFromOccupancy(std::vector<float> occ, const Grid& g) {
    SurfaceMesh mesh = polygonize(blur(blur(occ, g), g), g, 0.5f);
    taubinSmooth(mesh, 10);
    relaxTangentially(mesh, 10);
    taubinSmooth(mesh, 10);
    orientOutward(mesh);
    return mesh;
}

/// Morphological closing (dilation, then erosion) with a ball of `radius` voxels. An Eden-type automaton leaves
/// one- and two-voxel crevices between its lobes; polygonized, they become creases whose two sides nearly touch, so
/// that smoothing can push them through each other and any offset of the surface folds. Closing fills exactly those
/// crevices and keeps the lobes (Serra, "Image Analysis and Mathematical Morphology", 1982).
std::vector<std::uint8_t> closeOccupancy(const std::vector<std::uint8_t>& occ, const Grid& g, int radius) {
    std::vector<std::array<int, 3>> ball;
    for (int dk = -radius; dk <= radius; ++dk)
        for (int dj = -radius; dj <= radius; ++dj)
            for (int di = -radius; di <= radius; ++di)
                if (di * di + dj * dj + dk * dk <= radius * radius)
                    ball.push_back({di, dj, dk});
    const auto inside = [&](int i, int j, int k) {
        return i >= 0 && j >= 0 && k >= 0 && i < g.nx && j < g.ny && k < g.nz;
    };
    std::vector<std::uint8_t> dilated(occ.size(), 0);
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                if (!occ[g.index(i, j, k)])
                    continue;
                for (const auto& d : ball)
                    if (inside(i + d[0], j + d[1], k + d[2]))
                        dilated[g.index(i + d[0], j + d[1], k + d[2])] = 1;
            }
    std::vector<std::uint8_t> closed(occ.size(), 0);
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                if (!dilated[g.index(i, j, k)])
                    continue;
                bool all = true;
                for (const auto& d : ball)
                    if (!inside(i + d[0], j + d[1], k + d[2]) || !dilated[g.index(i + d[0], j + d[1], k + d[2])]) {
                        all = false;
                        break;
                    }
                closed[g.index(i, j, k)] = all || occ[g.index(i, j, k)] ? 1 : 0;
            }
    return closed;
}

/// Trilinear resampling of `field` (on `g`, zero outside) onto a grid of spacing `h` over the same box.
std::vector<float> resample(const std::vector<float>& field, const Grid& g, double h, Grid& out) {
    Bounds box;
    box.add(g.origin);
    box.add(g.center(g.nx - 1, g.ny - 1, g.nz - 1));
    out = Grid::covering(box, h, 1);
    const auto at = [&](int i, int j, int k) {
        return i < 0 || j < 0 || k < 0 || i >= g.nx || j >= g.ny || k >= g.nz ? 0.0 : double(field[g.index(i, j, k)]);
    };
    std::vector<float> result(out.size());
    for (int k = 0; k < out.nz; ++k)
        for (int j = 0; j < out.ny; ++j)
            for (int i = 0; i < out.nx; ++i) {
                const Vec3 q = (out.center(i, j, k) - g.origin) / g.h;
                const int i0 = static_cast<int>(std::floor(q.x)), j0 = static_cast<int>(std::floor(q.y)),
                          k0 = static_cast<int>(std::floor(q.z));
                const double fx = q.x - i0, fy = q.y - j0, fz = q.z - k0;
                double v = 0.0;
                for (int c = 0; c < 8; ++c) {
                    const int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
                    const double w = (di ? fx : 1.0 - fx) * (dj ? fy : 1.0 - fy) * (dk ? fz : 1.0 - fz);
                    v += w * at(i0 + di, j0 + dj, k0 + dk);
                }
                result[out.index(i, j, k)] = static_cast<float>(v);
            }
    return result;
}

/// The automaton's surface: closed occupancy (no crevices), blurred at the automaton's resolution, polygonized on a
/// grid of `spacing` mm (coarser than the automaton's voxels: the blurred field has no detail below two voxels, and
/// the organ adaptation and the merge cost grow with the triangle count), then smoothed (Taubin) and evened out.
SurfaceMesh automatonSurface(const std::vector<std::uint8_t>& occ, const Grid& g, const ShapeSpec& spec,
                             double spacing) {
    const std::vector<std::uint8_t> closed = closeOccupancy(occ, g, 2);
    std::vector<float> field(closed.begin(), closed.end());
    if (spec.pedunculated || spec.polyp)
        addCapsule(field, g, spec.base, spec.center, spec.stalkRadius);
    Grid coarse;
    const std::vector<float> sampled = resample(blur(blur(field, g), g), g, spacing, coarse);
    SurfaceMesh mesh = polygonize(sampled, coarse, 0.5f);
    taubinSmooth(mesh, 10);
    relaxTangentially(mesh, 10);
    taubinSmooth(mesh, 10);
    relaxTangentially(mesh, 5);
    orientOutward(mesh);
    return mesh;
}

} // namespace

SurfaceMesh skeletonShape(const ShapeSpec& spec, Rng& rng) {
    Profile profile;
    Vec3 start, dir, bendDir;
    double bend = 0.0;
    const bool stalked = spec.polyp || spec.pedunculated;
    if (stalked) {
        profile.stalked = true;
        profile.length = distance(spec.center, spec.base);
        profile.radius = spec.radius;
        profile.stalkRadius = spec.stalkRadius;
        start = spec.base;
        dir = normalized(spec.center - spec.base);
        Vec3 e1, e2;
        orthonormalFrame(dir, e1, e2);
        const double angle = rng.uniform(0.0, 2.0 * kPi);
        bendDir = e1 * std::cos(angle) + e2 * std::sin(angle);
        bend = spec.pedunculated || profile.length > 1.5 * spec.radius ? rng.uniform(0.05, 0.2) * profile.length : 0.0;
        // The bow's curvature peaks at 2 pi^2 bend / L^2 (L the bowed length); its radius stays above the stalk's
        // radius plus a few millimetres, or the stalk's inner side (and any offset of it) would fold.
        const double bowed = std::max(profile.length - profile.radius, 0.3 * profile.length);
        bend = std::min(bend, bowed * bowed / (2.0 * kPi * kPi * (profile.stalkRadius + 3.0)));
    } else {
        // A myoma: an ellipsoid of revolution whose axis lies mostly in the wall's tangent plane (across the wall
        // for a transmural one, which must reach both its surfaces).
        Vec3 e1, e2;
        orthonormalFrame(spec.intoWall, e1, e2);
        const double angle = rng.uniform(0.0, 2.0 * kPi);
        const Vec3 tangent = e1 * std::cos(angle) + e2 * std::sin(angle);
        dir = spec.transmural ? normalized(spec.intoWall + tangent * rng.uniform(0.0, 0.1))
                              : normalized(tangent + spec.intoWall * rng.uniform(-0.3, 0.3));
        profile.length = spec.radius * rng.uniform(1.0, 1.2);
        profile.radius = spec.radius;
        start = spec.center;
    }
    const double sLo = stalked ? -profile.stalkRadius - 1.0 : -profile.length - 1.0;
    const double sHi = stalked ? profile.length + profile.radius + 1.0 : profile.length + 1.0;
    const auto stations = contour(profile, sLo, sHi, 2.0 * kPi * spec.radius / kAround);

    // Lobulation: a few harmonics around and along the axis (polyps are more lobulated than myomas).
    const double amplitude = spec.polyp ? 0.09 : 0.05;
    struct Lobe {
        double weight, k, phase, axial, axialPhase;
    };
    std::vector<Lobe> lobes;
    double weightSum = 0.0;
    for (int k = 2; k <= 5; ++k) {
        Lobe l{rng.uniform(0.3, 1.0) / std::sqrt(static_cast<double>(k)), static_cast<double>(k),
               rng.uniform(0.0, 2.0 * kPi), rng.uniform(0.5, 1.5), rng.uniform(0.0, 2.0 * kPi)};
        weightSum += l.weight;
        lobes.push_back(l);
    }
    const double headStart = stalked ? profile.length - profile.radius : -1e300;
    auto curve = [&](double s) {
        if (bend == 0.0)
            return start + dir * s;
        // The stalk bows out and back before the head starts, so the head's rings stay parallel.
        const double x = std::clamp(s / std::max(profile.length - profile.radius, 0.3 * profile.length), 0.0, 1.0);
        return start + dir * s + bendDir * (bend * 0.5 * (1.0 - std::cos(2.0 * kPi * x)));
    };

    SurfaceMesh mesh;
    mesh.points.push_back(curve(stations.front().first));
    Vec3 prevT = dir, e1, e2;
    orthonormalFrame(dir, e1, e2);
    const std::size_t rings = stations.size() - 2;
    for (std::size_t k = 1; k + 1 < stations.size(); ++k) {
        const double s = stations[k].first, r = stations[k].second;
        const Vec3 tangent = normalized(curve(s + 1e-3) - curve(s - 1e-3));
        // Rotation-minimizing frame: project the previous normal onto the new normal plane.
        e1 = normalized(e1 - tangent * dot(e1, tangent));
        e2 = cross(tangent, e1);
        prevT = tangent;
        const double head = stalked ? smoothstep(headStart, headStart + 0.6 * profile.radius, s) : 1.0;
        const double along = stalked ? (s - profile.length) / profile.radius : s / profile.length;
        for (int j = 0; j < kAround; ++j) {
            const double theta = 2.0 * kPi * j / kAround;
            double m = 0.0;
            for (const Lobe& l : lobes)
                m += l.weight * std::cos(l.k * theta + l.phase) * std::cos(l.axial * kPi * along + l.axialPhase);
            const double rr = r * (1.0 + amplitude * head * m / weightSum);
            mesh.points.push_back(curve(s) + (e1 * std::cos(theta) + e2 * std::sin(theta)) * rr);
        }
    }
    (void)prevT;
    mesh.points.push_back(curve(stations.back().first));
    const auto ring = [&](std::size_t k, int j) {
        return static_cast<std::int32_t>(1 + k * kAround + static_cast<std::size_t>((j + kAround) % kAround));
    };
    const auto lastPole = static_cast<std::int32_t>(mesh.points.size() - 1);
    for (int j = 0; j < kAround; ++j) {
        mesh.triangles.push_back({0, ring(0, j), ring(0, j + 1)});
        for (std::size_t k = 0; k + 1 < rings; ++k) {
            mesh.triangles.push_back({ring(k, j), ring(k + 1, j), ring(k + 1, j + 1)});
            mesh.triangles.push_back({ring(k, j), ring(k + 1, j + 1), ring(k, j + 1)});
        }
        mesh.triangles.push_back({lastPole, ring(rings - 1, j + 1), ring(rings - 1, j)});
    }
    orientOutward(mesh);
    return mesh;
}

Result<SurfaceMesh> cellularAutomatonShape(const ShapeSpec& spec, const SurfaceMesh& organ, const GrowthTuning& tuning,
                                           Rng& rng, Progress& progress) {
    const double h = 2.0 * spec.radius / tuning.cellsPerDiameter;
    const Grid g = growthGrid(spec, h, 1.6 * spec.radius);
    const std::vector<std::uint8_t> tissue = insideMask(organ, g);
    std::vector<std::uint8_t> occ(g.size(), 0);
    const int ci = static_cast<int>(std::lround((spec.center.x - g.origin.x) / h));
    const int cj = static_cast<int>(std::lround((spec.center.y - g.origin.y) / h));
    const int ck = static_cast<int>(std::lround((spec.center.z - g.origin.z) / h));
    const std::array<std::array<int, 3>, 6> nb{{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
    occ[g.index(ci, cj, ck)] = 1;
    std::size_t count = 1;
    for (const auto& d : nb) {
        occ[g.index(ci + d[0], cj + d[1], ck + d[2])] = 1;
        ++count;
    }
    const double target = 4.0 / 3.0 * kPi * std::pow(spec.radius, 3) / (h * h * h);
    std::vector<std::size_t> born;
    // Bounding box of the tumour: only its neighbourhood is scanned each sweep.
    std::array<int, 3> lo{ci - 1, cj - 1, ck - 1}, hi{ci + 1, cj + 1, ck + 1};
    for (int sweep = 0; static_cast<double>(count) < target; ++sweep) {
        if (progress.cancelled())
            return fail(ErrorCode::Cancelled, "pathology growth cancelled");
        if (sweep > 4 * tuning.cellsPerDiameter * 10)
            break;
        born.clear();
        for (int k = std::max(1, lo[2] - 1); k <= std::min(g.nz - 2, hi[2] + 1); ++k)
            for (int j = std::max(1, lo[1] - 1); j <= std::min(g.ny - 2, hi[1] + 1); ++j)
                for (int i = std::max(1, lo[0] - 1); i <= std::min(g.nx - 2, hi[0] + 1); ++i) {
                    const std::size_t id = g.index(i, j, k);
                    if (occ[id])
                        continue;
                    int q = 0;
                    Vec3 from;
                    for (const auto& d : nb)
                        if (occ[g.index(i + d[0], j + d[1], k + d[2])]) {
                            ++q;
                            from += Vec3{static_cast<double>(-d[0]), static_cast<double>(-d[1]),
                                         static_cast<double>(-d[2])};
                        }
                    if (q == 0)
                        continue;
                    const double r = tissue[id] ? tuning.tissueResistance : tuning.yieldResistance;
                    // The wall's fibres guide growth along its tangent plane; the cavity and the outside have none.
                    // A transmural (hybrid) myoma, which must reach both the endometrium and the serosa, grows
                    // across the wall instead.
                    const double along = dot(normalized(from), spec.intoWall);
                    const double guide = !tissue[id]       ? 0.0
                                         : spec.transmural ? tuning.transmuralAnisotropy * along * along
                                                           : tuning.anisotropy * (1.0 - along * along);
                    const double p = std::min(1.0, 0.12 * (1.0 + 2.0 * q / 6.0) / r * (1.0 + guide));
                    if (rng.uniform() < p) {
                        born.push_back(id);
                        lo = {std::min(lo[0], i), std::min(lo[1], j), std::min(lo[2], k)};
                        hi = {std::max(hi[0], i), std::max(hi[1], j), std::max(hi[2], k)};
                    }
                }
        for (std::size_t id : born)
            occ[id] = 1;
        count += born.size();
    }
    SurfaceMesh mesh = automatonSurface(occ, g, spec, spec.radius / tuning.surfaceCellsPerRadius);
    // The placement owns the position, the automaton the shape: a tumour that drifted into yielding tissue keeps
    // its lopsided shape but is centred (volume centroid) where it was planned, as the other models are.
    if (!spec.pedunculated && !spec.polyp)
        translate(mesh, spec.center - volumeCentroid(mesh));
    return mesh;
}

Result<SurfaceMesh> particleShape(const ShapeSpec& spec, const SurfaceMesh& organ, const GrowthTuning& tuning, Rng& rng,
                                  Progress& progress) {
    const double h = 2.0 * spec.radius / tuning.cellsPerDiameter;
    const Grid g = growthGrid(spec, h, 1.6 * spec.radius);
    const std::vector<std::uint8_t> tissue = insideMask(organ, g);
    auto inTissue = [&](const Vec3& p) {
        const int i = static_cast<int>(std::lround((p.x - g.origin.x) / h));
        const int j = static_cast<int>(std::lround((p.y - g.origin.y) / h));
        const int k = static_cast<int>(std::lround((p.z - g.origin.z) / h));
        if (i < 0 || j < 0 || k < 0 || i >= g.nx || j >= g.ny || k >= g.nz)
            return false;
        return tissue[g.index(i, j, k)] != 0;
    };
    const auto n = static_cast<std::size_t>(tuning.particleCount);
    const double volume = 4.0 / 3.0 * kPi * std::pow(spec.radius, 3);
    // Cell radius so that n cells in a random close packing (~0.64) fill the volume.
    const double rho = std::cbrt(0.64 * volume * 3.0 / (4.0 * kPi * static_cast<double>(n)));
    std::vector<Vec3> cells{spec.center};
    std::vector<Vec3> disp;
    std::unordered_map<std::int64_t, std::vector<std::size_t>> hash;
    const double cell = 2.0 * rho;
    auto key = [&](const Vec3& p, int dx, int dy, int dz) {
        const auto x = static_cast<std::int64_t>(std::floor(p.x / cell)) + dx;
        const auto y = static_cast<std::int64_t>(std::floor(p.y / cell)) + dy;
        const auto z = static_cast<std::int64_t>(std::floor(p.z / cell)) + dz;
        return (x * 73856093) ^ (y * 19349663) ^ (z * 83492791);
    };
    while (cells.size() < n) {
        if (progress.cancelled())
            return fail(ErrorCode::Cancelled, "pathology growth cancelled");
        // Division: faster where the surroundings yield (cavity, outside) than in the resisting wall.
        const std::size_t current = cells.size();
        for (std::size_t i = 0; i < current && cells.size() < n; ++i) {
            const double p = inTissue(cells[i]) ? 0.5 / tuning.tissueResistance : 0.5 / tuning.yieldResistance;
            if (rng.uniform() >= std::min(p, 1.0))
                continue;
            const Vec3 d = randomUnit(rng) * (0.5 * rho);
            cells.push_back(cells[i] + d);
            cells[i] -= d;
        }
        // Relaxation: short-range repulsion, confinement strong in the wall, weak where it yields.
        for (int it = 0; it < 8; ++it) {
            hash.clear();
            for (std::size_t i = 0; i < cells.size(); ++i)
                hash[key(cells[i], 0, 0, 0)].push_back(i);
            disp.assign(cells.size(), Vec3{});
            for (std::size_t i = 0; i < cells.size(); ++i) {
                for (int dz = -1; dz <= 1; ++dz)
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx) {
                            auto found = hash.find(key(cells[i], dx, dy, dz));
                            if (found == hash.end())
                                continue;
                            for (std::size_t j : found->second) {
                                if (j <= i)
                                    continue;
                                Vec3 d = cells[i] - cells[j];
                                double len = norm(d);
                                if (len >= 2.0 * rho)
                                    continue;
                                if (len < 1e-9) {
                                    d = Vec3{1.0, 0.0, 0.0};
                                    len = 1.0;
                                }
                                const Vec3 push = d * (0.25 * (2.0 * rho - norm(cells[i] - cells[j])) / len);
                                disp[i] += push;
                                disp[j] -= push;
                            }
                        }
                const bool wall = inTissue(cells[i]);
                disp[i] -=
                    (cells[i] - spec.center) * (wall ? 0.02 * tuning.tissueResistance : 0.02 * tuning.yieldResistance);
                // The wall's fibres guide growth along its tangent plane; a transmural (hybrid) myoma, which spans
                // the wall, grows across it instead.
                const Vec3 across = spec.intoWall * dot(disp[i], spec.intoWall);
                if (wall)
                    disp[i] -= (spec.transmural ? disp[i] - across : across) * tuning.anisotropy;
            }
            for (std::size_t i = 0; i < cells.size(); ++i)
                cells[i] += disp[i];
        }
    }
    std::vector<float> field(g.size(), 0.0f);
    const double reach = 1.45 * rho;
    const int rv = static_cast<int>(std::ceil(reach / h));
    for (const Vec3& c : cells) {
        const int i0 = static_cast<int>(std::lround((c.x - g.origin.x) / h));
        const int j0 = static_cast<int>(std::lround((c.y - g.origin.y) / h));
        const int k0 = static_cast<int>(std::lround((c.z - g.origin.z) / h));
        for (int k = std::max(1, k0 - rv); k <= std::min(g.nz - 2, k0 + rv); ++k)
            for (int j = std::max(1, j0 - rv); j <= std::min(g.ny - 2, j0 + rv); ++j)
                for (int i = std::max(1, i0 - rv); i <= std::min(g.nx - 2, i0 + rv); ++i)
                    if (norm2(g.center(i, j, k) - c) <= reach * reach)
                        field[g.index(i, j, k)] = 1.0f;
    }
    if (spec.pedunculated || spec.polyp)
        addCapsule(field, g, spec.base, spec.center, spec.stalkRadius);
    return surfaceFromOccupancy(std::move(field), g);
}

double headDiameter(const std::vector<Vec3>& points, const Vec3& base, const Vec3& axis, double* stalkLength) {
    if (stalkLength)
        *stalkLength = 0.0;
    double tMin = 1e300, tMax = -1e300;
    for (const Vec3& p : points) {
        tMin = std::min(tMin, dot(p - base, axis));
        tMax = std::max(tMax, dot(p - base, axis));
    }
    const int bins = 40;
    const double w = std::max((tMax - tMin) / bins, 1e-9);
    // A bin's radius is measured from the centre of its own cross-section: a bowed or tilted stalk is as narrow as a
    // straight one.
    std::vector<Vec3> centre(bins);
    std::vector<double> count(bins, 0.0), radius(bins, 0.0);
    auto binOf = [&](const Vec3& p) {
        return static_cast<std::size_t>(std::clamp(static_cast<int>((dot(p - base, axis) - tMin) / w), 0, bins - 1));
    };
    for (const Vec3& p : points) {
        const std::size_t b = binOf(p);
        centre[b] += p - axis * dot(p - base, axis);
        count[b] += 1.0;
    }
    for (std::size_t b = 0; b < centre.size(); ++b)
        if (count[b] > 0.0)
            centre[b] = centre[b] / count[b];
    for (const Vec3& p : points) {
        const std::size_t b = binOf(p);
        const Vec3 offset = p - axis * dot(p - base, axis) - centre[b];
        radius[b] = std::max(radius[b], norm(offset));
    }
    const double maxR = *std::max_element(radius.begin(), radius.end());
    // The stalk: consecutive bins from the wall (t = 0) narrower than half the head.
    int b = std::clamp(static_cast<int>((0.0 - tMin) / w), 0, bins - 1);
    while (b < bins && radius[static_cast<std::size_t>(b)] < 0.5 * maxR)
        ++b;
    const double stalkEnd = tMin + b * w;
    if (stalkEnd < 2.0 || b >= bins) // shorter than 2 mm: sessile
        return diameter(points);
    if (stalkLength)
        *stalkLength = stalkEnd;
    std::vector<Vec3> head;
    for (const Vec3& p : points)
        if (dot(p - base, axis) > stalkEnd)
            head.push_back(p);
    return diameter(head);
}

} // namespace hs::pathology::detail
