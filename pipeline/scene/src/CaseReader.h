#pragma once
/// JSON (current schema version) -> CaseSpec: structure, types and field names only; value rules are checkCase()'s.

#include "hs/scene/CaseSpec.h"

#include <nlohmann/json.hpp>

#include <vector>

namespace hs::scene::detail {

/// Fills `spec` from `root` (an object already upgraded to the current version). Absent fields keep their
/// defaults; problems (wrong type, unknown field, missing required field, unknown choice) go to `issues` in
/// document order, and the field keeps its default.
void readCase(const nlohmann::json& root, CaseSpec& spec, std::vector<CaseIssue>& issues);

} // namespace hs::scene::detail
