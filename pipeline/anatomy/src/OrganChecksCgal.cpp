#include "OrganChecksCgal.h"

#include "hs/anatomy/OrganChecks.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>

namespace hs::anatomy {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

Mesh toCgal(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles) {
    Mesh mesh;
    std::vector<Mesh::Vertex_index> vertices;
    vertices.reserve(points.size());
    for (const auto& p : points)
        vertices.push_back(mesh.add_vertex(Point(p.x, p.y, p.z)));
    for (const auto& t : triangles)
        mesh.add_face(vertices[static_cast<std::size_t>(t[0])], vertices[static_cast<std::size_t>(t[1])],
                      vertices[static_cast<std::size_t>(t[2])]);
    return mesh;
}

} // namespace

bool hasSelfIntersections(const SurfaceMesh& surface) {
    const Mesh mesh = toCgal(surface.points, surface.triangles);
    if (mesh.number_of_faces() != surface.triangles.size())
        return true; // CGAL refused a face: the surface is not even a valid halfedge mesh
    return CGAL::Polygon_mesh_processing::does_self_intersect(mesh);
}

namespace detail {

std::vector<double> distancesToTriangles(const std::vector<Vec3>& trianglePoints,
                                         const std::vector<Triangle>& triangles, const std::vector<Vec3>& queries) {
    using Iterator = std::vector<Kernel::Triangle_3>::const_iterator;
    using Primitive = CGAL::AABB_triangle_primitive<Kernel, Iterator>;
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
    std::vector<Kernel::Triangle_3> soup;
    soup.reserve(triangles.size());
    auto pt = [&](std::int32_t i) {
        const Vec3& p = trianglePoints[static_cast<std::size_t>(i)];
        return Point(p.x, p.y, p.z);
    };
    for (const auto& t : triangles)
        soup.emplace_back(pt(t[0]), pt(t[1]), pt(t[2]));
    Tree tree(soup.begin(), soup.end());
    tree.accelerate_distance_queries();
    std::vector<double> out;
    out.reserve(queries.size());
    for (const auto& q : queries)
        out.push_back(std::sqrt(CGAL::to_double(tree.squared_distance(Point(q.x, q.y, q.z)))));
    return out;
}

std::vector<bool> insideClosedSurface(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles,
                                      const std::vector<Vec3>& queries) {
    const Mesh mesh = toCgal(points, triangles);
    CGAL::Side_of_triangle_mesh<Mesh, Kernel> side(mesh);
    std::vector<bool> out;
    out.reserve(queries.size());
    for (const auto& q : queries)
        out.push_back(side(Point(q.x, q.y, q.z)) == CGAL::ON_BOUNDED_SIDE);
    return out;
}

} // namespace detail

} // namespace hs::anatomy
