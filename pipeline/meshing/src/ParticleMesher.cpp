#include "hs/meshing/ParticleMesher.h"

#include "Delaunay.h"
#include "InterfaceVolume.h"
#include "MeshImprove.h"
#include "Parallel.h"
#include "Particles.h"
#include "Pinches.h"
#include "TriangleGrid.h"
#include "hs/core/Rng.h"
#include "hs/meshing/Geometry.h"
#include "hs/meshing/VoxelSpace.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <unordered_map>

namespace hs::meshing {
namespace {

/// Voxel (lattice) size per target edge length: the body-centred cubic lattice of cube a has edges of 0.866 a and
/// a, mean 0.91 a, so a = 1.1 edge gives the asked mean edge length.
constexpr double kVoxelPerEdge = 1.1;
/// Rest distance of the interaction profile per target edge length.
constexpr double kRestPerEdge = 1.0;
/// Boundary tets flatter than this (smallest dihedral, degrees) whose four vertices lie on the boundary are peeled.
constexpr double kPeelDihedralDeg = 15.0;
constexpr std::size_t kTetChunk = 8192;
/// Kept tets with a smaller dihedral angle (degrees) get their vertices moved (the quality bar is 15).
constexpr double kRepairDihedralDeg = 15.0;
/// Passes of the in-triangulation repair. One pass removes most slivers cheaply; the extracted mesh is improved
/// afterwards (improveTets), which fixes the rest faster than further passes (each pass costs about 0.4 s at 50k
/// vertices on liver.off and the later passes hardly help).
constexpr int kRepairRounds = 1;
/// Trial displacement of the sliver repair, per target edge length.
constexpr double kRepairStepPerEdge = 0.2;
/// Tets with a smaller dihedral angle (degrees) are improved after extraction: above the bar of 15 with margin.
constexpr double kImproveDihedralDeg = 17.0;
/// Passes of interface recovery (new interface particles, new triangulation) for multi-region bodies.
constexpr int kInterfacePasses = 3;

/// The region of a point: the id of the innermost surface containing it (kOutside outside the body or in a void).
class RegionLocator {
public:
    RegionLocator(const RegionModel& body, const VoxelSpace& voxels) : m_body(body), m_voxels(voxels) {
        for (const auto& rs : body.surfaces)
            m_grids.push_back(std::make_unique<detail::TriangleGrid>(rs.surface, voxels.region.spacing()));
    }
    std::int32_t regionAt(const Vec3& p) const {
        const auto& grid = m_voxels.region;
        const Index3 v = grid.voxelOf(p);
        if (!grid.contains(v))
            return VoxelSpace::kOutside;
        const std::int32_t r = grid.at(v);
        if (r != VoxelSpace::kSurface)
            return r;
        const std::size_t lin = grid.linear(v);
        std::int32_t region = VoxelSpace::kOutside;
        for (std::size_t s = 0; s < m_body.surfaces.size(); ++s) {
            const VoxelLabel l = m_voxels.surfaces[s].labels[lin];
            const bool inside = l == VoxelLabel::Inner || (l == VoxelLabel::Surface && m_grids[s]->inside(p));
            if (inside)
                region = m_body.surfaces[s].regionId == RegionModel::kVoidRegion ? VoxelSpace::kOutside
                                                                                 : m_body.surfaces[s].regionId;
        }
        return region;
    }

    const detail::TriangleGrid& surfaceGrid(std::size_t s) const { return *m_grids[s]; }

private:
    const RegionModel& m_body;
    const VoxelSpace& m_voxels;
    std::vector<std::unique_ptr<detail::TriangleGrid>> m_grids;
};

/// Copy of the body with every surface oriented outward (positive enclosed volume).
RegionModel orientedOutward(const RegionModel& body, std::vector<std::string>& warnings) {
    RegionModel out = body;
    for (auto& rs : out.surfaces) {
        if (enclosedVolume(rs.surface) < 0.0) {
            for (auto& t : rs.surface.triangles)
                std::swap(t[1], t[2]);
            warnings.push_back("surface '" + rs.name + "' was oriented inward; flipped");
        }
    }
    return out;
}

/// Removes flat tets at the boundary whose four vertices are boundary particles: they are the caps and slivers a
/// Delaunay tetrahedralization leaves on a curved surface; taking them away only flips a surface diagonal.
/// `region` is per Delaunay tet (negative: not in the mesh); peeled tets get kOutside. Only caps on the outline or
/// a void surface (all four vertices on that one surface) exposed to the outside are peeled: in a layer between two
/// nested surfaces thinner than one edge (a 0.8 mm cover over a pathology) every tet has four boundary particles and
/// is flat, and peeling would open the layer and then eat the pathology's own caps behind it.
std::size_t peelBoundarySlivers(const RegionModel& body, const std::vector<Vec3>& points, const detail::Particles& ps,
                                const detail::DelaunayOutput& dt, std::vector<std::int32_t>& region) {
    const std::size_t n = dt.tets.size();
    auto onBoundary = [&](std::int32_t v) {
        return ps.kind[static_cast<std::size_t>(v)] != detail::ParticleKind::Inner;
    };
    auto onePeelableSurface = [&](const Tet& tet) {
        const std::int32_t s = ps.surface[static_cast<std::size_t>(tet[0])];
        for (std::size_t i = 1; i < 4; ++i)
            if (ps.surface[static_cast<std::size_t>(tet[i])] != s)
                return false;
        return s == 0 || body.surfaces[static_cast<std::size_t>(s)].regionId == RegionModel::kVoidRegion;
    };
    auto peelable = [&](std::size_t t) {
        const Tet& tet = dt.tets[t];
        if (region[t] < 0 || !std::all_of(tet.begin(), tet.end(), onBoundary) || !onePeelableSurface(tet))
            return false;
        bool exposed = false;
        for (std::size_t f = 0; f < 4 && !exposed; ++f) {
            const std::int64_t nb = dt.neighbours[t][f];
            exposed = nb < 0 || region[static_cast<std::size_t>(nb)] < 0;
        }
        if (!exposed)
            return false;
        const TetShape s = tetShape(points[static_cast<std::size_t>(tet[0])], points[static_cast<std::size_t>(tet[1])],
                                    points[static_cast<std::size_t>(tet[2])], points[static_cast<std::size_t>(tet[3])]);
        return s.minDihedral < kPeelDihedralDeg;
    };
    std::vector<std::size_t> queue;
    for (std::size_t t = 0; t < n; ++t)
        if (peelable(t))
            queue.push_back(t);
    std::size_t count = 0;
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const std::size_t t = queue[head];
        if (!peelable(t))
            continue;
        region[t] = VoxelSpace::kOutside;
        ++count;
        for (std::size_t f = 0; f < 4; ++f) {
            const std::int64_t nb = dt.neighbours[t][f];
            if (nb >= 0 && peelable(static_cast<std::size_t>(nb)))
                queue.push_back(static_cast<std::size_t>(nb));
        }
    }
    return count;
}

/// The region of every tet by its centroid (negative: outside the body or in a void).
std::vector<std::int32_t> classifyTets(const std::vector<Vec3>& points, const RegionLocator& locator, int threads,
                                       const std::vector<Tet>& tets) {
    std::vector<std::int32_t> region(tets.size());
    detail::parallelChunks(tets.size(), kTetChunk, threads, [&](std::size_t, std::size_t b, std::size_t e) {
        for (std::size_t t = b; t < e; ++t) {
            const Tet& tet = tets[t];
            const Vec3 c = (points[static_cast<std::size_t>(tet[0])] + points[static_cast<std::size_t>(tet[1])] +
                            points[static_cast<std::size_t>(tet[2])] + points[static_cast<std::size_t>(tet[3])]) *
                           0.25;
            region[t] = locator.regionAt(c);
        }
    });
    return region;
}

/// Tets whose four vertices are boundary particles of a surface and of the surface it is directly nested in lie in
/// the layer between the two, i.e. in the outer surface's region. Their centroid says otherwise where the layer is
/// thinner than one edge: between the chords of the outer surface and the caps of the inner one the centroid can
/// fall inside the inner surface, and the tet then joins the pathology although it touches the outline. Tets the
/// centroid puts outside the body stay outside (a Delaunay tet may bridge a crease of the outline).
std::size_t classifyLayerTets(const RegionModel& body, const std::vector<std::int32_t>& parent,
                              const detail::Particles& ps, const std::vector<Tet>& tets,
                              std::vector<std::int32_t>& region) {
    if (body.surfaces.size() < 2)
        return 0;
    std::size_t changed = 0;
    for (std::size_t t = 0; t < tets.size(); ++t) {
        if (region[t] < 0)
            continue;
        std::int32_t lo = std::numeric_limits<std::int32_t>::max(), hi = -1;
        bool boundaryOnly = true;
        for (auto v : tets[t]) {
            const auto i = static_cast<std::size_t>(v);
            boundaryOnly = boundaryOnly && ps.kind[i] != detail::ParticleKind::Inner;
            lo = std::min(lo, ps.surface[i]);
            hi = std::max(hi, ps.surface[i]);
        }
        if (!boundaryOnly || lo == hi || parent[static_cast<std::size_t>(hi)] != lo)
            continue;
        bool twoSurfaces = true;
        for (auto v : tets[t])
            twoSurfaces = twoSurfaces && (ps.surface[static_cast<std::size_t>(v)] == lo ||
                                          ps.surface[static_cast<std::size_t>(v)] == hi);
        const std::int32_t layer = body.surfaces[static_cast<std::size_t>(lo)].regionId;
        if (!twoSurfaces || layer == RegionModel::kVoidRegion || region[t] == layer)
            continue;
        region[t] = layer;
        ++changed;
    }
    return changed;
}

/// Tets whose inner particles lie in different regions, or that join an inner particle to a surface that does not
/// bound its region, cross an interface (Delaunay did not recover it there):
/// adds an interface particle where the segment between two such particles meets the nearest nested surface, unless
/// a particle is already close. Returns how many were added; the caller tetrahedralizes again.
std::size_t addInterfaceParticles(const detail::DelaunayOutput& dt, const RegionModel& body,
                                  const RegionLocator& locator, const VoxelSpace& voxels, double edge,
                                  detail::Particles& ps) {
    if (body.surfaces.size() < 2)
        return 0;
    const std::vector<std::int32_t> parent = detail::parentSurfaces(body);
    // An inner particle of region r and a particle on surface s: the edge crosses an interface unless s bounds r
    // (s is r's surface or nested directly in it). In a layer thinner than one edge Delaunay joins the outline's
    // particles to the pathology's inner particles through the pathology's surface.
    auto bounds = [&](std::int32_t r, std::int32_t s) {
        const auto su = static_cast<std::size_t>(s);
        return body.surfaces[su].regionId == r ||
               (parent[su] >= 0 && body.surfaces[static_cast<std::size_t>(parent[su])].regionId == r);
    };
    auto crosses = [&](std::uint32_t a, std::uint32_t b) {
        const bool innerA = ps.kind[a] == detail::ParticleKind::Inner,
                   innerB = ps.kind[b] == detail::ParticleKind::Inner;
        if (innerA && innerB)
            return ps.region[a] != ps.region[b];
        if (innerA != innerB)
            return innerA ? !bounds(ps.region[a], ps.surface[b]) : !bounds(ps.region[b], ps.surface[a]);
        return false;
    };
    std::vector<std::pair<std::uint32_t, std::uint32_t>> crossing;
    for (const Tet& t : dt.tets)
        for (std::size_t i = 0; i < 4; ++i)
            for (std::size_t j = i + 1; j < 4; ++j) {
                const auto a = static_cast<std::uint32_t>(t[i]), b = static_cast<std::uint32_t>(t[j]);
                if (crosses(a, b))
                    crossing.emplace_back(std::min(a, b), std::max(a, b));
            }
    std::sort(crossing.begin(), crossing.end());
    crossing.erase(std::unique(crossing.begin(), crossing.end()), crossing.end());
    // Particles hashed by voxel for the "already close" test.
    const auto& grid = voxels.region;
    std::vector<std::int32_t> head(grid.size(), -1), next(ps.size(), -1);
    auto insert = [&](std::size_t i) {
        const Index3 v = grid.voxelOf(ps.position[i]);
        if (!grid.contains(v))
            return;
        next.resize(std::max(next.size(), i + 1), -1);
        next[i] = head[grid.linear(v)];
        head[grid.linear(v)] = static_cast<std::int32_t>(i);
    };
    for (std::size_t i = 0; i < ps.size(); ++i)
        insert(i);
    const double r2 = (0.35 * edge) * (0.35 * edge);
    auto occupied = [&](const Vec3& p) {
        const Index3 c = grid.voxelOf(p);
        for (std::int64_t dk = -1; dk <= 1; ++dk)
            for (std::int64_t dj = -1; dj <= 1; ++dj)
                for (std::int64_t di = -1; di <= 1; ++di) {
                    const Index3 nb{c[0] + di, c[1] + dj, c[2] + dk};
                    if (!grid.contains(nb))
                        continue;
                    for (std::int32_t i = head[grid.linear(nb)]; i >= 0; i = next[static_cast<std::size_t>(i)])
                        if (norm2(ps.position[static_cast<std::size_t>(i)] - p) < r2)
                            return true;
                }
        return false;
    };
    std::size_t added = 0;
    for (const auto& [a, b] : crossing) {
        const Vec3 mid = (ps.position[a] + ps.position[b]) * 0.5;
        detail::SurfaceHit best;
        std::size_t bestSurface = 0;
        double bestD = 1e300;
        for (std::size_t s = 1; s < body.surfaces.size(); ++s) {
            const detail::SurfaceHit hit = locator.surfaceGrid(s).closestWithin(mid, bestD);
            if (hit.triangle >= 0 && hit.closest.distance2 < bestD) {
                bestD = hit.closest.distance2;
                best = hit;
                bestSurface = s;
            }
        }
        if (best.triangle < 0 || occupied(best.closest.point))
            continue;
        ps.add(best.closest.point, detail::ParticleKind::Surface, static_cast<std::int32_t>(bestSurface), best.triangle,
               -1);
        insert(ps.size() - 1);
        ++added;
    }
    return added;
}

/// The same tet by an even permutation (orientation kept): smallest index first, then the smallest of the rest.
Tet canonicalTet(const Tet& t) {
    static constexpr int kToFront[4][4] = {{0, 1, 2, 3}, {1, 0, 3, 2}, {2, 3, 0, 1}, {3, 2, 1, 0}};
    const auto k = static_cast<std::size_t>(std::min_element(t.begin(), t.end()) - t.begin());
    Tet m{};
    for (std::size_t i = 0; i < 4; ++i)
        m[i] = t[static_cast<std::size_t>(kToFront[k][i])];
    // Rotating the last three cyclically is even too.
    while (m[1] > m[2] || m[1] > m[3])
        m = {m[0], m[2], m[3], m[1]};
    return m;
}

/// The input feature edge a feature particle lies on: the edge of its triangle closest to it.
std::array<Vec3, 2> featureSegment(const SurfaceMesh& mesh, std::int32_t triangle, const Vec3& p) {
    const Triangle& t = mesh.triangles[static_cast<std::size_t>(triangle)];
    std::array<Vec3, 2> best{};
    double bestD = 1e300;
    for (std::size_t k = 0; k < 3; ++k) {
        const Vec3& a = mesh.points[static_cast<std::size_t>(t[k])];
        const Vec3& b = mesh.points[static_cast<std::size_t>(t[(k + 1) % 3])];
        const double len2 = norm2(b - a);
        const double s = len2 > 0.0 ? std::clamp(dot(p - a, b - a) / len2, 0.0, 1.0) : 0.0;
        const double d = norm2(a + (b - a) * s - p);
        if (d < bestD) {
            bestD = d;
            best = {a, b};
        }
    }
    return best;
}

/// Where each particle may go during mesh improvement: inner particles anywhere, surface and interface particles
/// along their surface, feature particles along their feature edge, corners nowhere.
class ParticleConstraints {
public:
    ParticleConstraints(const RegionModel& body, const std::vector<detail::SurfaceAdjacency>& adjacency,
                        detail::Particles& ps)
        : m_body(body), m_adjacency(adjacency), m_ps(ps), m_freedom(ps.size(), detail::VertexFreedom::Fixed) {
        for (std::size_t i = 0; i < ps.size(); ++i) {
            switch (ps.kind[i]) {
            case detail::ParticleKind::Inner:
                m_freedom[i] = detail::VertexFreedom::Free;
                break;
            case detail::ParticleKind::Surface:
                m_freedom[i] = detail::VertexFreedom::Surface;
                break;
            case detail::ParticleKind::Feature:
                m_freedom[i] = detail::VertexFreedom::Feature;
                m_segments[static_cast<std::uint32_t>(i)] = featureSegment(surface(i), ps.triangle[i], ps.position[i]);
                break;
            case detail::ParticleKind::Corner:
                break;
            }
        }
    }

    const std::vector<detail::VertexFreedom>& freedom() const { return m_freedom; }

    detail::MeshImproveCallbacks callbacks() {
        detail::MeshImproveCallbacks cb;
        cb.project = [this](std::uint32_t v, const Vec3& candidate) {
            if (m_ps.kind[v] == detail::ParticleKind::Feature) {
                const auto& [a, b] = m_segments.at(v);
                return a + (b - a) * std::clamp(dot(candidate - a, b - a) / norm2(b - a), 0.0, 1.0);
            }
            Vec3 projected;
            detail::projectByWalk(surface(v), adjacency(v), m_ps.triangle[v], candidate, projected);
            return projected;
        };
        cb.constraintAxis = [this](std::uint32_t v) {
            if (m_ps.kind[v] == detail::ParticleKind::Feature) {
                const auto& [a, b] = m_segments.at(v);
                return normalized(b - a);
            }
            return adjacency(v).faceNormals[static_cast<std::size_t>(m_ps.triangle[v])];
        };
        cb.moved = [this](std::uint32_t v, const Vec3& position) {
            if (m_ps.kind[v] != detail::ParticleKind::Surface)
                return;
            Vec3 projected;
            m_ps.triangle[v] = detail::projectByWalk(surface(v), adjacency(v), m_ps.triangle[v], position, projected);
        };
        return cb;
    }

private:
    const SurfaceMesh& surface(std::size_t i) const {
        return m_body.surfaces[static_cast<std::size_t>(m_ps.surface[i])].surface;
    }
    const detail::SurfaceAdjacency& adjacency(std::size_t i) const {
        return m_adjacency[static_cast<std::size_t>(m_ps.surface[i])];
    }

    const RegionModel& m_body;
    const std::vector<detail::SurfaceAdjacency>& m_adjacency;
    detail::Particles& m_ps;
    std::vector<detail::VertexFreedom> m_freedom;
    std::unordered_map<std::uint32_t, std::array<Vec3, 2>> m_segments; ///< feature particle -> its input edge
};

/// Improves the kept tets (flips, boundary flips, smoothing; see MeshImprove.h) with every particle on its
/// constraint. Replaces `tets` and `region` by the kept, improved tets.
Result<detail::MeshImproveStats> improveTets(const RegionModel& body,
                                             const std::vector<detail::SurfaceAdjacency>& adjacency,
                                             detail::Particles& ps, std::vector<Tet>& tets,
                                             std::vector<std::int32_t>& region, Progress& progress) {
    // In canonical order: the improvement is sequential and its result depends on the order of the tets, which
    // CGAL's cell storage does not fix.
    std::vector<std::pair<Tet, std::int32_t>> sorted;
    for (std::size_t t = 0; t < tets.size(); ++t)
        if (region[t] >= 0)
            sorted.emplace_back(canonicalTet(tets[t]), region[t]);
    std::sort(sorted.begin(), sorted.end());
    tets.clear();
    region.clear();
    for (const auto& [t, r] : sorted) {
        tets.push_back(t);
        region.push_back(r);
    }
    ParticleConstraints constraints(body, adjacency, ps);
    detail::MeshImproveParams params;
    params.targetDihedralDeg = kImproveDihedralDeg;
    return detail::improveMesh(ps.position, tets, region, constraints.freedom(), params, constraints.callbacks(),
                               progress);
}

void recordImprovement(const detail::MeshImproveStats& stats, StepTiming& step) {
    auto& counts = step.counts;
    counts.emplace_back("badBefore", static_cast<std::int64_t>(stats.badBefore));
    counts.emplace_back("badAfter", static_cast<std::int64_t>(stats.badAfter));
    counts.emplace_back("edgeRemovals", static_cast<std::int64_t>(stats.edgeRemovals));
    counts.emplace_back("faceFlips", static_cast<std::int64_t>(stats.faceFlips));
    counts.emplace_back("boundaryFlips", static_cast<std::int64_t>(stats.boundaryFlips));
    counts.emplace_back("smoothedVertices", static_cast<std::int64_t>(stats.smoothedVertices));
    counts.emplace_back("contractions", static_cast<std::int64_t>(stats.contractions));
    counts.emplace_back("passes", stats.passes);
    counts.emplace_back("minDihedralBeforeMilliDeg", std::lround(stats.minDihedralBefore * 1000.0));
    counts.emplace_back("minDihedralAfterMilliDeg", std::lround(stats.minDihedralAfter * 1000.0));
}

/// The final mesh: only referenced points (in particle order), tets rotated to start at their smallest index
/// (orientation kept) and sorted: a canonical form, whatever order the triangulation produced them in.
TetMesh assemble(const detail::Particles& ps, const std::vector<Tet>& tets, const std::vector<std::int32_t>& regions) {
    // `regions` is per tet; negative ones are not part of the mesh.
    TetMesh mesh;
    std::vector<std::int32_t> newIndex(ps.size(), -1);
    for (std::size_t t = 0; t < tets.size(); ++t)
        if (regions[t] >= 0)
            for (auto v : tets[t])
                newIndex[static_cast<std::size_t>(v)] = 0;
    std::vector<std::int32_t>& kind = mesh.pointLabels["particleKind"];
    for (std::size_t i = 0; i < ps.size(); ++i)
        if (newIndex[i] == 0) {
            newIndex[i] = static_cast<std::int32_t>(mesh.points.size());
            mesh.points.push_back(ps.position[i]);
            kind.push_back(static_cast<std::int32_t>(ps.kind[i]));
        }
    std::vector<std::pair<Tet, std::int32_t>> sorted;
    sorted.reserve(tets.size());
    for (std::size_t t = 0; t < tets.size(); ++t) {
        if (regions[t] < 0)
            continue;
        Tet m{newIndex[static_cast<std::size_t>(tets[t][0])], newIndex[static_cast<std::size_t>(tets[t][1])],
              newIndex[static_cast<std::size_t>(tets[t][2])], newIndex[static_cast<std::size_t>(tets[t][3])]};
        sorted.emplace_back(canonicalTet(m), regions[t]);
    }
    std::sort(sorted.begin(), sorted.end());
    mesh.tets.reserve(sorted.size());
    mesh.regions.reserve(sorted.size());
    for (const auto& [t, r] : sorted) {
        mesh.tets.push_back(t);
        mesh.regions.push_back(r);
    }
    return mesh;
}

} // namespace

Result<ParticleMeshResult> meshParticles(const RegionModel& input, const ParticleMeshParams& params,
                                         Progress& progress) {
    ParticleMeshResult result;
    StageTimings& timings = result.timings;
    const int threads = detail::resolveThreads(params.threads);
    if (params.relaxationIterations < 0 || params.relaxationIterations > 10000)
        return fail(ErrorCode::InvalidInput, "relaxation iterations must be in 0..10000");
    if (!(params.featureAngleDeg > 0.0 && params.featureAngleDeg <= 180.0))
        return fail(ErrorCode::InvalidInput, "feature angle must be in (0, 180] degrees");
    if (params.particlesPerVoxel < 1 || params.particlesPerVoxel > 16)
        return fail(ErrorCode::InvalidInput, "particles per voxel must be in 1..16");

    RegionModel body;
    {
        ScopedStepTimer timer(timings, "validate");
        HS_TRY(validate(input));
        body = orientedOutward(input, result.warnings);
    }
    auto edge = resolveEdgeLength(body, params);
    if (!edge.ok())
        return edge.failure();
    result.targetEdgeLength = *edge;
    if (progress.cancelled())
        return fail(ErrorCode::Cancelled, "meshing cancelled");

    VoxelSpace voxels;
    {
        ScopedStepTimer timer(timings, "voxelize");
        auto sub = progress.sub(0.0, 0.1);
        auto built = buildVoxelSpace(body, kVoxelPerEdge * *edge, threads, sub);
        if (!built.ok())
            return built.failure();
        voxels = std::move(built.value());
        timings.step("voxelize").counts.emplace_back("voxels", static_cast<std::int64_t>(voxels.region.size()));
    }

    std::vector<detail::SurfaceAdjacency> adjacency;
    detail::Particles particles;
    {
        ScopedStepTimer timer(timings, "seed");
        for (const auto& rs : body.surfaces)
            adjacency.push_back(detail::buildAdjacency(rs.surface));
        detail::SeedingInput in;
        in.body = &body;
        in.voxels = &voxels;
        in.adjacency = &adjacency;
        in.edge = *edge;
        in.params = &params;
        auto sub = progress.sub(0.1, 0.15);
        auto seeded = detail::seedParticles(in, sub);
        if (!seeded.ok())
            return seeded.failure();
        particles = std::move(seeded.value());
        timings.step("seed").counts.emplace_back("particles", static_cast<std::int64_t>(particles.size()));
    }
    if (particles.size() < 4)
        return fail(ErrorCode::InvalidInput, "the target edge length " + std::to_string(*edge) +
                                                 " mm is too large for this body: fewer than 4 particles");

    {
        ScopedStepTimer timer(timings, "relax");
        auto sub = progress.sub(0.15, 0.6);
        auto stats = detail::relaxParticles(particles, body, voxels, adjacency, kRestPerEdge * *edge,
                                            params.relaxationIterations, threads, sub);
        if (!stats.ok())
            return stats.failure();
        result.relaxationEnergy = stats->energy;
        timings.step("relax").counts.emplace_back("iterations", stats->iterations);
    }

    const RegionLocator locator(body, voxels);
    detail::DelaunayOutput dt;
    std::int64_t interfaceParticles = 0;
    for (int pass = 0;; ++pass) {
        ScopedStepTimer timer(timings, "tetrahedralize");
        if (progress.cancelled())
            return fail(ErrorCode::Cancelled, "meshing cancelled");
        detail::SliverRepairParams repair;
        repair.minDihedralDeg = kRepairDihedralDeg;
        repair.step = kRepairStepPerEdge * *edge;
        repair.seed = Rng::deriveSeed(params.seed, 7);
        repair.rounds = kRepairRounds;
        detail::SliverRepairCallbacks callbacks;
        callbacks.kept = [&](const Vec3& c) { return locator.regionAt(c) >= 0; };
        callbacks.surelyKept = [&](const std::array<std::uint32_t, 4>& ids) {
            return std::any_of(ids.begin(), ids.end(),
                               [&](std::uint32_t i) { return particles.kind[i] == detail::ParticleKind::Inner; });
        };
        callbacks.constrain = [&](std::uint32_t i, Vec3& candidate) {
            switch (particles.kind[i]) {
            case detail::ParticleKind::Inner: {
                const Index3 v = voxels.region.voxelOf(candidate);
                return voxels.region.contains(v) && voxels.region.at(v) == particles.region[i];
            }
            case detail::ParticleKind::Surface: {
                const auto s = static_cast<std::size_t>(particles.surface[i]);
                Vec3 projected;
                detail::projectByWalk(body.surfaces[s].surface, adjacency[s], particles.triangle[i], candidate,
                                      projected);
                candidate = projected;
                return true;
            }
            default:
                return false; // feature and corner particles stay on their features
            }
        };
        auto sub = progress.sub(0.6, 0.9);
        auto built = detail::delaunayTetrahedra(particles.position, repair, callbacks, sub);
        if (!built.ok())
            return built.failure();
        dt = std::move(built.value());
        auto& step = timings.step("tetrahedralize");
        step.counts.emplace_back("delaunayTets", static_cast<std::int64_t>(dt.tets.size()));
        step.counts.emplace_back("repairedTets", static_cast<std::int64_t>(dt.repairedTets));
        step.counts.emplace_back("movedVertices", static_cast<std::int64_t>(dt.movedVertices));
        progress.report("meshing.tetrahedralize", 1.0);
        if (pass >= kInterfacePasses)
            break;
        const std::size_t added = addInterfaceParticles(dt, body, locator, voxels, *edge, particles);
        interfaceParticles += static_cast<std::int64_t>(added);
        if (added == 0)
            break;
    }
    timings.step("tetrahedralize").counts.emplace_back("interfaceParticles", interfaceParticles);
    if (progress.cancelled())
        return fail(ErrorCode::Cancelled, "meshing cancelled");

    std::vector<std::int32_t> region;
    {
        ScopedStepTimer timer(timings, "clean");
        region = classifyTets(particles.position, locator, threads, dt.tets);
        const std::size_t layerTets = classifyLayerTets(body, detail::parentSurfaces(body), particles, dt.tets, region);
        timings.step("clean").counts.emplace_back("layerTets", static_cast<std::int64_t>(layerTets));
        const std::size_t peeled = peelBoundarySlivers(body, particles.position, particles, dt, region);
        timings.step("clean").counts.emplace_back("peeled", static_cast<std::int64_t>(peeled));
    }
    std::vector<Tet> tets = std::move(dt.tets);
    {
        ScopedStepTimer timer(timings, "improve");
        auto sub = progress.sub(0.9, 0.95);
        auto improved = improveTets(body, adjacency, particles, tets, region, sub);
        if (!improved.ok())
            return improved.failure();
        recordImprovement(*improved, timings.step("improve"));
    }
    {
        ScopedStepTimer timer(timings, "interfaceVolume");
        const detail::InterfaceVolumeStats stats =
            detail::matchInterfaceVolumes(body, adjacency, particles, tets, region, kImproveDihedralDeg);
        auto& counts = timings.step("interfaceVolume").counts;
        counts.emplace_back("surfaces", static_cast<std::int64_t>(stats.surfaces));
        counts.emplace_back("movedVertices", static_cast<std::int64_t>(stats.movedVertices));
        counts.emplace_back("keptVertices", static_cast<std::int64_t>(stats.keptVertices));
        counts.emplace_back("largestOffsetMicrometres", std::lround(stats.largestOffset * 1000.0));
    }
    {
        // After the flips and the interface offsets, so that what the simulator gets has a manifold boundary.
        ScopedStepTimer timer(timings, "pinches");
        const detail::PinchStats stats = detail::openPinches(tets, region, body.surfaces.front().regionId);
        auto& counts = timings.step("pinches").counts;
        counts.emplace_back("pinches", static_cast<std::int64_t>(stats.pinchedBefore));
        counts.emplace_back("removedTets", static_cast<std::int64_t>(stats.removedTets));
        counts.emplace_back("pinchesLeft", static_cast<std::int64_t>(stats.pinchedAfter));
        if (stats.pinchedAfter > 0)
            result.warnings.push_back(
                std::to_string(stats.pinchedAfter) +
                " pinched boundary edges or vertices are left (two parts of the body touch there)");
    }
    {
        ScopedStepTimer timer(timings, "assemble");
        result.mesh = assemble(particles, tets, region);
    }
    if (result.mesh.tets.empty())
        return fail(ErrorCode::InvalidInput, "the mesh of this body is empty: the target edge length " +
                                                 std::to_string(*edge) + " mm is too large");
    {
        ScopedStepTimer timer(timings, "quality");
        result.quality = measureQuality(result.mesh, &input, threads);
    }
    progress.report("meshing.done", 1.0);
    return result;
}

} // namespace hs::meshing
