#include "hs/texture/Bake.h"

#include "MeshAdjacency.h"
#include "Parallel.h"
#include "SpatialGrid.h"

#include "hs/core/Rng.h"
#include "hs/texture/ImageFiles.h"
#include "hs/texture/Synthesis.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace hs::texture {
namespace {

using Weights3 = std::array<float, kAppearanceCount>;

/// Per-class look besides the base texture.
struct ClassLook {
    float roughness; ///< 0..1
    float bump;      ///< factor on BakeParams::bumpMm
};
constexpr std::array<ClassLook, kAppearanceCount> kLooks{{{0.42f, 1.0f}, {0.62f, 0.45f}, {0.22f, 0.2f}}};

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

Status checkParams(const BakeParams& p) {
    if (p.size < 64 || p.size > 8192)
        return fail(ErrorCode::LimitExceeded, "bake size " + std::to_string(p.size) + " outside 64..8192 texels");
    if (p.baseTextureSize < 64 || p.baseTextureSize > 4096)
        return fail(ErrorCode::LimitExceeded,
                    "baseTextureSize " + std::to_string(p.baseTextureSize) + " outside 64..4096 pixels");
    if (!(p.tileMm > 0.1 && p.tileMm < 1000.0))
        return fail(ErrorCode::InvalidInput, "tileMm " + std::to_string(p.tileMm) + " outside 0.1..1000 mm");
    if (!(p.blendMm >= 0.0 && p.blendMm <= 50.0))
        return fail(ErrorCode::InvalidInput, "blendMm " + std::to_string(p.blendMm) + " outside 0..50 mm");
    if (!(p.bumpMm >= 0.0 && p.bumpMm <= 5.0))
        return fail(ErrorCode::InvalidInput, "bumpMm " + std::to_string(p.bumpMm) + " outside 0..5 mm");
    return {};
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

/// Which face (and where in it) each texel shows.
struct TexelMap {
    int size = 0;
    std::vector<std::int32_t> face;
    std::vector<std::array<float, 2>> bary; ///< weights of corners 1 and 2
    std::vector<std::uint8_t> exact;        ///< 1: texel centre inside the face; 0: touched only
    std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(size) + x; }
};

TexelMap rasterize(const SurfaceMesh& mesh, const Atlas& atlas, int threads) {
    TexelMap map;
    map.size = atlas.size;
    const auto n = static_cast<std::size_t>(atlas.size) * atlas.size;
    map.face.assign(n, -1);
    map.bary.assign(n, {0.0f, 0.0f});
    map.exact.assign(n, 0);
    const double s = atlas.size;
    detail::parallelRanges(atlas.size, threads, [&](int rowBegin, int rowEnd) {
        for (int pass = 0; pass < 2; ++pass) { // 0: centres inside; 1: touched texels not yet taken
            for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
                const auto& uvt = atlas.uvTriangles[f];
                std::array<double, 3> X, Y;
                for (std::size_t k = 0; k < 3; ++k) {
                    const UvVertex& q = atlas.uvVertices[static_cast<std::size_t>(uvt[k])];
                    X[k] = q.u * s;
                    Y[k] = (1.0 - q.v) * s;
                }
                const double area2 = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
                if (area2 == 0.0)
                    continue;
                const int x0 = std::max(0, static_cast<int>(std::floor(std::min({X[0], X[1], X[2]}))) - 1);
                const int x1 = std::min(atlas.size - 1, static_cast<int>(std::floor(std::max({X[0], X[1], X[2]}))) + 1);
                const int y0 = std::max(rowBegin, static_cast<int>(std::floor(std::min({Y[0], Y[1], Y[2]}))) - 1);
                const int y1 = std::min(rowEnd - 1, static_cast<int>(std::floor(std::max({Y[0], Y[1], Y[2]}))) + 1);
                // Edge k is opposite corner k; margin: half a texel measured along the edge normal.
                std::array<double, 3> margin;
                for (std::size_t k = 0; k < 3; ++k) {
                    const double ex = X[(k + 2) % 3] - X[(k + 1) % 3], ey = Y[(k + 2) % 3] - Y[(k + 1) % 3];
                    margin[k] = pass == 0 ? 0.0 : 0.5 * (std::fabs(ex) + std::fabs(ey)) / std::fabs(area2);
                }
                for (int y = y0; y <= y1; ++y)
                    for (int x = x0; x <= x1; ++x) {
                        const double px = x + 0.5, py = y + 0.5;
                        std::array<double, 3> l;
                        l[0] = ((X[1] - px) * (Y[2] - py) - (X[2] - px) * (Y[1] - py)) / area2;
                        l[1] = ((X[2] - px) * (Y[0] - py) - (X[0] - px) * (Y[2] - py)) / area2;
                        l[2] = 1.0 - l[0] - l[1];
                        if (l[0] < -margin[0] || l[1] < -margin[1] || l[2] < -margin[2])
                            continue;
                        const std::size_t i = map.index(x, y);
                        if (map.face[i] >= 0)
                            continue;
                        if (pass == 1) { // clamp onto the triangle
                            for (auto& v : l)
                                v = std::max(0.0, v);
                            const double sum = l[0] + l[1] + l[2];
                            for (auto& v : l)
                                v /= sum;
                        }
                        map.face[i] = static_cast<std::int32_t>(f);
                        map.bary[i] = {static_cast<float>(l[1]), static_cast<float>(l[2])};
                        map.exact[i] = pass == 0 ? 1 : 0;
                    }
            }
        }
    });
    return map;
}

/// Vessel segments bucketed by grid cell for per-texel lookups.
struct VesselIndex {
    detail::SpatialGrid grid{1.0};
    const std::vector<VesselSegment>* segments = nullptr;
    double reach = 0.0; ///< largest radius + margin, mm
    double query = 0.0; ///< search radius around a point for segment midpoints, mm
};

VesselIndex indexVessels(const VesselNetwork& net, double texelMm) {
    VesselIndex index;
    index.segments = &net.segments;
    double maxR = 0.0, maxLen = 0.0;
    for (const auto& s : net.segments) {
        maxR = std::max({maxR, s.radiusA, s.radiusB});
        maxLen = std::max(maxLen, distance(s.a, s.b));
    }
    index.reach = maxR + 2.0 * texelMm;
    index.query = 0.5 * maxLen + index.reach;
    index.grid = detail::SpatialGrid(std::max(0.5, index.query));
    for (std::size_t i = 0; i < net.segments.size(); ++i)
        index.grid.insert(static_cast<std::int32_t>(i), (net.segments[i].a + net.segments[i].b) * 0.5);
    return index;
}

struct VesselSample {
    float cover = 0.0f;  ///< 0..1, already times contrast
    float radius = 0.0f; ///< mm of the covering vessel
    float height = 0.0f; ///< relief, mm
};

VesselSample sampleVessels(const VesselIndex& index, const Vec3& p, double texelMm, double cellHalf) {
    VesselSample out;
    if (!index.segments || index.segments->empty())
        return out;
    const auto& segs = *index.segments;
    index.grid.forEachNear(p, cellHalf, [&](std::int32_t id) {
        const VesselSegment& s = segs[static_cast<std::size_t>(id)];
        const Vec3 ab = s.b - s.a;
        const double len2 = norm2(ab);
        const double t = len2 > 0 ? std::clamp(dot(p - s.a, ab) / len2, 0.0, 1.0) : 0.0;
        const double d = distance(p, s.a + ab * t);
        const double r = s.radiusA + (s.radiusB - s.radiusA) * t;
        const double drawn = std::max(r, 0.5 * texelMm); // at least one texel wide, fainter when thinner
        if (d > drawn + texelMm)
            return;
        const double edge = std::clamp((drawn - d) / texelMm + 0.5, 0.0, 1.0);
        const double cover = edge * std::min(1.0, r / (0.5 * texelMm)) * s.contrast;
        if (cover > out.cover) {
            out.cover = static_cast<float>(cover);
            out.radius = static_cast<float>(r);
        }
        if (d < r)
            out.height = std::max(out.height, static_cast<float>(0.5 * r * std::sqrt(1.0 - (d / r) * (d / r))));
    });
    return out;
}

/// Blood colour by calibre: capillaries bright red, larger (deeper) vessels darker and bluer.
void vesselColour(float radius, float* rgb) {
    const float t = std::clamp((radius - 0.03f) / 0.3f, 0.0f, 1.0f);
    rgb[0] = 0.70f + (0.42f - 0.70f) * t;
    rgb[1] = 0.10f + (0.05f - 0.10f) * t;
    rgb[2] = 0.13f + (0.16f - 0.13f) * t;
}

struct Shading {
    ImageU8 albedo, roughness;
    std::vector<float> height;
    std::vector<std::uint8_t> covered;
};

Shading shade(const SurfaceMesh& mesh, const TexelMap& map, const std::vector<Vec3>& normals,
              const std::vector<Weights3>& weights, const std::array<Tile, kAppearanceCount>& tiles,
              const VesselIndex& vessels, const BakeParams& params, double texelMm, int threads) {
    Shading out;
    const int n = map.size;
    out.albedo = ImageU8::create(n, n, 3).value();
    out.roughness = ImageU8::create(n, n, 1).value();
    out.height.assign(static_cast<std::size_t>(n) * n, 0.0f);
    out.covered.assign(static_cast<std::size_t>(n) * n, 0);
    const double cellHalf = vessels.query;
    detail::parallelRanges(n, threads, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
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
                    bump += w[c] * kLooks[c].bump * (lum - tiles[c].meanLum);
                }
                const VesselSample v = sampleVessels(vessels, p, texelMm, cellHalf);
                if (v.cover > 0.0f) {
                    float vc[3];
                    vesselColour(v.radius, vc);
                    for (int k = 0; k < 3; ++k)
                        rgb[k] += (vc[k] - rgb[k]) * v.cover;
                    rough += (0.3f - rough) * v.cover;
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

/// Tangent-space normals from height differences inside each chart (x along +u, y along +v).
ImageU8 normalMap(const TexelMap& map, const Shading& shading, const Atlas& atlas, double texelMm, double strength,
                  int threads) {
    const int n = map.size;
    ImageU8 out = ImageU8::create(n, n, 3, 0).value();
    detail::parallelRanges(n, threads, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < n; ++x) {
                const std::size_t i = map.index(x, y);
                if (!shading.covered[i])
                    continue;
                const std::int32_t chart = atlas.chartOfFace[static_cast<std::size_t>(map.face[i])];
                const auto h = [&](int xx, int yy, float& value) {
                    if (xx < 0 || yy < 0 || xx >= n || yy >= n)
                        return false;
                    const std::size_t j = map.index(xx, yy);
                    if (!shading.covered[j] || atlas.chartOfFace[static_cast<std::size_t>(map.face[j])] != chart)
                        return false;
                    value = shading.height[j];
                    return true;
                };
                const auto slope = [&](int dx, int dy) {
                    float a = 0, b = 0;
                    const float c = shading.height[i];
                    const bool hasA = h(x + dx, y + dy, a), hasB = h(x - dx, y - dy, b);
                    if (hasA && hasB)
                        return (a - b) / (2.0 * texelMm);
                    if (hasA)
                        return (a - c) / texelMm;
                    if (hasB)
                        return (c - b) / texelMm;
                    return 0.0;
                };
                const double du = slope(1, 0) * strength, dv = slope(0, -1) * strength; // v grows upwards
                const Vec3 nn = normalized(Vec3(-du, -dv, 1.0));
                out.at(x, y, 0) = static_cast<std::uint8_t>(std::lround((nn.x * 0.5 + 0.5) * 255.0));
                out.at(x, y, 1) = static_cast<std::uint8_t>(std::lround((nn.y * 0.5 + 0.5) * 255.0));
                out.at(x, y, 2) = static_cast<std::uint8_t>(std::lround((nn.z * 0.5 + 0.5) * 255.0));
            }
    });
    return out;
}

/// Fills the gutters: `rings` passes of averaging covered 8-neighbours into empty texels (so mipmaps and bilinear
/// filtering at chart borders fetch chart colours), then a constant for what is still empty.
void fillGutters(std::vector<ImageU8*> images, std::vector<std::uint8_t> covered, int size, int rings,
                 const std::vector<std::array<std::uint8_t, 4>>& fallback) {
    std::vector<std::uint8_t> next = covered;
    for (int ring = 0; ring < rings; ++ring) {
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * size + x;
                if (covered[i])
                    continue;
                std::array<std::array<int, 4>, 4> sum{};
                int count = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int xx = x + dx, yy = y + dy;
                        if (xx < 0 || yy < 0 || xx >= size || yy >= size ||
                            !covered[static_cast<std::size_t>(yy) * size + xx])
                            continue;
                        ++count;
                        for (std::size_t m = 0; m < images.size(); ++m)
                            for (int c = 0; c < images[m]->channels(); ++c)
                                sum[m][static_cast<std::size_t>(c)] += images[m]->at(xx, yy, c);
                    }
                if (count == 0)
                    continue;
                for (std::size_t m = 0; m < images.size(); ++m)
                    for (int c = 0; c < images[m]->channels(); ++c)
                        images[m]->at(x, y, c) =
                            static_cast<std::uint8_t>((sum[m][static_cast<std::size_t>(c)] + count / 2) / count);
                next[i] = 1;
            }
        covered = next;
    }
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            if (!covered[static_cast<std::size_t>(y) * size + x])
                for (std::size_t m = 0; m < images.size(); ++m)
                    for (int c = 0; c < images[m]->channels(); ++c)
                        images[m]->at(x, y, c) = fallback[m][static_cast<std::size_t>(c)];
}

/// Bilinear albedo at (u, v).
void sampleAlbedo(const ImageU8& img, double u, double v, double* out) {
    const double fx = u * img.width() - 0.5, fy = (1.0 - v) * img.height() - 0.5;
    const int x0 = std::clamp(static_cast<int>(std::floor(fx)), 0, img.width() - 1);
    const int y0 = std::clamp(static_cast<int>(std::floor(fy)), 0, img.height() - 1);
    const int x1 = std::min(x0 + 1, img.width() - 1), y1 = std::min(y0 + 1, img.height() - 1);
    const double ax = std::clamp(fx - x0, 0.0, 1.0), ay = std::clamp(fy - y0, 0.0, 1.0);
    for (int c = 0; c < 3; ++c)
        out[c] = (img.at(x0, y0, c) * (1 - ax) + img.at(x1, y0, c) * ax) * (1 - ay) +
                 (img.at(x0, y1, c) * (1 - ax) + img.at(x1, y1, c) * ax) * ay;
}

/// Mean squared albedo step across chart seams (both sides sampled at the same surface points) over the mean squared
/// step between horizontally neighbouring texels of one chart.
double chartSeamRatio(const SurfaceMesh& mesh, const Atlas& atlas, const ImageU8& albedo, const TexelMap& map) {
    const auto adj = detail::faceNeighbours(mesh);
    double seam = 0.0;
    std::int64_t seamCount = 0;
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
        for (std::size_t k = 0; k < 3; ++k) {
            const std::int32_t g = adj[f][k];
            if (g < 0 || static_cast<std::size_t>(g) < f ||
                atlas.chartOfFace[f] == atlas.chartOfFace[static_cast<std::size_t>(g)])
                continue;
            const std::int32_t va = mesh.triangles[f][k], vb = mesh.triangles[f][(k + 1) % 3];
            const auto uvOf = [&](std::size_t face, std::int32_t vertex) {
                for (std::size_t c = 0; c < 3; ++c)
                    if (mesh.triangles[face][c] == vertex)
                        return atlas.uvVertices[static_cast<std::size_t>(atlas.uvTriangles[face][c])];
                return UvVertex{};
            };
            const UvVertex a1 = uvOf(f, va), b1 = uvOf(f, vb);
            const UvVertex a2 = uvOf(static_cast<std::size_t>(g), va), b2 = uvOf(static_cast<std::size_t>(g), vb);
            for (double t : {0.25, 0.5, 0.75}) {
                double c1[3], c2[3];
                sampleAlbedo(albedo, a1.u + (b1.u - a1.u) * t, a1.v + (b1.v - a1.v) * t, c1);
                sampleAlbedo(albedo, a2.u + (b2.u - a2.u) * t, a2.v + (b2.v - a2.v) * t, c2);
                seam += (c1[0] - c2[0]) * (c1[0] - c2[0]) + (c1[1] - c2[1]) * (c1[1] - c2[1]) +
                        (c1[2] - c2[2]) * (c1[2] - c2[2]);
                ++seamCount;
            }
        }
    double inside = 0.0;
    std::int64_t insideCount = 0;
    for (int y = 0; y < map.size; ++y)
        for (int x = 0; x + 1 < map.size; ++x) {
            const std::size_t i = map.index(x, y);
            if (!map.exact[i] || !map.exact[i + 1] ||
                atlas.chartOfFace[static_cast<std::size_t>(map.face[i])] !=
                    atlas.chartOfFace[static_cast<std::size_t>(map.face[i + 1])])
                continue;
            double s = 0.0;
            for (int c = 0; c < 3; ++c) {
                const double d = static_cast<double>(albedo.at(x, y, c)) - albedo.at(x + 1, y, c);
                s += d * d;
            }
            inside += s;
            ++insideCount;
        }
    if (seamCount == 0 || insideCount == 0 || inside <= 0.0)
        return 0.0;
    return (seam / static_cast<double>(seamCount)) / (inside / static_cast<double>(insideCount));
}

Result<ImageU8> exemplarFor(const BakeParams& params, Appearance cls) {
    const std::string& file = params.exemplarFiles[static_cast<std::size_t>(cls)];
    if (file.empty())
        return makeExemplar(cls, 256, Rng::deriveSeed(params.seed, 100 + static_cast<std::uint64_t>(cls)));
    ImageReadLimits limits;
    limits.minSide = SynthesisParams::kMinExemplarSide;
    limits.maxSide = SynthesisParams::kMaxExemplarSide;
    auto image = readImageRgb8(file, limits);
    if (!image.ok())
        return fail(image.error().code, appearanceName(cls) + " exemplar: " + image.error().detail);
    return image;
}

} // namespace

std::vector<Appearance> classifyFaces(const SurfaceMesh& surface, const AppearanceLabels& labels) {
    std::vector<Appearance> out(surface.triangles.size(), Appearance::Endometrium);
    const auto it = surface.faceLabels.find(labels.appearanceLabel);
    if (it == surface.faceLabels.end() || it->second.size() != surface.triangles.size())
        return out;
    const auto contains = [](const std::vector<std::int32_t>& list, std::int32_t v) {
        return std::find(list.begin(), list.end(), v) != list.end();
    };
    for (std::size_t f = 0; f < out.size(); ++f) {
        if (contains(labels.polypValues, it->second[f]))
            out[f] = Appearance::Polyp;
        else if (contains(labels.myomaValues, it->second[f]))
            out[f] = Appearance::Myoma;
    }
    return out;
}

Result<BakeResult> bakeAppearance(const SurfaceMesh& surface, const BakeParams& params, Progress& progress) {
    HS_TRY(checkParams(params));
    HS_TRY(validate(surface));
    if (surface.triangles.empty())
        return fail(ErrorCode::InvalidInput, "bake: the surface has no triangles");
    const int threads = detail::threadCount(params.threads);
    BakeResult result;
    result.faceAppearance = classifyFaces(surface, params.labels);
    for (Appearance a : result.faceAppearance)
        ++result.stats.facesPerClass[static_cast<std::size_t>(a)];

    {
        ScopedStepTimer timer(result.timings, "atlas");
        AtlasParams ap;
        ap.size = params.size;
        ap.padding = params.padding;
        Progress::Sub sub = progress.sub(0.0, 0.1);
        auto atlas = buildAtlas(surface, ap, sub);
        if (!atlas.ok())
            return atlas.failure();
        result.atlas = std::move(atlas.value());
        result.timings.step("atlas").counts = {{"charts", result.atlas.stats.charts}};
    }
    std::array<Tile, kAppearanceCount> tiles;
    {
        ScopedStepTimer timer(result.timings, "synthesis");
        for (Appearance cls : kAppearances) {
            const auto c = static_cast<std::size_t>(cls);
            if (result.stats.facesPerClass[c] == 0)
                continue;
            auto exemplar = exemplarFor(params, cls);
            if (!exemplar.ok())
                return exemplar.failure();
            SynthesisParams sp;
            sp.width = sp.height = params.baseTextureSize;
            sp.seed = Rng::deriveSeed(params.seed, 200 + c);
            sp.threads = threads;
            Progress::Sub sub = progress.sub(0.1 + 0.1 * static_cast<double>(c), 0.2 + 0.1 * static_cast<double>(c));
            auto synth = synthesizeTexture(*exemplar, sp, sub);
            if (!synth.ok())
                return fail(synth.error().code, appearanceName(cls) + " base texture: " + synth.error().detail);
            result.baseTextures[c] = std::move(synth->image);
            tiles[c] = toTile(result.baseTextures[c]);
        }
    }
    if (params.vessels) {
        ScopedStepTimer timer(result.timings, "vessels");
        VesselParams vp = params.vesselParams;
        vp.seed = Rng::deriveSeed(params.seed, 300);
        Progress::Sub sub = progress.sub(0.4, 0.6);
        auto vessels = growVessels(surface, result.faceAppearance, vp, sub);
        if (!vessels.ok())
            return vessels.failure();
        result.vessels = std::move(vessels.value());
        result.stats.vesselSegments = static_cast<std::int64_t>(result.vessels.segments.size());
        result.timings.step("vessels").counts = {{"segments", result.stats.vesselSegments}};
    }
    if (progress.cancelled())
        return fail(ErrorCode::Cancelled, "bake cancelled");

    const double texelMm = 1.0 / std::max(1e-9, result.atlas.stats.texelsPerMm);
    TexelMap map;
    {
        ScopedStepTimer timer(result.timings, "rasterize");
        map = rasterize(surface, result.atlas, threads);
    }
    progress.report("texture.bake", 0.7);
    Shading shading;
    {
        ScopedStepTimer timer(result.timings, "shade");
        const std::vector<Vec3> normals = vertexNormals(surface);
        const std::vector<Weights3> weights =
            vertexWeights(surface, result.faceAppearance, params.labels, params.blendMm);
        const VesselIndex vessels = indexVessels(result.vessels, texelMm);
        shading = shade(surface, map, normals, weights, tiles, vessels, params, texelMm, threads);
    }
    if (progress.cancelled())
        return fail(ErrorCode::Cancelled, "bake cancelled");
    progress.report("texture.bake", 0.85);
    {
        ScopedStepTimer timer(result.timings, "normals");
        result.normal = normalMap(map, shading, result.atlas, texelMm, params.normalStrength, threads);
    }
    result.albedo = std::move(shading.albedo);
    result.roughness = std::move(shading.roughness);
    result.coverage = ImageU8::create(map.size, map.size, 1).value();
    for (std::size_t i = 0; i < map.face.size(); ++i) {
        result.stats.coveredTexels += shading.covered[i];
        result.coverage.data()[i] = map.face[i] < 0 ? 0 : (map.exact[i] ? 255 : 128);
    }
    {
        std::vector<std::int64_t> owned(surface.triangles.size(), 0);
        for (std::size_t i = 0; i < map.face.size(); ++i)
            if (map.face[i] >= 0)
                ++owned[static_cast<std::size_t>(map.face[i])];
        result.stats.facesWithoutTexels = std::count(owned.begin(), owned.end(), 0);
    }
    {
        ScopedStepTimer timer(result.timings, "gutter");
        std::array<std::int64_t, 4> mean{};
        for (std::size_t i = 0; i < map.face.size(); ++i)
            if (shading.covered[i]) {
                for (std::size_t c = 0; c < 3; ++c)
                    mean[c] += result.albedo.data()[i * 3 + c];
                mean[3] += result.roughness.data()[i];
            }
        const std::int64_t cov = std::max<std::int64_t>(1, result.stats.coveredTexels);
        const std::vector<std::array<std::uint8_t, 4>> fallback{{static_cast<std::uint8_t>(mean[0] / cov),
                                                                 static_cast<std::uint8_t>(mean[1] / cov),
                                                                 static_cast<std::uint8_t>(mean[2] / cov), 0},
                                                                {128, 128, 255, 0},
                                                                {static_cast<std::uint8_t>(mean[3] / cov), 0, 0, 0}};
        fillGutters({&result.albedo, &result.normal, &result.roughness}, shading.covered, map.size,
                    result.atlas.stats.padding + 1, fallback);
    }
    {
        ScopedStepTimer timer(result.timings, "seams");
        result.stats.chartSeamRatio = chartSeamRatio(surface, result.atlas, result.albedo, map);
    }
    result.stats.atlas = result.atlas.stats;
    progress.report("texture.bake", 1.0);
    return result;
}

} // namespace hs::texture
