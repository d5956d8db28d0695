#include "hs/meshing/LibraryVersions.h"

#include <CGAL/version_macros.h>

namespace hs::meshing {

LibraryVersions libraryVersions() {
    return {{"cgal", CGAL_VERSION_STR}};
}

} // namespace hs::meshing
