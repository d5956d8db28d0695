// The compiler's own version macros; clang defines __GNUC__ too, so it is tested first.

#include "hs/core/LibraryVersions.h"

namespace hs {

std::string compilerVersion() {
#if defined(__clang__)
    return "clang " + std::to_string(__clang_major__) + "." + std::to_string(__clang_minor__) + "." +
           std::to_string(__clang_patchlevel__);
#elif defined(__GNUC__)
    return "gcc " + std::to_string(__GNUC__) + "." + std::to_string(__GNUC_MINOR__) + "." +
           std::to_string(__GNUC_PATCHLEVEL__);
#else
#error "compilerVersion() knows gcc and clang only"
#endif
}

} // namespace hs
