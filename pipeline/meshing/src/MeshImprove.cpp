#include "MeshImprove.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace hs::meshing::detail {
namespace {

constexpr double kRadToDeg = 57.295779513082320876798;
/// An operation must raise the worst angle of the tets it changes by at least this (degrees): no cycling.
constexpr double kMinGainDeg = 1e-3;
/// Worklist items between two cancellation checks.
constexpr std::size_t kCancelEvery = 32;
/// Smoothing: tets within this of the star's worst angle (degrees) are active in the ascent direction.
constexpr double kActiveBandDeg = 0.5;
/// Smoothing: first trial step and finite-difference step, per mean edge length of the star.
constexpr double kFirstStepPerEdge = 0.25;
constexpr double kGradientStepPerEdge = 1e-4;
constexpr int kLineSearchHalvings = 10;

using TetId = std::uint32_t;
constexpr TetId kNoTet = std::numeric_limits<TetId>::max();

/// Faces of a positive tet, oriented so that (face, opposite vertex) is an even permutation of the tet.
constexpr int kFace[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

/// Tets around an edge (a, b): tet i is (a, b, vertices[i], vertices[i + 1]) positively oriented (indices modulo
/// the ring size when closed). An open ring starts and ends at boundary faces.
struct EdgeRing {
    std::vector<std::int32_t> vertices;
    std::vector<TetId> tets;
    bool closed = false;
    std::int32_t region = 0;
};

bool evenPermutation(const std::array<int, 4>& p) {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            inversions += p[static_cast<std::size_t>(i)] > p[static_cast<std::size_t>(j)];
    return inversions % 2 == 0;
}

/// The element of the convex hull of `g` closest to the origin (Gilbert's algorithm): the steepest direction that
/// raises every active angle (Klingner & Shewchuk's nonsmooth ascent).
Vec3 minNormInHull(const std::vector<Vec3>& g) {
    Vec3 w = g.front();
    for (int it = 0; it < 64; ++it) {
        std::size_t best = 0;
        double bestDot = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < g.size(); ++i)
            if (dot(g[i], w) < bestDot) {
                bestDot = dot(g[i], w);
                best = i;
            }
        const double ww = dot(w, w);
        if (bestDot >= ww * (1.0 - 1e-9))
            break;
        const Vec3 diff = g[best] - w;
        const double len2 = norm2(diff);
        if (len2 <= 0.0)
            break;
        const double lambda = std::clamp(-dot(w, diff) / len2, 0.0, 1.0);
        w += diff * lambda;
    }
    return w;
}

class Improver {
public:
    Improver(std::vector<Vec3>& points, const std::vector<Tet>& tets, const std::vector<std::int32_t>& regions,
             const std::vector<VertexFreedom>& freedom, const MeshImproveParams& params,
             const MeshImproveCallbacks& callbacks)
        : m_points(points), m_freedom(freedom), m_params(params), m_cb(callbacks), m_vertexTets(points.size()),
          m_boundary(points.size(), -1) {
        m_tets.reserve(tets.size() + tets.size() / 16);
        for (std::size_t t = 0; t < tets.size(); ++t)
            addTet(tets[t], regions[t]);
    }

    Result<MeshImproveStats> run(Progress& progress) {
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

    void output(std::vector<Tet>& tets, std::vector<std::int32_t>& regions) const {
        tets.clear();
        regions.clear();
        for (std::size_t t = 0; t < m_tets.size(); ++t)
            if (m_alive[t]) {
                tets.push_back(m_tets[t]);
                regions.push_back(m_region[t]);
            }
    }

private:
    // ---- mesh bookkeeping ----

    double quality(const Tet& t) const { return minDihedralDeg(point(t[0]), point(t[1]), point(t[2]), point(t[3])); }
    const Vec3& point(std::int32_t v) const { return m_points[static_cast<std::size_t>(v)]; }

    TetId addTet(const Tet& t, std::int32_t region) {
        const auto id = static_cast<TetId>(m_tets.size());
        m_tets.push_back(t);
        m_region.push_back(region);
        m_alive.push_back(1);
        m_quality.push_back(quality(t));
        for (auto v : t)
            m_vertexTets[static_cast<std::size_t>(v)].push_back(id);
        return id;
    }

    void killTet(TetId id) {
        m_alive[id] = 0;
        for (auto v : m_tets[id]) {
            auto& list = m_vertexTets[static_cast<std::size_t>(v)];
            list.erase(std::find(list.begin(), list.end(), id));
        }
    }

    static bool contains(const Tet& t, std::int32_t v) { return std::find(t.begin(), t.end(), v) != t.end(); }

    bool edgeExists(std::int32_t a, std::int32_t b) const {
        for (TetId t : m_vertexTets[static_cast<std::size_t>(a)])
            if (contains(m_tets[t], b))
                return true;
        return false;
    }

    /// The tet across face k of tet t (kNoTet at the boundary).
    TetId neighbourAcross(TetId t, int k) const {
        const Tet& tet = m_tets[t];
        const std::int32_t a = tet[static_cast<std::size_t>(kFace[k][0])];
        const std::int32_t b = tet[static_cast<std::size_t>(kFace[k][1])];
        const std::int32_t c = tet[static_cast<std::size_t>(kFace[k][2])];
        for (TetId u : m_vertexTets[static_cast<std::size_t>(a)])
            if (u != t && contains(m_tets[u], b) && contains(m_tets[u], c))
                return u;
        return kNoTet;
    }

    /// Whether v lies on a face without a neighbour of the same region (outer boundary or interface): the faces of
    /// its star through v, as the pairs of their other two vertices, must each come twice, from the same region.
    bool onBoundary(std::int32_t v) {
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

    VertexFreedom freedomOf(std::int32_t v) {
        const VertexFreedom f = m_freedom[static_cast<std::size_t>(v)];
        return f == VertexFreedom::Free && onBoundary(v) ? VertexFreedom::Fixed : f;
    }

    double worstQuality() const {
        double worst = 180.0;
        for (std::size_t t = 0; t < m_tets.size(); ++t)
            if (m_alive[t])
                worst = std::min(worst, m_quality[t]);
        return worst;
    }

    /// Bad tets by quality (worst first), then by their sorted vertices: a deterministic order.
    std::vector<std::pair<double, Tet>> worklist() const {
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

    TetId findTet(const Tet& sortedKey) const {
        for (TetId t : m_vertexTets[static_cast<std::size_t>(sortedKey[0])]) {
            Tet key = m_tets[t];
            std::sort(key.begin(), key.end());
            if (key == sortedKey)
                return t;
        }
        return kNoTet;
    }

    // ---- operations ----

    /// Tries, in this order, until one succeeds: removal of each edge, 2-3 flip of each face, smoothing of the
    /// vertices (several may move), contraction of an inner vertex. Flips first: they are cheap and local, and
    /// Delaunay slivers are mostly fixed by a 3-2 or 4-4 flip.
    bool improveTet(TetId t) {
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

    /// The ring of tets around edge (a, b); false when it is not a simple ring of one region or too long.
    bool edgeRing(std::int32_t a, std::int32_t b, EdgeRing& ring) const {
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

    /// Outward normal of face (a, b, c) of a tet whose fourth vertex is `inner`.
    Vec3 outwardNormal(std::int32_t a, std::int32_t b, std::int32_t c, std::int32_t inner) const {
        Vec3 n = normalized(cross(point(b) - point(a), point(c) - point(a)));
        if (dot(n, point(inner) - point(a)) > 0.0)
            n = -n;
        return n;
    }

    /// Removes edge (a, b): the polygon of its ring is re-triangulated for the best worst tet by dynamic programming
    /// (Klincsek; Shewchuk's edge removal), tets (a, triangle) and (b, reversed triangle). At the boundary the ring
    /// is open and the removal flips the two boundary faces at (a, b) when they are nearly coplanar (with one tet
    /// in the ring: the tet is peeled).
    bool removeEdge(std::int32_t a, std::int32_t b) {
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

    /// The triangulation of polygon r (closed by the chord from its last to its first vertex) whose tets
    /// (a, triangle) and (b, reversed triangle) have the best worst angle, by dynamic programming over sub-polygons
    /// r_i..r_j (Klincsek 1980). Returns that angle (180 for a polygon of two vertices: no tets).
    double bestTriangulation(std::int32_t a, std::int32_t b, const std::vector<std::int32_t>& r,
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

    /// An open ring may be re-triangulated when its two end faces are true boundary faces (no tet of another
    /// region behind them: interfaces stay as they are) and nearly coplanar, so the surface barely moves.
    bool boundaryRemovalAllowed(std::int32_t a, std::int32_t b, const EdgeRing& ring) {
        const auto& r = ring.vertices;
        const std::size_t n = ring.tets.size();
        const TetId first = ring.tets.front(), last = ring.tets.back();
        // The face (a, b, r0) of the first tet is opposite r1; (a, b, r_n) of the last is opposite r_{n-1}.
        for (const auto& [t, opposite] : {std::pair{first, r[1]}, std::pair{last, r[n - 1]}}) {
            const auto k =
                static_cast<int>(std::find(m_tets[t].begin(), m_tets[t].end(), opposite) - m_tets[t].begin());
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

    /// 2-3 flip of face k of tet t with the tet behind it (same region): the three tets around the new edge.
    bool flip23(TetId t, int k) {
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

    double qualityWith(TetId t, std::int32_t v, const Vec3& x) const {
        const Tet& tet = m_tets[t];
        std::array<Vec3, 4> p;
        for (std::size_t i = 0; i < 4; ++i)
            p[i] = tet[i] == v ? x : point(tet[i]);
        return minDihedralDeg(p[0], p[1], p[2], p[3]);
    }

    double starWorst(const std::vector<TetId>& star, std::int32_t v, const Vec3& x) const {
        double worst = 180.0;
        for (TetId t : star)
            worst = std::min(worst, qualityWith(t, v, x));
        return worst;
    }

    Vec3 constrained(std::int32_t v, VertexFreedom f, const Vec3& x) const {
        return f == VertexFreedom::Free ? x : m_cb.project(static_cast<std::uint32_t>(v), x);
    }

    /// Moves v to raise the worst smallest dihedral angle of its star: nonsmooth steepest ascent over the active
    /// tets (Freitag & Ollivier-Gooch; Klingner & Shewchuk), finite-difference gradients, halving line search.
    /// Surface and feature vertices move in their tangent space and are projected back.
    bool smoothVertex(std::int32_t v) {
        const VertexFreedom f = freedomOf(v);
        if (f == VertexFreedom::Fixed || (f != VertexFreedom::Free && !m_cb.project))
            return false;
        const std::vector<TetId> star = m_vertexTets[static_cast<std::size_t>(v)];
        if (star.empty())
            return false;
        const Vec3 origin = point(v);
        double edgeSum = 0.0;
        int edges = 0;
        for (TetId t : star)
            for (auto w : m_tets[t])
                if (w != v) {
                    edgeSum += distance(point(w), origin);
                    ++edges;
                }
        const double edge = edgeSum / edges;
        const Vec3 axis = f == VertexFreedom::Free ? Vec3{} : m_cb.constraintAxis(static_cast<std::uint32_t>(v));
        const double before = starWorst(star, v, origin);
        Vec3 x = origin;
        double current = before;
        for (int step = 0; step < m_params.smoothingSteps; ++step) {
            const Vec3 d = ascentDirection(star, v, x, kGradientStepPerEdge * edge, f, axis);
            const double dn = norm(d);
            if (!(dn > 1e-9))
                break;
            bool accepted = false;
            double alpha = kFirstStepPerEdge * edge / dn;
            for (int halving = 0; halving < kLineSearchHalvings && !accepted; ++halving, alpha *= 0.5) {
                const Vec3 y = constrained(v, f, x + d * alpha);
                const double w = starWorst(star, v, y);
                if (w > current + 1e-6) {
                    x = y;
                    current = w;
                    accepted = true;
                }
            }
            if (!accepted)
                break;
        }
        if (!(current > before + kMinGainDeg))
            return false;
        m_points[static_cast<std::size_t>(v)] = x;
        for (TetId t : star)
            m_quality[t] = quality(m_tets[t]);
        if (m_cb.moved)
            m_cb.moved(static_cast<std::uint32_t>(v), x);
        ++m_stats.smoothedVertices;
        return true;
    }

    /// The steepest direction raising every tet of the star within kActiveBandDeg of its worst (the point of the
    /// convex hull of their gradients closest to the origin), in the vertex's tangent space (a plane for Surface
    /// vertices with normal `axis`, the line `axis` for Feature vertices). Central differences of step h (mm).
    Vec3 ascentDirection(const std::vector<TetId>& star, std::int32_t v, const Vec3& x, double h, VertexFreedom f,
                         const Vec3& axis) const {
        std::vector<double> values(star.size());
        double worst = 180.0;
        for (std::size_t i = 0; i < star.size(); ++i) {
            values[i] = qualityWith(star[i], v, x);
            worst = std::min(worst, values[i]);
        }
        std::vector<Vec3> gradients;
        for (std::size_t i = 0; i < star.size(); ++i) {
            if (values[i] > worst + kActiveBandDeg)
                continue;
            Vec3 g;
            for (int q = 0; q < 3; ++q) {
                Vec3 dx;
                dx[q] = h;
                g[q] = (qualityWith(star[i], v, x + dx) - qualityWith(star[i], v, x - dx)) / (2.0 * h);
            }
            if (f == VertexFreedom::Surface)
                g -= axis * dot(g, axis);
            else if (f == VertexFreedom::Feature)
                g = axis * dot(g, axis);
            gradients.push_back(g);
        }
        return minNormInHull(gradients);
    }

    // ---- mean quality ----

    double radiusRatioWith(TetId t, std::int32_t v, const Vec3& x) const {
        const Tet& tet = m_tets[t];
        std::array<Vec3, 4> p;
        for (std::size_t i = 0; i < 4; ++i)
            p[i] = tet[i] == v ? x : point(tet[i]);
        return radiusRatio(p[0], p[1], p[2], p[3]);
    }

    /// One sweep in vertex order over the vertices that may move (inner ones freely, surface and feature ones along
    /// their constraint) and whose star has a tet of radius ratio below params.radiusRatioBelow: each is moved
    /// towards its optimal-Delaunay point (the volume-weighted mean of its star's circumcentres, Chen & Xu 2004;
    /// Alliez et al. 2005), all or half the way, or to the centroid of its neighbours, whichever raises the sum of
    /// the star's radius ratios most while keeping its smallest dihedral angle at least min(before, target). The
    /// worst-angle passes above fix the slivers; this raises the many fair tets of the boundary layer, which dominate
    /// the mean on thin bodies. Returns the number of moved vertices.
    std::size_t smoothRadiusRatioSweep() {
        std::size_t moved = 0;
        for (std::size_t vi = 0; vi < m_points.size(); ++vi) {
            const auto v = static_cast<std::int32_t>(vi);
            const std::vector<TetId>& star = m_vertexTets[vi];
            if (star.empty())
                continue;
            const VertexFreedom f = freedomOf(v);
            if (f == VertexFreedom::Fixed || (f != VertexFreedom::Free && !m_params.radiusRatioOnSurfaces) ||
                (f != VertexFreedom::Free && !m_cb.project))
                continue;
            const Vec3 origin = point(v);
            double before = 0.0, worstRatio = 1.0, worstAngle = 180.0, volumes = 0.0, corners = 0.0;
            Vec3 odt, centroid;
            for (TetId t : star) {
                const Tet& tet = m_tets[t];
                const Vec3 &a = point(tet[0]), &b = point(tet[1]), &c = point(tet[2]), &d = point(tet[3]);
                const double r = radiusRatio(a, b, c, d);
                before += r;
                worstRatio = std::min(worstRatio, r);
                worstAngle = std::min(worstAngle, m_quality[t]);
                const double vol = dot(b - a, cross(c - a, d - a));
                odt += circumcentre(a, b, c, d) * vol;
                volumes += vol;
                for (auto w : tet)
                    if (w != v) {
                        centroid += point(w);
                        corners += 1.0;
                    }
            }
            if (worstRatio >= m_params.radiusRatioBelow || !(volumes > 0.0))
                continue;
            const Vec3 axis = f == VertexFreedom::Free ? Vec3{} : m_cb.constraintAxis(static_cast<std::uint32_t>(v));
            // Candidates in the tangent space; only the chosen one is projected onto the constraint (the walk is
            // the expensive part) and checked again there.
            auto along = [&](const Vec3& target, double fraction) {
                Vec3 d = (target - origin) * fraction;
                if (f == VertexFreedom::Surface)
                    d -= axis * dot(d, axis);
                else if (f == VertexFreedom::Feature)
                    d = axis * dot(d, axis);
                return origin + d;
            };
            auto starSum = [&](const Vec3& x) {
                double sum = 0.0;
                for (TetId t : star) {
                    const double r = radiusRatioWith(t, v, x);
                    if (!(r > 0.0))
                        return -1.0;
                    sum += r;
                }
                return sum;
            };
            const Vec3 odtPoint = odt / volumes, centre = centroid / corners;
            std::array<std::pair<double, Vec3>, 3> candidates{
                {{0.0, along(odtPoint, 1.0)}, {0.0, along(odtPoint, 0.5)}, {0.0, along(centre, 1.0)}}};
            for (auto& [sum, x] : candidates)
                sum = starSum(x);
            std::sort(candidates.begin(), candidates.end(),
                      [](const auto& a, const auto& b) { return a.first > b.first; });
            const double floorAngle = std::min(worstAngle, m_params.targetDihedralDeg);
            const double least = before + 1e-9 * double(star.size());
            Vec3 chosenPoint;
            const Vec3* chosen = nullptr;
            for (const auto& [sum, x] : candidates) {
                if (!(sum > least))
                    break;
                chosenPoint = constrained(v, f, x);
                if ((f == VertexFreedom::Free || starSum(chosenPoint) > least) &&
                    starWorst(star, v, chosenPoint) >= floorAngle) {
                    chosen = &chosenPoint;
                    break;
                }
            }
            if (!chosen)
                continue;
            m_points[vi] = *chosen;
            for (TetId t : star)
                m_quality[t] = quality(m_tets[t]);
            if (m_cb.moved)
                m_cb.moved(static_cast<std::uint32_t>(v), *chosen);
            ++moved;
        }
        m_stats.radiusRatioMoves += moved;
        return moved;
    }

    /// Removes inner vertex v by contracting it onto the neighbour w whose cone over v's link (the tets of v not
    /// containing w, with v replaced by w) has the best worst tet. The link, the boundary of the cavity, does not
    /// change, so when every new tet is positive they fill the cavity exactly.
    bool contractVertex(std::int32_t v) {
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

    std::vector<Vec3>& m_points;
    const std::vector<VertexFreedom>& m_freedom;
    const MeshImproveParams& m_params;
    const MeshImproveCallbacks& m_cb;
    std::vector<Tet> m_tets;
    std::vector<std::int32_t> m_region;
    std::vector<std::uint8_t> m_alive;
    std::vector<double> m_quality;
    std::vector<std::vector<TetId>> m_vertexTets;
    std::vector<std::int8_t> m_boundary; ///< per vertex: -1 unknown, 0 inside, 1 on a boundary or interface face
    std::vector<std::array<std::int32_t, 3>> m_faceScratch; ///< onBoundary: faces through the vertex
    MeshImproveStats m_stats;
};

} // namespace

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
