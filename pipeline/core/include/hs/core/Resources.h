#pragma once
/// Finding the files that ship in resources/ (default model, default case, exemplars).

#include <string>

namespace hs {

/// The resources folder: $HS_RESOURCES_DIR when set; else <executable>/../share/hysteroscene/resources when it
/// exists (an installed tree); else the source tree's resources/ (a build tree).
std::string resourcesDir();

/// `relative` inside resourcesDir() ("models/uterus-default.h5").
std::string resourcePath(const std::string& relative);

} // namespace hs
