#pragma once
// Helpers shared by the baseline backends (no third-party types).

#include "hs/core/RegionModel.h"
#include "hs/core/TetMesh.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hs::meshing::detail {

/// For each surface, the index of the surface directly containing it (-1 for surfaces[0]).
inline std::vector<int> parentSurfaces(const RegionModel& body) {
    std::vector<int> parent(body.surfaces.size(), -1);
    for (std::size_t j = 1; j < body.surfaces.size(); ++j) {
        const SurfaceMesh& sj = body.surfaces[j].surface;
        const Vec3 probe = sj.points[static_cast<std::size_t>(sj.triangles[0][0])];
        for (std::size_t k = j; k-- > 0;)
            if (std::fabs(windingNumber(body.surfaces[k].surface, probe)) > 0.5) {
                parent[j] = static_cast<int>(k);
                break;
            }
    }
    return parent;
}

/// A point strictly inside the region of surface `s` (inside it, outside its children): a vertex moved inward
/// by a small fraction of its shortest incident edge, checked with winding numbers.
inline bool interiorPoint(const RegionModel& body, std::size_t s, const std::vector<int>& parent, Vec3& out) {
    const SurfaceMesh& mesh = body.surfaces[s].surface;
    const double sign = enclosedVolume(mesh) < 0.0 ? -1.0 : 1.0;
    for (std::size_t f = 0; f < mesh.triangles.size(); f += std::max<std::size_t>(1, mesh.triangles.size() / 64)) {
        const Triangle& t = mesh.triangles[f];
        const Vec3 a = mesh.points[static_cast<std::size_t>(t[0])], b = mesh.points[static_cast<std::size_t>(t[1])],
                   c = mesh.points[static_cast<std::size_t>(t[2])];
        const Vec3 n = normalized(cross(b - a, c - a)) * sign;
        const double l = std::min({distance(a, b), distance(b, c), distance(c, a)});
        const Vec3 p = (a + b + c) / 3.0 - n * (0.05 * l);
        if (std::fabs(windingNumber(mesh, p)) < 0.5)
            continue;
        bool inChild = false;
        for (std::size_t j = s + 1; j < body.surfaces.size() && !inChild; ++j)
            if (parent[j] == static_cast<int>(s) && std::fabs(windingNumber(body.surfaces[j].surface, p)) > 0.5)
                inChild = true;
        if (!inChild) {
            out = p;
            return true;
        }
    }
    return false;
}

/// Flips negatively oriented tets in place.
inline void orientPositive(TetMesh& mesh) {
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
        if (signedVolume(mesh, t) < 0.0)
            std::swap(mesh.tets[t][2], mesh.tets[t][3]);
}

} // namespace hs::meshing::detail
