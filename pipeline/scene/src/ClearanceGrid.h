#pragma once
/// The free space of a tetrahedral body as a signed clearance grid (private to hs::scene; used by the scope
/// passage check).

#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/TetMesh.h"
#include "hs/core/VoxelGrid.h"

#include <cstdint>
#include <vector>

namespace hs::scene::detail {

struct ClearanceGrid {
    VoxelGrid<std::uint8_t> tissue; ///< 1 where the voxel centre lies in a tet (closed tets: a face counts)
    /// mm: distance from the voxel centre to the tissue boundary, > 0 in free space, < 0 in tissue. From the exact
    /// Euclidean distance between voxel centres of the other kind, less half a voxel, so within about half a
    /// voxel of the true distance.
    VoxelGrid<float> clearanceMm;
};

/// Squared distance, in voxels, from every voxel centre of a grid of `dims` to the nearest centre where
/// mask == target (infinite when there is none): exact, by Felzenszwalb and Huttenlocher's lower envelope of
/// parabolas along each axis in turn. Cancelled on request.
Result<std::vector<double>> squaredVoxelDistance(const Index3& dims, const std::vector<std::uint8_t>& mask,
                                                 std::uint8_t target, Progress& progress);

/// Rasterizes `tets` onto a grid of `voxelMm` over `box` (voxel centres tested against every tet whose box holds
/// them), then the two distance transforms. Expects a valid mesh; fails with InvalidInput when no voxel centre lies
/// in tissue (the mesh is thinner than a voxel), LimitExceeded above `maxVoxels`, Cancelled on request.
Result<ClearanceGrid> buildClearanceGrid(const TetMesh& tets, const Bounds& box, double voxelMm, std::int64_t maxVoxels,
                                         Progress& progress);

} // namespace hs::scene::detail
