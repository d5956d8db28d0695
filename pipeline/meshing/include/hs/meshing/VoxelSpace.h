#pragma once
/// The augmented voxel space of the particle mesher (Sierra et al. 2004, sec. 2.2): each voxel is outer, surface
/// (its closed box really intersects a triangle: exact triangle-box overlap) or inner; outer voxels are found by
/// 26-neighbour region growing from the grid border.

#include "hs/core/Progress.h"
#include "hs/core/RegionModel.h"
#include "hs/core/VoxelGrid.h"

#include <cstdint>
#include <vector>

namespace hs::meshing {

enum class VoxelLabel : std::uint8_t { Outer = 0, Surface = 1, Inner = 2 };

/// The voxelization of one input surface, on the shared grid.
struct SurfaceVoxels {
    VoxelGrid<VoxelLabel> labels;        ///< with respect to this surface alone
    std::vector<std::uint32_t> start;    ///< CSR: voxel v's triangles are triangles[start[v] .. start[v+1])
    std::vector<std::int32_t> triangles; ///< triangles associated with each surface voxel
};

struct VoxelSpace {
    static constexpr std::int32_t kOutside = -2; ///< region value of outer voxels (and of void regions)
    static constexpr std::int32_t kSurface = -3; ///< region value of voxels touched by any surface

    std::vector<SurfaceVoxels> surfaces; ///< one per RegionModel surface
    /// Combined labels: kOutside, kSurface, or the region id of an inner voxel (the innermost surface wins).
    VoxelGrid<std::int32_t> region;
};

/// Voxelizes every surface of `body` on one grid of edge `voxelSize` (mm) covering the body with a one-voxel
/// border. Expects a valid body (validate(const RegionModel&)). Fails with InvalidInput for a non-positive size,
/// LimitExceeded above VoxelGrid::kMaxVoxels, Cancelled on request.
Result<VoxelSpace> buildVoxelSpace(const RegionModel& body, double voxelSize, int threads = 0,
                                   Progress& progress = Progress::none());

} // namespace hs::meshing
