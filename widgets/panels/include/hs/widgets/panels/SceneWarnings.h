#pragma once
/// A scene's warnings as a supervisor reads them: each warning's text with what it means for the training scene, by
/// the stage that wrote it (the text before its first ": ", docs/scene-format.md): "pathology", "merge", "meshing",
/// "descriptors", "measurement", "seating", "hydrometra", "simulation", "texture" and the mesh bars "mesh-...".

#include <QString>

#include <string>
#include <vector>

namespace hs::widgets {

/// What a warning means for the scene (translated); a pointer to the documentation for a source it does not know.
QString warningMeaning(const std::string& warning);

/// The warnings as an HTML list, each with its meaning beneath it; empty for none.
QString warningsHtml(const std::vector<std::string>& warnings);

} // namespace hs::widgets
