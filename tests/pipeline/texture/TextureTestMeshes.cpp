#include "TextureTestMeshes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>
#include <vector>

namespace hs::test {

TetMesh makeTetCube(int n, double sizeMm, double radiusMm) {
    TetMesh mesh;
    const auto id = [n](int x, int y, int z) { return static_cast<std::int32_t>((z * (n + 1) + y) * (n + 1) + x); };
    const double h = sizeMm / n;
    for (int z = 0; z <= n; ++z)
        for (int y = 0; y <= n; ++y)
            for (int x = 0; x <= n; ++x)
                mesh.points.push_back({x * h, y * h, z * h});
    // Kuhn subdivision of each cell: 6 tets along the main diagonal, all positively oriented.
    static const std::array<std::array<int, 3>, 6> kPerms{
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    const Vec3 centre{sizeMm / 2, sizeMm / 2, sizeMm};
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                for (const auto& perm : kPerms) {
                    std::array<int, 3> c{x, y, z};
                    Tet tet;
                    tet[0] = id(c[0], c[1], c[2]);
                    for (int k = 0; k < 3; ++k) {
                        ++c[static_cast<std::size_t>(perm[static_cast<std::size_t>(k)])];
                        tet[static_cast<std::size_t>(k + 1)] = id(c[0], c[1], c[2]);
                    }
                    const Vec3& p0 = mesh.points[static_cast<std::size_t>(tet[0])];
                    if (dot(mesh.points[static_cast<std::size_t>(tet[1])] - p0,
                            cross(mesh.points[static_cast<std::size_t>(tet[2])] - p0,
                                  mesh.points[static_cast<std::size_t>(tet[3])] - p0)) < 0)
                        std::swap(tet[2], tet[3]);
                    Vec3 mid;
                    for (auto v : tet)
                        mid += mesh.points[static_cast<std::size_t>(v)] * 0.25;
                    mesh.tets.push_back(tet);
                    mesh.regions.push_back(distance(mid, centre) < radiusMm ? 1 : 0);
                }
    return mesh;
}

SurfaceMesh subdivideMidpoint(const SurfaceMesh& mesh) {
    SurfaceMesh out;
    out.points = mesh.points;
    std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> mids;
    const auto mid = [&](std::int32_t a, std::int32_t b) {
        const auto key = std::make_pair(std::min(a, b), std::max(a, b));
        const auto it = mids.find(key);
        if (it != mids.end())
            return it->second;
        const auto idx = static_cast<std::int32_t>(out.points.size());
        out.points.push_back((mesh.points[static_cast<std::size_t>(a)] + mesh.points[static_cast<std::size_t>(b)]) *
                             0.5);
        mids.emplace(key, idx);
        return idx;
    };
    for (const auto& t : mesh.triangles) {
        const std::int32_t ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
        out.triangles.push_back({t[0], ab, ca});
        out.triangles.push_back({ab, t[1], bc});
        out.triangles.push_back({ca, bc, t[2]});
        out.triangles.push_back({ab, bc, ca});
    }
    for (const auto& [name, values] : mesh.faceLabels) {
        auto& dst = out.faceLabels[name];
        for (std::int32_t v : values)
            dst.insert(dst.end(), 4, v);
    }
    return out;
}

namespace {

SurfaceMesh geodesicSphere(int f) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    const std::vector<Vec3> ico{{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    const std::vector<std::array<int, 3>> faces{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                                {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                                {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                                {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    SurfaceMesh mesh;
    std::map<std::tuple<long long, long long, long long>, std::int32_t> index;
    const auto vertex = [&](const Vec3& p) {
        const Vec3 q = normalized(p);
        const auto key = std::make_tuple(std::llround(q.x * 1e7), std::llround(q.y * 1e7), std::llround(q.z * 1e7));
        const auto it = index.find(key);
        if (it != index.end())
            return it->second;
        const auto idx = static_cast<std::int32_t>(mesh.points.size());
        mesh.points.push_back(q);
        index.emplace(key, idx);
        return idx;
    };
    for (const auto& face : faces) {
        const Vec3 a = ico[static_cast<std::size_t>(face[0])], b = ico[static_cast<std::size_t>(face[1])],
                   c = ico[static_cast<std::size_t>(face[2])];
        const auto at = [&](int i, int j) { // i steps towards b, j towards c
            return a + (b - a) * (static_cast<double>(i) / f) + (c - a) * (static_cast<double>(j) / f);
        };
        for (int i = 0; i < f; ++i)
            for (int j = 0; j < f - i; ++j) {
                mesh.triangles.push_back({vertex(at(i, j)), vertex(at(i + 1, j)), vertex(at(i, j + 1))});
                if (j + 1 < f - i)
                    mesh.triangles.push_back({vertex(at(i + 1, j)), vertex(at(i + 1, j + 1)), vertex(at(i, j + 1))});
            }
    }
    return mesh;
}

} // namespace

void addPathologyBumps(SurfaceMesh& mesh, const Vec3& myomaDir, double myomaRadiusMm, double myomaHeightMm,
                       const Vec3& polypDir, double polypRadiusMm, double polypHeightMm) {
    const Bounds box = bounds(mesh);
    const std::vector<Vec3> normals = vertexNormals(mesh);
    const auto nearestTo = [&](const Vec3& dir) {
        const Vec3 target = box.center() + normalized(dir) * box.diagonal();
        std::size_t best = 0;
        for (std::size_t v = 1; v < mesh.points.size(); ++v)
            if (distance(mesh.points[v], target) < distance(mesh.points[best], target))
                best = v;
        return mesh.points[best];
    };
    const Vec3 myoma = nearestTo(myomaDir), polyp = nearestTo(polypDir);
    std::vector<std::int32_t> vertexRegion(mesh.points.size(), 0);
    std::vector<Vec3> moved = mesh.points;
    for (std::size_t v = 0; v < mesh.points.size(); ++v) {
        const double dm = distance(mesh.points[v], myoma) / myomaRadiusMm;
        const double dp = distance(mesh.points[v], polyp) / polypRadiusMm;
        // Myoma: a dome; polyp: a steep, rounded head (a smooth step).
        const double hm = dm < 1.0 ? myomaHeightMm * std::pow(1.0 - dm * dm, 1.5) : 0.0;
        const double hp = dp < 1.0 ? polypHeightMm * std::pow(1.0 - dp * dp, 0.35) : 0.0;
        moved[v] += normals[v] * (hm + hp);
        vertexRegion[v] = dp < 1.0 ? 2 : (dm < 1.0 ? 1 : 0);
    }
    mesh.points = moved;
    auto& region = mesh.faceLabels["region"];
    auto& contact = mesh.faceLabels["contact"];
    region.assign(mesh.triangles.size(), 0);
    contact.assign(mesh.triangles.size(), 0);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const auto& t = mesh.triangles[f];
        std::int32_t r = 0;
        bool mixed = false;
        for (std::int32_t v : t) {
            r = std::max(r, vertexRegion[static_cast<std::size_t>(v)]);
            mixed = mixed || vertexRegion[static_cast<std::size_t>(v)] != vertexRegion[static_cast<std::size_t>(t[0])];
        }
        region[f] = r;
        contact[f] = mixed ? 1 : 0;
    }
}

SurfaceMesh makeLabelledOrgan(int frequency, double radiusMm) {
    SurfaceMesh mesh = geodesicSphere(frequency);
    for (Vec3& p : mesh.points)
        p = Vec3(p.x * radiusMm * 0.8, p.y * radiusMm * 1.2, p.z * radiusMm * 0.6);
    addPathologyBumps(mesh, Vec3(1, 0.3, 0.2), radiusMm * 0.35, radiusMm * 0.18, Vec3(-0.5, 0.4, 0.8), radiusMm * 0.12,
                      radiusMm * 0.2);
    return mesh;
}

} // namespace hs::test
