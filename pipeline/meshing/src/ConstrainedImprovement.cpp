// Improvement of the kept tets with every particle held on its surface, feature edge or corner.
#include "MesherSteps.h"

#include "hs/meshing/Geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace hs::meshing::detail {

namespace {

/// The input feature edge a feature particle lies on: the edge of its triangle closest to it.
std::array<Vec3, 2> featureSegment(const SurfaceMesh& mesh, std::int32_t triangle, const Vec3& p) {
    const Triangle& t = mesh.triangles[static_cast<std::size_t>(triangle)];
    std::array<Vec3, 2> best{};
    double bestD = 1e300;
    for (std::size_t k = 0; k < 3; ++k) {
        const Vec3& a = mesh.points[static_cast<std::size_t>(t[k])];
        const Vec3& b = mesh.points[static_cast<std::size_t>(t[(k + 1) % 3])];
        const double len2 = norm2(b - a);
        const double s = len2 > 0.0 ? std::clamp(dot(p - a, b - a) / len2, 0.0, 1.0) : 0.0;
        const double d = norm2(a + (b - a) * s - p);
        if (d < bestD) {
            bestD = d;
            best = {a, b};
        }
    }
    return best;
}

/// Where each particle may go during mesh improvement: inner particles anywhere, surface and interface particles
/// along their surface, feature particles along their feature edge, corners nowhere.
class ParticleConstraints {
public:
    ParticleConstraints(const RegionModel& body, const std::vector<detail::SurfaceAdjacency>& adjacency,
                        detail::Particles& ps)
        : m_body(body), m_adjacency(adjacency), m_ps(ps), m_freedom(ps.size(), detail::VertexFreedom::Fixed) {
        for (std::size_t i = 0; i < ps.size(); ++i) {
            switch (ps.kind[i]) {
            case detail::ParticleKind::Inner:
                m_freedom[i] = detail::VertexFreedom::Free;
                break;
            case detail::ParticleKind::Surface:
                m_freedom[i] = detail::VertexFreedom::Surface;
                break;
            case detail::ParticleKind::Feature:
                m_freedom[i] = detail::VertexFreedom::Feature;
                m_segments[static_cast<std::uint32_t>(i)] = featureSegment(surface(i), ps.triangle[i], ps.position[i]);
                break;
            case detail::ParticleKind::Corner:
                break;
            }
        }
    }

    const std::vector<detail::VertexFreedom>& freedom() const { return m_freedom; }

    detail::MeshImproveCallbacks callbacks() {
        detail::MeshImproveCallbacks cb;
        cb.project = [this](std::uint32_t v, const Vec3& candidate) {
            if (m_ps.kind[v] == detail::ParticleKind::Feature) {
                const auto& [a, b] = m_segments.at(v);
                return a + (b - a) * std::clamp(dot(candidate - a, b - a) / norm2(b - a), 0.0, 1.0);
            }
            Vec3 projected;
            detail::projectByWalk(surface(v), adjacency(v), m_ps.triangle[v], candidate, projected);
            return projected;
        };
        cb.constraintAxis = [this](std::uint32_t v) {
            if (m_ps.kind[v] == detail::ParticleKind::Feature) {
                const auto& [a, b] = m_segments.at(v);
                return normalized(b - a);
            }
            return adjacency(v).faceNormals[static_cast<std::size_t>(m_ps.triangle[v])];
        };
        cb.moved = [this](std::uint32_t v, const Vec3& position) {
            if (m_ps.kind[v] != detail::ParticleKind::Surface)
                return;
            Vec3 projected;
            m_ps.triangle[v] = detail::projectByWalk(surface(v), adjacency(v), m_ps.triangle[v], position, projected);
        };
        return cb;
    }

private:
    const SurfaceMesh& surface(std::size_t i) const {
        return m_body.surfaces[static_cast<std::size_t>(m_ps.surface[i])].surface;
    }
    const detail::SurfaceAdjacency& adjacency(std::size_t i) const {
        return m_adjacency[static_cast<std::size_t>(m_ps.surface[i])];
    }

    const RegionModel& m_body;
    const std::vector<detail::SurfaceAdjacency>& m_adjacency;
    detail::Particles& m_ps;
    std::vector<detail::VertexFreedom> m_freedom;
    std::unordered_map<std::uint32_t, std::array<Vec3, 2>> m_segments; ///< feature particle -> its input edge
};

} // namespace

/// Improves the kept tets (flips, boundary flips, smoothing; see MeshImprove.h) with every particle on its
/// constraint. Replaces `tets` and `region` by the kept, improved tets.
Result<detail::MeshImproveStats> improveTets(const RegionModel& body,
                                             const std::vector<detail::SurfaceAdjacency>& adjacency,
                                             detail::Particles& ps, std::vector<Tet>& tets,
                                             std::vector<std::int32_t>& region, Progress& progress) {
    // In canonical order: the improvement is sequential and its result depends on the order of the tets, which
    // CGAL's cell storage does not fix.
    std::vector<std::pair<Tet, std::int32_t>> sorted;
    for (std::size_t t = 0; t < tets.size(); ++t)
        if (region[t] >= 0)
            sorted.emplace_back(canonicalTet(tets[t]), region[t]);
    std::sort(sorted.begin(), sorted.end());
    tets.clear();
    region.clear();
    for (const auto& [t, r] : sorted) {
        tets.push_back(t);
        region.push_back(r);
    }
    ParticleConstraints constraints(body, adjacency, ps);
    detail::MeshImproveParams params;
    params.targetDihedralDeg = kImproveDihedralDeg;
    params.radiusRatioSweeps = kRadiusRatioSweeps;
    params.radiusRatioBelow = kRadiusRatioBelow;
    return detail::improveMesh(ps.position, tets, region, constraints.freedom(), params, constraints.callbacks(),
                               progress);
}

void recordImprovement(const detail::MeshImproveStats& stats, StepTiming& step) {
    auto& counts = step.counts;
    counts.emplace_back("badBefore", static_cast<std::int64_t>(stats.badBefore));
    counts.emplace_back("badAfter", static_cast<std::int64_t>(stats.badAfter));
    counts.emplace_back("edgeRemovals", static_cast<std::int64_t>(stats.edgeRemovals));
    counts.emplace_back("faceFlips", static_cast<std::int64_t>(stats.faceFlips));
    counts.emplace_back("boundaryFlips", static_cast<std::int64_t>(stats.boundaryFlips));
    counts.emplace_back("smoothedVertices", static_cast<std::int64_t>(stats.smoothedVertices));
    counts.emplace_back("contractions", static_cast<std::int64_t>(stats.contractions));
    counts.emplace_back("passes", stats.passes);
    counts.emplace_back("radiusRatioMoves", static_cast<std::int64_t>(stats.radiusRatioMoves));
    counts.emplace_back("minDihedralBeforeMilliDeg", std::lround(stats.minDihedralBefore * 1000.0));
    counts.emplace_back("minDihedralAfterMilliDeg", std::lround(stats.minDihedralAfter * 1000.0));
}

} // namespace hs::meshing::detail
