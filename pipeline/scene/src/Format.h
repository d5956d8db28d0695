#pragma once
/// Text helpers shared by the case reader, the checks and the summary (private to hs::scene).

#include "hs/scene/CaseSpec.h"

#include <string>
#include <string_view>

namespace hs::scene::detail {

/// Shortest text that reads back to the same double ("25", "0.47", "1e+300"); "nan"/"inf" for non-finite values.
std::string formatNumber(double value);
/// "18..80" (each bound through formatNumber).
std::string formatRange(const Range& range);
/// "\"text\"" with quotes and backslashes escaped, control characters as \uXXXX, long text cut at 60 bytes.
std::string quoteText(std::string_view text);
/// Deepest nesting of arrays and objects in JSON text, scanned before parsing so that "[[[[..." never reaches the
/// parser.
int nestingDepth(std::string_view text);
/// Escapes one reference token of a JSON pointer ("~" -> "~0", "/" -> "~1", RFC 6901).
std::string escapePointerToken(std::string_view token);

/// `"a", "b", "c"` for every value of an enumeration.
template <class E, std::size_t N>
std::string choiceList(const std::array<E, N>& values) {
    std::string text;
    for (std::size_t i = 0; i < N; ++i) {
        if (i)
            text += ", ";
        text += quoteText(toString(values[i]));
    }
    return text;
}

} // namespace hs::scene::detail
