#pragma once
#include "hs/core/SurfaceMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace hs::texture::detail {

/// Per face, the face across each edge k (corners k, k+1); -1 on boundary and non-manifold edges.
std::vector<std::array<std::int32_t, 3>> faceNeighbours(const SurfaceMesh& mesh);

} // namespace hs::texture::detail
