#pragma once
/// The tubal ostia of an organ surface (its "tissue" face label), for tests that place pathologies beside or on them.

#include "hs/clinical/Tissue.h"
#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"

namespace hs::test {

/// The centre of the organ's right tubal ostium (+x of the organ frame): the mean of its labelled faces' vertices.
/// Internal when the organ labels none there.
inline Result<Vec3> rightOstiumCentre(const SurfaceMesh& organ) {
    const auto& tissue = organ.faceLabels.at(clinical::kSurfaceTissueLabel);
    Vec3 sum;
    double n = 0.0;
    for (std::size_t f = 0; f < organ.triangles.size(); ++f)
        if (static_cast<clinical::SurfaceTissue>(tissue[f]) == clinical::SurfaceTissue::TubalOstium)
            for (std::int32_t v : organ.triangles[f])
                if (organ.points[static_cast<std::size_t>(v)].x > 0.0) {
                    sum += organ.points[static_cast<std::size_t>(v)];
                    n += 1.0;
                }
    if (n == 0.0)
        return fail(ErrorCode::Internal, "the organ labels no right tubal ostium");
    return sum / n;
}

} // namespace hs::test
