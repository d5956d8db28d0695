#pragma once
/// The one writer of surfaces with texture coordinates: VTP through writeSurface (WriteOptions::textureCoordinates
/// and normals), Wavefront OBJ with vt lines here.

#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"

#include <array>
#include <string>
#include <vector>

namespace hs::io {

struct TexturedObjOptions {
    std::string comment = "hysteroscene textured surface"; ///< the first line, after "# "
    std::string materialLibrary; ///< when set: "mtllib <materialLibrary>" after the comment, "usemtl <material>"
    std::string material = "organ";
};

/// Wavefront OBJ text of `mesh` with one (u, v) per point, in OBJ's convention (v up from the image's bottom):
/// "v" lines with 17 significant digits, "vt" lines with 9 (both read back to the same numbers), "f a/a b/b c/c".
/// The caller checks that there is one uv per point.
std::string texturedObjText(const SurfaceMesh& mesh, const std::vector<std::array<float, 2>>& uv,
                            const TexturedObjOptions& options = {});

/// Writes texturedObjText atomically; InvalidInput on an invalid mesh or a uv count other than the point count.
Status writeTexturedObj(const SurfaceMesh& mesh, const std::vector<std::array<float, 2>>& uv, const std::string& path,
                        const TexturedObjOptions& options = {});

} // namespace hs::io
