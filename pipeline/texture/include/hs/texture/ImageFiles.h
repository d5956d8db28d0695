#pragma once
/// Reading and writing texture images (PNG, JPEG, EXR, and what else OpenImageIO reads) as hs::Image.
///
/// Every image file is untrusted: the reader checks the header's size against the limits before it allocates, and
/// fails with an Error naming the file and the allowed range. Writers go through a temporary file that is renamed into
/// place, and write no time stamps, so the same pixels give the same bytes.

#include "hs/core/Image.h"
#include "hs/core/Result.h"

#include <string>

namespace hs::texture {

struct ImageReadLimits {
    int maxSide = 8192; ///< pixels per side
    int minSide = 1;    ///< pixels per side
};

/// Reads an image as 8-bit RGB: grey is replicated, an opaque alpha dropped, 16-bit and float samples are clamped to
/// [0, 1] and scaled to 0..255 (no colour-space conversion: an EXR is taken as display-referred). Refused by name: an
/// image with any transparent pixel (alpha below 1: it has no colour there), an embedded colour profile that is not
/// sRGB (nothing converts it; no profile is read as sRGB), more than 4 channels.
Result<ImageU8> readImageRgb8(const std::string& path, const ImageReadLimits& limits = {});

/// Writes an 8-bit image (1, 3 or 4 channels) in the format of the file's extension (.png, .jpg/.jpeg, .exr, .tif),
/// atomically. EXR stores half floats in [0, 1].
Status writeImage(const ImageU8& image, const std::string& path);

} // namespace hs::texture
