#pragma once
/// The libraries hs::texture owns, for the scene's record (OpenCV and OpenImageIO stay private to hs::texture).

#include "hs/core/LibraryVersions.h"

namespace hs::texture {

/// "opencv" (filtering and resampling in synthesis and baking) and "openimageio" (exemplar files), from their
/// version macros.
LibraryVersions libraryVersions();

} // namespace hs::texture
