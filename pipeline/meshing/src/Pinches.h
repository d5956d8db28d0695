#pragma once
// Pinches of a tet mesh's boundary: two solid wedges that touch only along an edge (four boundary faces meet there),
// two solid cones that touch only at a vertex, or a solid belt round a vertex that two void cones touch. A simulator's
// surface extraction, collision and cutting expect a manifold boundary, so they are opened.

#include "hs/core/TetMesh.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace hs::meshing::detail {

struct PinchStats {
    std::size_t pinchedBefore = 0; ///< pinched edges and vertices, before
    std::size_t pinchedAfter = 0;  ///< left: every fan there touches another region
    std::size_t removedTets = 0;
    std::size_t splitVertices = 0; ///< copies of vertices made (openPinches' duplicateVertex)
};

/// Opens every pinch (a boundary edge shared by more than two boundary faces, a boundary vertex whose tets form more
/// than one fan) by removing the smallest fan of tets around it (tets joined across faces that contain the edge or
/// vertex), taking only fans whose tets all belong to `outerRegion` and have no face against another region (so no
/// interface becomes boundary). A vertex whose tets form one fan but whose boundary faces form several sheets (joined
/// across edges through it) loses the tets, under the same rule, of the cheapest path of its tets joined across faces
/// from its first sheet to another, a tet with a vertex off the boundary costing as much as ten on it. Removed tets
/// get region -1; tets with a negative region are not part of the mesh. Repeats until no pinch is left or no fan can
/// go (at most 8 passes). Deterministic: pinches in sorted order.
///
/// With `duplicateVertex` (given a vertex, it adds a copy at the same place and returns the copy's index), a vertex
/// whose tets form several fans, none of which may go with every vertex on the boundary (a cap or a spike: no notch),
/// is split instead: each fan but the first gets its own copy of the vertex, so nothing is removed there and the
/// cones touch as separate sheets (as CGAL's Polygon_mesh_processing::duplicate_non_manifold_vertices does for a
/// surface). `tets` then refer to the copies.
PinchStats openPinches(std::vector<Tet>& tets, std::vector<std::int32_t>& region, std::int32_t outerRegion,
                       const std::function<std::int32_t(std::int32_t)>& duplicateVertex = {});

} // namespace hs::meshing::detail
