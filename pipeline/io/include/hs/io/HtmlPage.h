#pragma once
/// Pieces of the project's self-contained HTML pages (the batch report, the simulator's trial report): text escaping,
/// inlined data, and plots drawn by Chart.js inlined from Debian's libjs-chart.js. A page that uses chartScripts()
/// sets `data-charts` on its body to the number of charts once they are drawn, or `data-chart-error` to the script's
/// error: headless checks read that from the DOM.
///
/// This header uses nlohmann-json (header-only); a target that includes it links nlohmann_json::nlohmann_json.

#include "hs/core/Result.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <string_view>

namespace hs::io {

/// Where Debian's libjs-chart.js puts the library (its UMD build).
inline constexpr std::string_view kDefaultChartLibrary = "/usr/share/javascript/chart.js/chart.min.js";

/// `text` with & < > " ' escaped, for HTML text and attribute values.
std::string htmlEscape(std::string_view text);
/// RFC 4648 base64 (data URIs).
std::string base64(std::string_view bytes);
/// `text` safe inside a <script> element: every "</" becomes "<\/".
std::string scriptSafe(std::string text);
/// printf's "%.*f".
std::string fixedText(double value, int decimals);

/// Reads the chart library (at most 16 MB); NotFound naming the file when it is missing.
[[nodiscard]] Result<std::string> readChartLibrary(const std::string& path = std::string(kDefaultChartLibrary));

/// The canvas of chart `index` (the `index`th configuration given to chartScripts), in a div of class `cssClass`.
std::string chartCanvas(std::size_t index, std::string_view cssClass = "chart");
/// Options shared by every chart: drawn at once (no animation: a page is a record, and headless checks read it
/// straight away), filling its box, `title` on top.
nlohmann::ordered_json chartOptions(const std::string& title);
/// The `index`th colour of the pages' palette, as "rgba(r, g, b, alpha)".
std::string chartColour(std::size_t index, double alpha = 0.85);
/// Two <script> elements: `library`, then one that draws a Chart per element of `configs` (a JSON array of Chart.js
/// configurations: type, data, options) on canvases chart-0 .. chart-N-1 and sets the body's data-charts, or
/// data-chart-error. Empty when `library` is empty (no plots).
std::string chartScripts(const std::string& library, const nlohmann::ordered_json& configs);

} // namespace hs::io
