// The textured surface on disk: UV-split mesh as VTK XML PolyData and Wavefront OBJ, and the bake's folder.
#include "hs/texture/Bake.h"
#include "hs/texture/ImageFiles.h"

#include "hs/io/AtomicFile.h"

#include <charconv>
#include <filesystem>
#include <string>
#include <system_error>

namespace hs::texture {
namespace {

/// Shortest round-trip text of a number, independent of the locale.
template <class T>
void append(std::string& out, T value) {
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof buf, value);
    out.append(buf, res.ptr);
}

void appendIntArray(std::string& out, const std::string& name, const std::vector<std::int32_t>& values) {
    out += "        <DataArray type=\"Int32\" Name=\"" + name + "\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < values.size(); ++i) {
        append(out, values[i]);
        out += (i % 16 == 15 || i + 1 == values.size()) ? '\n' : ' ';
    }
    out += "        </DataArray>\n";
}

bool validLabelName(const std::string& name) {
    if (name.empty() || name.size() > 64)
        return false;
    for (char c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
            return false;
    return true;
}

} // namespace

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

Status writeTexturedVtp(const TexturedSurface& s, const std::string& path) {
    HS_TRY(validate(s.mesh));
    if (s.uv.size() != s.mesh.points.size())
        return fail(ErrorCode::InvalidInput, path + ": " + std::to_string(s.uv.size()) + " UVs for " +
                                                 std::to_string(s.mesh.points.size()) + " points");
    for (const auto* labels : {&s.mesh.faceLabels, &s.mesh.vertexLabels})
        for (const auto& entry : *labels)
            if (!validLabelName(entry.first) || entry.first == "uv" || entry.first == "normals")
                return fail(ErrorCode::InvalidInput,
                            path + ": label name '" + entry.first + "' must be 1-64 characters of A-Z a-z 0-9 _ - .");
    std::string out;
    out.reserve(s.mesh.points.size() * 60 + s.mesh.triangles.size() * 40);
    out += "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <PolyData>\n    <Piece NumberOfPoints=\"";
    append(out, s.mesh.points.size());
    out += "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"";
    append(out, s.mesh.triangles.size());
    const bool withNormals = s.normals.size() == s.mesh.points.size();
    out += withNormals ? "\">\n      <PointData TCoords=\"uv\" Normals=\"normals\">\n"
                       : "\">\n      <PointData TCoords=\"uv\">\n";
    out += "        <DataArray type=\"Float32\" Name=\"uv\" NumberOfComponents=\"2\" format=\"ascii\">\n";
    for (const auto& q : s.uv) {
        append(out, q[0]);
        out += ' ';
        append(out, q[1]);
        out += '\n';
    }
    out += "        </DataArray>\n";
    if (withNormals) {
        out += "        <DataArray type=\"Float32\" Name=\"normals\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const Vec3& n : s.normals) {
            append(out, static_cast<float>(n.x));
            out += ' ';
            append(out, static_cast<float>(n.y));
            out += ' ';
            append(out, static_cast<float>(n.z));
            out += '\n';
        }
        out += "        </DataArray>\n";
    }
    for (const auto& [name, values] : s.mesh.vertexLabels)
        if (values.size() == s.mesh.points.size())
            appendIntArray(out, name, values);
    out += "      </PointData>\n      <CellData>\n";
    for (const auto& [name, values] : s.mesh.faceLabels)
        if (values.size() == s.mesh.triangles.size())
            appendIntArray(out, name, values);
    out += "      </CellData>\n      <Points>\n"
           "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const Vec3& p : s.mesh.points) {
        append(out, p.x);
        out += ' ';
        append(out, p.y);
        out += ' ';
        append(out, p.z);
        out += '\n';
    }
    out += "        </DataArray>\n      </Points>\n      <Polys>\n"
           "        <DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto& t : s.mesh.triangles) {
        append(out, t[0]);
        out += ' ';
        append(out, t[1]);
        out += ' ';
        append(out, t[2]);
        out += '\n';
    }
    out += "        </DataArray>\n        <DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < s.mesh.triangles.size(); ++i) {
        append(out, 3 * (i + 1));
        out += (i % 16 == 15 || i + 1 == s.mesh.triangles.size()) ? '\n' : ' ';
    }
    out += "        </DataArray>\n      </Polys>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
    return io::writeFileAtomically(path, out);
}

Status writeTexturedObj(const TexturedSurface& s, const std::string& path, const std::string& mtlName) {
    HS_TRY(validate(s.mesh));
    std::string out = "# hysteroscene textured surface\nmtllib " + mtlName + "\n";
    for (const Vec3& p : s.mesh.points) {
        out += "v ";
        append(out, p.x);
        out += ' ';
        append(out, p.y);
        out += ' ';
        append(out, p.z);
        out += '\n';
    }
    for (const auto& q : s.uv) {
        out += "vt ";
        append(out, q[0]);
        out += ' ';
        append(out, q[1]);
        out += '\n';
    }
    out += "usemtl organ\n";
    for (const auto& t : s.mesh.triangles) {
        out += 'f';
        for (std::int32_t i : t) {
            out += ' ';
            append(out, i + 1);
            out += '/';
            append(out, i + 1);
        }
        out += '\n';
    }
    return io::writeFileAtomically(path, out);
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
    HS_TRY(writeTexturedVtp(textured, file("surface.vtp")));
    HS_TRY(writeTexturedObj(textured, file("surface.obj"), "surface.mtl"));
    return io::writeFileAtomically(file("surface.mtl"), "# hysteroscene material\nnewmtl organ\nKd 1 1 1\n"
                                                        "map_Kd albedo.png\nnorm normal.png\nmap_Pr roughness.png\n");
}

} // namespace hs::texture
