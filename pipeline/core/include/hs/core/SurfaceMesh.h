#pragma once
/// Indexed triangle surface with named integer labels per vertex and per face.

#include "hs/core/Result.h"
#include "hs/core/Vec3.h"

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace hs {

using Triangle = std::array<std::int32_t, 3>;
/// Named label arrays ("region", "tissue", "contact", ...), each empty or one value per element. A std::map keeps
/// their order fixed, so files written from a mesh are byte-identical run to run.
using LabelMap = std::map<std::string, std::vector<std::int32_t>>;

struct SurfaceMesh {
    std::vector<Vec3> points;        ///< mm
    std::vector<Triangle> triangles; ///< indices into points, counter-clockwise seen from outside
    LabelMap vertexLabels;           ///< each array has points.size() entries
    LabelMap faceLabels;             ///< each array has triangles.size() entries

    std::size_t vertexCount() const { return points.size(); }
    std::size_t faceCount() const { return triangles.size(); }
};

/// The largest magnitude a mesh coordinate may have, in any length unit: 1e9 (1000 km in mm). Far beyond any real
/// object, and small enough that what is computed from coordinates stays finite: areas, volumes, grid cell sizes.
/// A finite 1e300 does not (its square is infinite, and a grid over it has NaN cells).
constexpr double kMaxCoordinate = 1e9;

/// Every coordinate finite and within +-kMaxCoordinate. Fails with InvalidInput naming the first offending
/// `element` ("point", "vertex") by index, its value and the allowed range.
Status checkCoordinates(const std::vector<Vec3>& points, const char* element);

/// Structural checks of a surface: what a mesher or a boolean needs to know before it starts.
struct SurfaceTopology {
    std::size_t boundaryEdges = 0;       ///< edges with one incident face (holes)
    std::size_t nonManifoldEdges = 0;    ///< edges with more than two incident faces
    std::size_t nonManifoldVertices = 0; ///< vertices whose incident faces form more than one fan
    std::size_t inconsistentEdges = 0;   ///< edges whose two faces traverse them in the same direction
    std::size_t degenerateFaces = 0;     ///< faces with a repeated index or zero area
    std::size_t unreferencedVertices = 0;
    std::size_t components = 0; ///< face-connected components

    bool isClosed() const { return boundaryEdges == 0 && nonManifoldEdges == 0; }
    bool isManifold() const { return nonManifoldEdges == 0 && nonManifoldVertices == 0; }
    /// Closed, manifold, consistently oriented, no degenerate faces: a surface that bounds a volume.
    bool isWatertight() const { return isClosed() && isManifold() && inconsistentEdges == 0 && degenerateFaces == 0; }
};

/// Indices in range, coordinates finite and within +-kMaxCoordinate, label arrays of the right size. Fails with
/// InvalidInput naming the first offending element.
Status validate(const SurfaceMesh& mesh);

Bounds bounds(const SurfaceMesh& mesh);
SurfaceTopology analyzeTopology(const SurfaceMesh& mesh);
/// Total triangle area, mm^2.
double surfaceArea(const SurfaceMesh& mesh);
/// Signed enclosed volume by the divergence theorem, mm^3; positive for an outward-oriented closed surface.
double enclosedVolume(const SurfaceMesh& mesh);
/// Unit normal of triangle `face` (zero for a degenerate one).
Vec3 faceNormal(const SurfaceMesh& mesh, std::size_t face);

/// The key of the undirected edge between vertices a and b (either order): the smaller id in the high 32 bits.
inline std::uint64_t edgeKey(std::int32_t a, std::int32_t b) {
    const auto lo = static_cast<std::uint32_t>(a < b ? a : b);
    const auto hi = static_cast<std::uint32_t>(a < b ? b : a);
    return (static_cast<std::uint64_t>(lo) << 32) | hi;
}
/// Area-weighted vertex normals.
std::vector<Vec3> vertexNormals(const SurfaceMesh& mesh);

} // namespace hs
