#include "hs/io/LibraryVersions.h"

#include <vtkVersionMacros.h>

namespace hs::io {

LibraryVersions libraryVersions() {
    return {{"vtk", VTK_VERSION}};
}

} // namespace hs::io
