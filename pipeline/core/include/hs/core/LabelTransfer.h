#pragma once
/// Carrying face labels from one surface to another that lies on (or near) it, e.g. from the merged organ surface to
/// the boundary of its tetrahedral mesh: each target face takes the labels of the source face nearest to its centroid.

#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"

#include <string>
#include <vector>

namespace hs {

/// For every face of `to`, finds the face of `from` closest to its centroid (exact point-triangle distance, uniform
/// grid search) and copies the values of the face labels `names` (each must exist on `from`; missing ones fail with
/// InvalidInput). Faces farther than `maxDistanceMm` from every source face get `fallback`. Deterministic: ties go to
/// the lower source face index.
[[nodiscard]] Status transferFaceLabels(const SurfaceMesh& from, SurfaceMesh& to, const std::vector<std::string>& names,
                                        double maxDistanceMm, std::int32_t fallback = 0);

} // namespace hs
