// The textured surface (the UV-split mesh) and the bake's folder; hs::io writes the files.
#include "hs/texture/Bake.h"
#include "hs/texture/ImageFiles.h"

#include "hs/core/Subdivision.h"
#include "hs/io/AtomicFile.h"
#include "hs/io/MeshIO.h"
#include "hs/io/TexturedSurface.h"

#include <filesystem>
#include <string>
#include <system_error>
#include <unordered_map>

namespace hs::texture {

TexturedSurface makeTexturedSurface(const SurfaceMesh& surface, const Atlas& atlas) {
    TexturedSurface out;
    out.mesh.points.reserve(atlas.uvVertices.size());
    out.uv.reserve(atlas.uvVertices.size());
    const std::vector<Vec3> normals = vertexNormals(surface);
    for (const UvVertex& q : atlas.uvVertices) {
        out.mesh.points.push_back(surface.points[static_cast<std::size_t>(q.vertex)]);
        out.uv.push_back({static_cast<float>(q.u), static_cast<float>(q.v)});
        out.normals.push_back(normals[static_cast<std::size_t>(q.vertex)]);
    }
    for (const auto& t : atlas.uvTriangles)
        out.mesh.triangles.push_back({t[0], t[1], t[2]});
    out.mesh.faceLabels = surface.faceLabels;
    out.mesh.faceLabels["chart"] = atlas.chartOfFace;
    for (const auto& [name, values] : surface.vertexLabels) {
        if (values.size() != surface.points.size())
            continue;
        auto& dst = out.mesh.vertexLabels[name];
        for (const UvVertex& q : atlas.uvVertices)
            dst.push_back(values[static_cast<std::size_t>(q.vertex)]);
    }
    return out;
}

TexturedSurface makeCloseUpSurface(const SurfaceMesh& surface, const Atlas& atlas, const CloseUpParams& params) {
    const int levels = params.levels;
    SurfaceMesh labelled =
        params.smoothing.iterations > 0 ? taubinSmooth(surface, params.seen, params.smoothing) : surface;
    labelled.vertexLabels.clear();
    labelled.faceLabels["chart"] = atlas.chartOfFace;
    std::vector<std::array<CornerUv, 3>> corners(surface.triangles.size());
    for (std::size_t f = 0; f < corners.size(); ++f)
        for (std::size_t k = 0; k < 3; ++k) {
            const UvVertex& q = atlas.uvVertices[static_cast<std::size_t>(atlas.uvTriangles[f][k])];
            corners[f][k] = {q.u, q.v};
        }
    SurfaceMesh smooth = loopSubdivide(labelled, levels);
    for (int i = 0; i < levels; ++i)
        corners = subdivideCorners(corners);
    if (!params.pits.empty()) {
        const std::vector<Vec3> before = vertexNormals(smooth);
        for (std::size_t v = 0; v < smooth.points.size(); ++v)
            for (const SurfacePit& pit : params.pits) {
                const double d = distance(smooth.points[v], pit.centreMm);
                const double len = norm(before[v]);
                if (d >= pit.radiusMm || len <= 0.0 || dot(before[v], pit.normal) < 0.5 * len)
                    continue;
                const double s = 1.0 - (d / pit.radiusMm) * (d / pit.radiusMm);
                smooth.points[v] -= pit.normal * (pit.depthMm * s * s);
            }
    }
    const std::vector<Vec3> normals = vertexNormals(smooth);

    // One output point per (point, chart), numbered in order of first use.
    const auto& chart = smooth.faceLabels.at("chart");
    std::unordered_map<std::uint64_t, std::int32_t> split;
    split.reserve(smooth.points.size() * 2);
    TexturedSurface out;
    out.mesh.triangles.resize(smooth.triangles.size());
    for (std::size_t f = 0; f < smooth.triangles.size(); ++f)
        for (std::size_t k = 0; k < 3; ++k) {
            const std::int32_t v = smooth.triangles[f][k];
            const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(v)) << 32) |
                                      static_cast<std::uint32_t>(chart[f]);
            const auto [it, inserted] = split.try_emplace(key, static_cast<std::int32_t>(out.mesh.points.size()));
            if (inserted) {
                out.mesh.points.push_back(smooth.points[static_cast<std::size_t>(v)]);
                out.uv.push_back({static_cast<float>(corners[f][k][0]), static_cast<float>(corners[f][k][1])});
                out.normals.push_back(normals[static_cast<std::size_t>(v)]);
            }
            out.mesh.triangles[f][k] = it->second;
        }
    out.mesh.faceLabels = std::move(smooth.faceLabels);
    return out;
}

Status writeBakeOutputs(const SurfaceMesh& surface, const BakeResult& result, const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec)
        return fail(ErrorCode::IoError, dir + ": cannot create the folder: " + ec.message());
    const auto file = [&dir](const char* name) { return (std::filesystem::path(dir) / name).string(); };
    HS_TRY(writeImage(result.albedo, file("albedo.png")));
    HS_TRY(writeImage(result.normal, file("normal.png")));
    HS_TRY(writeImage(result.roughness, file("roughness.png")));
    const TexturedSurface textured = makeTexturedSurface(surface, result.atlas);
    io::WriteOptions vtp;
    vtp.binary = false;
    vtp.textureCoordinates = &textured.uv;
    vtp.normals = &textured.normals;
    HS_TRY(io::writeSurface(textured.mesh, file("surface.vtp"), vtp));
    io::TexturedObjOptions obj;
    obj.materialLibrary = "surface.mtl";
    HS_TRY(io::writeTexturedObj(textured.mesh, textured.uv, file("surface.obj"), obj));
    return io::writeFileAtomically(file("surface.mtl"), "# hysteroscene material\nnewmtl organ\nKd 1 1 1\n"
                                                        "map_Kd albedo.png\nnorm normal.png\nmap_Pr roughness.png\n");
}

} // namespace hs::texture
