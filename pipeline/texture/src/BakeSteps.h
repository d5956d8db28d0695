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
    std::vector<std::array<float, 2>> bary; ///< weights of corners 1 and 2
    std::vector<std::uint8_t> exact;        ///< 1: texel centre inside the face; 0: touched only
    std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(size) + x; }
};

/// Vessel segments bucketed by grid cell for per-texel lookups.
struct VesselIndex {
    PointGrid grid;
    const std::vector<VesselSegment>* segments = nullptr;
    double reach = 0.0; ///< largest radius + margin, mm
    double query = 0.0; ///< search radius around a point for segment midpoints, mm
};

struct VesselSample {
    float cover = 0.0f;  ///< 0..1, already times contrast
    float radius = 0.0f; ///< mm of the covering vessel
    float height = 0.0f; ///< relief, mm
};

struct Shading {
    ImageU8 albedo, roughness;
    std::vector<float> height;
    std::vector<std::uint8_t> covered;
};

// Shading.cpp
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

/// The vessel covering p, if any: the strongest within one texel of its drawn width.
VesselSample sampleVessels(const VesselIndex& index, const Vec3& p, double texelMm, double cellHalf);

/// Blood colour by calibre: capillaries bright red, larger (deeper) vessels darker and bluer.
void vesselColour(float radius, float* rgb);

// NormalMap.cpp
/// Tangent-space normals from height differences inside each chart (x along +u, y along +v).
ImageU8 normalMap(const TexelMap& map, const Shading& shading, const Atlas& atlas, double texelMm, double strength,
                  int threads);

// Gutters.cpp
/// Fills the gutters: `rings` passes of averaging covered 8-neighbours into empty texels (so mipmaps and bilinear
/// filtering at chart borders fetch chart colours), then a constant for what is still empty.
void fillGutters(std::vector<ImageU8*> images, std::vector<std::uint8_t> covered, int size, int rings,
                 const std::vector<std::array<std::uint8_t, 4>>& fallback);

// SeamCheck.cpp
/// Mean squared albedo step across chart seams (both sides sampled at the same surface points) over the mean squared
/// step between horizontally neighbouring texels of one chart.
double chartSeamRatio(const SurfaceMesh& mesh, const Atlas& atlas, const ImageU8& albedo, const TexelMap& map);

} // namespace hs::texture::detail
