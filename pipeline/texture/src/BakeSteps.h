#pragma once
/// The steps of the bake (bakeAppearance): the texel map, the per-texel shading and the finished maps.

#include "hs/core/PointGrid.h"

#include "hs/texture/Bake.h"

#include <array>
#include <cstdint>
#include <vector>

namespace hs::texture::detail {

using Weights3 = std::array<float, kAppearanceCount>;

/// A tileable base texture as floats for bilinear sampling, with its mean luminance.
struct Tile {
    int size = 0;
    std::vector<float> rgb;
    float meanLum = 0.0f;

    void sample(double s, double t, float* out) const {
        const double fx = s * size - 0.5, fy = t * size - 0.5;
        const double x0f = std::floor(fx), y0f = std::floor(fy);
        const auto ax = static_cast<float>(fx - x0f), ay = static_cast<float>(fy - y0f);
        const auto wrap = [this](double v) {
            const auto i = static_cast<long long>(v) % size;
            return static_cast<std::size_t>(i < 0 ? i + size : i);
        };
        const std::size_t x0 = wrap(x0f), x1 = wrap(x0f + 1), y0 = wrap(y0f), y1 = wrap(y0f + 1);
        const auto n = static_cast<std::size_t>(size);
        for (std::size_t c = 0; c < 3; ++c) {
            const float a = rgb[(y0 * n + x0) * 3 + c], b = rgb[(y0 * n + x1) * 3 + c];
            const float d = rgb[(y1 * n + x0) * 3 + c], e = rgb[(y1 * n + x1) * 3 + c];
            out[c] = (a + (b - a) * ax) * (1 - ay) + (d + (e - d) * ax) * ay;
        }
    }
};

/// Which face (and where in it) each texel shows.
struct TexelMap {
    int size = 0;
    std::vector<std::int32_t> face;
    /// Weights of corners 1 and 2; a texel outside its face (exact 0) has weights beyond 0..1: the face extended.
    std::vector<std::array<float, 2>> bary;
    std::vector<std::uint8_t> exact; ///< 1: texel centre inside the face; 0: within a texel outside it
    std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(size) + x; }
};

/// Vessel segments bucketed by grid cell for per-texel lookups.
struct VesselIndex {
    PointGrid grid;
    const std::vector<VesselSegment>* segments = nullptr;
    double reach = 0.0; ///< largest radius + margin, mm
    double query = 0.0; ///< search radius around a point for segment midpoints, mm
};

/// What the vessels beneath a point take from the light its mucosa remits, per channel (red, green, blue), 0..1,
/// already times their class's contrast: the strongest of them in each channel (vesselShadow).
struct VesselSample {
    std::array<float, 3> shadow{};
};

struct Shading {
    ImageU8 albedo, roughness;
    std::vector<float> height;
    std::vector<std::uint8_t> covered;
};

// Shading.cpp
/// The canal's frame in the form the texels need it.
struct CanalAxes {
    Vec3 origin, axis, anterior, lateral;
    double lengthMm = 0.0, radiusMm = 0.0, wallRadiusMm = 0.0;
};

CanalAxes canalAxes(const CanalFrame& c);

/// What the canal's relief does at p: its height (mm), how much of it is folds (0..1) and where the crests are
/// (0 cleft .. 1 crest), and the internal os's ring (0..1); how close p lies to the canal's lumen (1 within its
/// width + 1 mm of the axis, 0 beyond + 2 mm) and the canal's share of the mucosa there by the distance along the
/// axis (1 below the internal os, 0 above it, over 1.5 mm either side).
struct CanalRelief {
    double foldHeightMm = 0.0, ringHeightMm = 0.0;
    float folds = 0.0f, crest = 0.0f, ring = 0.0f;
    float lumen = 0.0f, canalShare = 0.0f;
};

CanalRelief canalRelief(const CanalAxes& a, const Vec3& p);

Tile toTile(const ImageU8& image);

/// Per-vertex class weights: incident face classes (contact faces half endometrium), smoothed over ~blendMm.
std::vector<Weights3> vertexWeights(const SurfaceMesh& mesh, const std::vector<Appearance>& faceClass,
                                    const AppearanceLabels& labels, double blendMm);

/// The albedo and roughness of every texel; stops between rows once `progress` is cancelled (the caller then
/// returns Cancelled and the partial maps are dropped).
Shading shade(const SurfaceMesh& mesh, const TexelMap& map, const std::vector<Vec3>& normals,
              const std::vector<Weights3>& weights, const std::array<Tile, kAppearanceCount>& tiles,
              const VesselIndex& vessels, const BakeParams& params, double texelMm, int threads,
              const Progress& progress);

// TexelMap.cpp
TexelMap rasterize(const SurfaceMesh& mesh, const Atlas& atlas, int threads);

// VesselIndex.cpp
VesselIndex indexVessels(const VesselNetwork& net, double texelMm);

/// The vessels' shadow at p (VesselSample), over every vessel whose shadow reaches it.
VesselSample sampleVessels(const VesselIndex& index, const Vec3& p, double texelMm, double cellHalf);

// NormalMap.cpp
/// Tangent-space normals: the relief's surface gradient inside each chart, in the frame a renderer rebuilds (T along
/// +u, B = N x T with N the face's normal); `texelMm` serves only faces too thin to have a frame.
ImageU8 normalMap(const SurfaceMesh& mesh, const TexelMap& map, const Shading& shading, const Atlas& atlas,
                  double texelMm, double strength, int threads);

// Gutters.cpp
/// Fills the gutters: `rings` passes of averaging covered 8-neighbours into empty texels (so mipmaps and bilinear
/// filtering at chart borders fetch chart colours), then a constant for what is still empty.
void fillGutters(std::vector<ImageU8*> images, std::vector<std::uint8_t> covered, int size, int rings,
                 const std::vector<std::array<std::uint8_t, 4>>& fallback);

// SeamCheck.cpp
/// Bilinear sample of the first three channels of `img` at (u, v) (v upwards, texel row (1 - v) * height).
void sampleBilinear(const ImageU8& img, double u, double v, double* out);

/// Mean squared albedo step across chart seams (both sides sampled at the same surface points) over the mean squared
/// step between horizontally neighbouring texels of one chart.
double chartSeamRatio(const SurfaceMesh& mesh, const Atlas& atlas, const ImageU8& albedo, const TexelMap& map);

} // namespace hs::texture::detail
