#pragma once
/// The libraries hs::io owns, for the scene's record (VTK stays private to hs::io).

#include "hs/core/LibraryVersions.h"

namespace hs::io {

/// "vtk" -> VTK_VERSION of the headers this build compiled against.
LibraryVersions libraryVersions();

} // namespace hs::io
