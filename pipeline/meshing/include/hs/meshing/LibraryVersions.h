#pragma once
/// The libraries hs::meshing owns, for the scene's record (CGAL stays private to hs::meshing). The optional
/// baselines report theirs through meshing::methodLibraryVersions (BaselineMeshers.h).

#include "hs/core/LibraryVersions.h"

namespace hs::meshing {

/// "cgal" (the Delaunay tetrahedralisation of the particles), CGAL_VERSION_STR.
LibraryVersions libraryVersions();

} // namespace hs::meshing
