#pragma once
/// Tetrahedral mesh with a region id per tetrahedron.

#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"

#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace hs {

/// Four point indices; positive orientation: dot(p1 - p0, cross(p2 - p0, p3 - p0)) > 0.
using Tet = std::array<std::int32_t, 4>;

/// A face's points in increasing order: the key that finds the same face from both its tets.
inline std::array<std::int32_t, 3> sortedFace(std::int32_t a, std::int32_t b, std::int32_t c) {
    std::array<std::int32_t, 3> f{a, b, c};
    if (f[0] > f[1])
        std::swap(f[0], f[1]);
    if (f[1] > f[2])
        std::swap(f[1], f[2]);
    if (f[0] > f[1])
        std::swap(f[0], f[1]);
    return f;
}

struct TetMesh {
    std::vector<Vec3> points; ///< mm
    std::vector<Tet> tets;
    std::vector<std::int32_t> regions; ///< one region id per tet (empty: every tet in region 0)
    LabelMap tetLabels;                ///< further per-tet arrays ("material", ...), each tets.size() entries
    LabelMap pointLabels;              ///< per-point arrays, each points.size() entries

    std::size_t vertexCount() const { return points.size(); }
    std::size_t tetCount() const { return tets.size(); }
    std::int32_t regionOf(std::size_t tet) const { return regions.empty() ? 0 : regions[tet]; }
};

/// Indices in range, coordinates finite and within +-kMaxCoordinate, array sizes. Fails with InvalidInput naming the
/// first offence.
Status validate(const TetMesh& mesh);

Bounds bounds(const TetMesh& mesh);
/// Signed volume of tet `t`, mm^3 (positive when positively oriented).
double signedVolume(const TetMesh& mesh, std::size_t t);
/// Sum of |tet volume|, mm^3.
double totalVolume(const TetMesh& mesh);
/// Sum of |tet volume| per region id, mm^3.
std::map<std::int32_t, double> regionVolumes(const TetMesh& mesh);
/// Count of tets with signed volume <= 0 (inverted or degenerate).
std::size_t invertedTetCount(const TetMesh& mesh, double minVolume = 0.0);

/// The boundary faces: faces of exactly one tet, oriented outward, plus (with includeInterfaces) faces shared by two
/// tets of different regions, once, oriented out of the lower region id. Face labels: "region" (the tet's region),
/// "otherRegion" (-1 on the outer boundary). Only referenced points are kept, in first-use order, with their
/// original index in the vertex label "sourcePoint".
SurfaceMesh extractBoundary(const TetMesh& mesh, bool includeInterfaces = false);

/// The three points of face `k` of a tet (the face opposite its point k), wound outward for a positive tet.
inline constexpr int kTetFacePoints[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
/// For every tet, the tet across each of its faces (face k as in kTetFacePoints), -1 on the boundary. A face shared
/// by more than two tets (a non-manifold mesh) links only its first two.
std::vector<std::array<std::int32_t, 4>> tetNeighbours(const TetMesh& mesh);

} // namespace hs
