#include "hs/core/SurfaceMesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <unordered_map>

namespace hs {
namespace {

Status validateLabels(const LabelMap& labels, std::size_t expected, const char* what) {
    for (const auto& [name, values] : labels) {
        if (!values.empty() && values.size() != expected)
            return fail(ErrorCode::InvalidInput, std::string(what) + " label '" + name + "' has " +
                                                     std::to_string(values.size()) + " values, expected " +
                                                     std::to_string(expected));
    }
    return {};
}

/// Union-find over face indices, for connected components.
struct DisjointSets {
    std::vector<std::size_t> parent;
    explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
    std::size_t find(std::size_t i) {
        while (parent[i] != i) {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        return i;
    }
    void unite(std::size_t a, std::size_t b) {
        a = find(a);
        b = find(b);
        if (a != b)
            parent[std::max(a, b)] = std::min(a, b);
    }
};

} // namespace

Status checkCoordinates(const std::vector<Vec3>& points, const char* element) {
    for (std::size_t i = 0; i < points.size(); ++i) {
        for (const double c : {points[i].x, points[i].y, points[i].z}) {
            if (!(std::abs(c) <= kMaxCoordinate)) { // NaN fails this too
                std::ostringstream out;
                out << element << ' ' << i << " has coordinate " << c << ", allowed " << -kMaxCoordinate << ".."
                    << kMaxCoordinate;
                return fail(ErrorCode::InvalidInput, out.str());
            }
        }
    }
    return {};
}

Status validate(const SurfaceMesh& mesh) {
    HS_TRY(checkCoordinates(mesh.points, "vertex"));
    const auto n = static_cast<std::int64_t>(mesh.points.size());
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        for (auto v : mesh.triangles[f]) {
            if (v < 0 || v >= n)
                return fail(ErrorCode::InvalidInput, "triangle " + std::to_string(f) + " references vertex " +
                                                         std::to_string(v) + ", allowed 0.." + std::to_string(n - 1));
        }
    }
    HS_TRY(validateLabels(mesh.vertexLabels, mesh.points.size(), "vertex"));
    HS_TRY(validateLabels(mesh.faceLabels, mesh.triangles.size(), "face"));
    return {};
}

Bounds bounds(const SurfaceMesh& mesh) {
    Bounds b;
    for (const auto& p : mesh.points)
        b.add(p);
    return b;
}

Vec3 faceNormal(const SurfaceMesh& mesh, std::size_t face) {
    const auto& t = mesh.triangles[face];
    const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
    const Vec3& b = mesh.points[static_cast<std::size_t>(t[1])];
    const Vec3& c = mesh.points[static_cast<std::size_t>(t[2])];
    return normalized(cross(b - a, c - a));
}

std::vector<Vec3> vertexNormals(const SurfaceMesh& mesh) {
    std::vector<Vec3> normals(mesh.points.size());
    for (const auto& t : mesh.triangles) {
        const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
        const Vec3& b = mesh.points[static_cast<std::size_t>(t[1])];
        const Vec3& c = mesh.points[static_cast<std::size_t>(t[2])];
        const Vec3 n = cross(b - a, c - a); // length = 2 * area: area weighting
        for (auto v : t)
            normals[static_cast<std::size_t>(v)] += n;
    }
    for (auto& n : normals)
        n = normalized(n);
    return normals;
}

double surfaceArea(const SurfaceMesh& mesh) {
    double area = 0.0;
    for (const auto& t : mesh.triangles) {
        const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
        const Vec3& b = mesh.points[static_cast<std::size_t>(t[1])];
        const Vec3& c = mesh.points[static_cast<std::size_t>(t[2])];
        area += 0.5 * norm(cross(b - a, c - a));
    }
    return area;
}

double enclosedVolume(const SurfaceMesh& mesh) {
    // Sum of signed tetrahedra (origin shifted to the bounding-box centre for accuracy).
    const Vec3 o = bounds(mesh).center();
    double volume6 = 0.0;
    for (const auto& t : mesh.triangles) {
        const Vec3 a = mesh.points[static_cast<std::size_t>(t[0])] - o;
        const Vec3 b = mesh.points[static_cast<std::size_t>(t[1])] - o;
        const Vec3 c = mesh.points[static_cast<std::size_t>(t[2])] - o;
        volume6 += dot(a, cross(b, c));
    }
    return volume6 / 6.0;
}

SurfaceTopology analyzeTopology(const SurfaceMesh& mesh) {
    SurfaceTopology topo;
    const std::size_t nv = mesh.points.size();
    const std::size_t nf = mesh.triangles.size();

    // Edge -> (count, net direction): a consistently oriented manifold edge is used once in each direction.
    struct EdgeUse {
        int count = 0;
        int forward = 0; // uses as (lo -> hi) minus uses as (hi -> lo)
        std::size_t firstFace = 0;
    };
    std::unordered_map<std::uint64_t, EdgeUse> edges;
    edges.reserve(nf * 2);
    std::vector<char> referenced(nv, 0);
    DisjointSets components(nf);

    for (std::size_t f = 0; f < nf; ++f) {
        const auto& t = mesh.triangles[f];
        const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
        const Vec3& b = mesh.points[static_cast<std::size_t>(t[1])];
        const Vec3& c = mesh.points[static_cast<std::size_t>(t[2])];
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || norm2(cross(b - a, c - a)) == 0.0)
            ++topo.degenerateFaces;
        for (int k = 0; k < 3; ++k) {
            const std::int32_t u = t[static_cast<std::size_t>(k)];
            const std::int32_t w = t[static_cast<std::size_t>((k + 1) % 3)];
            referenced[static_cast<std::size_t>(u)] = 1;
            if (u == w)
                continue;
            auto [it, inserted] = edges.try_emplace(edgeKey(u, w));
            EdgeUse& use = it->second;
            if (inserted)
                use.firstFace = f;
            else
                components.unite(use.firstFace, f);
            ++use.count;
            use.forward += (u < w) ? 1 : -1;
        }
    }
    for (const auto& [key, use] : edges) {
        if (use.count == 1)
            ++topo.boundaryEdges;
        else if (use.count > 2)
            ++topo.nonManifoldEdges;
        else if (use.forward != 0)
            ++topo.inconsistentEdges;
    }
    topo.unreferencedVertices = static_cast<std::size_t>(std::count(referenced.begin(), referenced.end(), 0));

    std::size_t roots = 0;
    for (std::size_t f = 0; f < nf; ++f)
        if (components.find(f) == f)
            ++roots;
    topo.components = roots;

    // Non-manifold vertices: the faces around a vertex must form a single fan (connected through shared edges).
    std::vector<std::vector<std::size_t>> vertexFaces(nv);
    for (std::size_t f = 0; f < nf; ++f)
        for (auto v : mesh.triangles[f])
            vertexFaces[static_cast<std::size_t>(v)].push_back(f);
    for (std::size_t v = 0; v < nv; ++v) {
        const auto& faces = vertexFaces[v];
        if (faces.size() < 2)
            continue;
        // Within the fan, faces are linked when they share an edge through v.
        std::unordered_map<std::int32_t, std::size_t> firstByOther;
        DisjointSets fan(faces.size());
        for (std::size_t i = 0; i < faces.size(); ++i) {
            for (auto w : mesh.triangles[faces[i]]) {
                if (static_cast<std::size_t>(w) == v)
                    continue;
                auto [it, inserted] = firstByOther.try_emplace(w, i);
                if (!inserted)
                    fan.unite(it->second, i);
            }
        }
        std::size_t fans = 0;
        for (std::size_t i = 0; i < faces.size(); ++i)
            if (fan.find(i) == i)
                ++fans;
        if (fans > 1)
            ++topo.nonManifoldVertices;
    }
    return topo;
}

} // namespace hs
