// writeBatchReport: the CSV table and the self-contained HTML page of a batch.
#include "hs/batch/Report.h"

#include "hs/batch/Curriculum.h"
#include "hs/batch/JobStatus.h"
#include "hs/io/AtomicFile.h"
#include "hs/io/HtmlPage.h"
#include "hs/io/MeshIO.h"
#include "hs/scene/JsonText.h"
#include "hs/texture/ImageFiles.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <unistd.h>

namespace hs::batch {

namespace {

namespace fs = std::filesystem;
using io::htmlEscape;
using nlohmann::ordered_json;

constexpr int kHistogramBins = 10;
/// A package's visual surface is a few MB; larger ones are not drawn.
constexpr std::int64_t kMaxThumbnailSurfaceBytes = 256 * 1024 * 1024;

struct Row {
    const Job* job = nullptr;
    std::string templateName;
    std::optional<scene::CaseSpec> spec;
    std::optional<StatusRecord> record;
    std::string problem;   ///< an unreadable case or record
    std::string thumbnail; ///< data URI, or empty
};

/// "polyp-0003-v01" -> "polyp".
std::string templateOf(const std::string& job) {
    const auto variant = job.rfind('-');
    const auto caseAt = variant == std::string::npos || variant == 0 ? std::string::npos : job.rfind('-', variant - 1);
    return caseAt == std::string::npos ? job : job.substr(0, caseAt);
}

std::string number(double value, int decimals) {
    return io::fixedText(value, decimals);
}

std::string stateOf(const Row& r) {
    if (r.record)
        return std::string(toString(r.record->state));
    return r.problem.empty() ? "pending" : "unreadable";
}

std::string askedPathologies(const scene::CaseSpec& spec) {
    std::string text;
    for (const scene::PathologySpec& p : spec.pathologies) {
        text += (text.empty() ? "" : "; ") + p.id + " " + std::string(clinical::toString(p.kind)) + " " +
                number(p.sizeMm, 1) + " mm";
        if (p.figo)
            text += " FIGO " + p.figo->toString();
        if (p.attachment)
            text += " " + std::string(clinical::toString(*p.attachment));
        if (const auto* c = std::get_if<clinical::ClinicalPlacement>(&p.placement))
            text += " " + std::string(clinical::toString(c->location));
    }
    return text;
}

std::string measuredPathologies(const SceneSummary& s) {
    std::string text;
    for (const PathologySummary& p : s.pathologies) {
        text += (text.empty() ? "" : "; ") + p.id + " " + number(p.sizeMm, 1) + " mm";
        if (!p.figo.empty())
            text += " FIGO " + p.figo;
        if (p.lasmar >= 0)
            text += " Lasmar " + std::to_string(p.lasmar);
    }
    return text;
}

/// The columns of the table, in order, for the CSV and the page.
const std::vector<std::string>& columns() {
    static const std::vector<std::string> names{
        "job",    "template",  "state",      "error",      "seconds",         "peakMemoryMb",   "ageYears",
        "parity", "gravidity", "menopausal", "asked",      "measured",        "lengthMm",       "widthMm",
        "apMm",   "volumeMl",  "vertices",   "tetrahedra", "meanRadiusRatio", "minDihedralDeg", "slivers",
        "scope",  "warnings",  "output"};
    return names;
}

std::vector<std::string> cells(const Row& r) {
    std::vector<std::string> c(columns().size());
    c[0] = r.job->name;
    c[1] = r.templateName;
    c[2] = stateOf(r);
    c[3] = r.problem;
    if (r.record) {
        if (r.record->error)
            c[3] = r.record->error->message();
        c[4] = number(r.record->seconds, 1);
        c[5] = number(r.record->peakMemoryMb, 0);
    }
    if (r.spec) {
        c[6] = number(r.spec->patient.ageYears, 1);
        c[7] = std::to_string(r.spec->patient.parity);
        c[8] = std::to_string(r.spec->patient.gravidity);
        c[9] = r.spec->patient.menopausal ? "yes" : "no";
        c[10] = askedPathologies(*r.spec);
    }
    if (r.record && r.record->scene) {
        const SceneSummary& s = *r.record->scene;
        c[11] = measuredPathologies(s);
        c[12] = number(s.organLengthMm, 1);
        c[13] = number(s.organWidthMm, 1);
        c[14] = number(s.organApMm, 1);
        c[15] = number(s.uterineVolumeMl, 1);
        c[16] = std::to_string(s.vertices);
        c[17] = std::to_string(s.tetrahedra);
        c[18] = number(s.meanRadiusRatio, 3);
        c[19] = number(s.minDihedralDeg, 1);
        c[20] = std::to_string(s.slivers);
        if (s.scopePasses)
            c[21] = (*s.scopePasses ? "passes, narrowest " : "does not pass, narrowest ") +
                    number(s.scopeNarrowestMm, 2) + " mm";
        for (const std::string& w : s.warnings)
            c[22] += (c[22].empty() ? "" : "\n") + w;
    }
    c[23] = r.job->output;
    return c;
}

/// One line per row: line breaks (multi-line errors) become "; ", and fields with commas or quotes are quoted.
std::string csvField(const std::string& text) {
    std::string flat;
    for (char ch : text)
        flat += ch == '\n' ? std::string("; ") : ch == '\r' ? std::string() : std::string(1, ch);
    if (flat.find_first_of(",\"") == std::string::npos)
        return flat;
    std::string quoted = "\"";
    for (char ch : flat)
        quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return quoted + "\"";
}

std::string csvText(const std::vector<Row>& rows) {
    std::string text;
    for (std::size_t i = 0; i < columns().size(); ++i)
        text += (i ? "," : "") + columns()[i];
    text += "\n";
    for (const Row& r : rows) {
        const auto c = cells(r);
        for (std::size_t i = 0; i < c.size(); ++i)
            text += (i ? "," : "") + csvField(c[i]);
        text += "\n";
    }
    return text;
}

// ---- Thumbnails: the organ's visual surface seen along its thinnest extent, pathologies drawn over it. ----

/// Z-buffered, Lambert-shaded triangles of `mesh` (those with `pathology` label == `wantPathology`) into `image`.
void rasterize(const SurfaceMesh& mesh, const std::vector<std::int32_t>* pathology, bool wantPathology, int u, int v,
               int w, double scale, const Vec3& low, ImageU8& image, const std::array<double, 3>& colour) {
    std::vector<double> depth(static_cast<std::size_t>(image.width()) * static_cast<std::size_t>(image.height()),
                              -std::numeric_limits<double>::infinity());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const bool isPathology = pathology && (*pathology)[t] != 0;
        if (isPathology != wantPathology)
            continue;
        const Vec3& a = mesh.points[static_cast<std::size_t>(mesh.triangles[t][0])];
        const Vec3& b = mesh.points[static_cast<std::size_t>(mesh.triangles[t][1])];
        const Vec3& c = mesh.points[static_cast<std::size_t>(mesh.triangles[t][2])];
        const Vec3 n = cross(b - a, c - a);
        const double length = norm(n);
        if (length <= 0.0)
            continue;
        const double shade = 0.35 + 0.65 * std::fabs(n[w]) / length;
        double px[3], py[3], pz[3];
        const Vec3* corners[3] = {&a, &b, &c};
        for (int k = 0; k < 3; ++k) {
            px[k] = ((*corners[k])[u] - low[u]) * scale;
            py[k] = static_cast<double>(image.height() - 1) - ((*corners[k])[v] - low[v]) * scale;
            pz[k] = (*corners[k])[w];
        }
        const int x0 = std::max(0, static_cast<int>(std::floor(std::min({px[0], px[1], px[2]}))));
        const int x1 = std::min(image.width() - 1, static_cast<int>(std::ceil(std::max({px[0], px[1], px[2]}))));
        const int y0 = std::max(0, static_cast<int>(std::floor(std::min({py[0], py[1], py[2]}))));
        const int y1 = std::min(image.height() - 1, static_cast<int>(std::ceil(std::max({py[0], py[1], py[2]}))));
        const double area = (px[1] - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (py[1] - py[0]);
        if (std::fabs(area) < 1e-12)
            continue;
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                const double sx = x + 0.5, sy = y + 0.5;
                const double l1 = ((px[2] - px[1]) * (sy - py[1]) - (py[2] - py[1]) * (sx - px[1])) / area;
                const double l2 = ((px[0] - px[2]) * (sy - py[2]) - (py[0] - py[2]) * (sx - px[2])) / area;
                const double l3 = 1.0 - l1 - l2;
                if (l1 < 0.0 || l2 < 0.0 || l3 < 0.0)
                    continue;
                const double z = l1 * pz[0] + l2 * pz[1] + l3 * pz[2];
                double& d = depth[static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width()) +
                                  static_cast<std::size_t>(x)];
                if (z <= d)
                    continue;
                d = z;
                for (int ch = 0; ch < 3; ++ch)
                    image.at(x, y, ch) = static_cast<std::uint8_t>(std::clamp(colour[ch] * shade, 0.0, 255.0));
                image.at(x, y, 3) = 255;
            }
        }
    }
}

/// The organ of a package drawn as a PNG file at `pngPath` (written atomically).
Status drawThumbnail(const std::string& packageFolder, const std::string& pngPath, int widthPx) {
    io::ReadLimits limits;
    limits.maxFileBytes = kMaxThumbnailSurfaceBytes;
    auto mesh = io::readSurface((fs::path(packageFolder) / "surface.vtp").string(), limits);
    if (!mesh)
        return mesh.failure();
    if (mesh->points.empty())
        return fail(ErrorCode::InvalidInput, packageFolder + ": empty surface");
    Vec3 low = mesh->points.front(), high = mesh->points.front();
    for (const Vec3& p : mesh->points)
        for (int k = 0; k < 3; ++k) {
            low[k] = std::min(low[k], p[k]);
            high[k] = std::max(high[k], p[k]);
        }
    // View along the thinnest extent (the antero-posterior depth for a uterus); the longest is vertical.
    std::array<int, 3> axes{0, 1, 2};
    std::sort(axes.begin(), axes.end(), [&](int a, int b) { return high[a] - low[a] < high[b] - low[b]; });
    const int w = axes[0], u = axes[1], v = axes[2];
    const double scale = (widthPx - 2) / std::max(high[u] - low[u], 1e-9);
    const int heightPx = std::clamp(static_cast<int>(std::ceil((high[v] - low[v]) * scale)) + 2, 8, 4 * widthPx);
    auto image = ImageU8::create(widthPx, heightPx, 4, 0);
    if (!image)
        return image.failure();
    const auto it = mesh->faceLabels.find("pathology");
    const std::vector<std::int32_t>* pathology =
        it != mesh->faceLabels.end() && it->second.size() == mesh->triangles.size() ? &it->second : nullptr;
    rasterize(*mesh, pathology, false, u, v, w, scale, low, *image, {232.0, 170.0, 160.0});
    if (pathology) // drawn over the organ: a submucosal myoma or a polyp lies inside it
        rasterize(*mesh, pathology, true, u, v, w, scale, low, *image, {150.0, 40.0, 60.0});
    const std::string scratch = pngPath + ".tmp-" + std::to_string(getpid()) + ".png";
    HS_TRY(texture::writeImage(*image, scratch));
    std::error_code ec;
    fs::rename(scratch, pngPath, ec);
    if (ec) {
        fs::remove(scratch, ec);
        return fail(ErrorCode::IoError, pngPath + ": cannot write the thumbnail");
    }
    return {};
}

/// The organ thumbnail of an ok job as a data URI. Thumbnails are kept in REPORT/thumbnails/, named by the digest of
/// the package's manifest (a package's bytes decide its picture): a report written again draws only new packages.
Result<std::string> thumbnail(const std::string& packageFolder, const std::string& manifestSha256,
                              const std::string& thumbnailFolder, int widthPx) {
    const bool digest =
        manifestSha256.size() == 64 && manifestSha256.find_first_not_of("0123456789abcdef") == std::string::npos;
    if (!digest)
        return fail(ErrorCode::InvalidInput, packageFolder + ": the status record has no package digest");
    const std::string png =
        (fs::path(thumbnailFolder) / (manifestSha256.substr(0, 32) + "-" + std::to_string(widthPx) + ".png")).string();
    std::error_code ec;
    if (!fs::exists(png, ec))
        HS_TRY(drawThumbnail(packageFolder, png, widthPx));
    auto bytes = io::readFile(png, 64 * 1024 * 1024);
    if (!bytes)
        return bytes.failure();
    return "data:image/png;base64," + io::base64(*bytes);
}

// ---- Distributions: the drawn values of each sampled field against what the curriculum asked. ----

struct Chart {
    std::string title;
    std::vector<std::string> labels;
    std::vector<std::pair<std::string, std::vector<double>>> datasets;
};

Chart histogram(const std::string& title, const NumberSampler& asked, const std::vector<double>& drawn,
                const std::vector<double>& measured) {
    Chart chart;
    const double lo = asked.lowest(), hi = asked.highest();
    chart.title = title + " (asked " +
                  (asked.range ? "uniform " + scene::formatRange(*asked.range)
                               : "one of " + std::to_string(asked.values.size()) + " values " +
                                     scene::formatNumber(lo) + ".." + scene::formatNumber(hi)) +
                  ")";
    const double width = (hi - lo) / kHistogramBins;
    for (int b = 0; b < kHistogramBins; ++b)
        chart.labels.push_back(number(lo + b * width, 1) + "-" + number(lo + (b + 1) * width, 1));
    const auto bin = [&](double value) {
        if (!(width > 0.0))
            return 0;
        return std::clamp(static_cast<int>(std::floor((value - lo) / width)), 0, kHistogramBins - 1);
    };
    std::vector<double> counts(kHistogramBins, 0.0);
    for (double d : drawn)
        counts[static_cast<std::size_t>(bin(d))] += 1.0;
    chart.datasets.emplace_back("drawn", counts);
    if (asked.range) {
        chart.datasets.emplace_back(
            "asked (uniform, expected)",
            std::vector<double>(kHistogramBins, static_cast<double>(drawn.size()) / kHistogramBins));
    }
    if (!measured.empty()) {
        std::vector<double> m(kHistogramBins, 0.0);
        for (double d : measured)
            m[static_cast<std::size_t>(bin(d))] += 1.0; // beyond the range: counted in the edge bins
        chart.datasets.emplace_back("measured (edge bins hold what lies beyond)", m);
    }
    return chart;
}

/// Drawn counts of each asked value (and of anything else drawn or measured), with the expected equal share.
Chart choices(const std::string& title, const std::vector<std::string>& asked, const std::vector<std::string>& drawn,
              const std::vector<std::string>& measured = {}) {
    Chart chart;
    chart.title = title + " (asked one of " + std::to_string(asked.size()) + ")";
    chart.labels = asked;
    const auto index = [&chart](const std::string& value) {
        auto it = std::find(chart.labels.begin(), chart.labels.end(), value);
        if (it == chart.labels.end()) {
            chart.labels.push_back(value);
            for (auto& [name, data] : chart.datasets)
                data.push_back(0.0);
            return chart.labels.size() - 1;
        }
        return static_cast<std::size_t>(it - chart.labels.begin());
    };
    chart.datasets.emplace_back("drawn", std::vector<double>(chart.labels.size(), 0.0));
    chart.datasets.emplace_back("asked (equal share, expected)",
                                std::vector<double>(chart.labels.size(), static_cast<double>(drawn.size()) /
                                                                             static_cast<double>(asked.size())));
    if (!measured.empty())
        chart.datasets.emplace_back("measured", std::vector<double>(chart.labels.size(), 0.0));
    for (const std::string& d : drawn)
        chart.datasets[0].second[index(d)] += 1.0;
    for (const std::string& m : measured)
        chart.datasets[2].second[index(m)] += 1.0;
    for (std::size_t i = asked.size(); i < chart.labels.size(); ++i)
        chart.datasets[1].second[i] = 0.0;
    return chart;
}

template <class T>
std::vector<std::string> keys(const std::vector<T>& values) {
    std::vector<std::string> out;
    for (const T& v : values) {
        if constexpr (std::is_same_v<T, bool>)
            out.push_back(v ? "true" : "false");
        else if constexpr (std::is_same_v<T, clinical::FigoType>)
            out.push_back(v.toString());
        else
            out.push_back(std::string(toString(v)));
    }
    return out;
}

/// A numeric sampler with few distinct values (a list, or an integer range of at most 20) as a choice chart.
std::optional<std::vector<std::string>> discreteValues(const NumberSampler& s, bool integer) {
    std::vector<std::string> values;
    if (!s.range) {
        for (double v : s.values)
            values.push_back(scene::formatNumber(v));
        return values;
    }
    if (!integer || s.range->max - s.range->min > 20.0)
        return std::nullopt;
    for (double v = std::ceil(s.range->min); v <= s.range->max; v += 1.0)
        values.push_back(scene::formatNumber(v));
    return values;
}

void patientCharts(const CaseTemplate& t, const std::vector<const Row*>& rows, std::vector<Chart>& charts) {
    const auto numeric = [&](const char* field, const std::optional<NumberSampler>& s, auto get, bool integer = false) {
        if (!s || s->fixed())
            return;
        std::vector<double> drawn;
        for (const Row* r : rows)
            if (r->spec)
                drawn.push_back(get(r->spec->patient));
        const std::string title = t.name + ": patient " + field;
        if (const auto values = discreteValues(*s, integer)) {
            std::vector<std::string> drawnText;
            for (double d : drawn)
                drawnText.push_back(scene::formatNumber(d));
            charts.push_back(choices(title, *values, drawnText));
        } else {
            charts.push_back(histogram(title, *s, drawn, {}));
        }
    };
    numeric("ageYears", t.patient.ageYears, [](const clinical::PatientParams& p) { return p.ageYears; });
    numeric(
        "parity", t.patient.parity, [](const clinical::PatientParams& p) { return double(p.parity); }, true);
    numeric(
        "gravidity", t.patient.gravidity, [](const clinical::PatientParams& p) { return double(p.gravidity); }, true);
    numeric("heightCm", t.patient.heightCm, [](const clinical::PatientParams& p) { return p.heightCm; });
    numeric("weightKg", t.patient.weightKg, [](const clinical::PatientParams& p) { return p.weightKg; });
    if (t.patient.menopausal && t.patient.menopausal->values.size() > 1) {
        std::vector<std::string> drawn;
        for (const Row* r : rows)
            if (r->spec)
                drawn.push_back(r->spec->patient.menopausal ? "true" : "false");
        charts.push_back(choices(t.name + ": patient menopausal", keys(t.patient.menopausal->values), drawn));
    }
}

void pathologyCharts(const CaseTemplate& t, const std::vector<const Row*>& rows, std::vector<Chart>& charts) {
    if (!t.pathologies)
        return;
    for (std::size_t j = 0; j < t.pathologies->size(); ++j) {
        const PathologySampler& s = (*t.pathologies)[j];
        const std::string prefix = t.name + ": " + s.id + " ";
        std::vector<double> drawnSize, measuredSize;
        std::vector<std::string> drawnFigo, measuredFigo, drawnLocation;
        for (const Row* r : rows) {
            if (r->spec && j < r->spec->pathologies.size()) {
                const scene::PathologySpec& p = r->spec->pathologies[j];
                drawnSize.push_back(p.sizeMm);
                if (p.figo)
                    drawnFigo.push_back(p.figo->toString());
                if (const auto* c = std::get_if<clinical::ClinicalPlacement>(&p.placement))
                    drawnLocation.push_back(std::string(clinical::toString(c->location)));
            }
            if (r->record && r->record->scene)
                for (const PathologySummary& m : r->record->scene->pathologies)
                    if (m.id == s.id) {
                        measuredSize.push_back(m.sizeMm);
                        if (!m.figo.empty())
                            measuredFigo.push_back(m.figo);
                    }
        }
        if (!s.sizeMm.fixed() || !measuredSize.empty())
            charts.push_back(histogram(prefix + "sizeMm", s.sizeMm, drawnSize, measuredSize));
        if (!s.figo.values.empty())
            charts.push_back(choices(prefix + "FIGO", keys(s.figo.values), drawnFigo, measuredFigo));
        if (s.location.values.size() > 1)
            charts.push_back(choices(prefix + "location", keys(s.location.values), drawnLocation));
    }
}

/// Chart.js configurations: one bar chart per distribution.
ordered_json chartConfigs(const std::vector<Chart>& charts) {
    auto list = ordered_json::array();
    for (const Chart& c : charts) {
        auto datasets = ordered_json::array();
        for (const auto& [label, data] : c.datasets)
            datasets.push_back({{"label", label},
                                {"data", data},
                                {"backgroundColor", io::chartColour(datasets.size(), datasets.empty() ? 0.85 : 0.6)}});
        list.push_back({{"type", "bar"},
                        {"data", {{"labels", c.labels}, {"datasets", datasets}}},
                        {"options", io::chartOptions(c.title)}});
    }
    return list;
}

constexpr std::string_view kPageStyle =
    "<style>body{font-family:sans-serif;margin:1em}table{border-collapse:collapse;font-size:12px}"
    "td,th{border:1px solid #ccc;padding:2px 4px;vertical-align:top}tr.failed{background:#fdd}"
    "tr.pending{color:#888}.charts{display:flex;flex-wrap:wrap}.chart{width:420px;height:260px;margin:4px}"
    "nav{margin:0.5em 0}nav a{margin-right:1em}</style>";

std::string pageHead(const std::string& title) {
    return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + htmlEscape(title) +
           "</title>\n" + std::string(kPageStyle) + "</head>\n<body>\n<h1>" + htmlEscape(title) + "</h1>\n";
}

/// "pages/cases-0001.html" for page 0, relative to the report folder.
std::string pagePath(std::size_t page) {
    char name[40];
    std::snprintf(name, sizeof name, "pages/cases-%04zu.html", page + 1);
    return name;
}

/// The rows [first, last) on a page of their own: the full table with the organs, links to the neighbours.
std::string casePage(const std::string& title, const std::vector<Row>& rows, std::size_t page, std::size_t pages,
                     std::size_t first, std::size_t last) {
    const std::string heading = title + ": cases " + std::to_string(first + 1) + "-" + std::to_string(last) + " of " +
                                std::to_string(rows.size());
    std::string nav = "<nav><a href=\"../report.html\">index</a>";
    if (page > 0)
        nav += "<a href=\"" + fs::path(pagePath(page - 1)).filename().string() + "\">previous</a>";
    if (page + 1 < pages)
        nav += "<a href=\"" + fs::path(pagePath(page + 1)).filename().string() + "\">next</a>";
    nav += "</nav>\n";
    std::string h = pageHead(heading) + nav + "<table>\n<tr><th>organ</th>";
    for (const std::string& c : columns())
        h += "<th>" + htmlEscape(c) + "</th>";
    h += "</tr>\n";
    for (std::size_t i = first; i < last; ++i) {
        const Row& r = rows[i];
        h += "<tr id=\"" + htmlEscape(r.job->name) + "\" class=\"" + stateOf(r) + "\"><td>" +
             (r.thumbnail.empty() ? "" : "<img alt=\"organ\" src=\"" + r.thumbnail + "\">") + "</td>";
        for (const std::string& c : cells(r))
            h += "<td>" + htmlEscape(c) + "</td>";
        h += "</tr>\n";
    }
    return h + "</table>\n" + nav + "</body></html>\n";
}

/// A scene warning with its numbers and quoted names taken out, so that the same warning of many scenes counts as
/// one kind: "pathology: polyp '...': at its nominal seat it would cover or hide the right tubal ostium; seated N mm
/// away on the same wall".
std::string warningKind(const std::string& warning) {
    std::string kind;
    for (std::size_t i = 0; i < warning.size() && kind.size() < 160; ++i) {
        const char ch = warning[i];
        if (ch == '\'') {
            const std::size_t end = warning.find('\'', i + 1);
            if (end != std::string::npos) {
                kind += "'...'";
                i = end;
                continue;
            }
        }
        if (std::isdigit(static_cast<unsigned char>(ch))) {
            while (i + 1 < warning.size() &&
                   (std::isdigit(static_cast<unsigned char>(warning[i + 1])) || warning[i + 1] == '.'))
                ++i;
            kind += 'N';
            continue;
        }
        kind += ch;
    }
    return kind;
}

/// The index: the summary, the distributions, one line per page of cases, and every job not ok with its error.
std::string indexPage(const std::string& title, const std::vector<Row>& rows, std::size_t rowsPerPage,
                      const std::vector<Chart>& charts, const std::string& chartLibrary, const std::string& summary) {
    std::string h = pageHead(title) + "<p>" + htmlEscape(summary) + "</p>\n<h2>Drawn against asked</h2>\n";
    if (chartLibrary.empty())
        h += "<p>No plots: the chart library (Debian's libjs-chart.js) is not installed.</p>\n";
    h += "<div class=\"charts\">\n";
    for (std::size_t i = 0; i < charts.size(); ++i)
        h += io::chartCanvas(i);
    h += "</div>\n<h2>Cases</h2>\n<p>" + std::to_string(rowsPerPage) +
         " cases a page, each with its organ; every case is also in report.csv.</p>\n<table>\n"
         "<tr><th>page</th><th>cases</th><th>first job</th><th>last job</th><th>ok</th><th>failed</th>"
         "<th>pending</th></tr>\n";
    std::string notOk;
    for (std::size_t first = 0, page = 0; first < rows.size(); first += rowsPerPage, ++page) {
        const std::size_t last = std::min(first + rowsPerPage, rows.size());
        std::size_t ok = 0, failed = 0;
        for (std::size_t i = first; i < last; ++i) {
            const Row& r = rows[i];
            const std::string state = stateOf(r);
            ok += state == "ok";
            failed += state == "failed" || state == "unreadable";
            if (state == "failed" || state == "unreadable")
                notOk += "<li><a href=\"" + pagePath(page) + "#" + htmlEscape(r.job->name) + "\">" +
                         htmlEscape(r.job->name) + "</a>: " + htmlEscape(cells(r)[3]) + "</li>\n";
        }
        h += "<tr><td><a href=\"" + pagePath(page) + "\">" + std::to_string(page + 1) + "</a></td><td>" +
             std::to_string(first + 1) + "-" + std::to_string(last) + "</td><td>" + htmlEscape(rows[first].job->name) +
             "</td><td>" + htmlEscape(rows[last - 1].job->name) + "</td><td>" + std::to_string(ok) + "</td><td>" +
             std::to_string(failed) + "</td><td>" + std::to_string(last - first - ok - failed) + "</td></tr>\n";
    }
    h += "</table>\n";
    // Every warning kind with the number of scenes that have it: a fallback or a missed bar is never hidden.
    std::map<std::string, std::size_t> kinds;
    for (const Row& r : rows) {
        if (!r.record || !r.record->scene)
            continue;
        std::set<std::string> ofScene;
        for (const std::string& w : r.record->scene->warnings)
            ofScene.insert(warningKind(w));
        for (const std::string& k : ofScene)
            ++kinds[k];
    }
    h += "<h2>Warnings</h2>\n";
    if (kinds.empty()) {
        h += "<p>No scene has a warning.</p>\n";
    } else {
        std::vector<std::pair<std::string, std::size_t>> sorted(kinds.begin(), kinds.end());
        std::stable_sort(sorted.begin(), sorted.end(),
                         [](const auto& a, const auto& b) { return a.second > b.second; });
        h += "<table>\n<tr><th>scenes</th><th>warning (numbers as N, names as '...')</th></tr>\n";
        for (const auto& [kind, count] : sorted)
            h += "<tr><td>" + std::to_string(count) + "</td><td>" + htmlEscape(kind) + "</td></tr>\n";
        h += "</table>\n";
    }
    if (!notOk.empty())
        h += "<h2>Jobs that failed</h2>\n<ul>\n" + notOk + "</ul>\n";
    h += io::chartScripts(chartLibrary, chartConfigs(charts));
    return h + "</body></html>\n";
}

/// Removes the case pages a longer report left beyond `pages`.
void removeStalePages(const std::string& pagesFolder, std::size_t pages) {
    std::error_code ec;
    for (fs::directory_iterator it(pagesFolder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        std::size_t number = 0;
        if (name.size() == 15 && name.rfind("cases-", 0) == 0 && name.substr(10) == ".html" &&
            std::sscanf(name.c_str() + 6, "%4zu", &number) == 1 && number > pages) {
            std::error_code removeError;
            fs::remove(it->path(), removeError);
        }
    }
}

} // namespace

Result<ReportResult> writeBatchReport(const std::string& batchFolder, const Manifest& manifest,
                                      const ReportParams& params) {
    ReportResult result;
    const std::string folder = batchPath(batchFolder, kReportFolder);
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec)
        return fail(ErrorCode::IoError, folder + ": " + ec.message());
    auto curriculumText = io::readFile(batchPath(batchFolder, kCurriculumFile), kMaxCurriculumFileBytes);
    if (!curriculumText)
        return curriculumText.failure();
    auto curriculum = parseCurriculum(*curriculumText, batchPath(batchFolder, kCurriculumFile));
    if (!curriculum)
        return curriculum.failure();

    std::map<std::string, scene::CaseSpec> cases;
    std::vector<Row> rows;
    std::size_t ok = 0, failed = 0;
    double seconds = 0.0;
    const std::string thumbnails = (fs::path(folder) / "thumbnails").string();
    const std::string pagesFolder = (fs::path(folder) / "pages").string();
    for (const std::string& sub : {thumbnails, pagesFolder}) {
        fs::create_directories(sub, ec);
        if (ec)
            return fail(ErrorCode::IoError, sub + ": " + ec.message());
    }
    for (const Job& job : manifest.jobs) {
        Row r;
        r.job = &job;
        r.templateName = templateOf(job.name);
        if (!cases.count(job.caseFile)) {
            auto spec = scene::loadCase(batchPath(batchFolder, job.caseFile));
            if (spec)
                cases.emplace(job.caseFile, std::move(*spec));
            else
                r.problem = spec.error().message();
        }
        if (cases.count(job.caseFile))
            r.spec = cases.at(job.caseFile);
        auto record = readStatus(batchFolder, job.name);
        if (!record)
            r.problem = record.error().message();
        else if (*record && (*record)->seed == job.seed)
            r.record = **record;
        if (r.record && r.record->state == JobState::Ok) {
            ++ok;
            seconds += r.record->seconds;
            auto image = thumbnail(batchPath(batchFolder, job.output), r.record->packageManifestSha256, thumbnails,
                                   params.thumbnailWidthPx);
            if (image)
                r.thumbnail = *image;
            else
                result.warnings.push_back(job.name + ": no thumbnail: " + image.error().message());
        } else if (r.record) {
            ++failed;
        }
        rows.push_back(std::move(r));
    }

    std::vector<Chart> charts;
    for (const CaseTemplate& t : curriculum->templates) {
        std::vector<const Row*> ofTemplate;
        for (const Row& r : rows)
            if (r.templateName == t.name)
                ofTemplate.push_back(&r);
        patientCharts(t, ofTemplate, charts);
        pathologyCharts(t, ofTemplate, charts);
    }
    std::string library;
    if (auto text = io::readChartLibrary(params.chartLibrary))
        library = *text;
    else
        result.warnings.push_back("no plots: " + text.error().message() + " (install libjs-chart.js)");

    const std::string title = curriculum->title.empty() ? "Batch report" : curriculum->title;
    const std::string summary = std::to_string(manifest.jobs.size()) + " jobs: " + std::to_string(ok) + " ok, " +
                                std::to_string(failed) + " failed, " +
                                std::to_string(manifest.jobs.size() - ok - failed) + " pending; " +
                                number(ok ? seconds / static_cast<double>(ok) : 0.0, 1) +
                                " s per ok job. Master seed " + std::to_string(curriculum->seed) + ".";
    result.csvPath = (fs::path(folder) / "report.csv").string();
    result.htmlPath = (fs::path(folder) / "report.html").string();
    HS_TRY(io::writeFileAtomically(result.csvPath, csvText(rows)));
    const std::size_t perPage = std::max<std::size_t>(params.rowsPerPage, 1);
    const std::size_t pages = (rows.size() + perPage - 1) / perPage;
    for (std::size_t page = 0; page < pages; ++page) {
        const std::size_t first = page * perPage;
        HS_TRY(
            io::writeFileAtomically((fs::path(folder) / pagePath(page)).string(),
                                    casePage(title, rows, page, pages, first, std::min(first + perPage, rows.size()))));
    }
    removeStalePages(pagesFolder, pages);
    HS_TRY(io::writeFileAtomically(result.htmlPath, indexPage(title, rows, perPage, charts, library, summary)));
    result.rows = rows.size();
    result.pages = pages;
    result.charts = library.empty() ? 0 : charts.size();
    return result;
}

} // namespace hs::batch
