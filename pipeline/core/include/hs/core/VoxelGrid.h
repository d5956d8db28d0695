#pragma once
/// A regular 3-D grid of values over an axis-aligned box.

#include "hs/core/Result.h"
#include "hs/core/Vec3.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace hs {

using Index3 = std::array<std::int64_t, 3>;

template <class T>
class VoxelGrid {
public:
    /// Largest grid this project allocates (2^31 voxels); larger requests fail with LimitExceeded.
    static constexpr std::int64_t kMaxVoxels = std::int64_t(1) << 31;

    VoxelGrid() = default;

    /// A grid of dims[0] x dims[1] x dims[2] voxels of edge `spacing` (mm), voxel (0,0,0) with its min corner at
    /// `origin`, every voxel set to `fill`.
    static Result<VoxelGrid> create(const Vec3& origin, double spacing, const Index3& dims, const T& fill = T{}) {
        if (!(spacing > 0.0) || !std::isfinite(spacing))
            return fail(ErrorCode::InvalidInput, "voxel spacing must be a finite positive length in mm");
        if (!isFinite(origin))
            return fail(ErrorCode::InvalidInput, "voxel grid origin must be finite");
        std::int64_t count = 1;
        for (int i = 0; i < 3; ++i) {
            if (dims[i] <= 0)
                return fail(ErrorCode::InvalidInput, "voxel grid dimensions must be positive");
            if (dims[i] > kMaxVoxels || count > kMaxVoxels / dims[i])
                return fail(ErrorCode::LimitExceeded, "voxel grid of " + std::to_string(dims[0]) + " x " +
                                                          std::to_string(dims[1]) + " x " + std::to_string(dims[2]) +
                                                          " exceeds the limit of 2^31 voxels");
            count *= dims[i];
        }
        VoxelGrid grid;
        grid.m_origin = origin;
        grid.m_spacing = spacing;
        grid.m_dims = dims;
        grid.m_data.assign(static_cast<std::size_t>(count), fill);
        return grid;
    }

    const Index3& dims() const { return m_dims; }
    const Vec3& origin() const { return m_origin; }
    double spacing() const { return m_spacing; }
    std::size_t size() const { return m_data.size(); }

    bool contains(const Index3& ijk) const {
        return ijk[0] >= 0 && ijk[1] >= 0 && ijk[2] >= 0 && ijk[0] < m_dims[0] && ijk[1] < m_dims[1] &&
               ijk[2] < m_dims[2];
    }
    std::size_t linear(const Index3& ijk) const {
        return static_cast<std::size_t>((ijk[2] * m_dims[1] + ijk[1]) * m_dims[0] + ijk[0]);
    }
    Index3 unlinear(std::size_t index) const {
        const auto i = static_cast<std::int64_t>(index);
        return {i % m_dims[0], (i / m_dims[0]) % m_dims[1], i / (m_dims[0] * m_dims[1])};
    }
    T& at(const Index3& ijk) { return m_data[linear(ijk)]; }
    const T& at(const Index3& ijk) const { return m_data[linear(ijk)]; }
    T& operator[](std::size_t i) { return m_data[i]; }
    const T& operator[](std::size_t i) const { return m_data[i]; }

    /// Voxel containing world point p (may lie outside the grid: check contains()).
    Index3 voxelOf(const Vec3& p) const {
        return {static_cast<std::int64_t>(std::floor((p.x - m_origin.x) / m_spacing)),
                static_cast<std::int64_t>(std::floor((p.y - m_origin.y) / m_spacing)),
                static_cast<std::int64_t>(std::floor((p.z - m_origin.z) / m_spacing))};
    }
    Vec3 minCorner(const Index3& ijk) const {
        return m_origin + Vec3(double(ijk[0]), double(ijk[1]), double(ijk[2])) * m_spacing;
    }
    Vec3 center(const Index3& ijk) const { return minCorner(ijk) + Vec3(0.5, 0.5, 0.5) * m_spacing; }

    std::vector<T>& data() { return m_data; }
    const std::vector<T>& data() const { return m_data; }

private:
    Vec3 m_origin;
    double m_spacing = 1.0;
    Index3 m_dims{0, 0, 0};
    std::vector<T> m_data;
};

} // namespace hs
