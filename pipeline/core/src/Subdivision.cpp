#include "hs/core/Subdivision.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace hs {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Edge {
    std::int32_t a = 0, b = 0;
    std::int32_t opposite[2] = {-1, -1};
    int faces = 0;
};

/// Loop's weight of each neighbour of an interior point of valence n.
double loopBeta(std::size_t n) {
    const double c = 3.0 / 8.0 + 0.25 * std::cos(2.0 * kPi / static_cast<double>(n));
    return (5.0 / 8.0 - c * c) / static_cast<double>(n);
}

double angleBetween(const Vec3& u, const Vec3& v) {
    const double nu = norm(u), nv = norm(v);
    if (nu <= 0.0 || nv <= 0.0)
        return 0.0;
    return std::acos(std::clamp(dot(u, v) / (nu * nv), -1.0, 1.0)) * 180.0 / kPi;
}

} // namespace

SurfaceMesh loopSubdivide(const SurfaceMesh& mesh) {
    const std::size_t n = mesh.points.size();
    std::vector<Edge> edges;
    edges.reserve(mesh.triangles.size() * 3 / 2 + 1);
    std::unordered_map<std::uint64_t, std::int32_t> index;
    index.reserve(edges.capacity() * 2);
    std::vector<std::array<std::int32_t, 3>> faceEdges(mesh.triangles.size());
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const Triangle& t = mesh.triangles[f];
        for (int k = 0; k < 3; ++k) {
            const std::int32_t a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
            const std::int32_t c = t[static_cast<std::size_t>((k + 2) % 3)];
            const auto [it, inserted] = index.try_emplace(edgeKey(a, b), static_cast<std::int32_t>(edges.size()));
            if (inserted)
                edges.push_back({a, b, {-1, -1}, 0});
            Edge& e = edges[static_cast<std::size_t>(it->second)];
            if (e.faces < 2)
                e.opposite[e.faces] = c;
            ++e.faces;
            faceEdges[f][static_cast<std::size_t>(k)] = it->second;
        }
    }

    // Neighbours of each old point, and its crease neighbours, in edge order (deterministic sums).
    std::vector<std::vector<std::int32_t>> ring(n), crease(n);
    for (const Edge& e : edges) {
        ring[static_cast<std::size_t>(e.a)].push_back(e.b);
        ring[static_cast<std::size_t>(e.b)].push_back(e.a);
        if (e.faces != 2) {
            crease[static_cast<std::size_t>(e.a)].push_back(e.b);
            crease[static_cast<std::size_t>(e.b)].push_back(e.a);
        }
    }

    SurfaceMesh out;
    out.points.resize(n + edges.size());
    const auto& p = mesh.points;
    for (std::size_t v = 0; v < n; ++v) {
        const auto& nb = ring[v];
        if (nb.empty()) {
            out.points[v] = p[v];
        } else if (!crease[v].empty()) {
            const auto& cr = crease[v];
            out.points[v] =
                cr.size() == 2
                    ? p[v] * 0.75 + (p[static_cast<std::size_t>(cr[0])] + p[static_cast<std::size_t>(cr[1])]) * 0.125
                    : p[v];
        } else {
            const double beta = loopBeta(nb.size());
            Vec3 sum{};
            for (std::int32_t q : nb)
                sum += p[static_cast<std::size_t>(q)];
            out.points[v] = p[v] * (1.0 - beta * static_cast<double>(nb.size())) + sum * beta;
        }
    }
    for (std::size_t e = 0; e < edges.size(); ++e) {
        const Edge& E = edges[e];
        const Vec3& a = p[static_cast<std::size_t>(E.a)];
        const Vec3& b = p[static_cast<std::size_t>(E.b)];
        out.points[n + e] =
            E.faces == 2
                ? (a + b) * 0.375 +
                      (p[static_cast<std::size_t>(E.opposite[0])] + p[static_cast<std::size_t>(E.opposite[1])]) * 0.125
                : (a + b) * 0.5;
    }

    out.triangles.reserve(mesh.triangles.size() * 4);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const Triangle& t = mesh.triangles[f];
        const auto m = [&](int k) { return static_cast<std::int32_t>(n) + faceEdges[f][static_cast<std::size_t>(k)]; };
        const std::int32_t mab = m(0), mbc = m(1), mca = m(2);
        out.triangles.push_back({t[0], mab, mca});
        out.triangles.push_back({mab, t[1], mbc});
        out.triangles.push_back({mca, mbc, t[2]});
        out.triangles.push_back({mab, mbc, mca});
    }
    for (const auto& [name, values] : mesh.faceLabels) {
        auto& dst = out.faceLabels[name];
        dst.reserve(values.size() * 4);
        for (std::int32_t v : values)
            dst.insert(dst.end(), 4, v);
    }
    return out;
}

SurfaceMesh loopSubdivide(const SurfaceMesh& mesh, int levels) {
    SurfaceMesh out = mesh;
    out.vertexLabels.clear();
    for (int i = 0; i < levels; ++i)
        out = loopSubdivide(out);
    return out;
}

SurfaceMesh taubinSmooth(const SurfaceMesh& mesh, const std::vector<std::int32_t>& faceMask,
                         const TaubinParams& params) {
    const std::size_t n = mesh.points.size();
    std::vector<std::vector<std::int32_t>> ring(n);
    std::vector<char> moves(n, 0);
    std::unordered_map<std::uint64_t, char> seen;
    seen.reserve(mesh.triangles.size() * 2);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const Triangle& t = mesh.triangles[f];
        for (std::size_t k = 0; k < 3; ++k) {
            const std::int32_t a = t[k], b = t[(k + 1) % 3];
            if (faceMask.empty() || faceMask[f] != 0)
                moves[static_cast<std::size_t>(a)] = 1;
            if (!seen.emplace(edgeKey(a, b), 1).second)
                continue;
            ring[static_cast<std::size_t>(a)].push_back(b);
            ring[static_cast<std::size_t>(b)].push_back(a);
        }
    }
    std::vector<std::vector<std::int32_t>> facesOf(n);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
        for (std::int32_t v : mesh.triangles[f])
            facesOf[static_cast<std::size_t>(v)].push_back(static_cast<std::int32_t>(f));
    SurfaceMesh out = mesh;
    std::vector<Vec3> next(n);
    // Smallest angle (degrees) and normal of face f with point v at q.
    const auto shapeWith = [&](std::size_t f, std::int32_t v, const Vec3& q, Vec3& normal) {
        const Triangle& t = out.triangles[f];
        Vec3 c[3];
        for (std::size_t k = 0; k < 3; ++k)
            c[k] = t[k] == v ? q : out.points[static_cast<std::size_t>(t[k])];
        normal = cross(c[1] - c[0], c[2] - c[0]);
        double smallest = 180.0;
        for (std::size_t k = 0; k < 3; ++k)
            smallest = std::min(smallest, angleBetween(c[(k + 1) % 3] - c[k], c[(k + 2) % 3] - c[k]));
        return smallest;
    };
    // A move is kept only if no face around the point turns over or gets a smaller angle than params.minAngleDeg
    // (or than it had, if that was smaller already).
    const auto acceptable = [&](std::size_t v, const Vec3& q) {
        for (std::int32_t f : facesOf[v]) {
            Vec3 before, after;
            const double a0 =
                shapeWith(static_cast<std::size_t>(f), static_cast<std::int32_t>(v), out.points[v], before);
            const double a1 = shapeWith(static_cast<std::size_t>(f), static_cast<std::int32_t>(v), q, after);
            if (dot(before, after) <= 0.0 || a1 < std::min(a0, params.minAngleDeg))
                return false;
        }
        return true;
    };
    const auto step = [&](double factor) {
        for (std::size_t v = 0; v < n; ++v) {
            next[v] = out.points[v];
            if (!moves[v] || ring[v].empty())
                continue;
            Vec3 mean{};
            for (std::int32_t q : ring[v])
                mean += out.points[static_cast<std::size_t>(q)];
            mean = mean / static_cast<double>(ring[v].size());
            Vec3 p = out.points[v] + (mean - out.points[v]) * factor;
            const Vec3 shift = p - mesh.points[v];
            const double len = norm(shift);
            if (len > params.maxDisplacement)
                p = mesh.points[v] + shift * (params.maxDisplacement / len);
            if (acceptable(v, p))
                next[v] = p;
        }
        out.points.swap(next);
    };
    for (int i = 0; i < params.iterations; ++i) {
        step(params.lambda);
        step(params.mu);
    }
    return out;
}

std::vector<std::array<CornerUv, 3>> subdivideCorners(const std::vector<std::array<CornerUv, 3>>& corners) {
    std::vector<std::array<CornerUv, 3>> out;
    out.reserve(corners.size() * 4);
    const auto mid = [](const CornerUv& x, const CornerUv& y) {
        return CornerUv{(x[0] + y[0]) * 0.5, (x[1] + y[1]) * 0.5};
    };
    for (const auto& c : corners) {
        const CornerUv ab = mid(c[0], c[1]), bc = mid(c[1], c[2]), ca = mid(c[2], c[0]);
        out.push_back({c[0], ab, ca});
        out.push_back({ab, c[1], bc});
        out.push_back({ca, bc, c[2]});
        out.push_back({ab, bc, ca});
    }
    return out;
}

SurfaceShape measureSurfaceShape(const SurfaceMesh& mesh, const std::vector<std::int32_t>& mask) {
    SurfaceShape s;
    const auto counted = [&](std::size_t f) { return mask.empty() || mask[f] != 0; };
    s.minAngleDeg = 180.0;
    double edgeSum = 0.0;
    std::size_t edgeCount = 0;
    // Points at the same place are one point (a surface split along UV seams has its seam edges counted).
    std::vector<std::int32_t> canonical(mesh.points.size());
    {
        std::map<std::array<double, 3>, std::int32_t> at;
        for (std::size_t i = 0; i < mesh.points.size(); ++i) {
            const Vec3& p = mesh.points[i];
            canonical[i] = at.try_emplace({p.x, p.y, p.z}, static_cast<std::int32_t>(i)).first->second;
        }
    }
    std::unordered_map<std::uint64_t, std::int32_t> firstFace;
    firstFace.reserve(mesh.triangles.size() * 2);
    std::vector<double> deviations;
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        if (!counted(f))
            continue;
        ++s.faces;
        const Triangle& t = mesh.triangles[f];
        for (int k = 0; k < 3; ++k) {
            const Vec3& a = mesh.points[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
            const Vec3& b = mesh.points[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)])];
            const Vec3& c = mesh.points[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 2) % 3)])];
            s.minAngleDeg = std::min(s.minAngleDeg, angleBetween(b - a, c - a));
            const double len = distance(a, b);
            edgeSum += len;
            ++edgeCount;
            s.maxEdgeMm = std::max(s.maxEdgeMm, len);
            const auto key = edgeKey(canonical[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])],
                                     canonical[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)])]);
            const auto [it, inserted] = firstFace.try_emplace(key, static_cast<std::int32_t>(f));
            if (inserted)
                continue;
            const auto g = static_cast<std::size_t>(it->second);
            const double turn = angleBetween(faceNormal(mesh, f), faceNormal(mesh, g));
            deviations.push_back(turn);
            // Convex on the normals' side when this face's far corner lies behind the other face's plane.
            const Vec3& far = c;
            const Vec3& on = mesh.points[static_cast<std::size_t>(mesh.triangles[g][0])];
            const double side = dot(far - on, cross(mesh.points[static_cast<std::size_t>(mesh.triangles[g][1])] - on,
                                                    mesh.points[static_cast<std::size_t>(mesh.triangles[g][2])] - on));
            if (side < 0.0)
                s.maxRidgeDeg = std::max(s.maxRidgeDeg, turn);
            else
                s.maxValleyDeg = std::max(s.maxValleyDeg, turn);
        }
    }
    if (s.faces == 0)
        return SurfaceShape{};
    s.meanEdgeMm = edgeSum / static_cast<double>(edgeCount);
    if (!deviations.empty()) {
        std::sort(deviations.begin(), deviations.end());
        s.maxNormalDeviationDeg = deviations.back();
        s.p99NormalDeviationDeg =
            deviations[static_cast<std::size_t>(0.99 * static_cast<double>(deviations.size() - 1))];
        const auto sharp = deviations.end() - std::upper_bound(deviations.begin(), deviations.end(), 30.0);
        s.sharpEdgeFraction = static_cast<double>(sharp) / static_cast<double>(deviations.size());
    }
    return s;
}

} // namespace hs
