#pragma once
/// The libraries hs::anatomy owns, for the scene's record (Eigen and HDF5 stay private to hs::anatomy).

#include "hs/core/LibraryVersions.h"

namespace hs::anatomy {

/// "eigen" (the shape model's linear algebra) and "hdf5" (the shape model file), from their version macros.
LibraryVersions libraryVersions();

} // namespace hs::anatomy
