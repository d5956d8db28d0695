#include "hs/meshing/VoxelSpace.h"

#include "hs/core/Parallel.h"
#include "hs/meshing/Geometry.h"

#include <algorithm>
#include <cmath>

namespace hs::meshing {
namespace {

/// Voxel budget of the mesher (a grid of this many voxels costs about 1 GB with its per-surface arrays).
constexpr double kMaxMesherVoxels = 120.0e6;
constexpr std::size_t kTriangleChunk = 2048;

using Pair = std::pair<std::uint32_t, std::int32_t>; // (voxel, triangle)

Status associateTriangles(const SurfaceMesh& mesh, const VoxelGrid<std::int32_t>& grid, int threads, Progress& progress,
                          SurfaceVoxels& out) {
    const double h = grid.spacing();
    const Vec3 half(0.5 * h, 0.5 * h, 0.5 * h);
    const Index3 dims = grid.dims();
    std::vector<std::vector<Pair>> chunks(chunkCount(mesh.triangles.size(), kTriangleChunk));
    parallelChunks(mesh.triangles.size(), kTriangleChunk, threads, [&](std::size_t c, std::size_t b, std::size_t e) {
        if (progress.cancelled())
            return;
        std::vector<Pair>& pairs = chunks[c];
        for (std::size_t f = b; f < e; ++f) {
            const Triangle& t = mesh.triangles[f];
            const Vec3& p0 = mesh.points[static_cast<std::size_t>(t[0])];
            const Vec3& p1 = mesh.points[static_cast<std::size_t>(t[1])];
            const Vec3& p2 = mesh.points[static_cast<std::size_t>(t[2])];
            Index3 lo, hi;
            for (int q = 0; q < 3; ++q) {
                const double mn = std::min({p0[q], p1[q], p2[q]}), mx = std::max({p0[q], p1[q], p2[q]});
                // A triangle on a voxel face touches the voxels on both sides (closed boxes): widen by a hair.
                lo[q] = std::clamp<std::int64_t>(
                    static_cast<std::int64_t>(std::floor((mn - grid.origin()[q]) / h - 1e-9)), 0, dims[q] - 1);
                hi[q] = std::clamp<std::int64_t>(
                    static_cast<std::int64_t>(std::floor((mx - grid.origin()[q]) / h + 1e-9)), 0, dims[q] - 1);
            }
            for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
                for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
                    for (std::int64_t i = lo[0]; i <= hi[0]; ++i) {
                        const Index3 ijk{i, j, k};
                        if (triangleBoxOverlap(grid.center(ijk), half, p0, p1, p2))
                            pairs.emplace_back(static_cast<std::uint32_t>(grid.linear(ijk)),
                                               static_cast<std::int32_t>(f));
                    }
        }
    });
    HS_TRY(progress.check("meshing", "voxelizing"));
    // Counting sort by voxel; chunks are in triangle order, so each voxel's list is ascending.
    const std::size_t n = grid.size();
    out.start.assign(n + 1, 0);
    std::size_t total = 0;
    for (const auto& pairs : chunks) {
        total += pairs.size();
        for (const Pair& p : pairs)
            ++out.start[p.first + 1];
    }
    if (total > 0xFFFFFFF0u)
        return fail(ErrorCode::LimitExceeded, "too many triangle-voxel pairs; use a larger target edge length");
    for (std::size_t v = 0; v < n; ++v)
        out.start[v + 1] += out.start[v];
    out.triangles.resize(total);
    std::vector<std::uint32_t> cursor(out.start.begin(), out.start.end() - 1);
    for (const auto& pairs : chunks)
        for (const Pair& p : pairs)
            out.triangles[cursor[p.first]++] = p.second;
    return {};
}

/// Components of non-surface voxels that the growth from the border did not reach are inside the surface, unless
/// the surface encloses them only through a passage narrower than a voxel: the uterine cavity opens to the outside
/// by the cervical canal, a tube of 1-3 mm whose voxels are all surface voxels at a 2 mm edge, so the cavity was
/// taken for wall and filled (the organ meshed 2-3 % too large). Each such component is tested once, at its first
/// voxel, by the generalized winding number (its voxels touch no triangle, so the whole component is on one side).
void labelEnclosedOuter(const SurfaceMesh& mesh, SurfaceVoxels& sv) {
    auto& labels = sv.labels;
    const std::size_t n = labels.size();
    std::vector<std::uint8_t> seen(n, 0);
    std::vector<std::uint32_t> component;
    for (std::size_t v0 = 0; v0 < n; ++v0) {
        if (labels[v0] != VoxelLabel::Inner || seen[v0])
            continue;
        component.clear();
        component.push_back(static_cast<std::uint32_t>(v0));
        seen[v0] = 1;
        for (std::size_t head = 0; head < component.size(); ++head) {
            const Index3 c = labels.unlinear(component[head]);
            for (std::int64_t dk = -1; dk <= 1; ++dk)
                for (std::int64_t dj = -1; dj <= 1; ++dj)
                    for (std::int64_t di = -1; di <= 1; ++di) {
                        const Index3 nb{c[0] + di, c[1] + dj, c[2] + dk};
                        if (!labels.contains(nb))
                            continue;
                        const std::size_t v = labels.linear(nb);
                        if (labels[v] == VoxelLabel::Inner && !seen[v]) {
                            seen[v] = 1;
                            component.push_back(static_cast<std::uint32_t>(v));
                        }
                    }
        }
        if (std::fabs(windingNumber(mesh, labels.center(labels.unlinear(v0)))) < 0.5)
            for (std::uint32_t v : component)
                labels[v] = VoxelLabel::Outer;
    }
}

/// Outer voxels: 26-connected region growing over non-surface voxels from every border voxel.
void labelOuterAndInner(SurfaceVoxels& sv) {
    auto& labels = sv.labels;
    const Index3 d = labels.dims();
    const std::size_t n = labels.size();
    for (std::size_t v = 0; v < n; ++v)
        labels[v] = sv.start[v + 1] > sv.start[v] ? VoxelLabel::Surface : VoxelLabel::Inner;
    std::vector<std::uint32_t> queue;
    queue.reserve(n / 4 + 16);
    auto seed = [&](const Index3& ijk) {
        const std::size_t v = labels.linear(ijk);
        if (labels[v] == VoxelLabel::Inner) {
            labels[v] = VoxelLabel::Outer;
            queue.push_back(static_cast<std::uint32_t>(v));
        }
    };
    for (std::int64_t k = 0; k < d[2]; ++k)
        for (std::int64_t j = 0; j < d[1]; ++j)
            for (std::int64_t i = 0; i < d[0]; ++i)
                if (i == 0 || j == 0 || k == 0 || i == d[0] - 1 || j == d[1] - 1 || k == d[2] - 1)
                    seed({i, j, k});
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const Index3 c = labels.unlinear(queue[head]);
        for (std::int64_t dk = -1; dk <= 1; ++dk)
            for (std::int64_t dj = -1; dj <= 1; ++dj)
                for (std::int64_t di = -1; di <= 1; ++di) {
                    const Index3 nb{c[0] + di, c[1] + dj, c[2] + dk};
                    if (labels.contains(nb))
                        seed(nb);
                }
    }
}

} // namespace

Result<VoxelSpace> buildVoxelSpace(const RegionModel& body, double voxelSize, int threads, Progress& progress) {
    if (!(voxelSize > 0.0) || !std::isfinite(voxelSize))
        return fail(ErrorCode::InvalidInput, "voxel size must be a finite positive length in mm");
    if (body.surfaces.empty())
        return fail(ErrorCode::InvalidInput, "region model has no surface");
    threads = resolveThreads(threads);
    Bounds box;
    for (const auto& rs : body.surfaces)
        for (const Vec3& p : rs.surface.points)
            box.add(p);
    const Vec3 size = box.size();
    Index3 dims{};
    double count = 1.0;
    for (int q = 0; q < 3; ++q) {
        const double cells = std::ceil(size[q] / voxelSize) + 3.0; // one border voxel each side, one spare
        count *= cells;
        if (!(cells < 1e9))
            return fail(ErrorCode::LimitExceeded, "voxel grid too large for this edge length");
        dims[q] = static_cast<std::int64_t>(cells);
    }
    if (count > kMaxMesherVoxels)
        return fail(ErrorCode::LimitExceeded,
                    "voxel grid of " + std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " +
                        std::to_string(dims[2]) +
                        " voxels exceeds the mesher's limit of 1.2e8; use a larger edge length");
    const Vec3 origin = box.min - Vec3(1.0, 1.0, 1.0) * voxelSize;
    auto region = VoxelGrid<std::int32_t>::create(origin, voxelSize, dims, VoxelSpace::kOutside);
    if (!region.ok())
        return region.failure();
    VoxelSpace space;
    space.region = std::move(region.value());

    for (std::size_t s = 0; s < body.surfaces.size(); ++s) {
        SurfaceVoxels sv;
        auto labels = VoxelGrid<VoxelLabel>::create(origin, voxelSize, dims, VoxelLabel::Outer);
        if (!labels.ok())
            return labels.failure();
        sv.labels = std::move(labels.value());
        HS_TRY(associateTriangles(body.surfaces[s].surface, space.region, threads, progress, sv));
        labelOuterAndInner(sv);
        labelEnclosedOuter(body.surfaces[s].surface, sv);
        HS_TRY(progress.check("meshing", "voxelizing"));
        progress.report("meshing.voxelize", double(s + 1) / double(body.surfaces.size()));
        space.surfaces.push_back(std::move(sv));
    }
    // Combine: surface voxels of any surface, else the region of the innermost surface containing the voxel.
    const std::size_t n = space.region.size();
    for (std::size_t v = 0; v < n; ++v) {
        std::int32_t r = VoxelSpace::kOutside;
        for (std::size_t s = 0; s < space.surfaces.size(); ++s) {
            const VoxelLabel l = space.surfaces[s].labels[v];
            if (l == VoxelLabel::Surface) {
                r = VoxelSpace::kSurface;
                break;
            }
            if (l == VoxelLabel::Inner)
                r = body.surfaces[s].regionId == RegionModel::kVoidRegion ? VoxelSpace::kOutside
                                                                          : body.surfaces[s].regionId;
        }
        space.region[v] = r;
    }
    return space;
}

} // namespace hs::meshing
