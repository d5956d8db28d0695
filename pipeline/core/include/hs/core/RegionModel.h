#pragma once
/// The multi-region body a tetrahedral mesher fills: closed surfaces, each bounding one region.
///
/// Semantics (nesting by order):
///  - surfaces[0] is the outline of the body; everything outside it is outside the body.
///  - every later surface lies inside surfaces[0] and crosses no other surface (it may lie inside another later
///    surface, e.g. a necrotic core inside a myoma inside the wall).
///  - the region of a point is the regionId of the LAST surface (highest index) whose enclosed volume contains it;
///    so a later surface cuts its volume out of the regions it lies in. A regionId of kVoidRegion marks a cavity
///    (the uterine cavity, fluid): its volume is not meshed and its surface becomes part of the body's boundary.
///  - the surfaces themselves are the interfaces: a nested surface is shared by the region inside it and the region
///    around it, so a conforming mesh has faces on it from both sides.
/// Surfaces may be oriented either way (the mesher orients them outward); they must be closed, manifold, free of
/// zero-area triangles and self-intersections, and must not touch each other.

#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace hs {

struct RegionSurface {
    SurfaceMesh surface;       ///< closed, manifold triangle surface, mm
    std::int32_t regionId = 0; ///< region of the volume it encloses (minus later surfaces); kVoidRegion: not meshed
    std::string name;          ///< for messages ("wall", "myoma 1", a file name)
};

struct RegionModel {
    static constexpr std::int32_t kVoidRegion = -1;

    std::vector<RegionSurface> surfaces; ///< surfaces[0] is the outline; later ones are nested in it

    /// A model with one region per surface: surface i gets region id i (the common case of the CLI).
    static RegionModel fromSurfaces(std::vector<SurfaceMesh> surfaces, std::vector<std::string> names = {});
};

/// Checks the rules above. Fails with InvalidInput naming the surface (by name, else index) and the problem: no
/// surface, invalid indices or coordinates, open surfaces (boundary edges), non-manifold edges or vertices,
/// inconsistent orientation, zero-area triangles, self-intersections, two surfaces that cross or touch, and a nested
/// surface that lies outside surfaces[0].
Status validate(const RegionModel& model);

/// Generalized winding number of `surface` at `p` (Jacobson et al. 2013): 1 inside, 0 outside an outward-oriented
/// closed surface (-1 inside an inward-oriented one). O(triangles).
double windingNumber(const SurfaceMesh& surface, const Vec3& p);

} // namespace hs
