#pragma once
/// A UV atlas on a triangle surface: charts, their parameterisation and their packing into one square texture.
///
/// Charts: faces are grouped by the closest of 26 fixed directions to their normal (the cube's faces, edges and
/// corners), smoothed by neighbour majority, split into connected components; each chart is projected onto the plane
/// of its mean normal, and faces that would fold (projected area near zero or negative) are split off into charts of
/// their own, so every triangle gets positive UV area. Charts are rotated to their principal axes and shelf-packed at
/// one common scale (texels per mm) with `padding` empty texels around each, the largest scale that fits.

#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace hs::texture {

struct AtlasParams {
    int size = 2048;           ///< texture side in texels (64..8192)
    int padding = 0;           ///< texels of empty gutter around each chart; <= 0: size / 256, at least 2
    double maxAngleDeg = 40.0; ///< largest angle between a face normal and its chart's direction (10..80)
    int minChartFaces = 8;     ///< smaller components are merged into a neighbouring chart where the angle allows
};

/// A UV vertex: a mesh vertex as seen from one chart (vertices on chart borders have one per chart).
struct UvVertex {
    std::int32_t vertex = 0; ///< index into the surface's points
    double u = 0.0;          ///< [0, 1], left to right
    double v = 0.0;          ///< [0, 1], bottom to top (OpenGL/VTK convention: texel row = (1 - v) * size)
};

struct AtlasStats {
    int charts = 0;
    double l2Stretch = 1.0;   ///< area-weighted L2 stretch (Sander et al. 2001), normalised so 1 is isometric
    double maxStretch = 1.0;  ///< largest singular value of the UV-to-surface map over all faces, normalised alike
    double texelsPerMm = 0.0; ///< common scale of all charts
    double fill = 0.0;        ///< fraction of the texture covered by charts (without gutters)
    int padding = 0;          ///< gutter texels used
};

struct Atlas {
    int size = 0; ///< texture side, texels
    std::vector<UvVertex> uvVertices;
    std::vector<std::array<std::int32_t, 3>> uvTriangles; ///< per face: indices into uvVertices
    std::vector<std::int32_t> chartOfFace;                ///< per face
    AtlasStats stats;
};

/// Builds the atlas of `surface`. Fails with InvalidInput for an invalid or empty surface, LimitExceeded for a size
/// outside 64..8192, Cancelled on request.
[[nodiscard]] Result<Atlas> buildAtlas(const SurfaceMesh& surface, const AtlasParams& params,
                                       Progress& progress = Progress::none());

} // namespace hs::texture
