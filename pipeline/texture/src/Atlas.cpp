#include "hs/texture/Atlas.h"

#include "MeshAdjacency.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

namespace hs::texture {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Uv {
    double u = 0.0, v = 0.0;
};

} // namespace

namespace detail {

std::vector<std::array<std::int32_t, 3>> faceNeighbours(const SurfaceMesh& mesh) {
    struct EdgeRef {
        std::int64_t key;
        std::int32_t face;
        std::int32_t side;
    };
    std::vector<EdgeRef> edges;
    edges.reserve(mesh.triangles.size() * 3);
    const auto n = static_cast<std::int64_t>(mesh.points.size());
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const std::int64_t a = mesh.triangles[f][static_cast<std::size_t>(k)];
            const std::int64_t b = mesh.triangles[f][static_cast<std::size_t>((k + 1) % 3)];
            edges.push_back({std::min(a, b) * n + std::max(a, b), static_cast<std::int32_t>(f), k});
        }
    std::sort(edges.begin(), edges.end(),
              [](const EdgeRef& x, const EdgeRef& y) { return x.key != y.key ? x.key < y.key : x.face < y.face; });
    std::vector<std::array<std::int32_t, 3>> adj(mesh.triangles.size(), {-1, -1, -1});
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j].key == edges[i].key)
            ++j;
        if (j - i == 2) {
            adj[static_cast<std::size_t>(edges[i].face)][static_cast<std::size_t>(edges[i].side)] = edges[i + 1].face;
            adj[static_cast<std::size_t>(edges[i + 1].face)][static_cast<std::size_t>(edges[i + 1].side)] =
                edges[i].face;
        }
        i = j;
    }
    return adj;
}

} // namespace detail

namespace {

using detail::faceNeighbours;

/// The 26 directions of the cube's faces, edges and corners.
std::vector<Vec3> chartDirections() {
    std::vector<Vec3> dirs;
    for (int z = -1; z <= 1; ++z)
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x)
                if (x != 0 || y != 0 || z != 0)
                    dirs.push_back(normalized(Vec3(x, y, z)));
    return dirs;
}

/// Connected components of faces with equal labels.
std::vector<std::int32_t> components(const std::vector<std::int32_t>& label,
                                     const std::vector<std::array<std::int32_t, 3>>& adj, int& count) {
    std::vector<std::int32_t> comp(label.size(), -1);
    std::vector<std::int32_t> stack;
    count = 0;
    for (std::size_t seed = 0; seed < label.size(); ++seed) {
        if (comp[seed] >= 0)
            continue;
        comp[seed] = count;
        stack.push_back(static_cast<std::int32_t>(seed));
        while (!stack.empty()) {
            const auto f = static_cast<std::size_t>(stack.back());
            stack.pop_back();
            for (std::int32_t g : adj[f])
                if (g >= 0 && comp[static_cast<std::size_t>(g)] < 0 && label[static_cast<std::size_t>(g)] == label[f]) {
                    comp[static_cast<std::size_t>(g)] = count;
                    stack.push_back(g);
                }
        }
        ++count;
    }
    return comp;
}

/// Direction labels: closest direction, smoothed by neighbour majority, small islands merged.
std::vector<std::int32_t> directionLabels(const std::vector<Vec3>& normals,
                                          const std::vector<std::array<std::int32_t, 3>>& adj,
                                          const AtlasParams& params) {
    const std::vector<Vec3> dirs = chartDirections();
    const double cosMax = std::cos(params.maxAngleDeg * kPi / 180.0);
    std::vector<std::int32_t> label(normals.size(), 0);
    for (std::size_t f = 0; f < normals.size(); ++f) {
        double best = -2.0;
        for (std::size_t d = 0; d < dirs.size(); ++d) {
            const double c = dot(normals[f], dirs[d]);
            if (c > best) {
                best = c;
                label[f] = static_cast<std::int32_t>(d);
            }
        }
    }
    for (int iter = 0; iter < 4; ++iter) {
        std::vector<std::int32_t> next = label;
        for (std::size_t f = 0; f < normals.size(); ++f) {
            const auto& a = adj[f];
            for (int k = 0; k < 3; ++k) {
                if (a[static_cast<std::size_t>(k)] < 0)
                    continue;
                const std::int32_t l = label[static_cast<std::size_t>(a[static_cast<std::size_t>(k)])];
                int votes = 0;
                for (std::int32_t g : a)
                    votes += (g >= 0 && label[static_cast<std::size_t>(g)] == l) ? 1 : 0;
                if (l != label[f] && votes >= 2 && dot(normals[f], dirs[static_cast<std::size_t>(l)]) >= cosMax) {
                    next[f] = l;
                    break;
                }
            }
        }
        label.swap(next);
    }
    // Merge islands smaller than minChartFaces into the neighbouring direction where every face allows it.
    int count = 0;
    const std::vector<std::int32_t> comp = components(label, adj, count);
    std::vector<std::vector<std::int32_t>> members(static_cast<std::size_t>(count));
    for (std::size_t f = 0; f < comp.size(); ++f)
        members[static_cast<std::size_t>(comp[f])].push_back(static_cast<std::int32_t>(f));
    const double cosLoose = std::cos(std::min(params.maxAngleDeg + 15.0, 85.0) * kPi / 180.0);
    for (const auto& m : members) {
        if (static_cast<int>(m.size()) >= params.minChartFaces)
            continue;
        std::vector<int> votes(dirs.size(), 0);
        for (std::int32_t f : m)
            for (std::int32_t g : adj[static_cast<std::size_t>(f)])
                if (g >= 0 && label[static_cast<std::size_t>(g)] != label[static_cast<std::size_t>(f)])
                    ++votes[static_cast<std::size_t>(label[static_cast<std::size_t>(g)])];
        const auto best = static_cast<std::size_t>(std::max_element(votes.begin(), votes.end()) - votes.begin());
        if (votes[best] == 0)
            continue;
        const bool ok = std::all_of(m.begin(), m.end(), [&](std::int32_t f) {
            return dot(normals[static_cast<std::size_t>(f)], dirs[best]) >= cosLoose;
        });
        if (ok)
            for (std::int32_t f : m)
                label[static_cast<std::size_t>(f)] = static_cast<std::int32_t>(best);
    }
    return label;
}

struct Chart {
    std::vector<std::int32_t> faces;
    std::vector<std::int32_t> vertices; ///< mesh vertices, first-use order
    std::vector<Uv> uv;                 ///< per vertex above, mm
    double minU = 0, minV = 0, maxU = 0, maxV = 0;
    int x = 0, y = 0; ///< packed texel position of the box
};

/// Projects `faces` onto the plane of their mean normal; faces whose projection is nearly degenerate or flipped
/// are returned in `rejected`.
Chart projectChart(const SurfaceMesh& mesh, const std::vector<Vec3>& normals, const std::vector<double>& areas,
                   const std::vector<std::int32_t>& faces, std::vector<std::int32_t>& rejected,
                   std::vector<std::int32_t>& slot) {
    Vec3 mean;
    for (std::int32_t f : faces)
        mean += normals[static_cast<std::size_t>(f)] * areas[static_cast<std::size_t>(f)];
    mean = normalized(mean);
    if (norm(mean) == 0.0)
        mean = Vec3(0, 0, 1);
    const Vec3 helper = std::fabs(mean.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 t = normalized(cross(helper, mean));
    const Vec3 b = cross(mean, t);
    Chart chart;
    for (std::int32_t f : faces) {
        const auto& tri = mesh.triangles[static_cast<std::size_t>(f)];
        const double projected = dot(normals[static_cast<std::size_t>(f)], mean);
        const bool degenerate = areas[static_cast<std::size_t>(f)] <= 0.0;
        if (!degenerate && projected < 0.2 && faces.size() > 1) {
            rejected.push_back(f);
            continue;
        }
        chart.faces.push_back(f);
        for (std::int32_t v : tri) {
            if (slot[static_cast<std::size_t>(v)] >= 0)
                continue;
            slot[static_cast<std::size_t>(v)] = static_cast<std::int32_t>(chart.vertices.size());
            chart.vertices.push_back(v);
            const Vec3& p = mesh.points[static_cast<std::size_t>(v)];
            chart.uv.push_back({dot(p, t), dot(p, b)});
        }
    }
    for (std::int32_t v : chart.vertices)
        slot[static_cast<std::size_t>(v)] = -1;
    return chart;
}

/// Rotates the chart onto its principal axes (a tighter box) and records its bounds.
void alignChart(Chart& chart) {
    double mu = 0, mv = 0;
    for (const Uv& q : chart.uv) {
        mu += q.u;
        mv += q.v;
    }
    mu /= static_cast<double>(chart.uv.size());
    mv /= static_cast<double>(chart.uv.size());
    double sxx = 0, syy = 0, sxy = 0;
    for (const Uv& q : chart.uv) {
        sxx += (q.u - mu) * (q.u - mu);
        syy += (q.v - mv) * (q.v - mv);
        sxy += (q.u - mu) * (q.v - mv);
    }
    const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
    const double c = std::cos(-angle), s = std::sin(-angle);
    chart.minU = chart.minV = 1e300;
    chart.maxU = chart.maxV = -1e300;
    for (Uv& q : chart.uv) {
        const double u = (q.u - mu) * c - (q.v - mv) * s, v = (q.u - mu) * s + (q.v - mv) * c;
        q = {u, v};
        chart.minU = std::min(chart.minU, u);
        chart.maxU = std::max(chart.maxU, u);
        chart.minV = std::min(chart.minV, v);
        chart.maxV = std::max(chart.maxV, v);
    }
}

int boxSide(double extentMm, double scale, int padding) {
    return static_cast<int>(std::ceil(extentMm * scale)) + 2 * padding + 1;
}

/// Shelf packing, tallest first, at `scale` texels per mm. False if it does not fit into size x size.
bool pack(std::vector<Chart>& charts, const std::vector<std::size_t>& order, double scale, int padding, int size) {
    int x = 0, y = 0, shelf = 0;
    for (std::size_t i : order) {
        Chart& c = charts[i];
        const int w = boxSide(c.maxU - c.minU, scale, padding), h = boxSide(c.maxV - c.minV, scale, padding);
        if (w > size)
            return false;
        if (x + w > size) {
            y += shelf;
            x = 0;
            shelf = 0;
        }
        if (y + h > size)
            return false;
        c.x = x;
        c.y = y;
        x += w;
        shelf = std::max(shelf, h);
    }
    return true;
}

AtlasStats stretchStats(const SurfaceMesh& mesh, const Atlas& atlas, double scale) {
    AtlasStats stats;
    double sum3 = 0.0, sum2 = 0.0, l2 = 0.0, maxS = 0.0;
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const auto& tri = mesh.triangles[f];
        const auto& uvt = atlas.uvTriangles[f];
        std::array<Vec3, 3> p;
        std::array<Uv, 3> q;
        for (std::size_t k = 0; k < 3; ++k) {
            p[k] = mesh.points[static_cast<std::size_t>(tri[k])];
            const UvVertex& w = atlas.uvVertices[static_cast<std::size_t>(uvt[k])];
            q[k] = {w.u * atlas.size / scale, w.v * atlas.size / scale}; // mm
        }
        const double a2 = 0.5 * ((q[1].u - q[0].u) * (q[2].v - q[0].v) - (q[2].u - q[0].u) * (q[1].v - q[0].v));
        const double a3 = 0.5 * norm(cross(p[1] - p[0], p[2] - p[0]));
        if (a2 <= 0.0 || a3 <= 0.0)
            continue;
        const Vec3 ss = (p[0] * (q[1].v - q[2].v) + p[1] * (q[2].v - q[0].v) + p[2] * (q[0].v - q[1].v)) / (2 * a2);
        const Vec3 st = (p[0] * (q[2].u - q[1].u) + p[1] * (q[0].u - q[2].u) + p[2] * (q[1].u - q[0].u)) / (2 * a2);
        const double a = dot(ss, ss), b = dot(ss, st), c = dot(st, st);
        const double big = std::sqrt(0.5 * ((a + c) + std::sqrt((a - c) * (a - c) + 4 * b * b)));
        l2 += a3 * 0.5 * (a + c);
        sum3 += a3;
        sum2 += a2;
        maxS = std::max(maxS, big);
    }
    if (sum3 > 0.0) {
        const double normaliser = std::sqrt(sum2 / sum3);
        stats.l2Stretch = std::sqrt(l2 / sum3) * normaliser;
        stats.maxStretch = maxS * normaliser;
    }
    return stats;
}

} // namespace

Result<Atlas> buildAtlas(const SurfaceMesh& surface, const AtlasParams& params, Progress& progress) {
    HS_TRY(validate(surface));
    if (surface.triangles.empty())
        return fail(ErrorCode::InvalidInput, "atlas: the surface has no triangles");
    if (params.size < 64 || params.size > 8192)
        return fail(ErrorCode::LimitExceeded, "atlas size " + std::to_string(params.size) + " outside 64..8192 texels");
    if (!(params.maxAngleDeg >= 10.0 && params.maxAngleDeg <= 80.0))
        return fail(ErrorCode::InvalidInput,
                    "atlas maxAngleDeg " + std::to_string(params.maxAngleDeg) + " outside 10..80 degrees");
    const int padding = params.padding > 0 ? params.padding : std::max(2, params.size / 256);
    const std::size_t faceCount = surface.triangles.size();
    std::vector<Vec3> normals(faceCount);
    std::vector<double> areas(faceCount);
    for (std::size_t f = 0; f < faceCount; ++f) {
        const auto& t = surface.triangles[f];
        const Vec3 c =
            cross(surface.points[static_cast<std::size_t>(t[1])] - surface.points[static_cast<std::size_t>(t[0])],
                  surface.points[static_cast<std::size_t>(t[2])] - surface.points[static_cast<std::size_t>(t[0])]);
        areas[f] = 0.5 * norm(c);
        normals[f] = normalized(c);
    }
    const auto adj = faceNeighbours(surface);
    const std::vector<std::int32_t> label = directionLabels(normals, adj, params);
    int count = 0;
    const std::vector<std::int32_t> comp = components(label, adj, count);
    HS_TRY(progress.check("atlas"));
    progress.report("texture.atlas", 0.3);

    // Project each component; split off what would fold, until everything is accepted.
    std::vector<std::vector<std::int32_t>> work(static_cast<std::size_t>(count));
    for (std::size_t f = 0; f < faceCount; ++f)
        work[static_cast<std::size_t>(comp[f])].push_back(static_cast<std::int32_t>(f));
    std::vector<Chart> charts;
    std::vector<std::int32_t> slot(surface.points.size(), -1);
    std::vector<std::int32_t> isRejected(faceCount, 0);
    for (std::size_t w = 0; w < work.size(); ++w) {
        std::vector<std::int32_t> rejected;
        Chart chart = projectChart(surface, normals, areas, work[w], rejected, slot);
        if (chart.faces.empty()) { // nothing projects well onto the mean plane (a fin): one chart per face
            for (std::int32_t f : rejected)
                work.push_back({f});
            continue;
        }
        if (!chart.faces.empty())
            charts.push_back(std::move(chart));
        if (rejected.empty())
            continue;
        // Components of the rejected faces become new work items.
        for (std::int32_t f : rejected)
            isRejected[static_cast<std::size_t>(f)] = 1;
        for (std::int32_t seed : rejected) {
            if (isRejected[static_cast<std::size_t>(seed)] != 1)
                continue;
            std::vector<std::int32_t> part{seed}, stack{seed};
            isRejected[static_cast<std::size_t>(seed)] = 2;
            while (!stack.empty()) {
                const std::int32_t f = stack.back();
                stack.pop_back();
                for (std::int32_t g : adj[static_cast<std::size_t>(f)])
                    if (g >= 0 && isRejected[static_cast<std::size_t>(g)] == 1) {
                        isRejected[static_cast<std::size_t>(g)] = 2;
                        part.push_back(g);
                        stack.push_back(g);
                    }
            }
            for (std::int32_t f : part)
                isRejected[static_cast<std::size_t>(f)] = 0;
            std::sort(part.begin(), part.end());
            work.push_back(std::move(part));
        }
    }
    for (Chart& c : charts)
        alignChart(c);
    progress.report("texture.atlas", 0.6);

    // The largest common scale at which the shelf packing fits.
    std::vector<std::size_t> order(charts.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return charts[a].maxV - charts[a].minV > charts[b].maxV - charts[b].minV;
    });
    double area2 = 0.0;
    for (const Chart& c : charts)
        area2 += (c.maxU - c.minU) * (c.maxV - c.minV);
    double lo = 0.0, hi = area2 > 0.0 ? std::sqrt(double(params.size) * params.size / area2) : 1.0;
    if (!pack(charts, order, 0.0, padding, params.size))
        return fail(ErrorCode::LimitExceeded, "atlas: " + std::to_string(charts.size()) + " charts do not fit into " +
                                                  std::to_string(params.size) + " x " + std::to_string(params.size) +
                                                  " texels with padding " + std::to_string(padding) +
                                                  "; use a larger size");
    for (int iter = 0; iter < 30; ++iter) {
        const double mid = 0.5 * (lo + hi);
        (pack(charts, order, mid, padding, params.size) ? lo : hi) = mid;
    }
    const double scale = lo;
    pack(charts, order, scale, padding, params.size);

    Atlas atlas;
    atlas.size = params.size;
    atlas.uvTriangles.resize(faceCount);
    atlas.chartOfFace.resize(faceCount, -1);
    const double n = params.size;
    double covered = 0.0;
    for (std::size_t ci = 0; ci < charts.size(); ++ci) {
        const Chart& c = charts[ci];
        const auto base = static_cast<std::int32_t>(atlas.uvVertices.size());
        for (std::size_t k = 0; k < c.vertices.size(); ++k) {
            const double x = c.x + padding + 0.5 + (c.uv[k].u - c.minU) * scale;
            const double y = c.y + padding + 0.5 + (c.uv[k].v - c.minV) * scale;
            // (u, v) keeps the chart's counter-clockwise orientation; the bake maps v to texel row (1 - v) * size.
            atlas.uvVertices.push_back({c.vertices[k], x / n, y / n});
        }
        for (std::size_t k = 0; k < c.vertices.size(); ++k)
            slot[static_cast<std::size_t>(c.vertices[k])] = base + static_cast<std::int32_t>(k);
        for (std::int32_t f : c.faces) {
            atlas.chartOfFace[static_cast<std::size_t>(f)] = static_cast<std::int32_t>(ci);
            const auto& t = surface.triangles[static_cast<std::size_t>(f)];
            atlas.uvTriangles[static_cast<std::size_t>(f)] = {slot[static_cast<std::size_t>(t[0])],
                                                              slot[static_cast<std::size_t>(t[1])],
                                                              slot[static_cast<std::size_t>(t[2])]};
        }
        for (std::int32_t v : c.vertices)
            slot[static_cast<std::size_t>(v)] = -1;
        covered += (c.maxU - c.minU) * (c.maxV - c.minV) * scale * scale;
    }
    atlas.stats = stretchStats(surface, atlas, scale);
    atlas.stats.charts = static_cast<int>(charts.size());
    atlas.stats.texelsPerMm = scale;
    atlas.stats.padding = padding;
    atlas.stats.fill = covered / (n * n);
    progress.report("texture.atlas", 1.0);
    return atlas;
}

} // namespace hs::texture
