#include "hs/io/MeshIO.h"

#include "Formats.h"
#include "Parsing.h"
#include "hs/io/AtomicFile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace hs::io {
namespace {

struct FormatEntry {
    MeshFormat format;
    const char* name;
    const char* extension;
};

constexpr FormatEntry kFormats[] = {
    {MeshFormat::Obj, "obj", ".obj"},     {MeshFormat::Stl, "stl", ".stl"},     {MeshFormat::Ply, "ply", ".ply"},
    {MeshFormat::Off, "off", ".off"},     {MeshFormat::Vtp, "vtp", ".vtp"},     {MeshFormat::Vtu, "vtu", ".vtu"},
    {MeshFormat::GmshMsh, "msh", ".msh"}, {MeshFormat::Medit, "mesh", ".mesh"},
};

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

} // namespace

std::string formatName(MeshFormat format) {
    for (const auto& entry : kFormats)
        if (entry.format == format)
            return entry.name;
    return "unknown";
}

Result<MeshFormat> formatFromPath(const std::string& path) {
    const std::string ext = lowerExtension(path);
    for (const auto& entry : kFormats)
        if (ext == entry.extension)
            return entry.format;
    std::string known;
    for (const auto& entry : kFormats)
        known += std::string(known.empty() ? "" : ", ") + entry.extension;
    return fail(ErrorCode::InvalidInput, path + ": unknown mesh file extension '" + ext + "' (known: " + known + ")");
}

bool isSurfaceFormat(MeshFormat format) {
    return format == MeshFormat::Obj || format == MeshFormat::Stl || format == MeshFormat::Ply ||
           format == MeshFormat::Off || format == MeshFormat::Vtp;
}

bool isTetFormat(MeshFormat format) {
    return format == MeshFormat::Vtu || format == MeshFormat::GmshMsh || format == MeshFormat::Medit;
}

std::vector<std::string> supportedExtensions() {
    std::vector<std::string> out;
    for (const auto& entry : kFormats)
        out.emplace_back(entry.extension);
    return out;
}

Result<AnyMesh> readMesh(const std::string& path, const ReadLimits& limits) {
    const Result<MeshFormat> format = formatFromPath(path);
    if (!format.ok())
        return format.failure();
    auto wrap = [](auto result) -> Result<AnyMesh> {
        if (!result.ok())
            return result.failure();
        return AnyMesh(std::move(result).value());
    };
    switch (*format) {
    case MeshFormat::Obj:
        return wrap(detail::readObj(path, limits));
    case MeshFormat::Stl:
        return wrap(detail::readStl(path, limits));
    case MeshFormat::Ply:
        return wrap(detail::readPly(path, limits));
    case MeshFormat::Off:
        return wrap(detail::readOff(path, limits));
    case MeshFormat::Vtp:
        return wrap(detail::readVtp(path, limits));
    case MeshFormat::Vtu:
        return detail::readVtu(path, limits);
    case MeshFormat::GmshMsh:
        return wrap(detail::readGmsh(path, limits));
    case MeshFormat::Medit:
        return wrap(detail::readMedit(path, limits));
    }
    return fail(ErrorCode::Internal, path + ": unhandled format");
}

Result<SurfaceMesh> readSurface(const std::string& path, const ReadLimits& limits) {
    const Result<MeshFormat> format = formatFromPath(path);
    if (!format.ok())
        return format.failure();
    if (*format == MeshFormat::GmshMsh || *format == MeshFormat::Medit)
        return fail(ErrorCode::InvalidInput, path + ": " + formatName(*format) +
                                                 " holds a tetrahedral mesh, not a surface (read it with readTetMesh)");
    Result<AnyMesh> mesh = readMesh(path, limits);
    if (!mesh.ok())
        return mesh.failure();
    if (auto* surface = std::get_if<SurfaceMesh>(&*mesh))
        return std::move(*surface);
    return fail(ErrorCode::InvalidInput, path + ": holds tetrahedra, not a surface (read it with readTetMesh)");
}

Result<SurfaceMesh> readSurfaceWithArrays(const std::string& path, PointArrays& arrays, const ReadLimits& limits) {
    const Result<MeshFormat> format = formatFromPath(path);
    if (!format.ok())
        return format.failure();
    if (*format != MeshFormat::Vtp)
        return fail(ErrorCode::InvalidInput, path + ": point arrays are read from VTP files only");
    arrays.clear();
    return detail::readVtp(path, limits, &arrays);
}

Result<TetMesh> readTetMesh(const std::string& path, const ReadLimits& limits) {
    const Result<MeshFormat> format = formatFromPath(path);
    if (!format.ok())
        return format.failure();
    if (!isTetFormat(*format))
        return fail(ErrorCode::InvalidInput,
                    path + ": " + formatName(*format) + " holds a surface, not a tetrahedral mesh");
    Result<AnyMesh> mesh = readMesh(path, limits);
    if (!mesh.ok())
        return mesh.failure();
    if (auto* tets = std::get_if<TetMesh>(&*mesh))
        return std::move(*tets);
    return fail(ErrorCode::InvalidInput, path + ": holds only surface cells, no tetrahedra");
}

Status writeSurface(const SurfaceMesh& mesh, const std::string& path, const WriteOptions& options) {
    const Result<MeshFormat> format = formatFromPath(path);
    if (!format.ok())
        return format.failure();
    if (*format == MeshFormat::GmshMsh || *format == MeshFormat::Medit)
        return fail(ErrorCode::InvalidInput, path + ": " + formatName(*format) +
                                                 " stores tetrahedral meshes; a surface cannot be written to it");
    HS_TRY(detail::checkWritable(mesh, path));
    if (options.textureCoordinates && options.textureCoordinates->size() != mesh.points.size())
        return fail(ErrorCode::InvalidInput, path + ": " + std::to_string(options.textureCoordinates->size()) +
                                                 " texture coordinates for " + std::to_string(mesh.points.size()) +
                                                 " points");
    if (options.normals && options.normals->size() != mesh.points.size())
        return fail(ErrorCode::InvalidInput, path + ": " + std::to_string(options.normals->size()) + " normals for " +
                                                 std::to_string(mesh.points.size()) + " points");
    if (options.pointArrays)
        for (const auto& [name, array] : *options.pointArrays) {
            if (!detail::isPortableName(name) || name == "uv" || name == "normals" || mesh.faceLabels.count(name) ||
                mesh.vertexLabels.count(name))
                return fail(ErrorCode::InvalidInput,
                            path + ": point array name '" + name + "' is not a valid label name or is taken");
            if (array.components < 1 || array.components > 9 ||
                array.values.size() != mesh.points.size() * static_cast<std::size_t>(array.components))
                return fail(ErrorCode::InvalidInput, path + ": point array '" + name + "' has " +
                                                         std::to_string(array.values.size()) + " values for " +
                                                         std::to_string(mesh.points.size()) + " points x " +
                                                         std::to_string(array.components) + " components (1..9)");
            for (double v : array.values)
                if (!std::isfinite(v))
                    return fail(ErrorCode::InvalidInput, path + ": point array '" + name + "' has a non-finite value");
        }
    if (options.textureCoordinates || options.normals)
        for (const auto* labels : {&mesh.faceLabels, &mesh.vertexLabels})
            for (const char* reserved : {"uv", "normals"})
                if (labels->count(reserved))
                    return fail(ErrorCode::InvalidInput, path + ": label name '" + reserved +
                                                             "' is taken by the texture coordinates and normals");
    const MeshFormat f = *format;
    return writeAtomically(path, [&](const std::string& tmpPath) -> Status {
        switch (f) {
        case MeshFormat::Obj:
            return detail::writeObj(mesh, tmpPath);
        case MeshFormat::Stl:
            return detail::writeStl(mesh, tmpPath, options.binary);
        case MeshFormat::Ply:
            return detail::writePly(mesh, tmpPath, options.binary);
        case MeshFormat::Off:
            return detail::writeOff(mesh, tmpPath);
        case MeshFormat::Vtp:
            return detail::writeVtp(mesh, tmpPath, options);
        case MeshFormat::Vtu:
            return detail::writeVtuSurface(mesh, tmpPath, options);
        case MeshFormat::GmshMsh:
        case MeshFormat::Medit:
            break;
        }
        return fail(ErrorCode::Internal, path + ": unhandled format");
    });
}

Status writeTetMesh(const TetMesh& mesh, const std::string& path, const WriteOptions& options) {
    const Result<MeshFormat> format = formatFromPath(path);
    if (!format.ok())
        return format.failure();
    if (!isTetFormat(*format))
        return fail(ErrorCode::InvalidInput, path + ": " + formatName(*format) +
                                                 " stores surfaces; write the boundary (hs::extractBoundary) instead");
    HS_TRY(detail::checkWritable(mesh, path));
    const MeshFormat f = *format;
    return writeAtomically(path, [&](const std::string& tmpPath) -> Status {
        switch (f) {
        case MeshFormat::Vtu:
            return detail::writeVtu(mesh, tmpPath, options);
        case MeshFormat::GmshMsh:
            return detail::writeGmsh(mesh, tmpPath);
        case MeshFormat::Medit:
            return detail::writeMedit(mesh, tmpPath);
        default:
            break;
        }
        return fail(ErrorCode::Internal, path + ": unhandled format");
    });
}

} // namespace hs::io
