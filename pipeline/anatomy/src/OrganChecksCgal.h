#pragma once
/// The CGAL-backed parts of the organ checks; CGAL is included only in OrganChecksCgal.cpp (compile time).

#include "hs/core/SurfaceMesh.h"

#include <vector>

namespace hs::anatomy::detail {

/// Smallest distance from each query point to a triangle soup (AABB tree), mm.
std::vector<double> distancesToTriangles(const std::vector<Vec3>& trianglePoints,
                                         const std::vector<Triangle>& triangles, const std::vector<Vec3>& queries);

/// For a closed, outward-oriented surface: whether each query lies strictly inside.
std::vector<bool> insideClosedSurface(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles,
                                      const std::vector<Vec3>& queries);

} // namespace hs::anatomy::detail
