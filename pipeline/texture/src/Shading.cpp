// Per-texel shading: base textures blended by class, vessels drawn over them, roughness and relief.
#include "BakeSteps.h"

#include "hs/core/Parallel.h"
#include "hs/core/Units.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace hs::texture::detail {

namespace {

/// Per-class look besides the base texture.
struct ClassLook {
    float roughness; ///< 0..1
    float bump;      ///< factor on BakeParams::bumpMm
};
/// The endocervix's mucus glistens like the polyp's surface, rougher than it (papillae and clefts).
constexpr std::array<ClassLook, kAppearanceCount> kLooks{{{0.42f, 1.0f}, {0.62f, 0.45f}, {0.22f, 0.2f}, {0.30f, 0.8f}}};

/// The canal's folds (docs/texture.md, "The cervical canal"): a longitudinal ridge on the anterior and on the
/// posterior wall with oblique palmate folds branching upwards and outwards from it, the posterior ones between the
/// anterior ones rather than opposite them (Gray 1918); the folds die out on the lateral walls and towards the
/// isthmus, whose mucosa is smooth (Mhaskar). Heights and spacing are drawn to read at the scope's distance: about
/// ten folds a side over the canal, their slopes gentle enough that the lamp at 2 mm does not turn them black.
constexpr double kRidgeHalfWidthMm = 0.7;   ///< the longitudinal ridge's 1/e half-width
constexpr double kRidgeHeightMm = 0.1;      ///< the ridge's height
constexpr double kFoldSpacingMm = 2.6;      ///< between neighbouring palmate folds along the canal
constexpr double kFoldRisePerMm = 0.8;      ///< a fold climbs this many mm along the canal per mm away from the ridge
constexpr double kFoldHeightMm = 0.05;      ///< a palmate fold's height
constexpr double kFoldFullRad = 0.8;        ///< folds at full height up to this angle from their ridge ...
constexpr double kFoldEndRad = 1.35;        ///< ... and gone at this one (the lateral walls are smooth)
constexpr double kChevronRoundMm = 0.35;    ///< the V of the folds at the ridge rounded over about this width
constexpr double kSmoothIsthmusShare = 0.2; ///< the top fifth of the canal smooths out towards the internal os
constexpr double kOsRingHalfWidthMm = 0.9;  ///< the internal os's ring, its 1/e half-width along the canal
constexpr double kOsRingHeightMm = 0.08;    ///< the ring's fold height
constexpr float kOsRingPallor = 0.35f;      ///< the ring's blend towards the pale fibrous colour at its middle
constexpr float kFoldPallor = 0.25f;        ///< a fold's crest blends this far towards the pale colour ...
constexpr float kCleftShade = 0.18f;        ///< ... and its clefts darken by this share
constexpr std::array<float, 3> kPaleMucosa{0.94f, 0.80f, 0.78f};

double smoothstep(double edge0, double edge1, double x) {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

} // namespace

CanalAxes canalAxes(const CanalFrame& c) {
    CanalAxes a;
    a.origin = c.externalOsMm;
    a.lengthMm = distance(c.externalOsMm, c.internalOsMm);
    a.axis = normalized(c.internalOsMm - c.externalOsMm);
    a.anterior = normalized(c.anterior - a.axis * dot(c.anterior, a.axis));
    a.lateral = cross(a.axis, a.anterior);
    a.radiusMm = c.radiusMm;
    a.wallRadiusMm = c.wallRadiusMm > 0.0 ? c.wallRadiusMm : c.radiusMm;
    return a;
}

CanalRelief canalRelief(const CanalAxes& a, const Vec3& p) {
    CanalRelief r;
    const Vec3 q = p - a.origin;
    const double s = dot(q, a.axis);
    const double x = dot(q, a.lateral), y = dot(q, a.anterior);
    const double rho = std::sqrt(x * x + y * y);
    if (rho > a.radiusMm + 2.0)
        return r; // the serosa, the cavity's sides: not the canal's lumen
    r.lumen = static_cast<float>(1.0 - smoothstep(a.radiusMm + 1.0, a.radiusMm + 2.0, rho));
    r.canalShare = static_cast<float>(1.0 - smoothstep(a.lengthMm - 1.5, a.lengthMm + 1.5, s));
    // Faded with the lumen, like the folds below, so that nothing is cut off where the relief stops.
    const double ring =
        r.lumen * std::exp(-((s - a.lengthMm) / kOsRingHalfWidthMm) * ((s - a.lengthMm) / kOsRingHalfWidthMm));
    r.ring = static_cast<float>(ring);
    r.ringHeightMm = kOsRingHeightMm * ring;
    if (s <= 0.0 || s >= a.lengthMm)
        return r;
    const double theta = std::atan2(x, y); // 0 anterior, +-pi posterior
    const bool anteriorWall = std::abs(theta) < 0.5 * units::kPi;
    const double fromRidgeRad = anteriorWall ? std::abs(theta) : units::kPi - std::abs(theta);
    // Along the wall from the ridge, measured on the circle of the wall's typical radius: the local distance from the
    // axis would carry the coarse canal's facets into the folds (a facet is nearer the axis at its middle than at its
    // edges), and the folds' slopes would turn at every facet's edge. The V where the folds leave the ridge is rounded
    // off over kChevronRoundMm.
    const double straightMm = fromRidgeRad * a.wallRadiusMm;
    const double arcMm = std::sqrt(straightMm * straightMm + kChevronRoundMm * kChevronRoundMm) - kChevronRoundMm;
    const double fromRidge = fromRidgeRad;
    const double along =
        smoothstep(0.0, 1.5, s) * (1.0 - smoothstep((1.0 - kSmoothIsthmusShare) * a.lengthMm, a.lengthMm, s));
    const double ridge = std::exp(-(arcMm / kRidgeHalfWidthMm) * (arcMm / kRidgeHalfWidthMm));
    const double phase = (s - kFoldRisePerMm * arcMm) / kFoldSpacingMm + (anteriorWall ? 0.0 : 0.5);
    const double wave = 0.5 + 0.5 * std::cos(2.0 * units::kPi * (phase - std::floor(phase)));
    const double fold = wave * wave * (1.0 - smoothstep(kFoldFullRad, kFoldEndRad, fromRidge));
    const double reach = std::max(ridge, 1.0 - smoothstep(kFoldFullRad, kFoldEndRad, fromRidge));
    const double height = kRidgeHeightMm * ridge + kFoldHeightMm * fold;
    // Faded with the lumen (beyond the lumen's width + 2 mm the relief stops).
    r.foldHeightMm = along * height * r.lumen;
    r.folds = static_cast<float>(along * reach) * r.lumen;
    r.crest = static_cast<float>(std::clamp(height / kRidgeHeightMm, 0.0, 1.0));
    return r;
}

namespace {

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
        float s = 0.0f;
        for (const float c : x)
            s += c;
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
    const std::optional<CanalAxes> canal =
        params.canal ? std::optional<CanalAxes>(canalAxes(*params.canal)) : std::nullopt;
    constexpr auto kCanal = static_cast<std::size_t>(Appearance::CervicalCanal);
    constexpr auto kEndometrium = static_cast<std::size_t>(Appearance::Endometrium);
    std::array<float, kAppearanceCount> relief{};
    relief.fill(1.0f);
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
                               for (float& wc : w) // the face extended past its edge (TexelMap::bary)
                                   wc = std::clamp(wc, 0.0f, 1.0f);
                               // Near the canal, where its faces meet the cavity's, the classes split by the place
                               // along the canal rather than by the faces' weights (which would draw the faces'
                               // outline across the wall).
                               const float lumen = w[kCanal] + w[kEndometrium];
                               std::optional<CanalRelief> cr;
                               if (canal && lumen > 1e-3f) {
                                   cr = canalRelief(*canal, p);
                                   if (tiles[kCanal].size > 0) {
                                       const float wc = w[kCanal] + (lumen * cr->canalShare - w[kCanal]) * cr->lumen;
                                       w[kCanal] = wc;
                                       w[kEndometrium] = lumen - wc;
                                   }
                               }
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
                               double canalHeightMm = 0.0;
                               if (cr) {
                                   const float folds = w[kCanal] * cr->folds, ring = lumen * cr->ring;
                                   for (int k = 0; k < 3; ++k) {
                                       rgb[k] *= 1.0f - kCleftShade * folds * (1.0f - cr->crest);
                                       rgb[k] += (kPaleMucosa[k] - rgb[k]) *
                                                 std::min(1.0f, kFoldPallor * folds * cr->crest + kOsRingPallor * ring);
                                   }
                                   canalHeightMm = w[kCanal] * cr->foldHeightMm + lumen * cr->ringHeightMm;
                               }
                               // The vessels lie beneath the mucosa: they take light from it, not its place, and
                               // neither raise nor roughen its surface.
                               const VesselSample v = sampleVessels(vessels, p, texelMm, cellHalf);
                               for (std::size_t k = 0; k < 3; ++k)
                                   rgb[k] *= 1.0f - v.shadow[k];
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
                               out.height[i] = static_cast<float>(params.bumpMm * bump + canalHeightMm);
                               out.covered[i] = 1;
                           }
                   });
    return out;
}

} // namespace hs::texture::detail
