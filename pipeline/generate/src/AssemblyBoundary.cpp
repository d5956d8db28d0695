// The scene's labelled boundary (tissue and pathology labels carried over from the body outline) and what the
// texture stage needs of it: the faces the scope sees, the close-up levels and the tubal ostia.
#include "hs/generate/Assembly.h"

#include "AssemblySteps.h"
#include "hs/clinical/Tissue.h"
#include "hs/core/LabelTransfer.h"
#include "hs/core/Subdivision.h"
#include "hs/scene/ScopePassage.h"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace hs::generate {
namespace {

using detail::kTissueOstium;

/// The ostia are smaller than the mesh's triangles, so no boundary face may be nearest to an ostium face: carry
/// them the other way too, marking the boundary face nearest to each ostium face of the organ.
Status keepSmallTissueFeatures(const SurfaceMesh& outline, SurfaceMesh& boundary, double reach) {
    SurfaceMesh probe = outline;
    std::vector<std::int32_t> index(boundary.triangles.size());
    for (std::size_t f = 0; f < index.size(); ++f)
        index[f] = static_cast<std::int32_t>(f);
    boundary.faceLabels["faceIndex"] = std::move(index);
    const Status status = transferFaceLabels(boundary, probe, {"faceIndex"}, reach, -1);
    boundary.faceLabels.erase("faceIndex");
    HS_TRY(status);
    const auto& tissue = outline.faceLabels.at(clinical::kSurfaceTissueLabel);
    const auto& nearest = probe.faceLabels.at("faceIndex");
    auto& boundaryTissue = boundary.faceLabels.at(clinical::kSurfaceTissueLabel);
    for (std::size_t f = 0; f < tissue.size(); ++f)
        if (tissue[f] == kTissueOstium && nearest[f] >= 0)
            boundaryTissue[static_cast<std::size_t>(nearest[f])] = kTissueOstium;
    return {};
}

} // namespace

std::vector<std::int32_t> scopeSeenFaces(const SurfaceMesh& boundary) {
    std::vector<std::int32_t> seen(boundary.triangles.size(), 1);
    const auto tissue = boundary.faceLabels.find(clinical::kSurfaceTissueLabel);
    if (tissue == boundary.faceLabels.end())
        return seen;
    for (std::size_t f = 0; f < seen.size(); ++f)
        seen[f] = tissue->second[f] == clinical::labelValue(clinical::SurfaceTissue::Serosa) ? 0 : 1;
    return seen;
}

int visualSurfaceLevels(const SurfaceMesh& boundary) {
    const SurfaceShape shape = measureSurfaceShape(boundary, scopeSeenFaces(boundary));
    int levels = 0;
    for (double edge = shape.meanEdgeMm; edge > kVisualEdgeLengthMm && levels < kMaxVisualSurfaceLevels; edge /= 2.0)
        ++levels;
    return levels;
}

std::vector<OstiumOpening> ostiumOpenings(const SurfaceMesh& boundary) {
    std::vector<OstiumOpening> out;
    const auto tissue = boundary.faceLabels.find(clinical::kSurfaceTissueLabel);
    if (tissue == boundary.faceLabels.end())
        return out;
    // Union-find over the ostium faces, joined through shared points.
    const std::size_t faces = boundary.triangles.size();
    std::vector<std::int32_t> parent(faces, -1), ownerOfPoint(boundary.points.size(), -1);
    const auto find = [&](std::int32_t f) {
        while (parent[static_cast<std::size_t>(f)] != f)
            f = parent[static_cast<std::size_t>(f)] =
                parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(f)])];
        return f;
    };
    for (std::size_t f = 0; f < faces; ++f) {
        if (tissue->second[f] != kTissueOstium)
            continue;
        parent[f] = static_cast<std::int32_t>(f);
        for (std::int32_t v : boundary.triangles[f]) {
            std::int32_t& owner = ownerOfPoint[static_cast<std::size_t>(v)];
            if (owner < 0) {
                owner = static_cast<std::int32_t>(f);
                continue;
            }
            const std::int32_t a = find(owner), b = find(static_cast<std::int32_t>(f));
            if (a != b)
                parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
        }
    }
    std::map<std::int32_t, std::pair<Vec3, Vec3>> sums; // root -> (area-weighted centre, area-weighted normal)
    std::map<std::int32_t, double> areas;
    for (std::size_t f = 0; f < faces; ++f) {
        if (parent[f] < 0)
            continue;
        const Triangle& t = boundary.triangles[f];
        const Vec3& a = boundary.points[static_cast<std::size_t>(t[0])];
        const Vec3& b = boundary.points[static_cast<std::size_t>(t[1])];
        const Vec3& c = boundary.points[static_cast<std::size_t>(t[2])];
        const Vec3 n = cross(b - a, c - a); // |n| = 2 area
        const double area = 0.5 * norm(n);
        auto& sum = sums[find(static_cast<std::int32_t>(f))];
        sum.first += (a + b + c) * (area / 3.0);
        sum.second += n;
        areas[find(static_cast<std::int32_t>(f))] += area;
    }
    for (const auto& [root, sum] : sums) {
        const double area = areas.at(root);
        const double len = norm(sum.second);
        if (area <= 0.0 || len <= 0.0)
            continue;
        out.push_back({sum.first / area, sum.second / len});
    }
    return out;
}

std::vector<texture::DarkSpot> ostiumDarkSpots(const std::vector<OstiumOpening>& ostia) {
    std::vector<texture::DarkSpot> spots;
    for (const auto& o : ostia)
        spots.push_back({o.centreMm, 1.5 * kOstiumRadiusMm, 0.85});
    return spots;
}

std::optional<texture::CanalFrame> canalFrame(const SurfaceMesh& boundary) {
    const std::vector<std::int32_t> canal =
        facesWith(boundary, clinical::kSurfaceTissueLabel, detail::kTissueCervicalCanal);
    const std::vector<std::int32_t> ostia = facesWith(boundary, clinical::kSurfaceTissueLabel, kTissueOstium);
    if (canal.empty() || ostia.empty())
        return std::nullopt;
    const auto ends = scene::findScopeLandmarks(boundary, canal, ostia);
    if (!ends || distance(ends->externalOsMm, ends->internalOsMm) < 1.0)
        return std::nullopt;
    texture::CanalFrame frame;
    frame.externalOsMm = ends->externalOsMm;
    frame.internalOsMm = ends->internalOsMm;
    frame.anterior = Vec3{0.0, 1.0, 0.0};
    const Vec3 axis = normalized(frame.internalOsMm - frame.externalOsMm);
    std::vector<double> fromAxis; // per corner of a canal face (a point counts once per face it is in)
    for (const std::int32_t f : canal)
        for (const std::int32_t v : boundary.triangles[static_cast<std::size_t>(f)]) {
            const Vec3 q = boundary.points[static_cast<std::size_t>(v)] - frame.externalOsMm;
            fromAxis.push_back(norm(q - axis * dot(q, axis)));
            frame.radiusMm = std::max(frame.radiusMm, fromAxis.back());
        }
    std::nth_element(fromAxis.begin(), fromAxis.begin() + static_cast<std::ptrdiff_t>(fromAxis.size() / 2),
                     fromAxis.end());
    frame.wallRadiusMm = std::min(frame.radiusMm, fromAxis[fromAxis.size() / 2]);
    if (norm(frame.anterior - axis * dot(frame.anterior, axis)) < 1e-3 || frame.radiusMm <= 0.0)
        return std::nullopt;
    return frame;
}

texture::CloseUpParams closeUpParamsFor(const SurfaceMesh& boundary, const std::vector<OstiumOpening>& ostia) {
    texture::CloseUpParams p;
    for (const auto& o : ostia)
        p.pits.push_back({o.centreMm, o.normal, kOstiumRadiusMm, kOstiumDepthMm});
    p.levels = visualSurfaceLevels(boundary);
    p.seen = scopeSeenFaces(boundary);
    p.smoothing.iterations = 10;
    p.smoothing.maxDisplacement = kMaxVisualFairingMm;
    return p;
}

Result<SurfaceMesh> labelledBoundary(const TetMesh& tets, const SurfaceMesh& outline, const scene::CaseSpec& spec,
                                     double reachMm) {
    SurfaceMesh boundary = extractBoundary(tets);
    HS_TRY(transferFaceLabels(outline, boundary, {clinical::kSurfaceTissueLabel, merge::kPathologyLabel}, reachMm));
    HS_TRY(keepSmallTissueFeatures(outline, boundary, reachMm));
    std::vector<std::int32_t> appearance(boundary.triangles.size(), 0);
    const auto& over = boundary.faceLabels.at(merge::kPathologyLabel);
    for (std::size_t f = 0; f < appearance.size(); ++f) {
        const auto p = over[f] - 1; // 1 + index of the pathology a face is draped over
        if (p >= 0 && static_cast<std::size_t>(p) < spec.pathologies.size())
            appearance[f] =
                spec.pathologies[static_cast<std::size_t>(p)].kind == clinical::PathologyKind::Myoma ? 1 : 2;
    }
    boundary.faceLabels[kAppearanceLabel] = std::move(appearance);
    return boundary;
}

} // namespace hs::generate
