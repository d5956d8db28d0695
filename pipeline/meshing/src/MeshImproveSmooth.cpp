// The mesh improver's vertex smoothing: nonsmooth ascent of a star's worst dihedral angle, and the radius-ratio
// sweeps towards the optimal-Delaunay point.
#include "MeshImproveSteps.h"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>

namespace hs::meshing::detail {
namespace {

/// Smoothing: tets within this of the star's worst angle (degrees) are active in the ascent direction.
constexpr double kActiveBandDeg = 0.5;
/// Smoothing: first trial step and finite-difference step, per mean edge length of the star.
constexpr double kFirstStepPerEdge = 0.25;
constexpr double kGradientStepPerEdge = 1e-4;
constexpr int kLineSearchHalvings = 10;

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

} // namespace

std::array<Vec3, 4> Improver::pointsWith(TetId t, std::int32_t v, const Vec3& x) const {
    const Tet& tet = m_tets[t];
    std::array<Vec3, 4> p;
    for (std::size_t i = 0; i < 4; ++i)
        p[i] = tet[i] == v ? x : point(tet[i]);
    return p;
}

double Improver::qualityWith(TetId t, std::int32_t v, const Vec3& x) const {
    const auto p = pointsWith(t, v, x);
    return minDihedralDeg(p[0], p[1], p[2], p[3]);
}

double Improver::starWorst(const std::vector<TetId>& star, std::int32_t v, const Vec3& x) const {
    double worst = 180.0;
    for (TetId t : star)
        worst = std::min(worst, qualityWith(t, v, x));
    return worst;
}

Vec3 Improver::constrained(std::int32_t v, VertexFreedom f, const Vec3& x) const {
    return f == VertexFreedom::Free ? x : m_cb.project(static_cast<std::uint32_t>(v), x);
}

bool Improver::smoothVertex(std::int32_t v) {
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

Vec3 Improver::ascentDirection(const std::vector<TetId>& star, std::int32_t v, const Vec3& x, double h, VertexFreedom f,
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

double Improver::radiusRatioWith(TetId t, std::int32_t v, const Vec3& x) const {
    const auto p = pointsWith(t, v, x);
    return radiusRatio(p[0], p[1], p[2], p[3]);
}

std::size_t Improver::smoothRadiusRatioSweep() {
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
        std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
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

} // namespace hs::meshing::detail
