#include "hs/core/LabelTransfer.h"

#include "hs/core/TriangleGrid.h"

#include <algorithm>
#include <cmath>

namespace hs {
namespace {

double meanEdgeLength(const SurfaceMesh& mesh) {
    double sum = 0.0;
    for (const auto& t : mesh.triangles)
        for (int e = 0; e < 3; ++e)
            sum += distance(mesh.points[static_cast<std::size_t>(t[static_cast<std::size_t>(e)])],
                            mesh.points[static_cast<std::size_t>(t[static_cast<std::size_t>((e + 1) % 3)])]);
    return mesh.triangles.empty() ? 1.0 : sum / (3.0 * static_cast<double>(mesh.triangles.size()));
}

} // namespace

Status transferFaceLabels(const SurfaceMesh& from, SurfaceMesh& to, const std::vector<std::string>& names,
                          double maxDistanceMm, std::int32_t fallback) {
    HS_TRY(validate(from));
    HS_TRY(validate(to));
    if (!(maxDistanceMm > 0.0) || !std::isfinite(maxDistanceMm))
        return fail(ErrorCode::InvalidInput, "label transfer distance must be a finite positive length in mm");
    std::vector<const std::vector<std::int32_t>*> sources;
    for (const auto& name : names) {
        const auto it = from.faceLabels.find(name);
        if (it == from.faceLabels.end() || it->second.size() != from.triangles.size())
            return fail(ErrorCode::InvalidInput, "the source surface has no face label '" + name + "'");
        sources.push_back(&it->second);
    }
    const TriangleGrid grid(from, std::max(meanEdgeLength(from), 1e-6), /*insideTests=*/false);
    std::vector<std::vector<std::int32_t>> values(names.size(),
                                                  std::vector<std::int32_t>(to.triangles.size(), fallback));
    for (std::size_t f = 0; f < to.triangles.size(); ++f) {
        const auto& t = to.triangles[f];
        const Vec3 centroid = (to.points[static_cast<std::size_t>(t[0])] + to.points[static_cast<std::size_t>(t[1])] +
                               to.points[static_cast<std::size_t>(t[2])]) /
                              3.0;
        const std::int32_t source = grid.closestWithin(centroid, maxDistanceMm * maxDistanceMm).triangle;
        if (source < 0)
            continue;
        for (std::size_t n = 0; n < names.size(); ++n)
            values[n][f] = (*sources[n])[static_cast<std::size_t>(source)];
    }
    for (std::size_t n = 0; n < names.size(); ++n)
        to.faceLabels[names[n]] = std::move(values[n]);
    return {};
}

} // namespace hs
