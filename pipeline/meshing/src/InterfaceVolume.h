#pragma once
// Volume-matched placement of the particles of nested surfaces: a surface sampled at one edge length and meshed by
// chords encloses less than the input where it is convex (the chords cut the caps off), which on a small
// pathology at a 2 mm edge is 4-8 % of its volume.

#include "Particles.h"
#include "hs/core/RegionModel.h"
#include "hs/core/TetMesh.h"

#include <cstdint>
#include <vector>

namespace hs::meshing::detail {

struct InterfaceVolumeStats {
    std::size_t surfaces = 0;      ///< nested surfaces corrected
    std::size_t movedVertices = 0; ///< accepted vertex offsets, over all passes
    std::size_t keptVertices = 0;  ///< offsets refused (a tet of the star would get worse than the bar)
    double largestOffset = 0.0;    ///< mm, largest |offset| of a surface in a pass
};

/// Moves the surface particles of every nested, non-void surface along its outward normal by the same offset, so
/// that the volume the mesh encloses by that surface (its region and the regions nested in it) equals the volume
/// the input surface encloses: the chord polyhedron's vertices end up slightly outside the surface and its face
/// centres slightly inside, which also halves the largest deviation of a convex cap. Two passes (the second fixes
/// what the first left over, refused moves included); a vertex move is kept only when no tet of its star inverts
/// and the star's smallest dihedral angle stays at least min(its value before, `minDihedralDeg`). The outline
/// (surface 0) is not moved. Sequential in particle order: deterministic.
/// The innermost surface containing each nested surface (-1 for surface 0 and for a surface in none).
std::vector<std::int32_t> parentSurfaces(const RegionModel& body);

InterfaceVolumeStats matchInterfaceVolumes(const RegionModel& body, const std::vector<SurfaceAdjacency>& adjacency,
                                           Particles& ps, const std::vector<Tet>& tets,
                                           const std::vector<std::int32_t>& region, double minDihedralDeg);

} // namespace hs::meshing::detail
