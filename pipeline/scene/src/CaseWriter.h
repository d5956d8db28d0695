#pragma once
/// CaseSpec -> JSON (current schema version), the inverse of readCase().

#include "hs/scene/CaseSpec.h"

#include <nlohmann/json.hpp>

namespace hs::scene::detail {

/// The document for `spec`, fields in schema order.
nlohmann::ordered_json writeCase(const CaseSpec& spec);

} // namespace hs::scene::detail
