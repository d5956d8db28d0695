#pragma once
/// Versions of the libraries a build uses, as their version macros state them when it is compiled. A module that
/// owns a library reports it through its own `libraryVersions()` (hs::io: VTK, hs::anatomy: Eigen and HDF5, ...), so
/// no module includes another's third-party headers; the scene records them all (scene.json, manifest.json).

#include <map>
#include <string>

namespace hs {

/// Library name (lower case, "vtk") -> version ("9.1.0"), sorted by name.
using LibraryVersions = std::map<std::string, std::string>;

/// The compiler that built this library: "gcc 12.2.0" or "clang 14.0.6" (from its predefined macros).
std::string compilerVersion();

} // namespace hs
