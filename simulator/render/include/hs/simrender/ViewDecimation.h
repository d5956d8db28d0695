#pragma once
/// The surface the endoscopic view draws (docs/simulator.md, "Endoscopic view"): the visual surface's points in the
/// order its triangles first use them, the inner faces first, and, when asked, part of the points removed (a lighter
/// surface for a software rasterizer). Every point drawn is one of the visual surface's points (the deformed points,
/// World::visualPoints, are gathered through `sourcePoints`); borders and the texture's seams keep all their points,
/// so a lighter surface has the same outline, the same holes and no cracks along the seams.

#include "hs/core/SurfaceMesh.h"

#include <cstddef>
#include <string_view>
#include <vector>

namespace hs::simrender {

struct ViewDecimationParams {
    double targetReduction = 0.5; ///< share of the triangles to remove, 0 (none) .. 0.9; reached where the shape allows
};

struct DecimatedSurface {
    std::vector<std::size_t> sourcePoints; ///< per point of the lighter surface: the visual surface's point it is
    std::vector<Triangle> triangles;       ///< over the lighter surface's points; the inner faces first
    std::size_t innerTriangles = 0;        ///< triangles [0, innerTriangles) are inner faces, the rest outer ones
};

/// Removes points of `mesh` (Schroeder et al., "Decimation of triangle meshes", 1992: VTK's vtkDecimatePro, which
/// keeps the points it does not remove where they are) from its inner and its outer faces separately (`outer`: one
/// flag per triangle; empty: all inner), so the two sets still meet where they did. With no reduction the triangles
/// stay as they are, in their order. Deterministic. vtkDecimatePro does not bound the triangles' shape: slivers
/// appear.
[[nodiscard]] DecimatedSurface decimateForView(const SurfaceMesh& mesh, const std::vector<bool>& outer,
                                               const ViewDecimationParams& params = {});

/// Whether an OpenGL renderer string (glGetString(GL_RENDERER)) names a software rasterizer: Mesa's llvmpipe,
/// softpipe or swrast, SwiftShader, Microsoft's basic render driver.
[[nodiscard]] bool isSoftwareRenderer(std::string_view glRenderer);

} // namespace hs::simrender
