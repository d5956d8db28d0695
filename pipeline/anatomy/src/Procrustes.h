#pragma once
/// Generalised Procrustes alignment of shapes in correspondence (Gower 1975), rotation and translation only.

#include "hs/core/Vec3.h"

#include <vector>

namespace hs::anatomy::detail {

/// Moves `shape` rigidly onto `target` (least squares; Kabsch 1976 without reflection, or translation only).
void rigidAlign(std::vector<Vec3>& shape, const std::vector<Vec3>& target, bool rotation);

struct ProcrustesResult {
    std::vector<std::vector<Vec3>> aligned;
    std::vector<Vec3> mean;
    int iterations = 0;
    double changeMm = 0.0; ///< RMS movement of the mean in the last iteration
};

/// Aligns all shapes to their common mean; the mean is kept in the frame of the first shape.
ProcrustesResult generalizedProcrustes(const std::vector<std::vector<Vec3>>& shapes, bool rotation, int maxIterations,
                                       double toleranceMm);

} // namespace hs::anatomy::detail
