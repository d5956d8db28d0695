#pragma once
/// A small PNG encoder and decoder for the package's maps and the textures embedded in surface.glb (private).
///
/// Encoding: 8-bit greyscale, RGB or RGBA, not interlaced, every row with filter 1 (Sub), one IDAT chunk
/// compressed by zlib at level 9, no ancillary chunks (no time stamp, no gamma): the same pixels give the same
/// bytes with the same zlib. Decoding accepts exactly that family (8-bit, colour types 0/2/6, any filter per row,
/// any number of IDAT chunks) and refuses everything else with Unsupported; it checks CRCs and sizes before it
/// allocates. The texture module's files (OpenImageIO) are the general image path; this one exists because the
/// package needs the PNG bytes in memory and bit for bit reproducible.

#include "hs/core/Image.h"
#include "hs/core/Result.h"

#include <string>
#include <string_view>

namespace hs::scene::detail {

[[nodiscard]] Result<std::string> encodePng(const ImageU8& image);
[[nodiscard]] Result<ImageU8> decodePng(std::string_view bytes, const std::string& sourceName, int maxSide);

} // namespace hs::scene::detail
