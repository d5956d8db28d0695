#include "hs/generate/TissueLayers.h"

#include "hs/clinical/Tissue.h"
#include "hs/core/TriangleGeometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <queue>
#include <tuple>

namespace hs::generate {
namespace {

using FaceKey = std::array<std::int32_t, 3>;

Vec3 tetCentroid(const TetMesh& m, std::size_t t) {
    Vec3 c{0, 0, 0};
    for (auto p : m.tets[t])
        c = c + m.points[static_cast<std::size_t>(p)];
    return c * 0.25;
}

enum class Side : std::uint8_t { None, Cavity, Canal };

Side sideOf(std::int32_t tissue) {
    switch (static_cast<clinical::SurfaceTissue>(tissue)) {
    case clinical::SurfaceTissue::Endometrium:
    case clinical::SurfaceTissue::TubalOstium:
        return Side::Cavity;
    case clinical::SurfaceTissue::CervicalCanal:
    case clinical::SurfaceTissue::Ectocervix:
        return Side::Canal;
    case clinical::SurfaceTissue::Serosa:
        break;
    }
    return Side::None;
}

struct Source {
    std::array<Vec3, 3> triangle;
    Side side = Side::None;
};

double distanceTo(const Vec3& p, const Source& s) {
    return std::sqrt(closestPointOnTriangle(p, s.triangle[0], s.triangle[1], s.triangle[2]).distance2);
}

} // namespace

TissueLayers tissueLayers(const TetMesh& tets, std::int32_t wallRegion, const SurfaceMesh& boundary,
                          const TissueLayerParams& params) {
    const std::size_t n = tets.tets.size();
    TissueLayers out;
    out.layer.assign(n, WallLayer::Myometrium);

    // The tets across each face, and the tet that owns each boundary face.
    const auto neighbours = tetNeighbours(tets);
    std::map<FaceKey, std::int32_t> faceTet;
    for (std::size_t t = 0; t < n; ++t)
        for (int f = 0; f < 4; ++f)
            if (neighbours[t][static_cast<std::size_t>(f)] < 0) {
                const auto& tet = tets.tets[t];
                faceTet.emplace(sortedFace(tet[static_cast<std::size_t>(kTetFacePoints[f][0])],
                                           tet[static_cast<std::size_t>(kTetFacePoints[f][1])],
                                           tet[static_cast<std::size_t>(kTetFacePoints[f][2])]),
                                static_cast<std::int32_t>(t));
            }

    // The lining faces of the wall, as sources.
    std::vector<Source> sources;
    std::vector<std::pair<std::int32_t, std::int32_t>> seeds; // (tet, source)
    const auto tissueIt = boundary.faceLabels.find(clinical::kSurfaceTissueLabel);
    const auto sourceIt = boundary.vertexLabels.find("sourcePoint");
    if (tissueIt != boundary.faceLabels.end() && sourceIt != boundary.vertexLabels.end()) {
        const auto& tissue = tissueIt->second;
        const auto& sourcePoint = sourceIt->second;
        for (std::size_t f = 0; f < boundary.triangles.size(); ++f) {
            const Side side = sideOf(tissue[f]);
            if (side == Side::None)
                continue;
            const auto& tri = boundary.triangles[f];
            const auto a = sourcePoint[static_cast<std::size_t>(tri[0])];
            const auto b = sourcePoint[static_cast<std::size_t>(tri[1])];
            const auto c = sourcePoint[static_cast<std::size_t>(tri[2])];
            const auto it = faceTet.find(sortedFace(a, b, c));
            if (it == faceTet.end())
                continue;
            const auto owner = static_cast<std::size_t>(it->second);
            if (tets.regionOf(owner) != wallRegion) {
                if (side == Side::Cavity && params.coverPathologies && out.layer[owner] != WallLayer::Endometrium) {
                    out.layer[owner] = WallLayer::Endometrium;
                    ++out.coverTets;
                }
                continue;
            }
            Source s;
            s.triangle = {tets.points[static_cast<std::size_t>(a)], tets.points[static_cast<std::size_t>(b)],
                          tets.points[static_cast<std::size_t>(c)]};
            s.side = side;
            if (side == Side::Cavity)
                out.liningAreaMm2 += 0.5 * norm(cross(s.triangle[1] - s.triangle[0], s.triangle[2] - s.triangle[0]));
            seeds.emplace_back(it->second, static_cast<std::int32_t>(sources.size()));
            sources.push_back(s);
        }
    }
    if (sources.empty())
        return out;

    // Multi-source Dijkstra carrying each tet's nearest source; ties broken by tet then source index, so the
    // result does not depend on the order of equal distances.
    std::vector<Vec3> centroid(n);
    for (std::size_t t = 0; t < n; ++t)
        centroid[t] = tetCentroid(tets, t);
    constexpr double kUnreached = 1e300;
    std::vector<double> dist(n, kUnreached);
    std::vector<std::int32_t> nearest(n, -1);
    using Item = std::tuple<double, std::int32_t, std::int32_t>; // distance, tet, source
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    for (const auto& [t, s] : seeds)
        queue.emplace(distanceTo(centroid[static_cast<std::size_t>(t)], sources[static_cast<std::size_t>(s)]), t, s);
    while (!queue.empty()) {
        const auto [d, t, s] = queue.top();
        queue.pop();
        const auto ti = static_cast<std::size_t>(t);
        if (d > dist[ti] || (d == dist[ti] && nearest[ti] >= 0 && nearest[ti] <= s))
            continue;
        dist[ti] = d;
        nearest[ti] = s;
        for (const auto u : neighbours[ti]) {
            if (u < 0 || tets.regionOf(static_cast<std::size_t>(u)) != wallRegion)
                continue;
            const double du = distanceTo(centroid[static_cast<std::size_t>(u)], sources[static_cast<std::size_t>(s)]);
            const auto ui = static_cast<std::size_t>(u);
            if (du < dist[ui] || (du == dist[ui] && (nearest[ui] < 0 || s < nearest[ui])))
                queue.emplace(du, u, s);
        }
    }

    for (std::size_t t = 0; t < n; ++t) {
        if (tets.regionOf(t) != wallRegion || nearest[t] < 0)
            continue;
        const Side side = sources[static_cast<std::size_t>(nearest[t])].side;
        const double volume = std::abs(signedVolume(tets, t));
        if (side == Side::Canal && params.cervix) {
            out.layer[t] = WallLayer::Cervix;
            ++out.cervixTets;
            out.cervixVolumeMm3 += volume;
        } else if (side == Side::Cavity && dist[t] < params.endometriumThicknessMm) {
            out.layer[t] = WallLayer::Endometrium;
            ++out.endometriumTets;
            out.endometriumVolumeMm3 += volume;
        }
    }
    return out;
}

} // namespace hs::generate
