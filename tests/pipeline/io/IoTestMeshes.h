#pragma once
/// Small meshes and file helpers shared by the io tests.

#include "hs/core/SurfaceMesh.h"
#include "hs/core/TetMesh.h"

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

namespace hs::test {

/// A closed octahedron with coordinates that are not short decimals, two face labels and one vertex label.
inline SurfaceMesh labelledOctahedron() {
    SurfaceMesh mesh;
    const double a = 1.0 / 3.0;
    mesh.points = {{a, 0.1, 0.2},       {-a, 0.1, 0.2},      {0.0, 0.1 + a, 0.2},
                   {0.0, 0.1 - a, 0.2}, {0.0, 0.1, 0.2 + a}, {0.0, 0.1, 0.2 - 1e-3 - a}};
    // Outward-oriented: +x, -x, +y, -y, +z, -z are 0..5.
    mesh.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    mesh.faceLabels["region"] = {1, 1, 1, 1, 2, 2, 2, 2};
    mesh.faceLabels["tissue"] = {-7, 0, 3, 2147483647, -2147483647, 5, 6, 7};
    mesh.vertexLabels["sourcePoint"] = {10, 11, 12, 13, 14, 15};
    return mesh;
}

/// A cube (edge 1.5 mm, shifted off the origin) split into six positively oriented tetrahedra around its diagonal,
/// three regions, a per-tet label and a per-point label.
inline TetMesh labelledCube() {
    TetMesh mesh;
    for (int i = 0; i < 8; ++i)
        mesh.points.push_back({0.1 + 1.5 * (i & 1), -0.3 + 1.5 * ((i >> 1) & 1), 1.0 / 7.0 + 1.5 * ((i >> 2) & 1)});
    const int axes[6][2] = {{1, 2}, {1, 4}, {2, 1}, {2, 4}, {4, 1}, {4, 2}};
    for (const auto& ab : axes) {
        Tet tet{0, ab[0], ab[0] | ab[1], 7};
        mesh.tets.push_back(tet);
        if (signedVolume(mesh, mesh.tets.size() - 1) < 0.0)
            std::swap(mesh.tets.back()[1], mesh.tets.back()[2]);
    }
    mesh.regions = {1, 1, 2, 2, 3, 7};
    mesh.tetLabels["material"] = {10, 11, 12, 13, -14, 15};
    mesh.pointLabels["fixed"] = {1, 0, 0, 0, 0, 0, 0, 1};
    return mesh;
}

inline std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

/// A deterministic byte stream (xorshift), for garbage files.
inline std::string pseudoRandomBytes(std::size_t n, std::uint64_t seed) {
    std::string out(n, '\0');
    std::uint64_t x = seed * 2654435761ull + 1;
    for (auto& c : out) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        c = static_cast<char>(x & 0xff);
    }
    return out;
}

} // namespace hs::test
