// Surface fidelity: particles added where the kept tets' boundary strays from the input surfaces.
#include "MesherSteps.h"

#include "InterfaceVolume.h"

#include "hs/core/Parallel.h"
#include "hs/core/TriangleGrid.h"

#include <algorithm>
#include <cmath>

namespace hs::meshing::detail {

namespace {

constexpr std::size_t kSampleChunk = 4096;

/// A point of an input surface to add as a particle, and how far the boundary strays there (mm).
struct Candidate {
    double distance = 0.0;
    Vec3 point;
    std::int32_t surface = -1;
    std::int32_t triangle = -1;
};

} // namespace

TetMesh keptTets(const detail::DelaunayOutput& dt, const RegionModel& body, const RegionLocator& locator, int threads,
                 const detail::Particles& ps) {
    std::vector<std::int32_t> region = classifyTets(ps.position, locator, threads, dt.tets);
    classifyLayerTets(body, parentSurfaces(body), ps, dt.tets, region);
    peelBoundarySlivers(body, ps.position, ps, dt, region);
    TetMesh mesh;
    mesh.points = ps.position;
    for (std::size_t t = 0; t < dt.tets.size(); ++t)
        if (region[t] >= 0) {
            mesh.tets.push_back(dt.tets[t]);
            mesh.regions.push_back(region[t]);
        }
    return mesh;
}

std::size_t addFidelityParticles(const TetMesh& kept, const RegionModel& body, const RegionLocator& locator,
                                 const VoxelSpace& voxels, double tolerance, double minSpacing, int threads,
                                 detail::Particles& ps) {
    const SurfaceMesh boundary = extractBoundary(kept, true);
    if (boundary.triangles.empty())
        return 0;
    const TriangleGrid boundaryGrid(boundary, 0.0, false);
    const double cutoff = 1e3 * tolerance;

    // Input samples (vertices and face centroids) far from the boundary: the sample itself is the candidate.
    std::vector<Candidate> candidates;
    std::vector<std::size_t> dropped; // inner particles to remove
    for (std::size_t s = 0; s < body.surfaces.size(); ++s) {
        const SurfaceMesh& surface = body.surfaces[s].surface;
        const std::size_t nv = surface.points.size(), n = nv + surface.triangles.size();
        std::vector<Candidate> found(n);
        parallelChunks(n, kSampleChunk, threads, [&](std::size_t, std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                Vec3 p;
                std::int32_t triangle = -1;
                if (i < nv) {
                    p = surface.points[i];
                } else {
                    const Triangle& t = surface.triangles[i - nv];
                    p = (surface.points[static_cast<std::size_t>(t[0])] +
                         surface.points[static_cast<std::size_t>(t[1])] +
                         surface.points[static_cast<std::size_t>(t[2])]) /
                        3.0;
                    triangle = static_cast<std::int32_t>(i - nv);
                }
                const double d = boundaryGrid.distance(p, cutoff);
                if (!(d > tolerance))
                    continue;
                if (triangle < 0)
                    triangle = locator.surfaceGrid(s).closest(p).triangle;
                found[i] = {d, p, static_cast<std::int32_t>(s), triangle};
            }
        });
        for (const Candidate& c : found)
            if (c.triangle >= 0)
                candidates.push_back(c);
    }

    // Boundary vertices and face centroids far from every input surface: the input's closest point is the candidate.
    {
        const std::size_t nv = boundary.points.size(), n = nv + boundary.triangles.size();
        std::vector<Candidate> found(n);
        parallelChunks(n, kSampleChunk, threads, [&](std::size_t, std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                Vec3 c = i < nv ? boundary.points[i] : Vec3{};
                if (i >= nv) {
                    const Triangle& t = boundary.triangles[i - nv];
                    c = (boundary.points[static_cast<std::size_t>(t[0])] +
                         boundary.points[static_cast<std::size_t>(t[1])] +
                         boundary.points[static_cast<std::size_t>(t[2])]) /
                        3.0;
                }
                Candidate best;
                double best2 = cutoff * cutoff;
                for (std::size_t s = 0; s < body.surfaces.size(); ++s) {
                    const SurfaceHit hit = locator.surfaceGrid(s).closestWithin(c, best2);
                    if (hit.triangle >= 0 && hit.closest.distance2 < best2) {
                        best2 = hit.closest.distance2;
                        best = {std::sqrt(best2), hit.closest.point, static_cast<std::int32_t>(s), hit.triangle};
                    }
                }
                if (best.triangle >= 0 && best.distance > tolerance)
                    found[i] = best;
            }
        });
        for (const Candidate& c : found)
            if (c.triangle >= 0)
                candidates.push_back(c);
        // An inner particle left on the boundary that far from the input (the floor of a notch, where the body is
        // thinner than the particles' spacing) goes: the surface particles round it make the tets there.
        const auto& source = boundary.vertexLabels.at("sourcePoint");
        for (std::size_t i = 0; i < nv; ++i) {
            const auto p = static_cast<std::size_t>(source[i]);
            if (found[i].triangle >= 0 && p < ps.size() && ps.kind[p] == ParticleKind::Inner)
                dropped.push_back(p);
        }
    }

    // Farthest first; ties keep the order found (deterministic).
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return a.distance > b.distance; });
    ParticleHash hash(voxels.region, ps);
    const double spacing2 = minSpacing * minSpacing;
    std::size_t added = 0;
    for (const Candidate& c : candidates) {
        if (hash.occupied(c.point, spacing2))
            continue;
        ps.add(c.point, detail::ParticleKind::Surface, c.surface, c.triangle, -1);
        hash.insert(ps.size() - 1);
        ++added;
    }
    if (dropped.empty())
        return added;
    std::sort(dropped.begin(), dropped.end());
    dropped.erase(std::unique(dropped.begin(), dropped.end()), dropped.end());
    Particles remaining;
    for (std::size_t i = 0, d = 0; i < ps.size(); ++i) {
        if (d < dropped.size() && dropped[d] == i) {
            ++d;
            continue;
        }
        remaining.add(ps.position[i], ps.kind[i], ps.surface[i], ps.triangle[i], ps.region[i]);
    }
    ps = std::move(remaining);
    return added + dropped.size();
}

} // namespace hs::meshing::detail
