// Tissue raster and signed clearance of a tetrahedral body.

#include "ClearanceGrid.h"

#include "Format.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace hs::scene::detail {

namespace {

constexpr double kFar = std::numeric_limits<double>::infinity();

double orient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    return dot(b - a, cross(c - a, d - a));
}

/// Point in tet, whatever the tet's orientation: the four sub-volumes have the sign of the whole (zero allowed, so a
/// centre on a shared face is tissue).
bool inTet(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, double volume) {
    const double s = volume > 0.0 ? 1.0 : -1.0;
    return s * orient(p, b, c, d) >= 0.0 && s * orient(a, p, c, d) >= 0.0 && s * orient(a, b, p, d) >= 0.0 &&
           s * orient(a, b, c, p) >= 0.0;
}

std::int64_t clampIndex(double v, std::int64_t n) {
    return std::clamp(static_cast<std::int64_t>(std::floor(v)), std::int64_t(0), n - 1);
}

Status rasterizeTets(const TetMesh& tets, VoxelGrid<std::uint8_t>& grid, Progress& progress) {
    const double h = grid.spacing();
    const Index3& n = grid.dims();
    for (std::size_t t = 0; t < tets.tetCount(); ++t) {
        if ((t & 4095) == 0) {
            if (progress.cancelled())
                return fail(ErrorCode::Cancelled, "scope passage cancelled while rasterizing the tets");
            progress.report("scope.voxelize", double(t) / double(tets.tetCount()));
        }
        const auto& tet = tets.tets[t];
        const Vec3 &a = tets.points[std::size_t(tet[0])], &b = tets.points[std::size_t(tet[1])],
                   &c = tets.points[std::size_t(tet[2])], &d = tets.points[std::size_t(tet[3])];
        const double volume = orient(a, b, c, d);
        if (volume == 0.0)
            continue; // a flat tet holds no voxel centre that its neighbours do not hold
        Bounds box;
        for (const Vec3* p : {&a, &b, &c, &d})
            box.add(*p);
        // Voxel i's centre is origin + (i + 0.5) h: the centres inside [min, max].
        Index3 lo, hi;
        for (int k = 0; k < 3; ++k) {
            lo[k] = clampIndex(std::ceil((box.min[k] - grid.origin()[k]) / h - 0.5), n[k]);
            hi[k] = clampIndex((box.max[k] - grid.origin()[k]) / h - 0.5, n[k]);
        }
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z)
            for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
                for (std::int64_t x = lo[0]; x <= hi[0]; ++x) {
                    const Index3 ijk{x, y, z};
                    if (!grid.at(ijk) && inTet(grid.center(ijk), a, b, c, d, volume))
                        grid.at(ijk) = 1;
                }
    }
    return {};
}

/// Lower envelope of parabolas (Felzenszwalb and Huttenlocher, "Distance Transforms of Sampled Functions", Theory of
/// Computing 8, 2012, alg. DT(f)): d[q] = min_p (q - p)^2 + f[p] over the finite f[p]. Exact for integer inputs.
void distanceTransform1d(const std::vector<double>& f, std::vector<double>& d, std::vector<std::int64_t>& v,
                         std::vector<double>& z) {
    const auto n = static_cast<std::int64_t>(f.size());
    std::int64_t k = -1;
    for (std::int64_t q = 0; q < n; ++q) {
        const double fq = f[std::size_t(q)];
        if (fq == kFar)
            continue;
        double s = -kFar;
        while (k >= 0) {
            const std::int64_t p = v[std::size_t(k)];
            s = ((fq + double(q * q)) - (f[std::size_t(p)] + double(p * p))) / double(2 * (q - p));
            if (s > z[std::size_t(k)])
                break;
            --k;
        }
        ++k;
        v[std::size_t(k)] = q;
        z[std::size_t(k)] = k == 0 ? -kFar : s;
        z[std::size_t(k) + 1] = kFar;
    }
    if (k < 0) {
        std::fill(d.begin(), d.end(), kFar);
        return;
    }
    std::int64_t j = 0;
    for (std::int64_t q = 0; q < n; ++q) {
        while (z[std::size_t(j) + 1] < double(q))
            ++j;
        const std::int64_t p = v[std::size_t(j)];
        d[std::size_t(q)] = double((q - p) * (q - p)) + f[std::size_t(p)];
    }
}

} // namespace

Result<std::vector<double>> squaredVoxelDistance(const Index3& n, const std::vector<std::uint8_t>& mask,
                                                 std::uint8_t target, Progress& progress) {
    std::vector<double> dist2(mask.size());
    for (std::size_t i = 0; i < dist2.size(); ++i)
        dist2[i] = mask[i] == target ? 0.0 : kFar;
    const auto longest = static_cast<std::size_t>(std::max({n[0], n[1], n[2]}));
    std::vector<double> f(longest), d(longest), z(longest + 1);
    std::vector<std::int64_t> v(longest);
    const std::int64_t stride[3] = {1, n[0], n[0] * n[1]};
    for (int axis = 0; axis < 3; ++axis) {
        if (progress.cancelled())
            return fail(ErrorCode::Cancelled, "scope passage cancelled in the distance transform");
        const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        const auto len = std::size_t(n[axis]);
        f.resize(len);
        d.resize(len);
        for (std::int64_t j = 0; j < n[a2]; ++j)
            for (std::int64_t i = 0; i < n[a1]; ++i) {
                const std::int64_t base = i * stride[a1] + j * stride[a2];
                for (std::size_t q = 0; q < len; ++q)
                    f[q] = dist2[std::size_t(base + std::int64_t(q) * stride[axis])];
                distanceTransform1d(f, d, v, z);
                for (std::size_t q = 0; q < len; ++q)
                    dist2[std::size_t(base + std::int64_t(q) * stride[axis])] = d[q];
            }
    }
    return dist2;
}

Result<ClearanceGrid> buildClearanceGrid(const TetMesh& tets, const Bounds& box, double voxelMm, std::int64_t maxVoxels,
                                         Progress& progress) {
    Index3 dims;
    double count = 1.0;
    for (int k = 0; k < 3; ++k) {
        const double cells = std::ceil(box.size()[k] / voxelMm) + 1.0;
        count *= cells;
        dims[k] = cells < 4e9 ? static_cast<std::int64_t>(cells) : std::int64_t(4e9);
    }
    if (count > double(maxVoxels))
        return fail(ErrorCode::LimitExceeded, "scope passage: a voxel grid of " + std::to_string(dims[0]) + " x " +
                                                  std::to_string(dims[1]) + " x " + std::to_string(dims[2]) +
                                                  " voxels of " + formatNumber(voxelMm) + " mm exceeds maxVoxels " +
                                                  std::to_string(maxVoxels) +
                                                  " (allowed 1 to 2^31); raise voxelFraction or maxVoxels");
    auto tissue = VoxelGrid<std::uint8_t>::create(box.min, voxelMm, dims, 0);
    if (!tissue.ok())
        return tissue.failure();
    Progress::Sub rasterProgress = progress.sub(0.0, 0.5);
    HS_TRY(rasterizeTets(tets, *tissue, rasterProgress));
    if (std::none_of(tissue->data().begin(), tissue->data().end(), [](std::uint8_t t) { return t != 0; }))
        return fail(ErrorCode::InvalidInput, "scope passage: no voxel centre of " + formatNumber(voxelMm) +
                                                 " mm lies in a tet; the mesh is empty or thinner than a voxel");

    auto toTissue = squaredVoxelDistance(dims, tissue->data(), 1, progress);
    if (!toTissue.ok())
        return toTissue.failure();
    progress.report("scope.distance", 0.75);
    auto toFree = squaredVoxelDistance(dims, tissue->data(), 0, progress);
    if (!toFree.ok())
        return toFree.failure();
    auto clearance = VoxelGrid<float>::create(box.min, voxelMm, dims, 0.0f);
    if (!clearance.ok())
        return clearance.failure();
    for (std::size_t i = 0; i < clearance->size(); ++i) {
        // The boundary lies between a centre and the nearest centre of the other kind: half a voxel on average.
        const bool free = (*tissue)[i] == 0;
        const double d = std::sqrt(free ? (*toTissue)[i] : (*toFree)[i]) * voxelMm - 0.5 * voxelMm;
        (*clearance)[i] = static_cast<float>(free ? d : -d);
    }
    progress.report("scope.distance", 1.0);
    return ClearanceGrid{std::move(tissue).value(), std::move(clearance).value()};
}

} // namespace hs::scene::detail
