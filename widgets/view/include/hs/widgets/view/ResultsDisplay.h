#pragma once
/// What the workstation's 3-D view shows of the pipeline's results: the furthest stage there is. The organ as the
/// shape model made it; then the displaced organ with the grown pathologies; then the merged body (one colour per
/// region); then the tetrahedral mesh with its tissues (myometrium, endometrium, cervix, each pathology); then the
/// textured visual surface.

#include "hs/core/SurfaceMesh.h"
#include "hs/generate/Generate.h"

#include <optional>
#include <utility>
#include <vector>

namespace hs::widgets {

class MeshDisplay;

enum class ResultLayer { None, Organ, Pathologies, Body, Tissues, Textured };

/// One surface of several, each part's faces labelled "region" with its region id.
SurfaceMesh combineRegions(const std::vector<std::pair<const SurfaceMesh*, int>>& parts);

/// Which layers `results` can show, furthest first is the default choice.
bool hasLayer(const generate::Generated& results, ResultLayer layer);

/// Shows `layer` of `results` (by default the furthest there is; the organ alone to click on its wall) and says which
/// it showed; None when there is nothing to show (the display is then left as it was).
ResultLayer showResults(MeshDisplay& display, const generate::Generated& results,
                        std::optional<ResultLayer> layer = std::nullopt);

} // namespace hs::widgets
