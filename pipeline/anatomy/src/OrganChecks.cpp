#include "hs/anatomy/OrganChecks.h"

#include "OrganChecksCgal.h"

#include "hs/core/TriangleGeometry.h"
#include "hs/core/TriangleGrid.h"

#include <algorithm>
#include <cmath>

namespace hs::anatomy {

namespace {

Status checkInstance(const SurfaceMesh& mesh, const TemplateLayout& l) {
    if (mesh.points.size() != static_cast<std::size_t>(l.vertexCount()) ||
        mesh.triangles.size() != static_cast<std::size_t>(l.faceCount()))
        return fail(ErrorCode::InvalidInput, "mesh is not an instance of the uterus template (" +
                                                 std::to_string(mesh.points.size()) + " vertices, expected " +
                                                 std::to_string(l.vertexCount()) + ")");
    return {};
}

/// Serosa faces: the fundal fan and the bands between serosa rings come first in the template.
std::vector<Triangle> serosaFaces(const SurfaceMesh& mesh, const TemplateLayout& l) {
    const auto count = static_cast<std::size_t>(l.around) * static_cast<std::size_t>(1 + 2 * (l.outerRings - 1));
    return {mesh.triangles.begin(), mesh.triangles.begin() + static_cast<std::ptrdiff_t>(count)};
}

/// Vertices of canal (from its third ring), cavity and cavity fundus.
std::vector<Vec3> innerVertices(const SurfaceMesh& mesh, const TemplateLayout& l) {
    std::vector<Vec3> out;
    for (int r = l.firstCanalRing() + 2; r < l.ringCount(); ++r)
        for (int j = 0; j < l.around; ++j)
            out.push_back(mesh.points[static_cast<std::size_t>(l.vertex(r, j))]);
    out.push_back(mesh.points[static_cast<std::size_t>(l.innerPole())]);
    return out;
}

int genusOf(const SurfaceMesh& mesh, const SurfaceTopology& topology) {
    if (!topology.isClosed() || topology.components != 1)
        return -1;
    const auto v = static_cast<long long>(mesh.points.size() - topology.unreferencedVertices);
    const auto f = static_cast<long long>(mesh.triangles.size());
    const long long e = 3 * f / 2;
    return static_cast<int>((2 - (v - e + f)) / 2);
}

} // namespace

Result<double> minimumWallThickness(const SurfaceMesh& mesh, const TemplateLayout& l) {
    HS_TRY(checkInstance(mesh, l));
    const auto d = detail::distancesToTriangles(mesh.points, serosaFaces(mesh, l), innerVertices(mesh, l));
    return *std::min_element(d.begin(), d.end());
}

Result<bool> wallAtLeast(const SurfaceMesh& mesh, const TemplateLayout& l, double minMm) {
    HS_TRY(checkInstance(mesh, l));
    if (!(minMm > 0.0))
        return fail(ErrorCode::InvalidInput, "minimum wall thickness must be > 0 mm");
    SurfaceMesh serosa;
    serosa.points = mesh.points;
    serosa.triangles = serosaFaces(mesh, l);
    const TriangleGrid grid(serosa, 0.0, false);
    const double min2 = minMm * minMm;
    for (const Vec3& p : innerVertices(mesh, l))
        if (grid.closestWithin(p, min2).triangle >= 0)
            return false;
    return true;
}

Result<OrganCheck> checkOrgan(const SurfaceMesh& mesh, const TemplateLayout& l) {
    HS_TRY(checkInstance(mesh, l));
    OrganCheck check;
    check.topology = analyzeTopology(mesh);
    check.genus = genusOf(mesh, check.topology);
    check.selfIntersecting = hasSelfIntersections(mesh);

    // The serosa closed by a fan over the portio's edge is the outer boundary of the organ.
    std::vector<Vec3> points = mesh.points;
    std::vector<Triangle> closed = serosaFaces(mesh, l);
    Vec3 centre;
    const int bottom = l.outerRings - 1;
    for (int j = 0; j < l.around; ++j)
        centre += mesh.points[static_cast<std::size_t>(l.vertex(bottom, j))];
    points.push_back(centre / l.around);
    const auto pole = static_cast<std::int32_t>(points.size() - 1);
    for (int j = 0; j < l.around; ++j)
        closed.push_back({l.vertex(bottom, j), pole, l.vertex(bottom, j + 1)});
    const auto inner = innerVertices(mesh, l);
    const auto inside = detail::insideClosedSurface(points, closed, inner);
    check.cavityOutsideCount = static_cast<int>(std::count(inside.begin(), inside.end(), false));
    check.cavityInside = check.cavityOutsideCount == 0;

    const auto wall = detail::distancesToTriangles(mesh.points, serosaFaces(mesh, l), inner);
    check.minWallMm = *std::min_element(wall.begin(), wall.end());
    return check;
}

} // namespace hs::anatomy
