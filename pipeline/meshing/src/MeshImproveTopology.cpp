// The mesh improver's topological operations: edge removal (interior n-to-m flips, boundary flips, peeling), 2-3
// face flips and contraction of an inner vertex onto a neighbour.
#include "MeshImproveSteps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace hs::meshing::detail {
namespace {

bool evenPermutation(const std::array<int, 4>& p) {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            inversions += p[static_cast<std::size_t>(i)] > p[static_cast<std::size_t>(j)];
    return inversions % 2 == 0;
}

} // namespace

bool Improver::edgeRing(std::int32_t a, std::int32_t b, EdgeRing& ring) const {
    ring.vertices.clear();
    ring.tets.clear();
    std::vector<std::array<std::int32_t, 2>> links; // (c, d) per tet: (a, b, c, d) positive
    std::vector<TetId> around;
    for (TetId t : m_vertexTets[static_cast<std::size_t>(a)])
        if (contains(m_tets[t], b))
            around.push_back(t);
    if (around.empty() || around.size() > static_cast<std::size_t>(m_params.maxRing))
        return false;
    ring.region = m_region[around.front()];
    for (TetId t : around) {
        if (m_region[t] != ring.region)
            return false; // an interface runs through the edge
        const Tet& tet = m_tets[t];
        std::array<int, 4> pos{};
        int rest = 2;
        for (int k = 0; k < 4; ++k) {
            const std::int32_t v = tet[static_cast<std::size_t>(k)];
            if (v == a)
                pos[0] = k;
            else if (v == b)
                pos[1] = k;
            else
                pos[static_cast<std::size_t>(rest++)] = k;
        }
        if (!evenPermutation(pos))
            std::swap(pos[2], pos[3]);
        links.push_back({tet[static_cast<std::size_t>(pos[2])], tet[static_cast<std::size_t>(pos[3])]});
    }
    // Start at a c that is nobody's d (open ring), else at the first tet (closed ring).
    std::size_t start = 0;
    int starts = 0;
    for (std::size_t i = 0; i < links.size(); ++i) {
        const bool isTarget =
            std::any_of(links.begin(), links.end(), [&](const auto& l) { return l[1] == links[i][0]; });
        if (!isTarget) {
            start = i;
            ++starts;
        }
    }
    if (starts > 1)
        return false;
    ring.closed = starts == 0;
    std::vector<std::uint8_t> used(links.size(), 0);
    std::size_t cur = start;
    ring.vertices.push_back(links[cur][0]);
    for (std::size_t step = 0; step < links.size(); ++step) {
        if (used[cur])
            return false;
        used[cur] = 1;
        ring.tets.push_back(around[cur]);
        const std::int32_t d = links[cur][1];
        if (step + 1 == links.size()) {
            if (ring.closed && d != ring.vertices.front())
                return false;
            if (!ring.closed)
                ring.vertices.push_back(d);
            break;
        }
        ring.vertices.push_back(d);
        std::size_t nextTet = links.size();
        for (std::size_t i = 0; i < links.size(); ++i)
            if (links[i][0] == d) {
                if (nextTet != links.size())
                    return false;
                nextTet = i;
            }
        if (nextTet == links.size())
            return false;
        cur = nextTet;
    }
    return true;
}

Vec3 Improver::outwardNormal(std::int32_t a, std::int32_t b, std::int32_t c, std::int32_t inner) const {
    Vec3 n = normalized(cross(point(b) - point(a), point(c) - point(a)));
    if (dot(n, point(inner) - point(a)) > 0.0)
        n = -n;
    return n;
}

bool Improver::removeEdge(std::int32_t a, std::int32_t b) {
    EdgeRing ring;
    if (!edgeRing(a, b, ring))
        return false;
    const std::size_t k = ring.vertices.size();
    if (ring.closed && k < 3)
        return false;
    double oldWorst = 180.0;
    for (TetId t : ring.tets)
        oldWorst = std::min(oldWorst, m_quality[t]);
    if (!ring.closed && !boundaryRemovalAllowed(a, b, ring))
        return false;
    std::vector<std::array<std::size_t, 3>> triangles;
    const double newWorst = bestTriangulation(a, b, ring.vertices, triangles);
    if (!(newWorst > oldWorst + kMinGainDeg) || newWorst <= 0.0)
        return false;
    // No new edge may exist already (it would run outside the ring).
    const auto& r = ring.vertices;
    for (const auto& tri : triangles)
        for (const auto& [i, j] : {std::pair{tri[0], tri[1]}, std::pair{tri[1], tri[2]}, std::pair{tri[0], tri[2]}})
            if (j - i >= 2 && !(ring.closed && i == 0 && j == k - 1) && edgeExists(r[i], r[j]))
                return false;
    for (TetId t : ring.tets)
        killTet(t);
    for (const auto& tri : triangles) {
        addTet({a, r[tri[0]], r[tri[1]], r[tri[2]]}, ring.region);
        addTet({b, r[tri[2]], r[tri[1]], r[tri[0]]}, ring.region);
    }
    if (ring.closed)
        ++m_stats.edgeRemovals;
    else
        ++m_stats.boundaryFlips;
    return true;
}

double Improver::bestTriangulation(std::int32_t a, std::int32_t b, const std::vector<std::int32_t>& r,
                                   std::vector<std::array<std::size_t, 3>>& triangles) const {
    const std::size_t k = r.size();
    triangles.clear();
    if (k < 3)
        return 180.0;
    // best[i][j]: worst angle of the best triangulation of r_i..r_j; split: its apex on the chord i-j.
    std::vector<double> best(k * k, 180.0);
    std::vector<std::size_t> split(k * k, 0);
    auto at = [k](std::size_t i, std::size_t j) { return i * k + j; };
    for (std::size_t len = 2; len < k; ++len)
        for (std::size_t i = 0; i + len < k; ++i) {
            const std::size_t j = i + len;
            double bestValue = -1e9;
            for (std::size_t m = i + 1; m < j; ++m) {
                double v = std::min(best[at(i, m)], best[at(m, j)]);
                if (v > bestValue)
                    v = std::min(v, minDihedralDeg(point(a), point(r[i]), point(r[m]), point(r[j])));
                if (v > bestValue)
                    v = std::min(v, minDihedralDeg(point(b), point(r[j]), point(r[m]), point(r[i])));
                if (v > bestValue) {
                    bestValue = v;
                    split[at(i, j)] = m;
                }
            }
            best[at(i, j)] = bestValue;
        }
    std::vector<std::pair<std::size_t, std::size_t>> stack{{0, k - 1}};
    while (!stack.empty()) {
        const auto [i, j] = stack.back();
        stack.pop_back();
        if (j - i < 2)
            continue;
        const std::size_t m = split[at(i, j)];
        triangles.push_back({i, m, j});
        stack.emplace_back(i, m);
        stack.emplace_back(m, j);
    }
    return best[at(0, k - 1)];
}

bool Improver::boundaryRemovalAllowed(std::int32_t a, std::int32_t b, const EdgeRing& ring) {
    const auto& r = ring.vertices;
    const std::size_t n = ring.tets.size();
    const TetId first = ring.tets.front(), last = ring.tets.back();
    // The face (a, b, r0) of the first tet is opposite r1; (a, b, r_n) of the last is opposite r_{n-1}.
    for (const auto& [t, opposite] : {std::pair{first, r[1]}, std::pair{last, r[n - 1]}}) {
        const auto k = static_cast<int>(std::find(m_tets[t].begin(), m_tets[t].end(), opposite) - m_tets[t].begin());
        if (neighbourAcross(t, k) != kNoTet)
            return false; // an interface face: the other region's tets share it
    }
    const Vec3 n0 = outwardNormal(a, b, r[0], r[1]);
    const Vec3 n1 = outwardNormal(a, b, r[n], r[n - 1]);
    if (dot(n0, n1) < std::cos(m_params.coplanarDeg / kRadToDeg))
        return false;
    if (n == 1) {
        // Peeling: the two other faces must be inner faces of the same region, so the boundary stays a
        // manifold and no other region is laid open (in a layer thinner than one edge the tet behind is often
        // the nested region's).
        const Tet& tet = m_tets[first];
        for (int k = 0; k < 4; ++k) {
            const std::int32_t v = tet[static_cast<std::size_t>(k)];
            if (v != a && v != b)
                continue;
            const TetId behind = neighbourAcross(first, k);
            if (behind == kNoTet || m_region[behind] != ring.region)
                return false;
        }
    } else if (edgeExists(r[0], r[n])) {
        return false;
    }
    return true;
}

bool Improver::flip23(TetId t, int k) {
    const TetId u = neighbourAcross(t, k);
    if (u == kNoTet || m_region[u] != m_region[t])
        return false;
    const Tet& tet = m_tets[t];
    const std::int32_t d = tet[static_cast<std::size_t>(k)];
    const std::int32_t a = tet[static_cast<std::size_t>(kFace[k][0])];
    const std::int32_t b = tet[static_cast<std::size_t>(kFace[k][1])];
    const std::int32_t c = tet[static_cast<std::size_t>(kFace[k][2])];
    std::int32_t e = -1;
    for (auto v : m_tets[u])
        if (v != a && v != b && v != c)
            e = v;
    if (e < 0 || edgeExists(d, e))
        return false;
    const double oldWorst = std::min(m_quality[t], m_quality[u]);
    // (a, b, c, d) is positive, so seen from d the ring around (d, e) runs a, c, b.
    const std::array<Tet, 3> created{Tet{d, e, a, c}, Tet{d, e, c, b}, Tet{d, e, b, a}};
    for (const Tet& n : created)
        if (!(quality(n) > oldWorst + kMinGainDeg))
            return false;
    const std::int32_t region = m_region[t];
    killTet(t);
    killTet(u);
    for (const Tet& n : created)
        addTet(n, region);
    ++m_stats.faceFlips;
    return true;
}

bool Improver::contractVertex(std::int32_t v) {
    if (!m_params.contractVertices || freedomOf(v) != VertexFreedom::Free)
        return false;
    const std::vector<TetId> star = m_vertexTets[static_cast<std::size_t>(v)];
    double oldWorst = 180.0;
    std::vector<std::int32_t> neighbours;
    for (TetId t : star) {
        oldWorst = std::min(oldWorst, m_quality[t]);
        for (auto w : m_tets[t])
            if (w != v)
                neighbours.push_back(w);
    }
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    std::int32_t bestW = -1;
    double bestWorst = oldWorst + kMinGainDeg;
    for (std::int32_t w : neighbours) {
        double worst = 180.0;
        for (TetId t : star) {
            if (contains(m_tets[t], w))
                continue;
            worst = std::min(worst, qualityWith(t, v, point(w)));
            if (worst <= bestWorst)
                break;
        }
        if (worst > bestWorst) {
            bestWorst = worst;
            bestW = w;
        }
    }
    if (bestW < 0)
        return false;
    // New edges (w, x) must not exist elsewhere already.
    for (std::int32_t x : neighbours)
        if (x != bestW) {
            bool inStar = false;
            for (TetId t : star)
                inStar = inStar || (contains(m_tets[t], bestW) && contains(m_tets[t], x));
            if (!inStar && edgeExists(bestW, x))
                return false;
        }
    std::vector<std::pair<Tet, std::int32_t>> created;
    for (TetId t : star) {
        if (contains(m_tets[t], bestW))
            continue;
        Tet n = m_tets[t];
        std::replace(n.begin(), n.end(), v, bestW);
        created.emplace_back(n, m_region[t]);
    }
    for (TetId t : star)
        killTet(t);
    for (const auto& [n, r] : created)
        addTet(n, r);
    ++m_stats.contractions;
    return true;
}

} // namespace hs::meshing::detail
