// Validation of a RegionModel. Self-intersections and crossings are found with CGAL's Polygon Mesh Processing
// (exact predicates); CGAL is header-only here, so hs_core gains no link dependency.
#include "hs/core/RegionModel.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

namespace hs {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using FaceIndex = CgalMesh::Face_index;

std::string surfaceLabel(const RegionModel& model, std::size_t i) {
    const std::string& name = model.surfaces[i].name;
    return name.empty() ? "surface " + std::to_string(i) : "surface " + std::to_string(i) + " (" + name + ")";
}

Status checkTopology(const RegionModel& model, std::size_t i) {
    const SurfaceMesh& mesh = model.surfaces[i].surface;
    const std::string label = surfaceLabel(model, i);
    if (auto status = validate(mesh); !status.ok())
        return fail(ErrorCode::InvalidInput, label + ": " + status.error().detail);
    if (mesh.triangles.size() < 4)
        return fail(ErrorCode::InvalidInput, label + " has " + std::to_string(mesh.triangles.size()) +
                                                 " triangles; a closed surface needs at least 4");
    const SurfaceTopology topo = analyzeTopology(mesh);
    // Zero area up to rounding: twice the area below 1e-10 of the squared longest edge.
    std::size_t degenerate = 0;
    for (const Triangle& t : mesh.triangles) {
        const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
        const Vec3& b = mesh.points[static_cast<std::size_t>(t[1])];
        const Vec3& c = mesh.points[static_cast<std::size_t>(t[2])];
        const double longest2 = std::max({norm2(b - a), norm2(c - b), norm2(a - c)});
        if (!(norm(cross(b - a, c - a)) > 1e-10 * longest2))
            ++degenerate;
    }
    if (degenerate > 0 || topo.degenerateFaces > 0)
        return fail(ErrorCode::InvalidInput, label + " has " +
                                                 std::to_string(std::max(degenerate, topo.degenerateFaces)) +
                                                 " zero-area (degenerate) triangles");
    if (topo.nonManifoldEdges > 0)
        return fail(ErrorCode::InvalidInput, label + " has " + std::to_string(topo.nonManifoldEdges) +
                                                 " non-manifold edges (shared by more than two triangles)");
    if (topo.boundaryEdges > 0)
        return fail(ErrorCode::InvalidInput,
                    label + " is open: " + std::to_string(topo.boundaryEdges) + " boundary edges (holes)");
    if (topo.nonManifoldVertices > 0)
        return fail(ErrorCode::InvalidInput,
                    label + " has " + std::to_string(topo.nonManifoldVertices) + " non-manifold vertices");
    if (topo.inconsistentEdges > 0)
        return fail(ErrorCode::InvalidInput,
                    label + " is inconsistently oriented at " + std::to_string(topo.inconsistentEdges) + " edges");
    return {};
}

/// Collects the first intersecting pair of each kind (within one surface, across two) and counts them all.
struct PairSink {
    const std::vector<std::size_t>* surfaceOfFace = nullptr;
    std::size_t selfCount = 0, crossCount = 0;
    std::pair<std::size_t, std::size_t> firstSelf{0, 0}, firstCross{0, 0}; // (surface, face) / (surface, surface)

    void add(FaceIndex a, FaceIndex b) {
        const std::size_t sa = (*surfaceOfFace)[static_cast<std::size_t>(a.idx())];
        const std::size_t sb = (*surfaceOfFace)[static_cast<std::size_t>(b.idx())];
        if (sa == sb) {
            if (selfCount++ == 0)
                firstSelf = {sa, 0};
        } else if (crossCount++ == 0) {
            firstCross = {std::min(sa, sb), std::max(sa, sb)};
        }
    }
};

struct PairOutput {
    using iterator_category = std::output_iterator_tag;
    using value_type = void;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = void;
    PairSink* sink;
    PairOutput& operator*() { return *this; }
    PairOutput& operator++() { return *this; }
    PairOutput operator++(int) { return *this; }
    PairOutput& operator=(const std::pair<FaceIndex, FaceIndex>& p) {
        sink->add(p.first, p.second);
        return *this;
    }
};

Status checkIntersections(const RegionModel& model) {
    CgalMesh combined;
    std::vector<std::size_t> surfaceOfFace;
    for (std::size_t s = 0; s < model.surfaces.size(); ++s) {
        const SurfaceMesh& mesh = model.surfaces[s].surface;
        std::vector<CgalMesh::Vertex_index> vertices;
        vertices.reserve(mesh.points.size());
        for (const Vec3& p : mesh.points)
            vertices.push_back(combined.add_vertex(Kernel::Point_3(p.x, p.y, p.z)));
        for (const Triangle& t : mesh.triangles) {
            const FaceIndex f =
                combined.add_face(vertices[static_cast<std::size_t>(t[0])], vertices[static_cast<std::size_t>(t[1])],
                                  vertices[static_cast<std::size_t>(t[2])]);
            if (f == CgalMesh::null_face())
                return fail(ErrorCode::InvalidInput, surfaceLabel(model, s) + " is not an orientable 2-manifold");
            surfaceOfFace.resize(static_cast<std::size_t>(f.idx()) + 1, s);
            surfaceOfFace[static_cast<std::size_t>(f.idx())] = s;
        }
    }
    PairSink sink;
    sink.surfaceOfFace = &surfaceOfFace;
    CGAL::Polygon_mesh_processing::self_intersections(combined, PairOutput{&sink});
    if (sink.selfCount > 0)
        return fail(ErrorCode::InvalidInput, surfaceLabel(model, sink.firstSelf.first) + " intersects itself (" +
                                                 std::to_string(sink.selfCount) + " intersecting triangle pairs)");
    if (sink.crossCount > 0)
        return fail(ErrorCode::InvalidInput, surfaceLabel(model, sink.firstCross.first) + " and " +
                                                 surfaceLabel(model, sink.firstCross.second) +
                                                 " cross or touch each other (" + std::to_string(sink.crossCount) +
                                                 " intersecting triangle pairs); nested surfaces must be disjoint");
    return {};
}

} // namespace

RegionModel RegionModel::fromSurfaces(std::vector<SurfaceMesh> surfaces, std::vector<std::string> names) {
    RegionModel model;
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        RegionSurface rs;
        rs.surface = std::move(surfaces[i]);
        rs.regionId = static_cast<std::int32_t>(i);
        if (i < names.size())
            rs.name = names[i];
        model.surfaces.push_back(std::move(rs));
    }
    return model;
}

double windingNumber(const SurfaceMesh& surface, const Vec3& p) {
    // Sum of signed solid angles (Van Oosterom & Strackee 1983) over 4 pi.
    double total = 0.0;
    for (const Triangle& t : surface.triangles) {
        const Vec3 a = surface.points[static_cast<std::size_t>(t[0])] - p;
        const Vec3 b = surface.points[static_cast<std::size_t>(t[1])] - p;
        const Vec3 c = surface.points[static_cast<std::size_t>(t[2])] - p;
        const double la = norm(a), lb = norm(b), lc = norm(c);
        const double numerator = dot(a, cross(b, c));
        const double denominator = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
        total += 2.0 * std::atan2(numerator, denominator);
    }
    return total / (4.0 * 3.14159265358979323846);
}

Status validate(const RegionModel& model) {
    if (model.surfaces.empty())
        return fail(ErrorCode::InvalidInput, "region model has no surface");
    for (std::size_t i = 0; i < model.surfaces.size(); ++i)
        HS_TRY(checkTopology(model, i));
    HS_TRY(checkIntersections(model));
    // Disjoint surfaces: one vertex tells on which side of the outline a whole nested surface lies.
    const SurfaceMesh& outline = model.surfaces[0].surface;
    const double outlineSign = enclosedVolume(outline) < 0.0 ? -1.0 : 1.0;
    for (std::size_t i = 1; i < model.surfaces.size(); ++i) {
        const Vec3& probe =
            model.surfaces[i].surface.points[static_cast<std::size_t>(model.surfaces[i].surface.triangles[0][0])];
        if (outlineSign * windingNumber(outline, probe) < 0.5)
            return fail(ErrorCode::InvalidInput, surfaceLabel(model, i) + " lies outside " + surfaceLabel(model, 0) +
                                                     "; later surfaces must be nested in the first one");
    }
    return {};
}

} // namespace hs
