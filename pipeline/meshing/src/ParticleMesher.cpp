#include "hs/meshing/ParticleMesher.h"

#include "Delaunay.h"
#include "InterfaceVolume.h"
#include "MeshImprove.h"
#include "MesherSteps.h"
#include "Particles.h"
#include "Pinches.h"
#include "hs/core/Parallel.h"
#include "hs/core/Rng.h"
#include "hs/core/Streams.h"
#include "hs/core/TriangleGrid.h"
#include "hs/meshing/Geometry.h"
#include "hs/meshing/VoxelSpace.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <unordered_map>

namespace hs::meshing {
namespace detail {

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

} // namespace detail

namespace {
using namespace detail;

/// Voxel (lattice) size per target edge length: the body-centred cubic lattice of cube a has edges of 0.866 a and
/// a, mean 0.91 a, so a = 1.1 edge gives the asked mean edge length.
constexpr double kVoxelPerEdge = 1.1;
/// Rest distance of the interaction profile per target edge length.
constexpr double kRestPerEdge = 1.0;
/// Kept tets with a smaller dihedral angle (degrees) get their vertices moved (the quality bar is 15).
constexpr double kRepairDihedralDeg = 15.0;
/// Passes of the in-triangulation repair. One pass removes most slivers cheaply; the extracted mesh is improved
/// afterwards (improveTets), which fixes the rest faster than further passes (each pass costs about 0.4 s at 50k
/// vertices on liver.off and the later passes hardly help).
constexpr int kRepairRounds = 1;
/// Trial displacement of the sliver repair, per target edge length.
constexpr double kRepairStepPerEdge = 0.2;
/// Passes of interface recovery (new interface particles, new triangulation) for multi-region bodies.
constexpr int kInterfacePasses = 3;
/// Passes of surface fidelity (new surface particles where the boundary strays from the input, new triangulation),
/// after the interfaces are recovered, and how far the boundary may stray (per target edge length). A uniform edge
/// resolves neither a slit nor a cover thinner than itself: there the boundary cut across and strayed up to 0.65
/// edge (the default organ, 1.03 % of its diagonal against the bar of 1 %).
constexpr int kFidelityPasses = 3;
constexpr double kFidelityPerEdge = 0.35;
/// New fidelity particles keep this far (per edge) from every particle.
constexpr double kFidelitySpacingPerEdge = 0.35;
/// Rounds of the same check on the finished tets (after improvement and the pinches), each a new triangulation.
constexpr int kFinishedFidelityRounds = 4;

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
    const int threads = resolveThreads(params.threads);
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
    HS_TRY(progress.check("meshing"));

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

    const RegionLocator locator(body, voxels);
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
        in.locator = &locator;
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
                                            params.relaxationIterations, threads, sub,
                                            params.seeding == Seeding::Lattice ? &locator : nullptr, *edge);
        if (!stats.ok())
            return stats.failure();
        result.relaxationEnergy = stats->energy;
        timings.step("relax").counts.emplace_back("iterations", stats->iterations);
    }

    // One Delaunay tetrahedralization of the particles, with its sliver repair.
    detail::DelaunayOutput dt;
    const auto triangulate = [&]() -> Status {
        ScopedStepTimer timer(timings, "tetrahedralize");
        HS_TRY(progress.check("meshing"));
        detail::SliverRepairParams repair;
        repair.minDihedralDeg = kRepairDihedralDeg;
        repair.step = kRepairStepPerEdge * *edge;
        repair.seed = Rng::deriveSeed(params.seed, streams::kMeshingSliverRepair);
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
        progress.report("meshing.tetrahedralize", 0.9);
        return {};
    };
    // The kept tets of the triangulation: classified, improved, their interfaces' volumes matched, their pinches
    // opened (each step's counts are those of the last call).
    std::vector<Tet> tets;
    std::vector<std::int32_t> region;
    const auto finish = [&]() -> Status {
        for (const char* name : {"clean", "improve", "interfaceVolume", "pinches"})
            timings.step(name).counts.clear();
        {
            ScopedStepTimer timer(timings, "clean");
            region = classifyTets(particles.position, locator, threads, dt.tets);
            const std::size_t layerTets =
                classifyLayerTets(body, detail::parentSurfaces(body), particles, dt.tets, region);
            timings.step("clean").counts.emplace_back("layerTets", static_cast<std::int64_t>(layerTets));
            const std::size_t peeled = peelBoundarySlivers(body, particles.position, particles, dt, region);
            timings.step("clean").counts.emplace_back("peeled", static_cast<std::int64_t>(peeled));
        }
        // Between the steps without progress of their own, so that a cancel never waits on more than one of them.
        progress.report("meshing.clean", 0.9);
        HS_TRY(progress.check("meshing", "cleaning the tetrahedra"));
        tets = std::move(dt.tets);
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
        progress.report("meshing.interfaceVolume", 0.96);
        HS_TRY(progress.check("meshing", "matching the interfaces' volumes"));
        {
            // After the flips and the interface offsets, so that what the simulator gets has a manifold boundary.
            ScopedStepTimer timer(timings, "pinches");
            const auto duplicate = [&particles](std::int32_t v) {
                const auto i = static_cast<std::size_t>(v);
                particles.add(particles.position[i], particles.kind[i], particles.surface[i], particles.triangle[i],
                              particles.region[i]);
                return static_cast<std::int32_t>(particles.size() - 1);
            };
            const detail::PinchStats stats =
                detail::openPinches(tets, region, body.surfaces.front().regionId, duplicate);
            auto& counts = timings.step("pinches").counts;
            counts.emplace_back("pinches", static_cast<std::int64_t>(stats.pinchedBefore));
            counts.emplace_back("removedTets", static_cast<std::int64_t>(stats.removedTets));
            counts.emplace_back("splitVertices", static_cast<std::int64_t>(stats.splitVertices));
            counts.emplace_back("pinchesLeft", static_cast<std::int64_t>(stats.pinchedAfter));
            if (stats.pinchedAfter > 0)
                result.warnings.push_back(
                    std::to_string(stats.pinchedAfter) +
                    " pinched boundary edges or vertices are left (two parts of the body touch there)");
        }
        return {};
    };

    std::int64_t interfaceParticles = 0, fidelityParticles = 0;
    int fidelityPasses = 0;
    const int fidelityPassesAllowed = params.surfaceFidelity ? kFidelityPasses : 0;
    for (int pass = 0;; ++pass) {
        HS_TRY(triangulate());
        if (pass >= kInterfacePasses + fidelityPassesAllowed)
            break;
        std::size_t added = 0;
        if (pass < kInterfacePasses) {
            added = addInterfaceParticles(dt, body, locator, voxels, *edge, particles);
            interfaceParticles += static_cast<std::int64_t>(added);
        }
        if (added == 0 && fidelityPasses < fidelityPassesAllowed) {
            added = addFidelityParticles(keptTets(dt, body, locator, threads, particles), body, locator, voxels,
                                         kFidelityPerEdge * *edge, kFidelitySpacingPerEdge * *edge, threads, particles);
            fidelityParticles += static_cast<std::int64_t>(added);
            ++fidelityPasses;
        }
        if (added == 0)
            break;
    }
    // The same check on the finished tets: pinches opened by removal leave notches, and boundary flips move the
    // surface. Where the finished boundary strays, the particles as triangulated get the new ones and are
    // tetrahedralized and finished again.
    for (int round = 0;; ++round) {
        detail::Particles triangulated = particles;
        HS_TRY(finish());
        if (round >= (params.surfaceFidelity ? kFinishedFidelityRounds : 0))
            break;
        TetMesh finished;
        finished.points = particles.position;
        finished.tets = tets;
        finished.regions = region;
        const std::size_t added = addFidelityParticles(finished, body, locator, voxels, kFidelityPerEdge * *edge,
                                                       kFidelitySpacingPerEdge * *edge, threads, triangulated);
        if (added == 0)
            break;
        fidelityParticles += static_cast<std::int64_t>(added);
        particles = std::move(triangulated);
        HS_TRY(triangulate());
    }
    timings.step("tetrahedralize").counts.emplace_back("interfaceParticles", interfaceParticles);
    timings.step("tetrahedralize").counts.emplace_back("fidelityParticles", fidelityParticles);
    HS_TRY(progress.check("meshing", "opening pinches"));
    {
        ScopedStepTimer timer(timings, "assemble");
        result.mesh = assemble(particles, tets, region);
    }
    progress.report("meshing.quality", 0.98);
    HS_TRY(progress.check("meshing", "measuring the quality"));
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