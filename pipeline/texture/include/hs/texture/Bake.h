#pragma once
/// Baking the appearance of the final surface into texture maps: the texture stage of the pipeline.
///
/// The surface (the boundary of the tetrahedral mesh, with its labels) gets a UV atlas; each appearance class gets a
/// tileable base texture synthesized from its exemplar; vessels are grown on the surface. Every texel is then shaded
/// from its 3-D position: the base textures by triplanar projection (so both sides of a chart seam sample the same
/// point and seams stay invisible), the vessels by distance to their segments, classes blended by smoothed per-vertex
/// weights where they meet; the vessels beneath the mucosa darken it. Height (mucosa bumps, canal folds) becomes a
/// tangent-space normal map.
///
/// Labels read (face labels; a surface without them is all endometrium):
///  - `appearanceLabel` (default "region"): values listed in myomaValues / polypValues are myoma / polyp, everything
///    else endometrium.
///  - `contactLabel` (default "contact"): a non-zero value marks a face at a pathology contact; its appearance is
///    blended half-and-half with the endometrium before smoothing.
///  - `canalLabel` (default "tissue"): values listed in canalValues are the cervical canal (unless the appearance
///    label makes the face a pathology).

#include "hs/core/Image.h"
#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/Subdivision.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/Timings.h"
#include "hs/texture/Atlas.h"
#include "hs/texture/Exemplars.h"
#include "hs/texture/Vessels.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hs::texture {

struct AppearanceLabels {
    std::string appearanceLabel = "region"; ///< face label that says which tissue a face belongs to
    std::vector<std::int32_t> myomaValues;  ///< values of appearanceLabel that are myoma
    std::vector<std::int32_t> polypValues;  ///< values of appearanceLabel that are polyp
    std::string contactLabel = "contact";   ///< face label marking contact faces (non-zero)
    std::string canalLabel = "tissue";      ///< face label that says which faces line the cervical canal
    std::vector<std::int32_t> canalValues;  ///< values of canalLabel that are the canal; empty: no canal
};

/// The cervical canal's frame, for the relief the bake draws on the canal's faces (docs/texture.md, "The cervical
/// canal"): the anterior and posterior longitudinal ridges with the oblique palmate folds branching from them (the
/// plicae palmatae, the arbor vitae), smoothing out towards the isthmus, and the internal os as a paler ring.
struct CanalFrame {
    Vec3 externalOsMm;   ///< centre of the external os
    Vec3 internalOsMm;   ///< centre of the internal os
    Vec3 anterior;       ///< towards the anterior wall (need not be perpendicular to the canal's axis)
    double radiusMm = 0; ///< the canal's largest distance from its axis: the os's ring reaches this + 2 mm from it
    /// The wall's typical distance from the axis (e.g. the median over its points): the folds' places around the
    /// wall are measured on a circle of this radius. 0: radiusMm. At most radiusMm.
    double wallRadiusMm = 0;
};

/// A round spot whose albedo darkens towards its centre (an opening whose depth the light does not reach: the tubal
/// ostia). The factor at distance d < radius is 1 - strength (1 - (d / radius)^2)^2.
struct DarkSpot {
    Vec3 centreMm;
    double radiusMm = 1.0;
    double strength = 0.85; ///< 0..1
};

struct BakeParams {
    int size = 2048;           ///< texture side, texels (64..8192)
    int padding = 0;           ///< gutter texels; <= 0: size / 256, at least 2
    int baseTextureSize = 512; ///< side of each synthesized, tileable base texture (64..4096)
    double tileMm = 20.0;      ///< mm of surface covered by one base-texture tile
    std::array<std::string, kAppearanceCount> exemplarFiles; ///< per class; empty: the procedural default
    /// The endometrium's state (the patient's cycle phase or menopause): its procedural exemplar, the density of its
    /// surface vessels and the height of its relief (endometrialSurface). A user's exemplar replaces only the first.
    EndometrialState endometrium = EndometrialState::Proliferative;
    AppearanceLabels labels;
    double blendMm = 2.5; ///< approximate width of the blend between classes, mm
    bool vessels = true;
    VesselParams vesselParams;       ///< its seed is replaced by one derived from `seed`
    double bumpMm = 0.06;            ///< height of the mucosa bumps from the base texture's luminance, mm
    double normalStrength = 1.0;     ///< scale of the slopes in the normal map
    std::vector<DarkSpot> darkSpots; ///< applied to the albedo after the vessels
    std::optional<CanalFrame> canal; ///< the canal's folds and the internal os's ring; none: the canal's look only
    std::uint64_t seed = 1;          ///< same seed, same maps
    int threads = 0;                 ///< 0: all cores; the maps do not depend on it
};

/// How a normal map's relief agrees across the chart seams of a surface (normalSeamAngles): at three places along each
/// seam edge, the angle between the normals a renderer rebuilds on its two sides from the map (bilinear samples; the
/// tangent dP/du of each face, the points' normals, B = N x T), against the angle between the normal at the seam and
/// the one a texel into the same face (the relief's own change over a texel). The relief is one surface on both sides,
/// so a map whose slopes are right turns across a seam no more than within a chart (ratio about 1); a chart whose
/// slopes are off shows as a patch with straight edges.
struct NormalSeamStats {
    std::int64_t samples = 0;
    double medianDeg = 0.0, p95Deg = 0.0, maxDeg = 0.0; ///< across the seams
    double insideP95Deg = 0.0;                          ///< a texel into the faces beside them
    double ratio = 0.0;                                 ///< mean squared angle across / mean squared angle inside
};
struct BakeStats {
    AtlasStats atlas;
    std::int64_t coveredTexels = 0;      ///< texels inside some triangle (before the gutter fill)
    std::int64_t facesWithoutTexels = 0; ///< faces that own no texel (tiny faces; still covered by a neighbour's)
    double chartSeamRatio = 0.0; ///< mean squared albedo step across chart seams / inside charts (about 1: invisible)
    NormalSeamStats normalSeams; ///< the normal map across the baked surface's chart seams
    std::array<std::int64_t, kAppearanceCount> facesPerClass{};
    std::int64_t vesselSegments = 0;
};

struct BakeResult {
    Atlas atlas;
    VesselNetwork vessels;
    ImageU8 albedo;    ///< RGB, sRGB
    ImageU8 normal;    ///< RGB, tangent space (x along +u, y along +v, z out), OpenGL convention
    ImageU8 roughness; ///< 1 channel, 0 smooth .. 255 rough
    ImageU8 coverage;  ///< 1 channel: 255 texel centre inside a triangle, 128 texel touched by one, 0 gutter
    std::array<ImageU8, kAppearanceCount> baseTextures; ///< the synthesized tiles
    std::vector<Appearance> faceAppearance;
    BakeStats stats;
    StageTimings timings; ///< atlas, synthesis, vessels, rasterize, shade, normals, gutter
    std::vector<std::string> warnings;
};

/// Which class each face is, from the labels (see above).
std::vector<Appearance> classifyFaces(const SurfaceMesh& surface, const AppearanceLabels& labels);

/// An exemplar image file as the texture stage reads it: 8-bit RGB, each side within the synthesis' exemplar limits
/// (SynthesisParams::kMinExemplarSide..kMaxExemplarSide). Errors name the file and the allowed range.
[[nodiscard]] Result<ImageU8> readExemplarFile(const std::string& path);

/// Bakes the maps of `surface`. Fails with InvalidInput for an invalid or empty surface or an unreadable exemplar
/// (naming the file), LimitExceeded for sizes out of range (naming the parameter), Cancelled on request.
[[nodiscard]] Result<BakeResult> bakeAppearance(const SurfaceMesh& surface, const BakeParams& params,
                                                Progress& progress = Progress::none());

/// Writes albedo.png, normal.png, roughness.png, surface.vtp (ASCII; points split along chart seams, point data
/// "uv" and "normals" as the active texture coordinates and normals, the face labels and "chart" as cell data) and
/// surface.obj + surface.mtl into `dir` (created if missing), every file atomically, through hs::io's writers.
Status writeBakeOutputs(const SurfaceMesh& surface, const BakeResult& result, const std::string& dir);

/// The surface split along chart seams, one point per UV vertex, with the UVs; labels carried over (vertex labels
/// through each UV vertex's source vertex). Face label "chart" added.
struct TexturedSurface {
    SurfaceMesh mesh;
    /// Per point, the atlas's (u, v) with v upwards: the texel row of v is (1 - v) * size from the maps' top row (the
    /// OBJ and VTK convention, as surface.obj and surface.vtp store it). A scene::VisualSurface's UVs have their
    /// origin at the top left: its v is 1 - this v.
    std::vector<std::array<float, 2>> uv;
    std::vector<Vec3> normals; ///< per point, of the unsplit surface, so shading stays smooth across seams
};
TexturedSurface makeTexturedSurface(const SurfaceMesh& surface, const Atlas& atlas);

/// A funnel pressed into the surface: every point within `radiusMm` of `centreMm` whose normal faces like `normal`
/// (cosine above 0.5) moves by depthMm (1 - (d / radius)^2)^2 against `normal` (the outward unit normal there).
struct SurfacePit {
    Vec3 centreMm;
    Vec3 normal;
    double radiusMm = 1.0;
    double depthMm = 2.0;
};

/// How makeCloseUpSurface refines.
struct CloseUpParams {
    int levels = 2;                 ///< Loop levels (>= 0); each quadruples the triangles (generate: at most 3)
    std::vector<std::int32_t> seen; ///< per face of the input: nonzero where the scope sees it (empty: everywhere)
    TaubinParams smoothing;         ///< applied to the seen faces' points before subdividing (iterations 0: none)
    std::vector<SurfacePit> pits;   ///< carved into the subdivided surface, before its normals
};

/// The visual surface for close-ups: the seen part of `surface` faired (taubinSmooth, removing the fins and spikes
/// of a faceted tet boundary), then `levels` levels of Loop subdivision (hs/core/Subdivision.h; each child face
/// keeps its parent's labels and chart, its UVs linear on the parent's UV triangle, so it shows the same texels as
/// the part of the parent it covers and seams stay where they were), then split along chart seams like
/// makeTexturedSurface, with the area-weighted normals of the unsplit smooth surface. Vertex labels are not carried
/// (the new points have none). Points are numbered in order of first use.
TexturedSurface makeCloseUpSurface(const SurfaceMesh& surface, const Atlas& atlas, const CloseUpParams& params);

/// The normal map's agreement across the chart seams of `drawn` (NormalSeamStats).
NormalSeamStats normalSeamAngles(const TexturedSurface& drawn, const ImageU8& normal);

} // namespace hs::texture
