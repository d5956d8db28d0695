#pragma once
/// Reading and writing surface and tetrahedral meshes. Every file is untrusted input: readers validate sizes,
/// counts, indices and coordinates, and fail with an Error naming the file and the problem; writers write to a
/// temporary name in the same folder and rename it into place, so a failed write never leaves a half file.

#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/TetMesh.h"

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace hs::io {

enum class MeshFormat {
    Obj,     ///< Wavefront OBJ (surface)
    Stl,     ///< STL, ASCII or binary (surface; binary when written unless asked otherwise)
    Ply,     ///< Stanford PLY, ASCII or binary (surface)
    Off,     ///< Object File Format (surface)
    Vtp,     ///< VTK XML PolyData (surface, with labels as cell/point data)
    Vtu,     ///< VTK XML UnstructuredGrid (tetrahedra, with region ids and labels)
    GmshMsh, ///< Gmsh MSH 4.1 ASCII (tetrahedra; physical tags = region ids)
    Medit,   ///< MEDIT .mesh (tetrahedra; references = region ids)
};

/// Lower-case name ("obj", "stl", ..., "msh", "mesh").
std::string formatName(MeshFormat format);
/// The format for a file name's extension (case-insensitive); InvalidInput (listing the known ones) otherwise.
Result<MeshFormat> formatFromPath(const std::string& path);
bool isSurfaceFormat(MeshFormat format);
bool isTetFormat(MeshFormat format);
/// Every extension the readers accept (".obj", ...), for file dialogs and help texts.
std::vector<std::string> supportedExtensions();

/// Limits that keep a hostile file from exhausting memory. Defaults are far above any scene this project makes.
struct ReadLimits {
    std::int64_t maxPoints = 50'000'000;       ///< points (vertices) per file
    std::int64_t maxCells = 200'000'000;       ///< triangles or tetrahedra per file
    std::int64_t maxFileBytes = 8'000'000'000; ///< 8 GB
};

/// A floating-point array with one tuple of `components` values per point, row-major (VTP point data).
struct PointArray {
    int components = 1; ///< 1..9
    std::vector<double> values;
};
using PointArrays = std::map<std::string, PointArray>;

struct WriteOptions {
    bool binary = true; ///< STL/PLY binary, VTP/VTU appended raw (false: ASCII everywhere the format allows)
    /// VTP/VTU binary: the appended data compressed with zlib (VTK's compressor, level 5; VTK, ParaView and meshio
    /// inflate it). Deterministic: the same mesh gives the same bytes.
    bool compress = true;
    /// VTP only: one (u, v) per point, written as the active texture coordinates "uv" (the other formats ignore it).
    /// A count other than the point count is an InvalidInput error.
    const std::vector<std::array<float, 2>>* textureCoordinates = nullptr;
    /// VTP only: the texture coordinates have their origin at the image's top left (glTF's and the scene's
    /// convention); they are written with VTK's bottom-left origin, (u, 1 - v), in Float64, where the flip is exact:
    /// 1 - (1 - v) gives back the same float v (for v = 0 and every v >= 2^-29).
    bool textureOriginTopLeft = false;
    /// VTP only: one normal per point, written as the active normals "normals" (Float32). A count other than the
    /// point count is an InvalidInput error, and so is a label named "uv" or "normals" next to either array.
    const std::vector<Vec3>* normals = nullptr;
    /// VTP only: further point arrays, written as Float64 point data. Names follow the label rules and may not be
    /// taken by a label, "uv" or "normals"; a size other than points x components, a component count outside 1..9
    /// or a non-finite value is an InvalidInput error.
    const PointArrays* pointArrays = nullptr;
};

/// Reads a surface in any surface format (chosen by extension). Polygons are fan-triangulated. Labels read where the
/// format carries them (VTP cell/point arrays of integer type, PLY int properties). A VTU holding only surface cells
/// is read as a surface too. A file without triangles is an InvalidInput error. docs/file-formats.md lists what each
/// format keeps.
Result<SurfaceMesh> readSurface(const std::string& path, const ReadLimits& limits = {});
/// A VTP surface and its floating-point point arrays (every point array of a non-integer type with 1..9 components,
/// "uv" and "normals" included) in `arrays`. A non-finite value is an InvalidInput error naming the array; any
/// other format is an InvalidInput error.
Result<SurfaceMesh> readSurfaceWithArrays(const std::string& path, PointArrays& arrays, const ReadLimits& limits = {});
/// Writes a surface; the format is chosen by extension (".vtu" writes triangle cells). Refuses (InvalidInput) a mesh
/// that fails hs::validate, has no triangles, or has label names outside 1-64 characters of A-Z a-z 0-9 _ - .
Status writeSurface(const SurfaceMesh& mesh, const std::string& path, const WriteOptions& options = {});

/// Reads a tetrahedral mesh (VTU, MSH 4.1, MEDIT). Non-tetrahedral volume cells are an InvalidInput error;
/// surface cells in MSH/MEDIT files are ignored.
Result<TetMesh> readTetMesh(const std::string& path, const ReadLimits& limits = {});
/// Writes a tetrahedral mesh (VTU, MSH 4.1, MEDIT); refuses invalid or empty meshes like writeSurface.
Status writeTetMesh(const TetMesh& mesh, const std::string& path, const WriteOptions& options = {});

/// Either kind of mesh, for tools that accept both (the CLI's info/convert, the workstation's Open).
using AnyMesh = std::variant<SurfaceMesh, TetMesh>;
/// Reads a file of any supported format: VTU with tetrahedra gives a TetMesh, VTU with only triangles a
/// SurfaceMesh.
Result<AnyMesh> readMesh(const std::string& path, const ReadLimits& limits = {});

} // namespace hs::io
