// The mesh improver's driver and bookkeeping: the worklist passes, the tet lists and vertex stars, and the tet
// quality measures (circumcentre, radius ratio, smallest dihedral angle).
#include "MeshImproveSteps.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace hs::meshing::detail {
namespace {

/// Worklist items between two cancellation checks.
constexpr std::size_t kCancelEvery = 32;

} // namespace

Improver::Improver(std::vector<Vec3>& points, const std::vector<Tet>& tets, const std::vector<std::int32_t>& regions,
                   const std::vector<VertexFreedom>& freedom, const MeshImproveParams& params,
                   const MeshImproveCallbacks& callbacks)
    : m_points(points), m_freedom(freedom), m_params(params), m_cb(callbacks), m_vertexTets(points.size()),
      m_boundary(points.size(), -1) {
    m_tets.reserve(tets.size() + tets.size() / 16);
    for (std::size_t t = 0; t < tets.size(); ++t)
        addTet(tets[t], regions[t]);
}

Result<MeshImproveStats> Improver::run(Progress& progress) {
    m_stats.minDihedralBefore = worstQuality();
    m_stats.badBefore = worklist().size();
    for (int pass = 0; pass < m_params.passes; ++pass) {
        const auto bad = worklist();
        if (bad.empty())
            break;
        std::size_t changed = 0;
        for (std::size_t i = 0; i < bad.size(); ++i) {
            if (i % kCancelEvery == 0)
                HS_TRY(progress.check("meshing", "improving the mesh"));
            const TetId t = findTet(bad[i].second);
            if (t != kNoTet && m_quality[t] < m_params.targetDihedralDeg && improveTet(t))
                ++changed;
        }
        m_stats.passes = pass + 1;
        if (changed == 0)
            break;
    }
    for (int sweep = 0; sweep < m_params.radiusRatioSweeps; ++sweep) {
        HS_TRY(progress.check("meshing", "improving the mesh"));
        if (smoothRadiusRatioSweep() == 0)
            break;
    }
    m_stats.minDihedralAfter = worstQuality();
    m_stats.badAfter = worklist().size();
    return m_stats;
}

void Improver::output(std::vector<Tet>& tets, std::vector<std::int32_t>& regions) const {
    tets.clear();
    regions.clear();
    for (std::size_t t = 0; t < m_tets.size(); ++t)
        if (m_alive[t]) {
            tets.push_back(m_tets[t]);
            regions.push_back(m_region[t]);
        }
}

TetId Improver::addTet(const Tet& t, std::int32_t region) {
    const auto id = static_cast<TetId>(m_tets.size());
    m_tets.push_back(t);
    m_region.push_back(region);
    m_alive.push_back(1);
    m_quality.push_back(quality(t));
    for (auto v : t)
        m_vertexTets[static_cast<std::size_t>(v)].push_back(id);
    return id;
}

void Improver::killTet(TetId id) {
    m_alive[id] = 0;
    for (auto v : m_tets[id]) {
        auto& list = m_vertexTets[static_cast<std::size_t>(v)];
        list.erase(std::find(list.begin(), list.end(), id));
    }
}

bool Improver::edgeExists(std::int32_t a, std::int32_t b) const {
    for (TetId t : m_vertexTets[static_cast<std::size_t>(a)])
        if (contains(m_tets[t], b))
            return true;
    return false;
}

TetId Improver::neighbourAcross(TetId t, int k) const {
    const Tet& tet = m_tets[t];
    const std::int32_t a = tet[static_cast<std::size_t>(kFace[k][0])];
    const std::int32_t b = tet[static_cast<std::size_t>(kFace[k][1])];
    const std::int32_t c = tet[static_cast<std::size_t>(kFace[k][2])];
    for (TetId u : m_vertexTets[static_cast<std::size_t>(a)])
        if (u != t && contains(m_tets[u], b) && contains(m_tets[u], c))
            return u;
    return kNoTet;
}

bool Improver::onBoundary(std::int32_t v) {
    std::int8_t& cached = m_boundary[static_cast<std::size_t>(v)];
    if (cached < 0) {
        std::vector<std::array<std::int32_t, 3>>& faces = m_faceScratch;
        faces.clear();
        for (TetId t : m_vertexTets[static_cast<std::size_t>(v)]) {
            const Tet& tet = m_tets[t];
            for (int k = 0; k < 4; ++k) {
                if (tet[static_cast<std::size_t>(k)] == v)
                    continue; // the face opposite v
                std::array<std::int32_t, 3> key{-1, -1, m_region[t]};
                for (int i = 0; i < 3; ++i) {
                    const std::int32_t w = tet[static_cast<std::size_t>(kFace[k][i])];
                    if (w != v)
                        (key[0] < 0 ? key[0] : key[1]) = w;
                }
                if (key[0] > key[1])
                    std::swap(key[0], key[1]);
                faces.push_back(key);
            }
        }
        std::sort(faces.begin(), faces.end());
        cached = 0;
        for (std::size_t i = 0; i < faces.size() && !cached;) {
            std::size_t j = i + 1;
            while (j < faces.size() && faces[j][0] == faces[i][0] && faces[j][1] == faces[i][1])
                ++j;
            cached = j - i != 2 || faces[i][2] != faces[i + 1][2];
            i = j;
        }
    }
    return cached == 1;
}

VertexFreedom Improver::freedomOf(std::int32_t v) {
    const VertexFreedom f = m_freedom[static_cast<std::size_t>(v)];
    return f == VertexFreedom::Free && onBoundary(v) ? VertexFreedom::Fixed : f;
}

double Improver::worstQuality() const {
    double worst = 180.0;
    for (std::size_t t = 0; t < m_tets.size(); ++t)
        if (m_alive[t])
            worst = std::min(worst, m_quality[t]);
    return worst;
}

std::vector<std::pair<double, Tet>> Improver::worklist() const {
    std::vector<std::pair<double, Tet>> bad;
    for (std::size_t t = 0; t < m_tets.size(); ++t)
        if (m_alive[t] && m_quality[t] < m_params.targetDihedralDeg) {
            Tet key = m_tets[t];
            std::sort(key.begin(), key.end());
            bad.emplace_back(m_quality[t], key);
        }
    std::sort(bad.begin(), bad.end());
    return bad;
}

TetId Improver::findTet(const Tet& sortedKey) const {
    for (TetId t : m_vertexTets[static_cast<std::size_t>(sortedKey[0])]) {
        Tet key = m_tets[t];
        std::sort(key.begin(), key.end());
        if (key == sortedKey)
            return t;
    }
    return kNoTet;
}

bool Improver::improveTet(TetId t) {
    const Tet tet = m_tets[t];
    static constexpr int kEdges[6][2] = {{0, 1}, {2, 3}, {0, 2}, {1, 3}, {0, 3}, {1, 2}};
    for (const auto& e : kEdges)
        if (removeEdge(tet[static_cast<std::size_t>(e[0])], tet[static_cast<std::size_t>(e[1])]))
            return true;
    for (int k = 0; k < 4; ++k)
        if (flip23(t, k))
            return true;
    bool smoothed = false;
    for (auto v : tet) {
        smoothed = smoothVertex(v) || smoothed;
        if (m_quality[t] >= m_params.targetDihedralDeg)
            return true;
    }
    // Last resort: an inner vertex that cannot move far enough goes (Klingner & Shewchuk's vertex deletion).
    for (auto v : tet)
        if (contractVertex(v))
            return true;
    return smoothed;
}

Vec3 circumcentre(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const Vec3 u = b - a, v = c - a, w = d - a;
    const double det = 2.0 * dot(u, cross(v, w));
    if (det == 0.0)
        return (a + b + c + d) * 0.25;
    return a + (cross(v, w) * norm2(u) + cross(w, u) * norm2(v) + cross(u, v) * norm2(w)) / det;
}

double radiusRatio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const Vec3 u = b - a, v = c - a, w = d - a;
    const double six = dot(u, cross(v, w)); // 6 x volume
    if (!(six > 0.0))
        return 0.0;
    const double faces = norm(cross(u, v)) + norm(cross(v, w)) + norm(cross(w, u)) + norm(cross(c - b, d - b));
    const double inradius = six / faces; // 3 V / (sum of areas), areas = |cross| / 2
    const double circumradius = distance(circumcentre(a, b, c, d), a);
    return 3.0 * inradius / circumradius;
}

double minDihedralDeg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const Vec3 ab = b - a, ac = c - a, ad = d - a;
    if (dot(ab, cross(ac, ad)) <= 0.0)
        return -1.0;
    const Vec3 n[4] = {normalized(cross(c - b, d - b)), normalized(cross(ad, ac)), normalized(cross(ab, ad)),
                       normalized(cross(ac, ab))};
    double worst = -1.0; // largest -cos(normal_i, normal_j) = cos(dihedral)
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            worst = std::max(worst, -dot(n[i], n[j]));
    return std::acos(std::clamp(worst, -1.0, 1.0)) * kRadToDeg;
}

Result<MeshImproveStats> improveMesh(std::vector<Vec3>& points, std::vector<Tet>& tets,
                                     std::vector<std::int32_t>& regions, const std::vector<VertexFreedom>& freedom,
                                     const MeshImproveParams& params, const MeshImproveCallbacks& callbacks,
                                     Progress& progress) {
    if (regions.size() != tets.size() || freedom.size() != points.size())
        return fail(ErrorCode::InvalidInput, "mesh improvement: tets, regions and vertex freedoms do not match");
    Improver improver(points, tets, regions, freedom, params, callbacks);
    auto stats = improver.run(progress);
    if (!stats.ok())
        return stats.failure();
    improver.output(tets, regions);
    return stats;
}

} // namespace hs::meshing::detail
