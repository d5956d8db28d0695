#include "hs/meshing/MeshTypes.h"

#include <cmath>

namespace hs::meshing {
namespace {

/// Vertices per mm^3 and per mm^2 for edge length 1 mm (the body-centred cubic lattice of the particle mesher at
/// voxel size 1.1 edge: 2 / 1.1^3 inside, plus the denser surface layer). Measured on the benchmark surfaces.
constexpr double kVolumeDensity = 1.5;
constexpr double kSurfaceDensity = 0.45;

} // namespace

std::string_view methodName(MeshMethod method) {
    switch (method) {
    case MeshMethod::Particle:
        return "particle";
    case MeshMethod::TetGen:
        return "tetgen";
    case MeshMethod::Cgal:
        return "cgal";
    }
    return "particle";
}

std::optional<MeshMethod> parseMethod(std::string_view name) {
    for (MeshMethod m : {MeshMethod::Particle, MeshMethod::TetGen, MeshMethod::Cgal})
        if (methodName(m) == name)
            return m;
    return std::nullopt;
}

double estimateVertexCount(const RegionModel& body, double edge) {
    if (body.surfaces.empty() || !(edge > 0.0))
        return 0.0;
    double volume = 0.0, area = 0.0;
    volume = std::fabs(enclosedVolume(body.surfaces[0].surface));
    for (const auto& rs : body.surfaces) {
        area += surfaceArea(rs.surface);
        if (&rs != &body.surfaces[0] && rs.regionId == RegionModel::kVoidRegion)
            volume -= std::fabs(enclosedVolume(rs.surface));
    }
    volume = std::max(volume, 0.0);
    return kVolumeDensity * volume / (edge * edge * edge) + kSurfaceDensity * area / (edge * edge);
}

Result<double> resolveEdgeLength(const RegionModel& body, const MeshParams& params) {
    if (body.surfaces.empty())
        return fail(ErrorCode::InvalidInput, "region model has no surface");
    if (std::isnan(params.targetEdgeLength) || params.targetEdgeLength < 0.0 || std::isinf(params.targetEdgeLength))
        return fail(ErrorCode::InvalidInput, "target edge length must be a finite positive length in mm");
    if (params.targetVertices < 0 || params.targetVertices > kMaxVertices)
        return fail(params.targetVertices < 0 ? ErrorCode::InvalidInput : ErrorCode::LimitExceeded,
                    "target vertex count " + std::to_string(params.targetVertices) + " outside 1.." +
                        std::to_string(kMaxVertices));
    Bounds box;
    for (const auto& rs : body.surfaces)
        for (const Vec3& p : rs.surface.points)
            box.add(p);
    const double diagonal = box.diagonal();
    if (!(diagonal > 0.0) || !std::isfinite(diagonal))
        return fail(ErrorCode::InvalidInput, "the body has an empty or non-finite bounding box");
    double edge = params.targetEdgeLength;
    if (!(edge > 0.0)) {
        if (params.targetVertices > 0) {
            // The count falls monotonically with the edge length: bisect on a log scale.
            double lo = diagonal * 1e-6, hi = diagonal;
            for (int i = 0; i < 80; ++i) {
                const double mid = std::sqrt(lo * hi);
                (estimateVertexCount(body, mid) > double(params.targetVertices) ? lo : hi) = mid;
            }
            edge = hi;
        } else {
            edge = diagonal / 25.0;
        }
    }
    const double expected = estimateVertexCount(body, edge);
    if (!(expected <= double(kMaxVertices)))
        return fail(ErrorCode::LimitExceeded, "edge length " + std::to_string(edge) + " mm would give about " +
                                                  std::to_string(static_cast<long long>(expected)) +
                                                  " vertices, above the limit of " + std::to_string(kMaxVertices));
    if (edge > diagonal)
        edge = diagonal;
    return edge;
}

} // namespace hs::meshing
