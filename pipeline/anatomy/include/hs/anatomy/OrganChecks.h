#pragma once
/// Checks that an organ instance is a valid solid for the later stages (merge, meshing), measured, not assumed.

#include "hs/anatomy/UterusGenerator.h"
#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"

namespace hs::anatomy {

struct OrganCheck {
    SurfaceTopology topology;
    bool selfIntersecting = false; ///< any two non-adjacent triangles intersect (CGAL PMP does_self_intersect)
    bool cavityInside = false;     ///< every canal and cavity vertex lies inside the closed serosa
    int cavityOutsideCount = 0;    ///< vertices for which that fails
    double minWallMm = 0.0;        ///< see minimumWallThickness
    int genus = -1;                ///< from the Euler characteristic (0 for a valid organ)

    /// Watertight, manifold, one component of genus 0, no self-intersection, cavity inside, wall >= minWallMm.
    bool valid(double requiredWallMm = 5.0) const {
        return topology.isWatertight() && topology.components == 1 && genus == 0 && !selfIntersecting && cavityInside &&
               minWallMm >= requiredWallMm;
    }
};

/// Wall thickness: the smallest distance from a vertex of the endometrium or the cervical canal to the serosa
/// (point-to-triangle, mm). The first two canal rings are left out: at the external os the wall ends in the
/// ectocervix, where canal and serosa meet by construction.
[[nodiscard]] Result<double> minimumWallThickness(const SurfaceMesh& mesh, const TemplateLayout& layout);

/// Whether the wall is at least `minMm` thick everywhere (same measure as minimumWallThickness, but it stops at the
/// first vertex closer than `minMm` and only looks at serosa triangles in a grid of `minMm` cells: the fast form
/// for the sampler's acceptance test). InvalidInput for a mesh that is not an instance of `layout`.
[[nodiscard]] Result<bool> wallAtLeast(const SurfaceMesh& mesh, const TemplateLayout& layout, double minMm);

/// Runs every check on an instance of `layout`. Fails only on a mesh that is not an instance of the layout.
[[nodiscard]] Result<OrganCheck> checkOrgan(const SurfaceMesh& mesh, const TemplateLayout& layout);

/// True when two triangles that share no vertex intersect, or two adjacent ones overlap (CGAL PMP).
bool hasSelfIntersections(const SurfaceMesh& mesh);

} // namespace hs::anatomy
