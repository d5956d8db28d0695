#include "hs/core/TetEmbedding.h"

#include "hs/core/Parallel.h"
#include "hs/core/TriangleGrid.h"

#include <algorithm>

namespace hs {
namespace {

/// A walk longer than this is a point far from the boundary tet it started at; the best tet so far is kept.
constexpr int kMaxWalkSteps = 256;

double smallest(const std::array<double, 4>& w) {
    return std::min(std::min(w[0], w[1]), std::min(w[2], w[3]));
}

} // namespace

std::array<double, 4> barycentric(const Vec3& q0, const Vec3& q1, const Vec3& q2, const Vec3& q3, const Vec3& p) {
    const Vec3 a = q1 - q0;
    const Vec3 b = q2 - q0;
    const Vec3 c = q3 - q0;
    const Vec3 d = p - q0;
    const double volume = dot(a, cross(b, c));
    if (volume == 0.0)
        return {0.0, 0.0, 0.0, 0.0};
    const double w1 = dot(d, cross(b, c)) / volume;
    const double w2 = dot(a, cross(d, c)) / volume;
    const double w3 = dot(a, cross(b, d)) / volume;
    return {1.0 - w1 - w2 - w3, w1, w2, w3};
}

std::array<double, 4> barycentricIn(const TetMesh& mesh, std::size_t tet, const Vec3& p) {
    const Tet& t = mesh.tets[tet];
    return barycentric(mesh.points[static_cast<std::size_t>(t[0])], mesh.points[static_cast<std::size_t>(t[1])],
                       mesh.points[static_cast<std::size_t>(t[2])], mesh.points[static_cast<std::size_t>(t[3])], p);
}

Vec3 embeddedPoint(const TetMesh& mesh, const TetEmbedding& e) {
    const Tet& t = mesh.tets[static_cast<std::size_t>(e.tet)];
    Vec3 p{};
    for (std::size_t k = 0; k < 4; ++k)
        p += mesh.points[static_cast<std::size_t>(t[k])] * e.weights[k];
    return p;
}

std::vector<TetEmbedding> embedPoints(const TetMesh& mesh, const std::vector<Vec3>& points, int threads) {
    std::vector<TetEmbedding> out(points.size());
    if (mesh.tets.empty() || points.empty())
        return out;
    const auto neighbours = tetNeighbours(mesh);
    SurfaceMesh shell;
    shell.points = mesh.points;
    std::vector<std::int32_t> faceTet;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
        for (std::size_t k = 0; k < 4; ++k) {
            if (neighbours[t][k] >= 0)
                continue;
            const Tet& tet = mesh.tets[t];
            shell.triangles.push_back({tet[static_cast<std::size_t>(kTetFacePoints[k][0])],
                                       tet[static_cast<std::size_t>(kTetFacePoints[k][1])],
                                       tet[static_cast<std::size_t>(kTetFacePoints[k][2])]});
            faceTet.push_back(static_cast<std::int32_t>(t));
        }
    const TriangleGrid grid(shell, 0.0, false);
    // The tets around each point (CSR), to try every tet at the nearest boundary face's corners.
    std::vector<std::uint32_t> start(mesh.points.size() + 1, 0);
    for (const Tet& t : mesh.tets)
        for (std::int32_t v : t)
            ++start[static_cast<std::size_t>(v) + 1];
    for (std::size_t i = 1; i < start.size(); ++i)
        start[i] += start[i - 1];
    std::vector<std::int32_t> around(start.back());
    {
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (std::size_t t = 0; t < mesh.tets.size(); ++t)
            for (std::int32_t v : mesh.tets[t])
                around[fill[static_cast<std::size_t>(v)]++] = static_cast<std::int32_t>(t);
    }
    parallelChunks(points.size(), evenChunk(points.size(), resolveThreads(threads)), resolveThreads(threads),
                   [&](std::size_t, std::size_t begin, std::size_t end) {
                       for (std::size_t i = begin; i < end; ++i) {
                           const Vec3& p = points[i];
                           const SurfaceHit hit = grid.closest(p);
                           if (hit.triangle < 0) {
                               // No boundary face at all (every face shared, e.g. by a repeated tet in an untrusted
                               // file): nothing to walk from; the first tet's weights say how far off the point is.
                               out[i] = {0, barycentricIn(mesh, 0, p)};
                               continue;
                           }
                           std::int32_t tet = faceTet[static_cast<std::size_t>(hit.triangle)];
                           TetEmbedding best{tet, barycentricIn(mesh, static_cast<std::size_t>(tet), p)};
                           std::array<double, 4> w = best.weights;
                           for (int step = 0; step < kMaxWalkSteps && smallest(w) < 0.0; ++step) {
                               const auto k =
                                   static_cast<std::size_t>(std::min_element(w.begin(), w.end()) - w.begin());
                               const std::int32_t next = neighbours[static_cast<std::size_t>(tet)][k];
                               if (next < 0)
                                   break;
                               tet = next;
                               w = barycentricIn(mesh, static_cast<std::size_t>(tet), p);
                               if (smallest(w) > smallest(best.weights))
                                   best = {tet, w};
                           }
                           for (std::int32_t corner : shell.triangles[static_cast<std::size_t>(hit.triangle)])
                               for (std::uint32_t a = start[static_cast<std::size_t>(corner)];
                                    a < start[static_cast<std::size_t>(corner) + 1]; ++a) {
                                   const auto candidate = static_cast<std::size_t>(around[a]);
                                   const auto cw = barycentricIn(mesh, candidate, p);
                                   if (smallest(cw) > smallest(best.weights))
                                       best = {static_cast<std::int32_t>(candidate), cw};
                               }
                           out[i] = best;
                       }
                   });
    return out;
}

} // namespace hs
