// Interface recovery: particles added where Delaunay tets cross an interface.
#include "MesherSteps.h"

#include "InterfaceVolume.h"

#include "hs/meshing/Geometry.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace hs::meshing::detail {

ParticleHash::ParticleHash(const VoxelGrid<std::int32_t>& grid, const Particles& ps)
    : m_grid(grid), m_ps(ps), m_head(grid.size(), -1) {
    for (std::size_t i = 0; i < ps.size(); ++i)
        insert(i);
}

void ParticleHash::insert(std::size_t i) {
    const Index3 v = m_grid.voxelOf(m_ps.position[i]);
    if (!m_grid.contains(v))
        return;
    m_next.resize(std::max(m_next.size(), i + 1), -1);
    m_next[i] = m_head[m_grid.linear(v)];
    m_head[m_grid.linear(v)] = static_cast<std::int32_t>(i);
}

bool ParticleHash::occupied(const Vec3& p, double radius2) const {
    const Index3 c = m_grid.voxelOf(p);
    for (std::int64_t dk = -1; dk <= 1; ++dk)
        for (std::int64_t dj = -1; dj <= 1; ++dj)
            for (std::int64_t di = -1; di <= 1; ++di) {
                const Index3 nb{c[0] + di, c[1] + dj, c[2] + dk};
                if (!m_grid.contains(nb))
                    continue;
                for (std::int32_t i = m_head[m_grid.linear(nb)]; i >= 0; i = m_next[static_cast<std::size_t>(i)])
                    if (norm2(m_ps.position[static_cast<std::size_t>(i)] - p) < radius2)
                        return true;
            }
    return false;
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
    ParticleHash hash(voxels.region, ps);
    const double r2 = (0.35 * edge) * (0.35 * edge);
    std::size_t added = 0;
    for (const auto& [a, b] : crossing) {
        const Vec3 mid = (ps.position[a] + ps.position[b]) * 0.5;
        SurfaceHit best;
        std::size_t bestSurface = 0;
        double bestD = 1e300;
        for (std::size_t s = 1; s < body.surfaces.size(); ++s) {
            const SurfaceHit hit = locator.surfaceGrid(s).closestWithin(mid, bestD);
            if (hit.triangle >= 0 && hit.closest.distance2 < bestD) {
                bestD = hit.closest.distance2;
                best = hit;
                bestSurface = s;
            }
        }
        if (best.triangle < 0 || hash.occupied(best.closest.point, r2))
            continue;
        ps.add(best.closest.point, detail::ParticleKind::Surface, static_cast<std::int32_t>(bestSurface), best.triangle,
               -1);
        hash.insert(ps.size() - 1);
        ++added;
    }
    return added;
}

} // namespace hs::meshing::detail
