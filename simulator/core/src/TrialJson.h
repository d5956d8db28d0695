#pragma once
// The trial header's JSON members and their checks, shared by trial files (Trial.cpp) and the reports that repeat
// the header (ReportRead.cpp). Internal to hs::sim.
#include "hs/core/Result.h"
#include "hs/scene/JsonText.h"
#include "hs/sim/Trial.h"

#include <string>

namespace hs::sim::detail {

/// Reads the header's members (sceneSha256, seed, physics, exercise, scope, fluid, device, startedUtc) from `root`,
/// recording an issue at each bad or missing one. The caller reads its own members and calls root.finish().
void readHeaderMembers(scene::ObjectReader& root, TrialHeader& h);
/// InvalidInput naming `name`, the field and its range.
[[nodiscard]] Status checkHeader(const TrialHeader& h, const std::string& name);

} // namespace hs::sim::detail
