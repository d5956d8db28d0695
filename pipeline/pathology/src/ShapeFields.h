#pragma once
/// Occupancy fields shared by the two field-based growth models (cellular automaton, particles): the grid a shape
/// grows on, capsules written into it, and the surface polygonized from it.

#include "Geometry.h"
#include "Shapes.h"

#include <vector>

namespace hs::pathology::detail {

/// Box blur [1 2 1]/4 along each axis.
std::vector<float> blur(const std::vector<float>& in, const Grid& g);

Grid growthGrid(const ShapeSpec& spec, double h, double reach);

void addCapsule(std::vector<float>& occ, const Grid& g, const Vec3& a, const Vec3& b, double radius);

/// Moves each vertex towards the centroid of its neighbours within its tangent plane: evens out the slivers of
/// marching tetrahedra without changing the shape.
void relaxTangentially(SurfaceMesh& mesh, int iterations);

SurfaceMesh surfaceFromOccupancy(std::vector<float> occ, const Grid& g);

} // namespace hs::pathology::detail
