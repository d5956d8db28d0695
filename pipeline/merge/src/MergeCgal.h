#pragma once
/// The CGAL part of the merge (the only file that includes CGAL): booleans, self-intersection tests, nearest faces.

#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"

#include <utility>
#include <vector>

namespace hs::merge::detail {

/// A watertight, 2-manifold, intersection-free surface that strictly contains `closed`, its vertices at distance
/// `offset` (mm) from it; concavities narrower than about `alpha` (mm) are bridged (alpha wrapping with an offset,
/// Portaneri, Rouxel-Labbe, Hemmer, Cohen-Steiner, Alliez, SIGGRAPH 2022; CGAL alpha_wrap_3). Deterministic.
SurfaceMesh offsetWrap(const SurfaceMesh& closed, double alpha, double offset);

/// The pairs of triangles (indices into mesh.triangles) of a surface that intersect each other.
std::vector<std::pair<std::size_t, std::size_t>> selfIntersections(const SurfaceMesh& mesh);

/// Union of closed, outward-oriented surfaces (exact-construction corefinement, CGAL PMP). BackendFailure when
/// CGAL cannot compute it.
Result<SurfaceMesh> unite(const SurfaceMesh& first, const std::vector<const SurfaceMesh*>& others);

/// For each query point, the index of the nearest face of `mesh` and the distance to it.
void nearestFaces(const SurfaceMesh& mesh, const std::vector<Vec3>& queries, std::vector<std::size_t>& face,
                  std::vector<double>& dist);

/// For each query point, whether it lies inside the closed surface.
std::vector<bool> insideOf(const SurfaceMesh& closed, const std::vector<Vec3>& queries);

} // namespace hs::merge::detail
