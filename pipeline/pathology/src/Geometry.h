#pragma once
/// Geometry helpers of the pathology stage: a regular grid, inside masks by column parity, marching tetrahedra,
/// Taubin smoothing, distances and rays. Closest points on triangles and the triangle grid are hs::core's.

#include "hs/core/SurfaceMesh.h"

#include <cstdint>
#include <vector>

namespace hs::pathology::detail {

struct Grid {
    Vec3 origin; ///< centre of voxel (0, 0, 0), mm
    double h = 1.0;
    int nx = 0, ny = 0, nz = 0;
    std::size_t size() const {
        return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) * static_cast<std::size_t>(nz);
    }
    std::size_t index(int i, int j, int k) const {
        return static_cast<std::size_t>(i) +
               static_cast<std::size_t>(nx) *
                   (static_cast<std::size_t>(j) + static_cast<std::size_t>(ny) * static_cast<std::size_t>(k));
    }
    Vec3 center(int i, int j, int k) const { return origin + Vec3{i * h, j * h, k * h}; }
    /// A grid with voxel edge h covering `box` plus `pad` voxels on each side.
    static Grid covering(const Bounds& box, double h, int pad);
};

/// 1 for voxel centres inside the closed surface (parity of crossings along z columns), else 0.
std::vector<std::uint8_t> insideMask(const SurfaceMesh& mesh, const Grid& grid);

/// Iso-surface {field = iso} by marching tetrahedra (Kuhn split of each cube, consistent across cubes, so the
/// result is closed and manifold); inside is field > iso; outward-oriented. Only the largest component is kept.
SurfaceMesh polygonize(std::vector<float> field, const Grid& grid, float iso);

/// Taubin's lambda|mu smoothing (Taubin 1995): smooths without shrinking.
void taubinSmooth(SurfaceMesh& mesh, int iterations, double lambda = 0.5, double mu = -0.53);

/// Flips every triangle when the enclosed volume is negative.
void orientOutward(SurfaceMesh& mesh);

/// Signed distance from p to a closed surface (negative inside), capped at `cutoff`; `box` is the surface's bounds.
double signedDistance(const SurfaceMesh& s, const Bounds& box, const Vec3& p, double cutoff);

/// Ray-triangle intersection (Moeller-Trumbore); t along dir (unit), true on a hit with t > tMin.
bool rayTriangle(const Vec3& origin, const Vec3& dir, const Vec3& a, const Vec3& b, const Vec3& c, double tMin,
                 double& t);

/// Largest distance between two points of the set (exact for up to 3000 points, else on a regular subsample).
double diameter(const std::vector<Vec3>& points);

using hs::centroid; // hs/core/Vec3.h
/// Volume centroid of a closed surface.
Vec3 volumeCentroid(const SurfaceMesh& mesh);

/// Rotation-free scaling about `center`.
void scaleAbout(SurfaceMesh& mesh, const Vec3& center, double factor);
void translate(SurfaceMesh& mesh, const Vec3& by);

/// Smallest distance from any vertex of a to the triangles of b (bounding-box filtered), mm.
double surfaceDistance(const SurfaceMesh& a, const SurfaceMesh& b, double cutoff);

/// Two unit vectors completing `n` (unit) to an orthonormal frame.
void orthonormalFrame(const Vec3& n, Vec3& e1, Vec3& e2);

double smoothstep(double e0, double e1, double x);

} // namespace hs::pathology::detail
