// Shared pieces of the self-contained HTML pages: escaping, base64, the inlined chart library and its driver script.
#include "hs/io/HtmlPage.h"

#include "hs/io/AtomicFile.h"

#include <cstdio>

namespace hs::io {

namespace {

/// Chart.js 3's UMD build is about 200 kB; anything far larger is not the library.
constexpr std::int64_t kMaxChartLibraryBytes = 16 * 1024 * 1024;

} // namespace

std::string htmlEscape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char ch : text) {
        switch (ch) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        case '\'':
            out += "&#39;";
            break;
        default:
            out += ch;
        }
    }
    return out;
}

std::string base64(std::string_view bytes) {
    static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const auto byte = [&bytes](std::size_t i) { return static_cast<unsigned>(static_cast<unsigned char>(bytes[i])); };
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned n = (byte(i) << 16) | (byte(i + 1) << 8) | byte(i + 2);
        for (int shift : {18, 12, 6, 0})
            out += kAlphabet[(n >> shift) & 63u];
    }
    if (i < bytes.size()) {
        unsigned n = byte(i) << 16;
        if (i + 1 < bytes.size())
            n |= byte(i + 1) << 8;
        out += kAlphabet[(n >> 18) & 63u];
        out += kAlphabet[(n >> 12) & 63u];
        out += i + 1 < bytes.size() ? kAlphabet[(n >> 6) & 63u] : '=';
        out += '=';
    }
    return out;
}

std::string scriptSafe(std::string text) {
    for (std::size_t at = 0; (at = text.find("</", at)) != std::string::npos; at += 3)
        text.replace(at, 2, "<\\/");
    return text;
}

std::string fixedText(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

Result<std::string> readChartLibrary(const std::string& path) {
    return readFile(path, kMaxChartLibraryBytes);
}

std::string chartCanvas(std::size_t index, std::string_view cssClass) {
    return "<div class=\"" + htmlEscape(cssClass) + "\"><canvas id=\"chart-" + std::to_string(index) +
           "\"></canvas></div>\n";
}

nlohmann::ordered_json chartOptions(const std::string& title) {
    return {{"animation", false},
            {"responsive", true},
            {"maintainAspectRatio", false},
            {"plugins", {{"title", {{"display", true}, {"text", title}}}}}};
}

std::string chartColour(std::size_t index, double alpha) {
    static const int kPalette[][3] = {{54, 110, 170}, {150, 150, 150}, {190, 40, 70}, {60, 150, 80}, {220, 140, 30}};
    const int* c = kPalette[index % (sizeof kPalette / sizeof kPalette[0])];
    return "rgba(" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) + ", " +
           fixedText(alpha, 2) + ")";
}

std::string chartScripts(const std::string& library, const nlohmann::ordered_json& configs) {
    if (library.empty())
        return {};
    return "<script>\n" + scriptSafe(library) +
           "\n</script>\n<script>\nconst chartConfigs = " + scriptSafe(configs.dump(-1, ' ', true)) + ";\n" +
           R"(try {
  chartConfigs.forEach((config, i) => new Chart(document.getElementById('chart-' + i), config));
  document.body.dataset.charts = String(chartConfigs.length);
} catch (e) {
  document.body.dataset.chartError = String(e);
}
</script>
)";
}

} // namespace hs::io
