// The tangent-space normal map from the shading's relief.
#include "BakeSteps.h"

#include "hs/core/Parallel.h"

#include <algorithm>
#include <cmath>

namespace hs::texture::detail {

namespace {

/// How a face's texel-space height gradient becomes slopes along the tangent frame a renderer builds for it: T along
/// +u (the texel's +x), B = N x T, N the face's normal. A chart is a planar projection, so a face tilted against its
/// chart's plane is foreshortened there: one texel covers more of the surface along the tilt than across it, and the
/// texel's axes are not orthogonal on the surface. Dividing texel differences by the texel's nominal size overstates
/// the slope by 1 / cos(tilt) (1.3x at the atlas's 40 degrees), and the neighbouring chart, seen head on, does not:
/// the relief changed at every seam.
struct FaceFrame {
    // (du, dv) = (hx * toU, (hy - hx * cross) * toV) for the height's differences per texel along +x (hx) and +y (hy).
    double toU = 0.0, cross = 0.0, toV = 0.0;
};

std::vector<FaceFrame> faceFrames(const SurfaceMesh& mesh, const Atlas& atlas, double texelMm) {
    const double s = atlas.size;
    const FaceFrame isometric{1.0 / texelMm, 0.0, -1.0 / texelMm}; // +y runs down the image, along -v
    std::vector<FaceFrame> frames(mesh.triangles.size(), isometric);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const auto& tri = mesh.triangles[f];
        const auto& uvt = atlas.uvTriangles[f];
        Vec3 p[3];
        double X[3], Y[3];
        for (std::size_t k = 0; k < 3; ++k) {
            p[k] = mesh.points[static_cast<std::size_t>(tri[k])];
            const UvVertex& q = atlas.uvVertices[static_cast<std::size_t>(uvt[k])];
            X[k] = q.u * s;
            Y[k] = (1.0 - q.v) * s; // the texel row, as the rasterizer places it
        }
        const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
        const double m11 = X[1] - X[0], m12 = X[2] - X[0], m21 = Y[1] - Y[0], m22 = Y[2] - Y[0];
        const double det = m11 * m22 - m12 * m21;
        const Vec3 n = normalized(cross(e1, e2));
        if (std::fabs(det) < 1e-12 || norm(n) == 0.0)
            continue;
        // [dP/dx dP/dy] = [e1 e2] M^-1: mm on the surface per texel along the image's axes.
        const Vec3 ax = (e1 * m22 - e2 * m21) / det;
        const Vec3 ay = (e2 * m11 - e1 * m12) / det;
        const double axLength = norm(ax);
        if (axLength < 1e-12)
            continue;
        const Vec3 t = ax / axLength;
        const Vec3 b = cross(n, t);
        const double ayB = dot(ay, b);
        if (std::fabs(ayB) < 1e-12)
            continue;
        // hx = |ax| du and hy = (ay.T) du + (ay.B) dv.
        frames[f] = {1.0 / axLength, dot(ay, t), 1.0 / ayB};
    }
    return frames;
}

} // namespace

/// Tangent-space normals: the surface gradient of the relief inside each chart, in the frame (T along +u, B = N x T,
/// N) a renderer rebuilds from the UVs and the surface's normals.
ImageU8 normalMap(const SurfaceMesh& mesh, const TexelMap& map, const Shading& shading, const Atlas& atlas,
                  double texelMm, double strength, int threads) {
    const int n = map.size;
    ImageU8 out = ImageU8::create(n, n, 3, 0).value();
    const std::vector<FaceFrame> frames = faceFrames(mesh, atlas, texelMm);
    parallelChunks(static_cast<std::size_t>(n), evenChunk(static_cast<std::size_t>(n), threads), threads,
                   [&](std::size_t, std::size_t y0Chunk, std::size_t y1Chunk) {
                       const int y0 = static_cast<int>(y0Chunk), y1 = static_cast<int>(y1Chunk);
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
                                   if (!shading.covered[j] ||
                                       atlas.chartOfFace[static_cast<std::size_t>(map.face[j])] != chart)
                                       return false;
                                   value = shading.height[j];
                                   return true;
                               };
                               // The height's difference per texel along (dx, dy).
                               const auto step = [&](int dx, int dy) {
                                   float a = 0, b = 0;
                                   const float c = shading.height[i];
                                   const bool hasA = h(x + dx, y + dy, a), hasB = h(x - dx, y - dy, b);
                                   if (hasA && hasB)
                                       return 0.5 * (a - b);
                                   if (hasA)
                                       return static_cast<double>(a - c);
                                   if (hasB)
                                       return static_cast<double>(c - b);
                                   return 0.0;
                               };
                               const FaceFrame& frame = frames[static_cast<std::size_t>(map.face[i])];
                               const double hx = step(1, 0), hy = step(0, 1);
                               const double du = hx * frame.toU * strength;
                               const double dv = (hy - hx * frame.toU * frame.cross) * frame.toV * strength;
                               const Vec3 nn = normalized(Vec3(-du, -dv, 1.0));
                               out.at(x, y, 0) = static_cast<std::uint8_t>(std::lround((nn.x * 0.5 + 0.5) * 255.0));
                               out.at(x, y, 1) = static_cast<std::uint8_t>(std::lround((nn.y * 0.5 + 0.5) * 255.0));
                               out.at(x, y, 2) = static_cast<std::uint8_t>(std::lround((nn.z * 0.5 + 0.5) * 255.0));
                           }
                   });
    return out;
}

} // namespace hs::texture::detail
