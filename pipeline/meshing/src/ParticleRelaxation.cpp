// Relaxation: particles pushed towards the rest distance by the interaction profile (Bossen & Heckbert 1996).
#include "MesherSteps.h"
#include "Particles.h"

#include "hs/core/Parallel.h"
#include "hs/core/PointGrid.h"
#include "hs/meshing/Geometry.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace hs::meshing::detail {

namespace {

// Relaxation schedule (Sierra et al.: the motility shrinks every iteration).
constexpr double kInitialMotility = 0.3; ///< step = motility * rest distance * force
constexpr double kMotilityDecay = 0.95;
constexpr double kMaxStep = 0.25;       ///< rest distances per iteration
constexpr double kConvergedMove = 2e-3; ///< stop when no particle moves more (rest distances)
constexpr std::size_t kParticleChunk = 2048;

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
Result<RelaxationStats> relaxParticles(Particles& ps, const RegionModel& body, const VoxelSpace& voxels,
                                       const std::vector<SurfaceAdjacency>& adjacency, double r0, int iterations,
                                       int threads, Progress& progress, const RegionLocator* locator, double edge) {
    RelaxationStats stats;
    const std::size_t n = ps.size();
    const double cutoff = kInteractionCutoff * r0;
    const double invR02 = 1.0 / (r0 * r0);
    const ProfileTable& table = profile();
    const auto& grid = voxels.region;
    Bounds box;
    for (const Vec3& p : ps.position)
        box.add(p);
    PointGrid neighbours;
    std::vector<Vec3> next(n);
    std::vector<std::int32_t> nextTriangle(ps.triangle);
    const std::size_t chunks = chunkCount(n, kParticleChunk);
    std::vector<double> chunkEnergy(chunks), chunkMove(chunks);
    double motility = kInitialMotility;
    // Inner particles in surface voxels keep kSurfaceVoxelClearance edges from every input surface (the region cannot
    // change on the way: a step is shorter than the clearance). The distance is searched up to clearance + slack and
    // remembered with the position it was measured at, so a particle queries again only once it has moved farther
    // than its slack (the same decisions as a query per move, by the triangle inequality).
    const double clearance = kSurfaceVoxelClearance * edge;
    const double searchRange = clearance + 0.5 * edge;
    std::vector<Vec3> clearAnchor(locator ? n : 0);
    std::vector<double> clearSlack(locator ? n : 0, -1.0);
    auto clearOfSurfaces = [&](std::size_t i, const Vec3& p) {
        if (clearSlack[i] >= 0.0 && norm2(p - clearAnchor[i]) <= clearSlack[i] * clearSlack[i])
            return true;
        double d = searchRange;
        for (std::size_t s = 0; s < body.surfaces.size(); ++s)
            d = std::min(d, locator->surfaceGrid(s).distance(p, searchRange));
        if (d < clearance)
            return false;
        clearAnchor[i] = p;
        clearSlack[i] = d - clearance;
        return true;
    };

    for (int it = 0; it < iterations; ++it) {
        HS_TRY(progress.check("meshing", "relaxing particles"));
        // Cells of one cut-off with a corner one cell below the first box, so every interacting pair lies in
        // neighbouring cells.
        neighbours.reset(box, cutoff, box.min - Vec3(cutoff, cutoff, cutoff), 1);
        neighbours.insertAll(ps.position);
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
                neighbours.forEachInCellsAround(xi, [&](std::int32_t id) {
                    const auto jdx = static_cast<std::size_t>(id);
                    // Boundary particles of two different sheets do not interact: across a layer or slit thinner
                    // than one edge they would thin each other out (see kCrossSurfaceRadius).
                    if (jdx == i || (si >= 0 && ps.surface[jdx] >= 0 && !sameSheet(ps, adjacency, jdx, si, normalI)))
                        return;
                    const Vec3 dx = xi - ps.position[jdx];
                    const double d2 = norm2(dx) * invR02;
                    if (d2 >= kInteractionCutoff * kInteractionCutoff)
                        return;
                    double fOverD = 0.0, e2 = 0.0;
                    table.lookup(d2, fOverD, e2);
                    force += dx * (fOverD / r0);
                    energy += 0.5 * e2;
                });
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
                            if (grid.contains(v) &&
                                (grid.at(v) == ps.region[i] ||
                                 (locator && grid.at(v) == VoxelSpace::kSurface && clearOfSurfaces(i, candidate)))) {
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
