#pragma once
/// surface.glb: the visual surface as glTF 2.0 binary with embedded PNG textures and a PBR metallic-roughness
/// material (private to hs::scene; tinygltf stays inside Gltf.cpp).

#include "hs/core/Result.h"
#include "hs/scene/Scene.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hs::scene::detail {

/// The embedded textures, already encoded as PNG (the same bytes as the package's maps, except the
/// metallic-roughness texture, which glTF wants with roughness in G and metalness in B).
struct GltfTextures {
    std::string albedoPng;            ///< empty: no base colour texture
    std::string normalPng;            ///< empty: no normal texture
    std::string metallicRoughnessPng; ///< empty: no metallic-roughness texture
};

/// The GLB bytes. Positions are converted from mm to metres (glTF's unit); normals are area-weighted vertex
/// normals; indices are 32-bit. Deterministic.
[[nodiscard]] Result<std::string> encodeGlb(const VisualSurface& surface, const GltfTextures& textures,
                                            const std::string& generator);

/// What the reader needs back from a GLB: the first primitive's positions (mm), triangles and TEXCOORD_0.
struct GlbSurface {
    std::vector<Vec3> points;
    std::vector<Triangle> triangles;
    std::vector<std::array<float, 2>> uvs;
};
/// Parses GLB bytes without touching the file system or decoding images. Errors name `sourceName`.
[[nodiscard]] Result<GlbSurface> decodeGlb(std::string_view bytes, const std::string& sourceName);

} // namespace hs::scene::detail
