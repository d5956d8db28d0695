// Seeding: corner, feature, surface and inner particles, thinned by priority (Sierra et al. 2004, sec. 2.2).
#include "Particles.h"

#include "MesherSteps.h"

#include "hs/core/Rng.h"
#include "hs/core/Streams.h"
#include "hs/meshing/Geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace hs::meshing::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Seeding radii, in target edge lengths: a candidate closer than this to an accepted particle is dropped.
constexpr double kCornerRadius = 0.2;      ///< corners against the corners of their own surface
constexpr double kFeatureRadius = 0.8;     ///< features against corners and features
constexpr double kSurfaceRadius = 0.75;    ///< surface candidates against accepted particles of their own sheet
constexpr double kInnerRadius = 0.6;       ///< inner candidates against surface, feature and corner particles
constexpr double kRandomInnerRadius = 0.5; ///< Seeding::Random: inner candidates against everything
constexpr int kSurfaceCandidatesPerVoxel = 3;

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
    // Corners: feature vertices that are not in the middle of a single feature line, thinned against the surface's
    // corners accepted before them (in vertex order). Where a merge leaves a seam of tiny triangles (edges of
    // 0.002-0.1 mm where a polyp's stalk or a myoma meets the wall), every kink among them is a corner; corners are
    // never moved, so tets between two of them 0.02 mm apart stayed slivers whatever the improvement did.
    for (std::size_t v = 0; v < mesh.points.size(); ++v) {
        if (degree[v] != 1 && degree[v] < 3)
            continue;
        const bool nearCorner =
            index.anyWithin(ps, mesh.points[v], kCornerRadius * in.edge, [&](std::size_t u, double) {
                return ps.kind[u] == ParticleKind::Corner && ps.surface[u] == si;
            });
        if (!nearCorner)
            index.add(ps, mesh.points[v], ParticleKind::Corner, si, adj.fan[adj.fanStart[v]], -1);
    }
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
        Rng rng = base.derive((static_cast<std::uint64_t>(s) << 40) ^ v); // hs/core/Streams.h
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
    const double clearance2 = kSurfaceVoxelClearance * in.edge * kSurfaceVoxelClearance * in.edge;
    // Where on its lattice point a surface voxel is inside the body, clear of the surfaces: the region there.
    auto surfaceVoxelRegion = [&](const Vec3& p) {
        const std::int32_t r = in.locator->regionAt(p);
        if (r < 0)
            return r;
        for (std::size_t s = 0; s < in.body->surfaces.size(); ++s)
            if (in.locator->surfaceGrid(s).closestWithin(p, clearance2).triangle >= 0)
                return std::int32_t(VoxelSpace::kOutside);
        return r;
    };
    for (std::size_t v = 0; v < grid.size(); ++v) {
        const std::int32_t voxelRegion = grid[v];
        const bool surfaceVoxel = voxelRegion == VoxelSpace::kSurface && lattice && in.locator;
        if (voxelRegion < 0 && !surfaceVoxel)
            continue;
        Rng rng = base.derive(streams::kMeshingSeedingInner ^ v);
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
            if (tooClose)
                continue;
            const std::int32_t region = surfaceVoxel ? surfaceVoxelRegion(p) : voxelRegion;
            if (region >= 0)
                index.add(ps, p, ParticleKind::Inner, -1, -1, region);
        }
    }
}

} // namespace

Result<Particles> seedParticles(const SeedingInput& in, Progress& progress) {
    Particles ps;
    AcceptedIndex index(in.voxels->region);
    const Rng base(in.params->seed);
    for (std::size_t s = 0; s < in.body->surfaces.size(); ++s)
        seedFeatures(in, s, ps, index);
    HS_TRY(progress.check("meshing", "seeding particles"));
    for (std::size_t s = 0; s < in.body->surfaces.size(); ++s) {
        seedSurface(in, s, base, ps, index);
        HS_TRY(progress.check("meshing", "seeding particles"));
    }
    progress.report("meshing.seed", 0.5);
    seedInner(in, base, ps, index);
    HS_TRY(progress.check("meshing", "seeding particles"));
    if (ps.size() > static_cast<std::size_t>(kMaxVertices))
        return fail(ErrorCode::LimitExceeded, std::to_string(ps.size()) + " particles exceed the limit of " +
                                                  std::to_string(kMaxVertices) + " vertices");
    progress.report("meshing.seed", 1.0);
    return ps;
}

} // namespace hs::meshing::detail
