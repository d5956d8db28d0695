// Occupancy fields shared by the cellular automaton and the particle growth model.
#include "Shapes.h"

#include "ShapeFields.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace hs::pathology::detail {

/// Box blur [1 2 1]/4 along each axis.
std::vector<float> blur(const std::vector<float>& in, const Grid& g) {
    std::vector<float> a = in, b(in.size());
    const std::array<std::size_t, 3> strides{1, static_cast<std::size_t>(g.nx),
                                             static_cast<std::size_t>(g.nx) * static_cast<std::size_t>(g.ny)};
    const std::array<int, 3> dims{g.nx, g.ny, g.nz};
    for (int axis = 0; axis < 3; ++axis) {
        for (int k = 0; k < g.nz; ++k)
            for (int j = 0; j < g.ny; ++j)
                for (int i = 0; i < g.nx; ++i) {
                    const std::array<int, 3> c{i, j, k};
                    const std::size_t id = g.index(i, j, k);
                    const std::size_t st = strides[static_cast<std::size_t>(axis)];
                    const bool lo = c[static_cast<std::size_t>(axis)] > 0;
                    const bool hi = c[static_cast<std::size_t>(axis)] + 1 < dims[static_cast<std::size_t>(axis)];
                    b[id] = 0.5f * a[id] + 0.25f * (lo ? a[id - st] : 0.0f) + 0.25f * (hi ? a[id + st] : 0.0f);
                }
        a.swap(b);
    }
    return a;
}

Grid growthGrid(const ShapeSpec& spec, double h, double reach) {
    Bounds box;
    box.add(spec.center - Vec3{reach, reach, reach});
    box.add(spec.center + Vec3{reach, reach, reach});
    if (spec.pedunculated || spec.polyp) {
        box.add(spec.base - Vec3{spec.stalkRadius, spec.stalkRadius, spec.stalkRadius} * 2.0);
        box.add(spec.base + Vec3{spec.stalkRadius, spec.stalkRadius, spec.stalkRadius} * 2.0);
    }
    return Grid::covering(box, h, 3);
}

void addCapsule(std::vector<float>& occ, const Grid& g, const Vec3& a, const Vec3& b, double radius) {
    const Vec3 ab = b - a;
    const double len2 = std::max(norm2(ab), 1e-12);
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                const Vec3 p = g.center(i, j, k);
                const double t = std::clamp(dot(p - a, ab) / len2, 0.0, 1.0);
                if (norm2(p - (a + ab * t)) <= radius * radius)
                    occ[g.index(i, j, k)] = 1.0f;
            }
}

/// Moves each vertex towards the centroid of its neighbours within its tangent plane: evens out the slivers of
/// marching tetrahedra without changing the shape.
void relaxTangentially(SurfaceMesh& mesh, int iterations) {
    std::vector<std::vector<std::int32_t>> nbr(mesh.points.size());
    for (const Triangle& t : mesh.triangles)
        for (std::size_t k = 0; k < 3; ++k)
            nbr[static_cast<std::size_t>(t[k])].push_back(t[(k + 1) % 3]);
    for (int it = 0; it < iterations; ++it) {
        const std::vector<Vec3> normals = vertexNormals(mesh);
        std::vector<Vec3> next = mesh.points;
        for (std::size_t i = 0; i < mesh.points.size(); ++i) {
            if (nbr[i].empty())
                continue;
            Vec3 c;
            for (std::int32_t j : nbr[i])
                c += mesh.points[static_cast<std::size_t>(j)];
            const Vec3 d = c / static_cast<double>(nbr[i].size()) - mesh.points[i];
            next[i] = mesh.points[i] + (d - normals[i] * dot(d, normals[i])) * 0.5;
        }
        mesh.points.swap(next);
    }
}

SurfaceMesh surfaceFromOccupancy(std::vector<float> occ, const Grid& g) {
    SurfaceMesh mesh = polygonize(blur(blur(occ, g), g), g, 0.5f);
    taubinSmooth(mesh, 10);
    relaxTangentially(mesh, 10);
    taubinSmooth(mesh, 10);
    orientOutward(mesh);
    return mesh;
}

} // namespace hs::pathology::detail
