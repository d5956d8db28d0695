#include "Geometry.h"

#include "hs/core/RegionModel.h"
#include "hs/core/TriangleGeometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace hs::pathology::detail {

Grid Grid::covering(const Bounds& box, double h, int pad) {
    Grid g;
    g.h = h;
    g.origin = box.min - Vec3{pad * h, pad * h, pad * h};
    const Vec3 s = box.size();
    g.nx = static_cast<int>(std::ceil(s.x / h)) + 2 * pad + 1;
    g.ny = static_cast<int>(std::ceil(s.y / h)) + 2 * pad + 1;
    g.nz = static_cast<int>(std::ceil(s.z / h)) + 2 * pad + 1;
    return g;
}

std::vector<std::uint8_t> insideMask(const SurfaceMesh& mesh, const Grid& grid) {
    // Column centres are nudged by an irrational fraction of a voxel so that no column passes through an edge or
    // vertex of the mesh in practice; each crossing is then counted once.
    const double ex = grid.h * 1.23456789e-4, ey = grid.h * 7.6543211e-5;
    std::vector<std::vector<double>> columns(static_cast<std::size_t>(grid.nx) * static_cast<std::size_t>(grid.ny));
    for (const Triangle& t : mesh.triangles) {
        const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
        const Vec3& b = mesh.points[static_cast<std::size_t>(t[1])];
        const Vec3& c = mesh.points[static_cast<std::size_t>(t[2])];
        const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        if (det == 0.0)
            continue;
        const double minX = std::min({a.x, b.x, c.x}), maxX = std::max({a.x, b.x, c.x});
        const double minY = std::min({a.y, b.y, c.y}), maxY = std::max({a.y, b.y, c.y});
        const int i0 = std::max(0, static_cast<int>(std::ceil((minX - grid.origin.x - ex) / grid.h)));
        const int i1 = std::min(grid.nx - 1, static_cast<int>(std::floor((maxX - grid.origin.x - ex) / grid.h)));
        const int j0 = std::max(0, static_cast<int>(std::ceil((minY - grid.origin.y - ey) / grid.h)));
        const int j1 = std::min(grid.ny - 1, static_cast<int>(std::floor((maxY - grid.origin.y - ey) / grid.h)));
        for (int j = j0; j <= j1; ++j) {
            const double y = grid.origin.y + j * grid.h + ey;
            for (int i = i0; i <= i1; ++i) {
                const double x = grid.origin.x + i * grid.h + ex;
                const double l1 = ((x - a.x) * (c.y - a.y) - (c.x - a.x) * (y - a.y)) / det;
                const double l2 = ((b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y)) / det;
                if (l1 < 0.0 || l2 < 0.0 || l1 + l2 > 1.0)
                    continue;
                const double z = a.z + l1 * (b.z - a.z) + l2 * (c.z - a.z);
                columns[static_cast<std::size_t>(j) * static_cast<std::size_t>(grid.nx) + static_cast<std::size_t>(i)]
                    .push_back(z);
            }
        }
    }
    std::vector<std::uint8_t> mask(grid.size(), 0);
    for (int j = 0; j < grid.ny; ++j)
        for (int i = 0; i < grid.nx; ++i) {
            auto& col =
                columns[static_cast<std::size_t>(j) * static_cast<std::size_t>(grid.nx) + static_cast<std::size_t>(i)];
            if (col.size() < 2)
                continue;
            std::sort(col.begin(), col.end());
            std::size_t below = 0;
            for (int k = 0; k < grid.nz; ++k) {
                const double z = grid.origin.z + k * grid.h;
                while (below < col.size() && col[below] < z)
                    ++below;
                if (below % 2 == 1)
                    mask[grid.index(i, j, k)] = 1;
            }
        }
    return mask;
}

namespace {

// The six tetrahedra of a cube around its diagonal 0-7 (corner bit 1: +x, 2: +y, 4: +z).
constexpr std::array<std::array<int, 4>, 6> kTets{
    {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}}};

void keepLargestComponent(SurfaceMesh& mesh) {
    const std::size_t nf = mesh.triangles.size();
    std::vector<std::int32_t> parent(mesh.points.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](std::int32_t x) {
        while (parent[static_cast<std::size_t>(x)] != x) {
            parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
            x = parent[static_cast<std::size_t>(x)];
        }
        return x;
    };
    for (const Triangle& t : mesh.triangles)
        for (int k = 1; k < 3; ++k)
            parent[static_cast<std::size_t>(find(t[static_cast<std::size_t>(k)]))] = find(t[0]);
    std::unordered_map<std::int32_t, std::size_t> count;
    for (const Triangle& t : mesh.triangles)
        ++count[find(t[0])];
    std::int32_t best = -1;
    std::size_t bestCount = 0;
    for (const Triangle& t : mesh.triangles) { // deterministic: first root with the maximal count
        const std::int32_t r = find(t[0]);
        if (count[r] > bestCount) {
            bestCount = count[r];
            best = r;
        }
    }
    SurfaceMesh out;
    std::vector<std::int32_t> remap(mesh.points.size(), -1);
    for (std::size_t f = 0; f < nf; ++f) {
        const Triangle& t = mesh.triangles[f];
        if (find(t[0]) != best)
            continue;
        Triangle nt{};
        for (std::size_t k = 0; k < 3; ++k) {
            auto& r = remap[static_cast<std::size_t>(t[k])];
            if (r < 0) {
                r = static_cast<std::int32_t>(out.points.size());
                out.points.push_back(mesh.points[static_cast<std::size_t>(t[k])]);
            }
            nt[k] = r;
        }
        out.triangles.push_back(nt);
    }
    mesh = std::move(out);
}

} // namespace

SurfaceMesh polygonize(std::vector<float> field, const Grid& grid, float iso) {
    // No sample exactly on the iso-value: every crossing then lies strictly inside an edge.
    for (float& v : field)
        if (std::fabs(v - iso) < 1e-6f)
            v = iso + 1e-6f;
    SurfaceMesh mesh;
    std::unordered_map<std::uint64_t, std::int32_t> edgeVertex;
    const std::uint64_t n = grid.size();
    auto vertexOn = [&](std::size_t ga, std::size_t gb, const Vec3& pa, const Vec3& pb) {
        const std::uint64_t key = std::min<std::uint64_t>(ga, gb) * n + std::max<std::uint64_t>(ga, gb);
        auto it = edgeVertex.find(key);
        if (it != edgeVertex.end())
            return it->second;
        const double fa = field[ga], fb = field[gb];
        double t = (static_cast<double>(iso) - fa) / (fb - fa);
        t = std::clamp(t, 0.02, 0.98); // keeps triangles away from zero area
        const auto id = static_cast<std::int32_t>(mesh.points.size());
        mesh.points.push_back(pa + (pb - pa) * t);
        edgeVertex.emplace(key, id);
        return id;
    };
    auto emit = [&](std::int32_t a, std::int32_t b, std::int32_t c, const Vec3& inC, const Vec3& outC) {
        const Vec3& pa = mesh.points[static_cast<std::size_t>(a)];
        const Vec3 nrm =
            cross(mesh.points[static_cast<std::size_t>(b)] - pa, mesh.points[static_cast<std::size_t>(c)] - pa);
        if (dot(nrm, outC - inC) >= 0.0)
            mesh.triangles.push_back({a, b, c});
        else
            mesh.triangles.push_back({a, c, b});
    };
    for (int k = 0; k + 1 < grid.nz; ++k)
        for (int j = 0; j + 1 < grid.ny; ++j)
            for (int i = 0; i + 1 < grid.nx; ++i) {
                std::array<std::size_t, 8> gi{};
                std::array<Vec3, 8> gp{};
                bool anyIn = false, anyOut = false;
                for (int c = 0; c < 8; ++c) {
                    const int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
                    gi[static_cast<std::size_t>(c)] = grid.index(i + di, j + dj, k + dk);
                    gp[static_cast<std::size_t>(c)] = grid.center(i + di, j + dj, k + dk);
                    (field[gi[static_cast<std::size_t>(c)]] > iso ? anyIn : anyOut) = true;
                }
                if (!anyIn || !anyOut)
                    continue;
                for (const auto& tet : kTets) {
                    std::array<int, 4> in{}, out{};
                    int ni = 0, no = 0;
                    for (int c : tet)
                        (field[gi[static_cast<std::size_t>(c)]] > iso ? in[static_cast<std::size_t>(ni++)]
                                                                      : out[static_cast<std::size_t>(no++)]) = c;
                    if (ni == 0 || no == 0)
                        continue;
                    Vec3 inC, outC;
                    for (int q = 0; q < ni; ++q)
                        inC += gp[static_cast<std::size_t>(in[static_cast<std::size_t>(q)])] / ni;
                    for (int q = 0; q < no; ++q)
                        outC += gp[static_cast<std::size_t>(out[static_cast<std::size_t>(q)])] / no;
                    auto v = [&](int a, int b) {
                        return vertexOn(gi[static_cast<std::size_t>(a)], gi[static_cast<std::size_t>(b)],
                                        gp[static_cast<std::size_t>(a)], gp[static_cast<std::size_t>(b)]);
                    };
                    if (ni == 1) {
                        emit(v(in[0], out[0]), v(in[0], out[1]), v(in[0], out[2]), inC, outC);
                    } else if (ni == 3) {
                        emit(v(in[0], out[0]), v(in[1], out[0]), v(in[2], out[0]), inC, outC);
                    } else {
                        const std::int32_t e00 = v(in[0], out[0]), e01 = v(in[0], out[1]);
                        const std::int32_t e11 = v(in[1], out[1]), e10 = v(in[1], out[0]);
                        emit(e00, e01, e11, inC, outC);
                        emit(e00, e11, e10, inC, outC);
                    }
                }
            }
    keepLargestComponent(mesh);
    return mesh;
}

void taubinSmooth(SurfaceMesh& mesh, int iterations, double lambda, double mu) {
    std::vector<std::vector<std::int32_t>> nbr(mesh.points.size());
    for (const Triangle& t : mesh.triangles)
        for (std::size_t k = 0; k < 3; ++k) {
            nbr[static_cast<std::size_t>(t[k])].push_back(t[(k + 1) % 3]);
            nbr[static_cast<std::size_t>(t[k])].push_back(t[(k + 2) % 3]);
        }
    for (auto& v : nbr) {
        std::sort(v.begin(), v.end());
        v.erase(std::unique(v.begin(), v.end()), v.end());
    }
    std::vector<Vec3> next(mesh.points.size());
    auto pass = [&](double w) {
        for (std::size_t i = 0; i < mesh.points.size(); ++i) {
            if (nbr[i].empty()) {
                next[i] = mesh.points[i];
                continue;
            }
            Vec3 avg;
            for (std::int32_t j : nbr[i])
                avg += mesh.points[static_cast<std::size_t>(j)];
            avg = avg / static_cast<double>(nbr[i].size());
            next[i] = mesh.points[i] + (avg - mesh.points[i]) * w;
        }
        mesh.points.swap(next);
    };
    for (int it = 0; it < iterations; ++it) {
        pass(lambda);
        pass(mu);
    }
}

void orientOutward(SurfaceMesh& mesh) {
    if (enclosedVolume(mesh) < 0.0)
        for (Triangle& t : mesh.triangles)
            std::swap(t[1], t[2]);
}

bool rayTriangle(const Vec3& origin, const Vec3& dir, const Vec3& a, const Vec3& b, const Vec3& c, double tMin,
                 double& t) {
    double u = 0.0, v = 0.0;
    return hs::rayTriangle(origin, dir, a, b, c, tMin, t, u, v);
}

double diameter(const std::vector<Vec3>& points) {
    const std::size_t n = points.size();
    const std::size_t stride = n > 3000 ? (n + 2999) / 3000 : 1;
    double best = 0.0;
    for (std::size_t i = 0; i < n; i += stride)
        for (std::size_t j = i + stride; j < n; j += stride)
            best = std::max(best, norm2(points[i] - points[j]));
    return std::sqrt(best);
}

Vec3 volumeCentroid(const SurfaceMesh& mesh) {
    Vec3 c;
    double v = 0.0;
    for (const Triangle& t : mesh.triangles) {
        const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
        const Vec3& b = mesh.points[static_cast<std::size_t>(t[1])];
        const Vec3& d = mesh.points[static_cast<std::size_t>(t[2])];
        const double tv = dot(a, cross(b, d)) / 6.0;
        v += tv;
        c += (a + b + d) * (tv / 4.0);
    }
    return v != 0.0 ? c / v : centroid(mesh.points);
}

void scaleAbout(SurfaceMesh& mesh, const Vec3& center, double factor) {
    for (Vec3& p : mesh.points)
        p = center + (p - center) * factor;
}

void translate(SurfaceMesh& mesh, const Vec3& by) {
    for (Vec3& p : mesh.points)
        p += by;
}

double surfaceDistance(const SurfaceMesh& a, const SurfaceMesh& b, double cutoff) {
    Bounds ba = bounds(a);
    ba.add(ba.min - Vec3{cutoff, cutoff, cutoff});
    ba.add(ba.max + Vec3{cutoff, cutoff, cutoff});
    double best = cutoff * cutoff;
    for (const Triangle& t : b.triangles) {
        const Vec3& p0 = b.points[static_cast<std::size_t>(t[0])];
        const Vec3& p1 = b.points[static_cast<std::size_t>(t[1])];
        const Vec3& p2 = b.points[static_cast<std::size_t>(t[2])];
        Bounds bt;
        bt.add(p0);
        bt.add(p1);
        bt.add(p2);
        if (bt.max.x < ba.min.x || bt.min.x > ba.max.x || bt.max.y < ba.min.y || bt.min.y > ba.max.y ||
            bt.max.z < ba.min.z || bt.min.z > ba.max.z)
            continue;
        for (const Vec3& p : a.points) {
            // Cheap reject: the triangle's box is farther than the best distance so far.
            const double dx = std::max({bt.min.x - p.x, 0.0, p.x - bt.max.x});
            const double dy = std::max({bt.min.y - p.y, 0.0, p.y - bt.max.y});
            const double dz = std::max({bt.min.z - p.z, 0.0, p.z - bt.max.z});
            if (dx * dx + dy * dy + dz * dz >= best)
                continue;
            best = std::min(best, closestPointOnTriangle(p, p0, p1, p2).distance2);
        }
    }
    return std::sqrt(best);
}

void orthonormalFrame(const Vec3& n, Vec3& e1, Vec3& e2) {
    const Vec3 helper = std::fabs(n.x) < 0.8 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
    e1 = normalized(cross(n, helper));
    e2 = cross(n, e1);
}

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

/// Signed distance from p to a closed surface (negative inside), capped at `cutoff`.
double signedDistance(const SurfaceMesh& s, const Bounds& box, const Vec3& p, double cutoff) {
    if (p.x < box.min.x - cutoff || p.y < box.min.y - cutoff || p.z < box.min.z - cutoff || p.x > box.max.x + cutoff ||
        p.y > box.max.y + cutoff || p.z > box.max.z + cutoff)
        return cutoff;
    double best = cutoff * cutoff;
    for (const Triangle& t : s.triangles)
        best = std::min(best, closestPointOnTriangle(p, s.points[static_cast<std::size_t>(t[0])],
                                                     s.points[static_cast<std::size_t>(t[1])],
                                                     s.points[static_cast<std::size_t>(t[2])])
                                  .distance2);
    const double d = std::sqrt(best);
    return windingNumber(s, p) > 0.5 ? -d : d;
}

} // namespace hs::pathology::detail
