#include "hs/anatomy/LibraryVersions.h"

#include <Eigen/Core>
#include <H5public.h>

namespace hs::anatomy {

LibraryVersions libraryVersions() {
    return {
        {"eigen", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
                      std::to_string(EIGEN_MINOR_VERSION)},
        {"hdf5",
         std::to_string(H5_VERS_MAJOR) + "." + std::to_string(H5_VERS_MINOR) + "." + std::to_string(H5_VERS_RELEASE)},
    };
}

} // namespace hs::anatomy
