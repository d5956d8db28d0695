#include "hs/texture/LibraryVersions.h"

#include <OpenImageIO/oiioversion.h>
#include <opencv2/core/version.hpp>

namespace hs::texture {

LibraryVersions libraryVersions() {
    return {
        {"opencv", CV_VERSION},
        {"openimageio", std::to_string(OIIO_VERSION_MAJOR) + "." + std::to_string(OIIO_VERSION_MINOR) + "." +
                            std::to_string(OIIO_VERSION_PATCH) + "." + std::to_string(OIIO_VERSION_TWEAK)},
    };
}

} // namespace hs::texture
