#include "MergeCgal.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>

#include <algorithm>
#include <iterator>
#include <tuple>

namespace hs::merge::detail {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using FastMesh = CGAL::Surface_mesh<Epick::Point_3>;
using ExactMesh = CGAL::Surface_mesh<Epeck::Point_3>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<FastMesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Epick, Primitive>>;

template <class Mesh>
Mesh toCgal(const SurfaceMesh& in) {
    using Point = typename Mesh::Point;
    Mesh out;
    std::vector<typename Mesh::Vertex_index> v;
    v.reserve(in.points.size());
    for (const Vec3& p : in.points)
        v.push_back(out.add_vertex(Point(p.x, p.y, p.z)));
    for (const Triangle& t : in.triangles)
        out.add_face(v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])],
                     v[static_cast<std::size_t>(t[2])]);
    return out;
}

template <class Mesh>
SurfaceMesh fromCgal(const Mesh& in) {
    SurfaceMesh out;
    std::vector<std::int32_t> index(in.number_of_vertices() + in.number_of_removed_vertices(), -1);
    for (auto v : in.vertices()) {
        const auto& p = in.point(v);
        index[v.idx()] = static_cast<std::int32_t>(out.points.size());
        out.points.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    }
    for (auto f : in.faces()) {
        Triangle t{};
        std::size_t k = 0;
        for (auto v : CGAL::vertices_around_face(in.halfedge(f), in))
            if (k < 3)
                t[k++] = index[v.idx()];
        out.triangles.push_back(t);
    }
    return out;
}

/// The same surface with its vertices in lexicographic order and its triangles (each starting at its smallest vertex,
/// orientation kept) sorted. CGAL's corefinement reports the same vertices and faces in an order that depends on
/// memory addresses, so without this the same input would not give the same bits.
SurfaceMesh canonical(const SurfaceMesh& in) {
    std::vector<std::int32_t> order(in.points.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = static_cast<std::int32_t>(i);
    const auto key = [&](std::int32_t i) {
        const Vec3& p = in.points[static_cast<std::size_t>(i)];
        return std::make_tuple(p.x, p.y, p.z);
    };
    std::stable_sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) { return key(a) < key(b); });
    SurfaceMesh out;
    std::vector<std::int32_t> newIndex(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        newIndex[static_cast<std::size_t>(order[i])] = static_cast<std::int32_t>(i);
        out.points.push_back(in.points[static_cast<std::size_t>(order[i])]);
    }
    for (const Triangle& t : in.triangles) {
        Triangle n{newIndex[static_cast<std::size_t>(t[0])], newIndex[static_cast<std::size_t>(t[1])],
                   newIndex[static_cast<std::size_t>(t[2])]};
        while (n[0] > n[1] || n[0] > n[2])
            n = {n[1], n[2], n[0]};
        out.triangles.push_back(n);
    }
    std::sort(out.triangles.begin(), out.triangles.end());
    return out;
}

} // namespace

SurfaceMesh offsetWrap(const SurfaceMesh& closed, double alpha, double offset) {
    const FastMesh m = toCgal<FastMesh>(closed);
    FastMesh wrap;
    CGAL::alpha_wrap_3(m, alpha, offset, wrap);
    return fromCgal(wrap);
}

std::vector<std::pair<std::size_t, std::size_t>> selfIntersections(const SurfaceMesh& mesh) {
    const FastMesh m = toCgal<FastMesh>(mesh); // faces in the order of mesh.triangles
    std::vector<std::pair<FastMesh::Face_index, FastMesh::Face_index>> pairs;
    PMP::self_intersections(m, std::back_inserter(pairs));
    std::vector<std::pair<std::size_t, std::size_t>> out;
    out.reserve(pairs.size());
    for (const auto& [a, b] : pairs)
        out.emplace_back(std::min(a.idx(), b.idx()), std::max(a.idx(), b.idx()));
    std::sort(out.begin(), out.end());
    return out;
}

Result<SurfaceMesh> unite(const SurfaceMesh& first, const std::vector<const SurfaceMesh*>& others) {
    ExactMesh body = toCgal<ExactMesh>(first);
    for (const SurfaceMesh* other : others) {
        ExactMesh add = toCgal<ExactMesh>(*other);
        ExactMesh out;
        bool ok = false;
        try {
            ok = PMP::corefine_and_compute_union(body, add, out);
        } catch (const std::exception& e) {
            return fail(ErrorCode::BackendFailure, std::string("CGAL corefinement failed: ") + e.what());
        }
        if (!ok)
            return fail(ErrorCode::BackendFailure, "CGAL corefinement could not compute the union (the result would "
                                                   "not be a manifold surface)");
        body = std::move(out);
    }
    return canonical(fromCgal(body));
}

void nearestFaces(const SurfaceMesh& mesh, const std::vector<Vec3>& queries, std::vector<std::size_t>& face,
                  std::vector<double>& dist) {
    const FastMesh m = toCgal<FastMesh>(mesh);
    Tree tree(faces(m).first, faces(m).second, m);
    tree.accelerate_distance_queries();
    face.resize(queries.size());
    dist.resize(queries.size());
    for (std::size_t i = 0; i < queries.size(); ++i) {
        const Epick::Point_3 q(queries[i].x, queries[i].y, queries[i].z);
        const auto hit = tree.closest_point_and_primitive(q);
        face[i] = static_cast<std::size_t>(hit.second.idx());
        dist[i] = std::sqrt(CGAL::squared_distance(q, hit.first));
    }
}

std::vector<bool> insideOf(const SurfaceMesh& closed, const std::vector<Vec3>& queries) {
    const FastMesh m = toCgal<FastMesh>(closed);
    CGAL::Side_of_triangle_mesh<FastMesh, Epick> side(m);
    std::vector<bool> inside(queries.size());
    for (std::size_t i = 0; i < queries.size(); ++i)
        inside[i] = side(Epick::Point_3(queries[i].x, queries[i].y, queries[i].z)) == CGAL::ON_BOUNDED_SIDE;
    return inside;
}

} // namespace hs::merge::detail
