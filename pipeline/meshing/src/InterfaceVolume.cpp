#include "InterfaceVolume.h"

#include "MeshImprove.h"

#include <algorithm>
#include <cmath>

namespace hs::meshing::detail {
namespace {

constexpr int kPasses = 2;

/// Whether surface `inner` is `outer` or lies (transitively) inside it.
bool nestedIn(const std::vector<std::int32_t>& parent, std::size_t inner, std::size_t outer) {
    for (auto s = static_cast<std::int32_t>(inner); s >= 0; s = parent[static_cast<std::size_t>(s)])
        if (static_cast<std::size_t>(s) == outer)
            return true;
    return false;
}

struct Stars {
    std::vector<std::uint32_t> start; ///< CSR: vertex -> tets of the mesh (region >= 0) containing it
    std::vector<std::uint32_t> tets;
};

Stars buildStars(std::size_t vertexCount, const std::vector<Tet>& tets, const std::vector<std::int32_t>& region) {
    Stars stars;
    stars.start.assign(vertexCount + 1, 0);
    for (std::size_t t = 0; t < tets.size(); ++t)
        if (region[t] >= 0)
            for (auto v : tets[t])
                ++stars.start[static_cast<std::size_t>(v) + 1];
    for (std::size_t v = 0; v < vertexCount; ++v)
        stars.start[v + 1] += stars.start[v];
    stars.tets.resize(stars.start.back());
    std::vector<std::uint32_t> cursor(stars.start.begin(), stars.start.end() - 1);
    for (std::size_t t = 0; t < tets.size(); ++t)
        if (region[t] >= 0)
            for (auto v : tets[t])
                stars.tets[cursor[static_cast<std::size_t>(v)]++] = static_cast<std::uint32_t>(t);
    return stars;
}

double starWorstAngle(const std::vector<Vec3>& points, const std::vector<Tet>& tets, const Stars& stars,
                      std::size_t v) {
    double worst = 180.0;
    for (std::uint32_t i = stars.start[v]; i < stars.start[v + 1]; ++i) {
        const Tet& t = tets[stars.tets[i]];
        worst = std::min(
            worst, minDihedralDeg(points[static_cast<std::size_t>(t[0])], points[static_cast<std::size_t>(t[1])],
                                  points[static_cast<std::size_t>(t[2])], points[static_cast<std::size_t>(t[3])]));
    }
    return worst;
}

double tetVolume(const std::vector<Vec3>& p, const Tet& t) {
    const Vec3& a = p[static_cast<std::size_t>(t[0])];
    return dot(p[static_cast<std::size_t>(t[1])] - a,
               cross(p[static_cast<std::size_t>(t[2])] - a, p[static_cast<std::size_t>(t[3])] - a)) /
           6.0;
}

} // namespace

/// As in inputRegionVolumes: the nearest earlier surface whose winding number at a vertex is 1.
std::vector<std::int32_t> parentSurfaces(const RegionModel& body) {
    const std::size_t n = body.surfaces.size();
    std::vector<std::int32_t> parent(n, -1);
    for (std::size_t j = 1; j < n; ++j) {
        const SurfaceMesh& sj = body.surfaces[j].surface;
        if (sj.triangles.empty())
            continue;
        const Vec3 probe = sj.points[static_cast<std::size_t>(sj.triangles[0][0])];
        for (std::size_t k = j; k-- > 0;)
            if (std::fabs(windingNumber(body.surfaces[k].surface, probe)) > 0.5) {
                parent[j] = static_cast<std::int32_t>(k);
                break;
            }
    }
    return parent;
}

InterfaceVolumeStats matchInterfaceVolumes(const RegionModel& body, const std::vector<SurfaceAdjacency>& adjacency,
                                           Particles& ps, const std::vector<Tet>& tets,
                                           const std::vector<std::int32_t>& region, double minDihedralDeg) {
    InterfaceVolumeStats stats;
    const std::size_t n = body.surfaces.size();
    if (n < 2)
        return stats;
    const std::vector<std::int32_t> parent = parentSurfaces(body);
    const Stars stars = buildStars(ps.size(), tets, region);
    for (std::size_t s = 1; s < n; ++s) {
        const auto& rs = body.surfaces[s];
        if (rs.regionId == RegionModel::kVoidRegion || rs.surface.triangles.empty())
            continue;
        // The regions inside s; a void inside s is not meshed and would need its own volume: leave such s alone.
        std::vector<std::int32_t> inside;
        bool hasVoid = false;
        for (std::size_t k = s; k < n; ++k)
            if (nestedIn(parent, k, s)) {
                hasVoid = hasVoid || body.surfaces[k].regionId == RegionModel::kVoidRegion;
                inside.push_back(body.surfaces[k].regionId);
            }
        if (hasVoid)
            continue;
        const double inputVolume = std::fabs(enclosedVolume(rs.surface));
        const double area = surfaceArea(rs.surface);
        if (!(area > 0.0))
            continue;
        ++stats.surfaces;
        const auto si = static_cast<std::int32_t>(s);
        for (int pass = 0; pass < kPasses; ++pass) {
            double meshVolume = 0.0;
            for (std::size_t t = 0; t < tets.size(); ++t)
                if (region[t] >= 0 && std::find(inside.begin(), inside.end(), region[t]) != inside.end())
                    meshVolume += tetVolume(ps.position, tets[t]);
            const double offset = (inputVolume - meshVolume) / area;
            stats.largestOffset = std::max(stats.largestOffset, std::fabs(offset));
            for (std::size_t v = 0; v < ps.size(); ++v) {
                if (ps.surface[v] != si || ps.kind[v] != ParticleKind::Surface || stars.start[v] == stars.start[v + 1])
                    continue;
                const Vec3 normal = adjacency[s].faceNormals[static_cast<std::size_t>(ps.triangle[v])];
                const Vec3 old = ps.position[v];
                const double before = starWorstAngle(ps.position, tets, stars, v);
                ps.position[v] = old + normal * offset;
                const double after = starWorstAngle(ps.position, tets, stars, v);
                if (after > 0.0 && after >= std::min(before, minDihedralDeg)) {
                    ++stats.movedVertices;
                } else {
                    ps.position[v] = old;
                    ++stats.keptVertices;
                }
            }
        }
    }
    return stats;
}

} // namespace hs::meshing::detail
