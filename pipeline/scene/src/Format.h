#pragma once
/// The text helpers of hs/scene/JsonText.h under the names the scene sources use.

#include "hs/scene/JsonText.h"

namespace hs::scene::detail {

using scene::choiceList;
using scene::escapePointerToken;
using scene::formatNumber;
using scene::formatRange;
using scene::quoteText;

} // namespace hs::scene::detail
