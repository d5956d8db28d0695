#include "Organ.h"

#include "Geometry.h"

#include "hs/clinical/Tissue.h"
#include "hs/core/TriangleGeometry.h"

#include <algorithm>
#include <cmath>

namespace hs::pathology::detail {

std::optional<RayHit> OrganInfo::ray(const Vec3& origin, const Vec3& dir, std::optional<Side> side, double tMin) const {
    std::optional<RayHit> best;
    for (std::size_t f = 0; f < mesh->triangles.size(); ++f) {
        if (side && faceSide[f] != *side)
            continue;
        const Triangle& tr = mesh->triangles[f];
        double t = 0.0;
        if (rayTriangle(origin, dir, mesh->points[static_cast<std::size_t>(tr[0])],
                        mesh->points[static_cast<std::size_t>(tr[1])], mesh->points[static_cast<std::size_t>(tr[2])],
                        tMin, t) &&
            (!best || t < best->t))
            best = RayHit{t, f, origin + dir * t};
    }
    return best;
}

std::pair<std::size_t, double> OrganInfo::nearestFace(const Vec3& p, std::optional<Side> side) const {
    std::size_t best = 0;
    double bestD2 = 1e300;
    for (std::size_t f = 0; f < mesh->triangles.size(); ++f) {
        if (side && faceSide[f] != *side)
            continue;
        const Triangle& tr = mesh->triangles[f];
        const double d2 = closestPointOnTriangle(p, mesh->points[static_cast<std::size_t>(tr[0])],
                                                 mesh->points[static_cast<std::size_t>(tr[1])],
                                                 mesh->points[static_cast<std::size_t>(tr[2])])
                              .distance2;
        if (d2 < bestD2) {
            bestD2 = d2;
            best = f;
        }
    }
    return {best, std::sqrt(bestD2)};
}

Result<OrganInfo> analyzeOrgan(const SurfaceMesh& organ) {
    const auto it = organ.faceLabels.find(clinical::kSurfaceTissueLabel);
    if (it == organ.faceLabels.end() || it->second.size() != organ.triangles.size())
        return fail(ErrorCode::InvalidInput, "the organ surface has no face label \"tissue\" (a uterus-template "
                                             "surface from the anatomy stage is expected)");
    const auto& tissue = it->second;
    OrganInfo info;
    info.mesh = &organ;
    info.faceSide.resize(organ.triangles.size());
    info.vertexSide.assign(organ.points.size(), Side::Serosa);
    std::vector<std::uint8_t> inCanal(organ.points.size(), 0), inEndo(organ.points.size(), 0);
    Vec3 ostR, ostL;
    int nR = 0, nL = 0;
    bool anySerosa = false;
    for (std::size_t f = 0; f < organ.triangles.size(); ++f) {
        const auto t = static_cast<clinical::SurfaceTissue>(tissue[f]);
        const bool cavity = t == clinical::SurfaceTissue::Endometrium || t == clinical::SurfaceTissue::CervicalCanal ||
                            t == clinical::SurfaceTissue::TubalOstium;
        info.faceSide[f] = cavity ? Side::Cavity : Side::Serosa;
        anySerosa = anySerosa || t == clinical::SurfaceTissue::Serosa;
        for (std::int32_t v : organ.triangles[f]) {
            const auto vi = static_cast<std::size_t>(v);
            if (cavity)
                info.vertexSide[vi] = Side::Cavity;
            if (t == clinical::SurfaceTissue::CervicalCanal)
                inCanal[vi] = 1;
            if (t == clinical::SurfaceTissue::Endometrium || t == clinical::SurfaceTissue::TubalOstium)
                inEndo[vi] = 1;
        }
    }
    Vec3 os;
    int nOs = 0;
    for (std::size_t v = 0; v < organ.points.size(); ++v)
        if (inCanal[v] && inEndo[v]) {
            os += organ.points[v];
            ++nOs;
        }
    if (nOs == 0 || !anySerosa)
        return fail(ErrorCode::InvalidInput, "the organ surface lacks the endometrium, cervical canal or serosa "
                                             "labels needed to place pathologies");
    info.internalOs = os / nOs;
    // The cavity's axis runs from the internal os through the centroid of the endometrium (on the midline); the
    // farthest endometrium vertex would be a cornu and tilt the axis sideways.
    Vec3 endoCentroid;
    double nEndo = 0.0;
    for (std::size_t v = 0; v < organ.points.size(); ++v)
        if (inEndo[v]) {
            endoCentroid += organ.points[v];
            nEndo += 1.0;
        }
    info.axis = normalized(endoCentroid / std::max(nEndo, 1.0) - info.internalOs);
    double far = 0.0;
    for (std::size_t v = 0; v < organ.points.size(); ++v)
        if (inEndo[v])
            far = std::max(far, dot(organ.points[v] - info.internalOs, info.axis));
    info.cavityFundus = info.internalOs + info.axis * far;
    info.cavityLengthMm = far;
    const Vec3 x{1.0, 0.0, 0.0};
    info.lateral = normalized(x - info.axis * dot(x, info.axis));
    info.anterior = cross(info.axis, info.lateral);
    info.cavityCenter = (info.internalOs + info.cavityFundus) * 0.5;

    for (std::size_t f = 0; f < organ.triangles.size(); ++f) {
        if (static_cast<clinical::SurfaceTissue>(tissue[f]) != clinical::SurfaceTissue::TubalOstium)
            continue;
        for (std::int32_t v : organ.triangles[f]) {
            const Vec3& p = organ.points[static_cast<std::size_t>(v)];
            if (dot(p - info.cavityCenter, info.lateral) > 0.0) {
                ostR += p;
                ++nR;
            } else {
                ostL += p;
                ++nL;
            }
        }
    }
    auto cornuByRay = [&](double sign) {
        const Vec3 dir = normalized(info.axis + info.lateral * sign);
        auto hit = info.ray(info.cavityCenter, dir, Side::Cavity);
        return hit ? hit->point : info.cavityCenter + dir * (0.5 * info.cavityLengthMm);
    };
    info.cornuRight = nR > 0 ? ostR / nR : cornuByRay(1.0);
    info.cornuLeft = nL > 0 ? ostL / nL : cornuByRay(-1.0);
    info.ostiumRight = nR > 0;
    info.ostiumLeft = nL > 0;
    info.cavityWidthMm = distance(info.cornuRight, info.cornuLeft);

    double minL = 1e300, maxL = -1e300, minA = 1e300, maxA = -1e300, top = 0.0;
    for (std::size_t v = 0; v < organ.points.size(); ++v) {
        const Vec3 d = organ.points[v] - info.internalOs;
        if (info.vertexSide[v] != Side::Serosa || dot(d, info.axis) < 0.0)
            continue;
        minL = std::min(minL, dot(d, info.lateral));
        maxL = std::max(maxL, dot(d, info.lateral));
        minA = std::min(minA, dot(d, info.anterior));
        maxA = std::max(maxA, dot(d, info.anterior));
        top = std::max(top, dot(d, info.axis));
    }
    info.corpusWidthMm = maxL - minL;
    info.corpusDepthMm = maxA - minA;
    info.corpusLengthMm = top;
    return info;
}

} // namespace hs::pathology::detail
