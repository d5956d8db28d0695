#include "Particles.h"

#include "Parallel.h"
#include "hs/core/Rng.h"
#include "hs/meshing/Geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace hs::meshing::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Seeding radii, in target edge lengths: a candidate closer than this to an accepted particle is dropped.
constexpr double kFeatureRadius = 0.8;  ///< features against corners and features
constexpr double kSurfaceRadius = 0.75; ///< surface candidates against accepted particles of their own sheet
/// Surface candidates against accepted particles of other sheets (other surfaces, the far side of a slit). Much
/// smaller than kSurfaceRadius: where two nested surfaces come closer than one edge (the 0.8 mm cover over a
/// pathology at a 2 mm edge), each keeps its own particles, so the layer between them is resolved instead of the
/// later surface losing its particles there.
constexpr double kCrossSurfaceRadius = 0.25;
constexpr double kInnerRadius = 0.6;       ///< inner candidates against surface, feature and corner particles
constexpr double kRandomInnerRadius = 0.5; ///< Seeding::Random: inner candidates against everything
/// Two boundary particles of one surface whose normals differ by more (cosine below this) lie on opposite sides
/// of a slit: different sheets.
constexpr double kSheetCos = -0.5;
constexpr int kSurfaceCandidatesPerVoxel = 3;

// Relaxation schedule (Sierra et al.: the motility shrinks every iteration).
constexpr double kInitialMotility = 0.3; ///< step = motility * rest distance * force
constexpr double kMotilityDecay = 0.95;
constexpr double kMaxStep = 0.25;       ///< rest distances per iteration
constexpr double kConvergedMove = 2e-3; ///< stop when no particle moves more (rest distances)
constexpr std::size_t kParticleChunk = 2048;

std::uint64_t edgeKey(std::int32_t a, std::int32_t b) {
    const auto lo = static_cast<std::uint32_t>(std::min(a, b));
    const auto hi = static_cast<std::uint32_t>(std::max(a, b));
    return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

/// Tables of the profile over d^2 in [0, cutoff^2]: force / d (so that the force vector is table * (xi - xj)) and
/// energy, both linearly interpolated.
struct ProfileTable {
    static constexpr int kSize = 4096;
    std::array<double, kSize + 1> forceOverD{};
    std::array<double, kSize + 1> energy{};
    double scale = 0.0; // index per unit d^2

    ProfileTable() {
        const double c2 = kInteractionCutoff * kInteractionCutoff;
        scale = kSize / c2;
        for (int i = 0; i <= kSize; ++i) {
            const double d = std::sqrt(std::max(double(i) / scale, 1e-4));
            forceOverD[static_cast<std::size_t>(i)] = interactionForce(std::max(d, 0.05)) / std::max(d, 0.05);
            energy[static_cast<std::size_t>(i)] = interactionEnergy(d);
        }
    }
    void lookup(double d2, double& fOverD, double& e) const {
        const double x = d2 * scale;
        const auto i = static_cast<std::size_t>(x);
        if (i >= static_cast<std::size_t>(kSize)) {
            fOverD = 0.0;
            e = 0.0;
            return;
        }
        const double w = x - double(i);
        fOverD = forceOverD[i] + w * (forceOverD[i + 1] - forceOverD[i]);
        e = energy[i] + w * (energy[i + 1] - energy[i]);
    }
};

const ProfileTable& profile() {
    static const ProfileTable table;
    return table;
}

/// A uniform hash of particles by cell (cell = rest distance * cutoff), rebuilt by counting sort.
struct NeighbourGrid {
    Vec3 origin;
    double cell = 1.0;
    std::int64_t dims[3] = {1, 1, 1};
    std::vector<std::uint32_t> start;
    std::vector<std::uint32_t> items;

    void build(const std::vector<Vec3>& points, const Bounds& box, double cellSize) {
        cell = cellSize;
        origin = box.min - Vec3(cell, cell, cell);
        for (int q = 0; q < 3; ++q)
            dims[q] = static_cast<std::int64_t>(std::floor((box.max[q] - origin[q]) / cell)) + 2;
        const auto n = static_cast<std::size_t>(dims[0] * dims[1] * dims[2]);
        start.assign(n + 1, 0);
        std::vector<std::uint32_t> cellOf(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            cellOf[i] = static_cast<std::uint32_t>(cellIndex(points[i]));
            ++start[cellOf[i] + 1];
        }
        for (std::size_t c = 0; c < n; ++c)
            start[c + 1] += start[c];
        items.resize(points.size());
        std::vector<std::uint32_t> cursor(start.begin(), start.end() - 1);
        for (std::size_t i = 0; i < points.size(); ++i)
            items[cursor[cellOf[i]]++] = static_cast<std::uint32_t>(i);
    }
    std::int64_t coord(const Vec3& p, int q) const {
        return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((p[q] - origin[q]) / cell)), 0,
                                        dims[q] - 1);
    }
    std::size_t cellIndex(const Vec3& p) const {
        return static_cast<std::size_t>((coord(p, 2) * dims[1] + coord(p, 1)) * dims[0] + coord(p, 0));
    }
};

/// Whether boundary particle u lies on the same sheet as a point of surface s with normal n: the same surface, with
/// normals less than about 120 degrees apart. Opposite sides of a slit or of a layer thinner than one edge (the
/// uterine cavity, the cover over a pathology) are different sheets and must keep their own particles.
bool sameSheet(const Particles& ps, const std::vector<SurfaceAdjacency>& adjacency, std::size_t u, std::int32_t s,
               const Vec3& n) {
    if (ps.surface[u] != s)
        return false;
    const Vec3& nu = adjacency[static_cast<std::size_t>(s)].faceNormals[static_cast<std::size_t>(ps.triangle[u])];
    return dot(nu, n) > kSheetCos;
}

/// Accepted particles hashed by voxel (head/next lists) for the seeding radius checks.
struct AcceptedIndex {
    const VoxelGrid<std::int32_t>* grid = nullptr;
    std::vector<std::int32_t> head;
    std::vector<std::int32_t> next;

    explicit AcceptedIndex(const VoxelGrid<std::int32_t>& g) : grid(&g), head(g.size(), -1) {}
    /// Whether `accept(index, squared distance)` holds for an accepted particle within `radius` of p.
    template <typename Accept>
    bool anyWithin(const Particles& ps, const Vec3& p, double radius, Accept&& accept) const {
        const Index3 c = grid->voxelOf(p);
        const double r2 = radius * radius;
        const auto reach = static_cast<std::int64_t>(std::ceil(radius / grid->spacing()));
        for (std::int64_t dk = -reach; dk <= reach; ++dk)
            for (std::int64_t dj = -reach; dj <= reach; ++dj)
                for (std::int64_t di = -reach; di <= reach; ++di) {
                    const Index3 nb{c[0] + di, c[1] + dj, c[2] + dk};
                    if (!grid->contains(nb))
                        continue;
                    for (std::int32_t i = head[grid->linear(nb)]; i >= 0; i = next[static_cast<std::size_t>(i)]) {
                        const auto u = static_cast<std::size_t>(i);
                        const double d2 = norm2(ps.position[u] - p);
                        if (d2 < r2 && accept(u, d2))
                            return true;
                    }
                }
        return false;
    }
    bool near(const Particles& ps, const Vec3& p, double radius) const {
        return anyWithin(ps, p, radius, [](std::size_t, double) { return true; });
    }
    /// True when an accepted particle of the same sheet (surface `s`, normal `n` within kSheetCos) lies closer than
    /// `sameRadius`, or any other one closer than `otherRadius`.
    bool nearOnSheet(const Particles& ps, const std::vector<SurfaceAdjacency>& adjacency, const Vec3& p, std::int32_t s,
                     const Vec3& n, double sameRadius, double otherRadius) const {
        const double same2 = sameRadius * sameRadius, other2 = otherRadius * otherRadius;
        return anyWithin(ps, p, std::max(sameRadius, otherRadius), [&](std::size_t u, double d2) {
            return d2 < other2 || (d2 < same2 && sameSheet(ps, adjacency, u, s, n));
        });
    }
    void add(Particles& ps, const Vec3& p, ParticleKind k, std::int32_t s, std::int32_t t, std::int32_t r) {
        const Index3 c = grid->voxelOf(p);
        const auto index = static_cast<std::int32_t>(ps.size());
        ps.add(p, k, s, t, r);
        next.push_back(-1);
        if (grid->contains(c)) {
            const std::size_t v = grid->linear(c);
            next.back() = head[v];
            head[v] = index;
        }
    }
};

void seedFeatures(const SeedingInput& in, std::size_t s, Particles& ps, AcceptedIndex& index) {
    const SurfaceMesh& mesh = in.body->surfaces[s].surface;
    const SurfaceAdjacency& adj = (*in.adjacency)[s];
    const double cosLimit = std::cos(in.params->featureAngleDeg * kPi / 180.0);
    // Edge -> the two faces (the surface is closed and manifold: exactly two), in first-seen order.
    std::unordered_map<std::uint64_t, std::pair<std::int32_t, std::int32_t>> faces;
    std::vector<std::uint64_t> order;
    faces.reserve(mesh.triangles.size() * 2);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const Triangle& t = mesh.triangles[f];
        for (int k = 0; k < 3; ++k) {
            const std::uint64_t key = edgeKey(t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]);
            auto [it, inserted] = faces.try_emplace(key, static_cast<std::int32_t>(f), -1);
            if (inserted)
                order.push_back(key);
            else
                it->second.second = static_cast<std::int32_t>(f);
        }
    }
    std::vector<std::uint64_t> featureEdges;
    std::vector<int> degree(mesh.points.size(), 0);
    for (std::uint64_t key : order) {
        const auto [f0, f1] = faces[key];
        if (f1 < 0)
            continue;
        if (dot(adj.faceNormals[static_cast<std::size_t>(f0)], adj.faceNormals[static_cast<std::size_t>(f1)]) <
            cosLimit) {
            featureEdges.push_back(key);
            ++degree[key >> 32];
            ++degree[key & 0xFFFFFFFFu];
        }
    }
    const auto si = static_cast<std::int32_t>(s);
    // Corners: feature vertices that are not in the middle of a single feature line.
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
        if (degree[v] == 1 || degree[v] >= 3)
            index.add(ps, mesh.points[v], ParticleKind::Corner, si, adj.fan[adj.fanStart[v]], -1);
    // Dense candidates along each feature edge, thinned against everything accepted so far.
    const double step = 0.4 * in.edge;
    for (std::uint64_t key : featureEdges) {
        const auto a = static_cast<std::size_t>(key >> 32), b = static_cast<std::size_t>(key & 0xFFFFFFFFu);
        const Vec3& pa = mesh.points[a];
        const Vec3& pb = mesh.points[b];
        const int pieces = std::max(1, static_cast<int>(std::ceil(distance(pa, pb) / step)));
        const std::int32_t tri = faces[key].first;
        for (int i = 0; i <= pieces; ++i) {
            const Vec3 p = pa + (pb - pa) * (double(i) / double(pieces));
            if (!index.near(ps, p, kFeatureRadius * in.edge))
                index.add(ps, p, ParticleKind::Feature, si, tri, -1);
        }
    }
}

void seedSurface(const SeedingInput& in, std::size_t s, const Rng& base, Particles& ps, AcceptedIndex& index) {
    const SurfaceMesh& mesh = in.body->surfaces[s].surface;
    const SurfaceVoxels& sv = in.voxels->surfaces[s];
    const auto& grid = in.voxels->region;
    const double h = grid.spacing();
    const auto si = static_cast<std::int32_t>(s);
    for (std::size_t v = 0; v < grid.size(); ++v) {
        const std::uint32_t b = sv.start[v], e = sv.start[v + 1];
        if (b == e)
            continue;
        Rng rng = base.derive((static_cast<std::uint64_t>(s) << 40) ^ v);
        const Vec3 corner = grid.minCorner(grid.unlinear(v));
        for (int c = 0; c < kSurfaceCandidatesPerVoxel; ++c) {
            const Vec3 q = corner + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * h;
            ClosestPoint best{q, 1e300, TriangleFeature::Face};
            std::int32_t bestTri = -1;
            for (std::uint32_t it = b; it < e; ++it) {
                const Triangle& t = mesh.triangles[static_cast<std::size_t>(sv.triangles[it])];
                const ClosestPoint cp = closestPointOnTriangle(q, mesh.points[static_cast<std::size_t>(t[0])],
                                                               mesh.points[static_cast<std::size_t>(t[1])],
                                                               mesh.points[static_cast<std::size_t>(t[2])]);
                if (cp.distance2 < best.distance2) {
                    best = cp;
                    bestTri = sv.triangles[it];
                }
            }
            if (bestTri >= 0 && !index.nearOnSheet(ps, *in.adjacency, best.point, si,
                                                   (*in.adjacency)[s].faceNormals[static_cast<std::size_t>(bestTri)],
                                                   kSurfaceRadius * in.edge, kCrossSurfaceRadius * in.edge))
                index.add(ps, best.point, ParticleKind::Surface, si, bestTri, -1);
        }
    }
}

void seedInner(const SeedingInput& in, const Rng& base, Particles& ps, AcceptedIndex& index) {
    const auto& grid = in.voxels->region;
    const double h = grid.spacing();
    const MeshParams& params = *in.params;
    const bool lattice = params.seeding == Seeding::Lattice;
    const double radius = (lattice ? kInnerRadius : kRandomInnerRadius) * in.edge;
    const std::size_t boundaryCount = ps.size();
    const double jitter = std::clamp(params.latticeJitter, 0.0, 0.24) * h;
    for (std::size_t v = 0; v < grid.size(); ++v) {
        const std::int32_t region = grid[v];
        if (region < 0)
            continue;
        Rng rng = base.derive((std::uint64_t(1) << 62) ^ v);
        const Vec3 corner = grid.minCorner(grid.unlinear(v));
        const int count = lattice ? 2 : std::clamp(params.particlesPerVoxel, 1, 16);
        for (int c = 0; c < count; ++c) {
            Vec3 p;
            if (lattice) {
                // Body-centred cubic lattice, both points strictly inside the voxel: (1/4,1/4,1/4) and (3/4,3/4,3/4).
                const double o = c == 0 ? 0.25 : 0.75;
                p = corner + Vec3(o, o, o) * h +
                    Vec3(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)) * jitter;
            } else {
                p = corner + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * h;
            }
            // Lattice points only need to keep clear of the boundary particles; random ones of everything.
            bool tooClose = false;
            if (lattice) {
                const Index3 cv = grid.voxelOf(p);
                const double r2 = radius * radius;
                for (std::int64_t dk = -1; dk <= 1 && !tooClose; ++dk)
                    for (std::int64_t dj = -1; dj <= 1 && !tooClose; ++dj)
                        for (std::int64_t di = -1; di <= 1 && !tooClose; ++di) {
                            const Index3 nb{cv[0] + di, cv[1] + dj, cv[2] + dk};
                            if (!grid.contains(nb) || grid.at(nb) != VoxelSpace::kSurface)
                                continue;
                            for (std::int32_t i = index.head[grid.linear(nb)]; i >= 0;
                                 i = index.next[static_cast<std::size_t>(i)])
                                if (static_cast<std::size_t>(i) < boundaryCount &&
                                    norm2(ps.position[static_cast<std::size_t>(i)] - p) < r2) {
                                    tooClose = true;
                                    break;
                                }
                        }
            } else {
                tooClose = index.near(ps, p, radius);
            }
            if (!tooClose)
                index.add(ps, p, ParticleKind::Inner, -1, -1, region);
        }
    }
}

} // namespace

double interactionForce(double d) {
    // Bossen & Heckbert 1996 ("A pliant method for anisotropic mesh generation"): repulsive below the rest
    // distance, weakly attractive just above it, vanishing beyond about 1.5.
    const double d4 = d * d * d * d;
    return (1.0 - d4) * std::exp(-d4);
}

double interactionEnergy(double d) {
    // phi(d) = integral of f from d to the cut-off (phi' = -f, phi(cutoff) = 0), by Simpson's rule.
    if (d >= kInteractionCutoff)
        return 0.0;
    const int n = 256;
    const double hstep = (kInteractionCutoff - d) / n;
    double sum = interactionForce(d) + interactionForce(kInteractionCutoff);
    for (int i = 1; i < n; ++i)
        sum += (i % 2 ? 4.0 : 2.0) * interactionForce(d + i * hstep);
    return sum * hstep / 3.0;
}

SurfaceAdjacency buildAdjacency(const SurfaceMesh& mesh) {
    SurfaceAdjacency adj;
    adj.fanStart.assign(mesh.points.size() + 1, 0);
    for (const Triangle& t : mesh.triangles)
        for (auto v : t)
            ++adj.fanStart[static_cast<std::size_t>(v) + 1];
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
        adj.fanStart[v + 1] += adj.fanStart[v];
    adj.fan.resize(adj.fanStart.back());
    std::vector<std::uint32_t> cursor(adj.fanStart.begin(), adj.fanStart.end() - 1);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
        for (auto v : mesh.triangles[f])
            adj.fan[cursor[static_cast<std::size_t>(v)]++] = static_cast<std::int32_t>(f);
    adj.faceNormals.resize(mesh.triangles.size());
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
        adj.faceNormals[f] = faceNormal(mesh, f);
    return adj;
}

std::int32_t projectByWalk(const SurfaceMesh& mesh, const SurfaceAdjacency& adj, std::int32_t start, const Vec3& p,
                           Vec3& projected) {
    auto closestOn = [&](std::int32_t f) {
        const Triangle& t = mesh.triangles[static_cast<std::size_t>(f)];
        return closestPointOnTriangle(p, mesh.points[static_cast<std::size_t>(t[0])],
                                      mesh.points[static_cast<std::size_t>(t[1])],
                                      mesh.points[static_cast<std::size_t>(t[2])]);
    };
    std::int32_t best = start;
    ClosestPoint bestPoint = closestOn(start);
    for (int walk = 0; walk < 16; ++walk) {
        const std::int32_t current = best;
        for (auto v : mesh.triangles[static_cast<std::size_t>(current)]) {
            for (std::uint32_t i = adj.fanStart[static_cast<std::size_t>(v)];
                 i < adj.fanStart[static_cast<std::size_t>(v) + 1]; ++i) {
                const std::int32_t f = adj.fan[i];
                if (f == current)
                    continue;
                const ClosestPoint cp = closestOn(f);
                if (cp.distance2 < bestPoint.distance2 || (cp.distance2 == bestPoint.distance2 && f < best)) {
                    bestPoint = cp;
                    best = f;
                }
            }
        }
        if (best == current)
            break;
    }
    projected = bestPoint.point;
    return best;
}

Result<Particles> seedParticles(const SeedingInput& in, Progress& progress) {
    Particles ps;
    AcceptedIndex index(in.voxels->region);
    const Rng base(in.params->seed);
    for (std::size_t s = 0; s < in.body->surfaces.size(); ++s)
        seedFeatures(in, s, ps, index);
    if (progress.cancelled())
        return fail(ErrorCode::Cancelled, "meshing cancelled while seeding particles");
    for (std::size_t s = 0; s < in.body->surfaces.size(); ++s) {
        seedSurface(in, s, base, ps, index);
        if (progress.cancelled())
            return fail(ErrorCode::Cancelled, "meshing cancelled while seeding particles");
    }
    progress.report("meshing.seed", 0.5);
    seedInner(in, base, ps, index);
    if (progress.cancelled())
        return fail(ErrorCode::Cancelled, "meshing cancelled while seeding particles");
    if (ps.size() > static_cast<std::size_t>(kMaxVertices))
        return fail(ErrorCode::LimitExceeded, std::to_string(ps.size()) + " particles exceed the limit of " +
                                                  std::to_string(kMaxVertices) + " vertices");
    progress.report("meshing.seed", 1.0);
    return ps;
}

Result<RelaxationStats> relaxParticles(Particles& ps, const RegionModel& body, const VoxelSpace& voxels,
                                       const std::vector<SurfaceAdjacency>& adjacency, double r0, int iterations,
                                       int threads, Progress& progress) {
    RelaxationStats stats;
    const std::size_t n = ps.size();
    const double cutoff = kInteractionCutoff * r0;
    const double invR02 = 1.0 / (r0 * r0);
    const ProfileTable& table = profile();
    const auto& grid = voxels.region;
    Bounds box;
    for (const Vec3& p : ps.position)
        box.add(p);
    NeighbourGrid neighbours;
    std::vector<Vec3> next(n);
    std::vector<std::int32_t> nextTriangle(ps.triangle);
    const std::size_t chunks = chunkCount(n, kParticleChunk);
    std::vector<double> chunkEnergy(chunks), chunkMove(chunks);
    double motility = kInitialMotility;

    for (int it = 0; it < iterations; ++it) {
        if (progress.cancelled())
            return fail(ErrorCode::Cancelled, "meshing cancelled while relaxing particles");
        neighbours.build(ps.position, box, cutoff);
        const double stepScale = motility * r0;
        const double maxStep = kMaxStep * r0;
        parallelChunks(n, kParticleChunk, threads, [&](std::size_t c, std::size_t begin, std::size_t end) {
            double energy = 0.0, maxMove = 0.0;
            for (std::size_t i = begin; i < end; ++i) {
                const Vec3 xi = ps.position[i];
                const std::int32_t si = ps.surface[i];
                const Vec3 normalI =
                    si >= 0
                        ? adjacency[static_cast<std::size_t>(si)].faceNormals[static_cast<std::size_t>(ps.triangle[i])]
                        : Vec3{};
                Vec3 force;
                std::int64_t cc[3];
                for (int q = 0; q < 3; ++q)
                    cc[q] = neighbours.coord(xi, q);
                for (std::int64_t k = std::max<std::int64_t>(cc[2] - 1, 0);
                     k <= std::min(cc[2] + 1, neighbours.dims[2] - 1); ++k)
                    for (std::int64_t j = std::max<std::int64_t>(cc[1] - 1, 0);
                         j <= std::min(cc[1] + 1, neighbours.dims[1] - 1); ++j) {
                        const std::int64_t row = (k * neighbours.dims[1] + j) * neighbours.dims[0];
                        const auto b =
                            neighbours.start[static_cast<std::size_t>(row + std::max<std::int64_t>(cc[0] - 1, 0))];
                        const auto e =
                            neighbours
                                .start[static_cast<std::size_t>(row + std::min(cc[0] + 1, neighbours.dims[0] - 1)) + 1];
                        for (std::uint32_t m = b; m < e; ++m) {
                            const std::uint32_t jdx = neighbours.items[m];
                            // Boundary particles of two different sheets do not interact: across a layer or slit
                            // thinner than one edge they would thin each other out (see kCrossSurfaceRadius).
                            if (jdx == i ||
                                (si >= 0 && ps.surface[jdx] >= 0 && !sameSheet(ps, adjacency, jdx, si, normalI)))
                                continue;
                            const Vec3 dx = xi - ps.position[jdx];
                            const double d2 = norm2(dx) * invR02;
                            if (d2 >= kInteractionCutoff * kInteractionCutoff)
                                continue;
                            double fOverD = 0.0, e2 = 0.0;
                            table.lookup(d2, fOverD, e2);
                            force += dx * (fOverD / r0);
                            energy += 0.5 * e2;
                        }
                    }
                Vec3 moved = xi;
                const ParticleKind kind = ps.kind[i];
                if (kind == ParticleKind::Inner || kind == ParticleKind::Surface) {
                    if (kind == ParticleKind::Surface) {
                        const Vec3& nrm = adjacency[static_cast<std::size_t>(ps.surface[i])]
                                              .faceNormals[static_cast<std::size_t>(ps.triangle[i])];
                        force -= nrm * dot(force, nrm);
                    }
                    Vec3 step = force * stepScale;
                    const double len = norm(step);
                    if (len > maxStep)
                        step *= maxStep / len;
                    if (kind == ParticleKind::Inner) {
                        // Inner particles stay inside the inner voxels of their region (halving the step once).
                        for (int attempt = 0; attempt < 2; ++attempt) {
                            const Vec3 candidate = xi + step;
                            const Index3 v = grid.voxelOf(candidate);
                            if (grid.contains(v) && grid.at(v) == ps.region[i]) {
                                moved = candidate;
                                break;
                            }
                            step *= 0.5;
                        }
                    } else {
                        const auto s = static_cast<std::size_t>(ps.surface[i]);
                        nextTriangle[i] =
                            projectByWalk(body.surfaces[s].surface, adjacency[s], ps.triangle[i], xi + step, moved);
                    }
                }
                next[i] = moved;
                maxMove = std::max(maxMove, norm2(moved - xi));
            }
            chunkEnergy[c] = energy;
            chunkMove[c] = maxMove;
        });
        double energy = 0.0, maxMove = 0.0;
        for (std::size_t c = 0; c < chunks; ++c) {
            energy += chunkEnergy[c];
            maxMove = std::max(maxMove, chunkMove[c]);
        }
        stats.energy.push_back(energy);
        ps.position.swap(next);
        ps.triangle = nextTriangle;
        stats.iterations = it + 1;
        stats.lastMaxMove = std::sqrt(maxMove);
        motility *= kMotilityDecay;
        progress.report("meshing.relax", double(it + 1) / double(std::max(iterations, 1)));
        if (stats.lastMaxMove < kConvergedMove * r0)
            break;
    }
    return stats;
}

} // namespace hs::meshing::detail
