// Per-texel shading: base textures blended by class, vessels drawn over them, roughness and relief.
#include "BakeSteps.h"

#include "hs/core/Parallel.h"

#include <algorithm>
#include <cmath>

namespace hs::texture::detail {

namespace {

/// Per-class look besides the base texture.
struct ClassLook {
    float roughness; ///< 0..1
    float bump;      ///< factor on BakeParams::bumpMm
};
constexpr std::array<ClassLook, kAppearanceCount> kLooks{{{0.42f, 1.0f}, {0.62f, 0.45f}, {0.22f, 0.2f}}};

/// Triplanar sample of a tile at p with normal n (Geiss 2007): three planar projections blended by |n|^4.
void triplanar(const Tile& tile, const Vec3& p, const Vec3& n, double tileMm, float* out) {
    double wx = n.x * n.x, wy = n.y * n.y, wz = n.z * n.z;
    wx *= wx;
    wy *= wy;
    wz *= wz;
    const double sum = wx + wy + wz;
    float a[3], b[3], c[3];
    tile.sample(p.y / tileMm, p.z / tileMm, a);
    tile.sample(p.z / tileMm + 0.37, p.x / tileMm + 0.61, b);
    tile.sample(p.x / tileMm + 0.13, p.y / tileMm + 0.29, c);
    for (int k = 0; k < 3; ++k)
        out[k] = sum > 0.0 ? static_cast<float>((a[k] * wx + b[k] * wy + c[k] * wz) / sum) : a[k];
}

} // namespace

Tile toTile(const ImageU8& image) {
    Tile tile;
    tile.size = image.width();
    tile.rgb.resize(image.data().size());
    double lum = 0.0;
    for (std::size_t i = 0; i < image.data().size(); ++i) {
        tile.rgb[i] = image.data()[i] / 255.0f;
        lum += tile.rgb[i];
    }
    tile.meanLum = static_cast<float>(lum / static_cast<double>(image.data().size()));
    return tile;
}
/// Per-vertex class weights: incident face classes (contact faces half endometrium), smoothed over ~blendMm.
std::vector<Weights3> vertexWeights(const SurfaceMesh& mesh, const std::vector<Appearance>& faceClass,
                                    const AppearanceLabels& labels, double blendMm) {
    const auto nv = mesh.points.size();
    std::vector<Weights3> w(nv, Weights3{});
    const auto contact = mesh.faceLabels.find(labels.contactLabel);
    const bool hasContact = contact != mesh.faceLabels.end() && contact->second.size() == mesh.triangles.size();
    double edgeSum = 0.0;
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        Weights3 fw{};
        fw[static_cast<std::size_t>(faceClass[f])] = 1.0f;
        if (hasContact && contact->second[f] != 0) {
            for (auto& x : fw)
                x *= 0.5f;
            fw[0] += 0.5f;
        }
        const auto& t = mesh.triangles[f];
        for (std::int32_t v : t)
            for (std::size_t c = 0; c < kAppearanceCount; ++c)
                w[static_cast<std::size_t>(v)][c] += fw[c];
        edgeSum += distance(mesh.points[static_cast<std::size_t>(t[0])], mesh.points[static_cast<std::size_t>(t[1])]);
    }
    for (auto& x : w) {
        const float s = x[0] + x[1] + x[2];
        for (auto& c : x)
            c = s > 0 ? c / s : 0.0f;
        if (s <= 0)
            x[0] = 1.0f;
    }
    const double meanEdge = mesh.triangles.empty() ? 1.0 : edgeSum / static_cast<double>(mesh.triangles.size());
    // Diffusion spreads about sqrt(iterations) edges; square to reach blendMm.
    const double edges = blendMm / std::max(1e-6, meanEdge);
    const int iterations = std::min(200, static_cast<int>(std::lround(edges * edges)));
    if (iterations == 0)
        return w;
    std::vector<std::vector<std::int32_t>> nbr(nv);
    for (const auto& t : mesh.triangles)
        for (std::size_t k = 0; k < 3; ++k) {
            nbr[static_cast<std::size_t>(t[k])].push_back(t[(k + 1) % 3]);
            nbr[static_cast<std::size_t>(t[k])].push_back(t[(k + 2) % 3]);
        }
    for (auto& n : nbr) {
        std::sort(n.begin(), n.end());
        n.erase(std::unique(n.begin(), n.end()), n.end());
    }
    std::vector<Weights3> next(nv);
    for (int it = 0; it < iterations; ++it) {
        for (std::size_t v = 0; v < nv; ++v) {
            Weights3 s = w[v];
            for (std::int32_t u : nbr[v])
                for (std::size_t c = 0; c < kAppearanceCount; ++c)
                    s[c] += w[static_cast<std::size_t>(u)][c];
            const auto n = static_cast<float>(nbr[v].size() + 1);
            for (std::size_t c = 0; c < kAppearanceCount; ++c)
                next[v][c] = s[c] / n;
        }
        w.swap(next);
    }
    return w;
}
Shading shade(const SurfaceMesh& mesh, const TexelMap& map, const std::vector<Vec3>& normals,
              const std::vector<Weights3>& weights, const std::array<Tile, kAppearanceCount>& tiles,
              const VesselIndex& vessels, const BakeParams& params, double texelMm, int threads,
              const Progress& progress) {
    Shading out;
    const int n = map.size;
    out.albedo = ImageU8::create(n, n, 3).value();
    out.roughness = ImageU8::create(n, n, 1).value();
    out.height.assign(static_cast<std::size_t>(n) * n, 0.0f);
    out.covered.assign(static_cast<std::size_t>(n) * n, 0);
    const double cellHalf = vessels.query;
    std::array<float, kAppearanceCount> relief{1.0f, 1.0f, 1.0f};
    relief[static_cast<std::size_t>(Appearance::Endometrium)] =
        static_cast<float>(endometrialSurface(params.endometrium).relief);
    parallelChunks(static_cast<std::size_t>(n), evenChunk(static_cast<std::size_t>(n), threads), threads,
                   [&](std::size_t, std::size_t y0Chunk, std::size_t y1Chunk) {
                       const int y0 = static_cast<int>(y0Chunk), y1 = static_cast<int>(y1Chunk);
                       for (int y = y0; y < y1 && !progress.cancelled(); ++y)
                           for (int x = 0; x < n; ++x) {
                               const std::size_t i = map.index(x, y);
                               const std::int32_t f = map.face[i];
                               if (f < 0)
                                   continue;
                               const auto& t = mesh.triangles[static_cast<std::size_t>(f)];
                               const float b1 = map.bary[i][0], b2 = map.bary[i][1], b0 = 1.0f - b1 - b2;
                               const std::array<float, 3> b{b0, b1, b2};
                               Vec3 p, nrm;
                               Weights3 w{};
                               for (std::size_t k = 0; k < 3; ++k) {
                                   const auto v = static_cast<std::size_t>(t[k]);
                                   p += mesh.points[v] * b[k];
                                   nrm += normals[v] * b[k];
                                   for (std::size_t c = 0; c < kAppearanceCount; ++c)
                                       w[c] += weights[v][c] * b[k];
                               }
                               nrm = normalized(nrm);
                               float rgb[3] = {0, 0, 0};
                               float rough = 0.0f, bump = 0.0f;
                               for (std::size_t c = 0; c < kAppearanceCount; ++c) {
                                   if (w[c] < 1e-3f || tiles[c].size == 0)
                                       continue;
                                   float s[3];
                                   triplanar(tiles[c], p, nrm, params.tileMm, s);
                                   const float lum = (s[0] + s[1] + s[2]) / 3.0f;
                                   for (int k = 0; k < 3; ++k)
                                       rgb[k] += w[c] * s[k];
                                   rough += w[c] * (kLooks[c].roughness + 0.25f * (tiles[c].meanLum - lum));
                                   bump += w[c] * kLooks[c].bump * relief[c] * (lum - tiles[c].meanLum);
                               }
                               const VesselSample v = sampleVessels(vessels, p, texelMm, cellHalf);
                               if (v.cover > 0.0f) {
                                   float vc[3];
                                   vesselColour(v.radius, vc);
                                   for (int k = 0; k < 3; ++k)
                                       rgb[k] += (vc[k] - rgb[k]) * v.cover;
                                   rough += (0.3f - rough) * v.cover;
                               }
                               for (const DarkSpot& spot : params.darkSpots) {
                                   const double d = distance(p, spot.centreMm);
                                   if (d >= spot.radiusMm)
                                       continue;
                                   const double q = 1.0 - (d / spot.radiusMm) * (d / spot.radiusMm);
                                   const auto keep = static_cast<float>(1.0 - spot.strength * q * q);
                                   for (float& c : rgb)
                                       c *= keep;
                               }
                               for (int k = 0; k < 3; ++k)
                                   out.albedo.at(x, y, k) =
                                       static_cast<std::uint8_t>(std::lround(std::clamp(rgb[k], 0.0f, 1.0f) * 255.0f));
                               out.roughness.at(x, y) =
                                   static_cast<std::uint8_t>(std::lround(std::clamp(rough, 0.02f, 1.0f) * 255.0f));
                               out.height[i] = static_cast<float>(params.bumpMm) * bump + v.height;
                               out.covered[i] = 1;
                           }
                   });
    return out;
}

} // namespace hs::texture::detail
