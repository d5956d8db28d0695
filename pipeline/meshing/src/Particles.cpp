// Particles shared by seeding and relaxation: surface adjacency, projection walks, sheets.
#include "Particles.h"

#include "hs/meshing/Geometry.h"

#include <algorithm>
#include <cmath>

namespace hs::meshing::detail {

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

} // namespace hs::meshing::detail
