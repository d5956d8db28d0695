// The textured surface (the UV-split mesh) and the bake's folder; hs::io writes the files.
#include "hs/texture/Bake.h"
#include "hs/texture/ImageFiles.h"

#include "hs/io/AtomicFile.h"
#include "hs/io/MeshIO.h"
#include "hs/io/TexturedSurface.h"

#include <filesystem>
#include <string>
#include <system_error>

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
