// The trial report: JSON for machines (every double with 17 significant digits, so two replays compare bit for bit)
// and one self-contained HTML page for the trainee and the supervisor (docs/simulator.md, "Report").
#include "hs/sim/Metrics.h"

#include "hs/core/Units.h"
#include "hs/io/AtomicFile.h"
#include "hs/io/HtmlPage.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>

namespace hs::sim {

namespace {

using io::fixedText;
using io::htmlEscape;
using nlohmann::ordered_json;

constexpr int kReportVersion = 2; // 2: the series has the pump's set pressure
/// The visualized-surface plot draws at most this many faces (evenly strided); the JSON keeps them all.
constexpr std::size_t kMaxPlottedSurfaceSamples = 20000;

// ---- JSON: a small writer, because the report's doubles must read back bit for bit in every JSON reader. ----

/// Appends JSON text. Doubles are written with %.17g (non-finite values as null), strings through nlohmann's escaping.
class JsonWriter {
public:
    std::string text;

    void open(char bracket) {
        comma();
        text += bracket;
        m_first = true;
    }
    void close(char bracket) {
        text += bracket;
        m_first = false;
    }
    void key(const char* name) {
        comma();
        text += ordered_json(name).dump();
        text += ':';
        m_first = true; // the value follows without a comma
    }
    void value(double v) {
        comma();
        if (!std::isfinite(v)) {
            text += "null";
            return;
        }
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.17g", v);
        text += buffer;
    }
    void value(std::uint64_t v) {
        comma();
        text += std::to_string(v);
    }
    void value(int v) {
        comma();
        text += std::to_string(v);
    }
    void value(bool v) {
        comma();
        text += v ? "true" : "false";
    }
    void value(const std::string& v) {
        comma();
        text += ordered_json(v).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    }
    template <class T>
    void field(const char* name, const T& v) {
        key(name);
        value(v);
    }
    /// One array per column: {"timeS": [...], ...} reads and diffs better than an object per row.
    template <class Row, class Get>
    void column(const char* name, const std::vector<Row>& rows, Get get) {
        key(name);
        open('[');
        for (const Row& r : rows)
            value(get(r));
        close(']');
    }

private:
    void comma() {
        if (!m_first)
            text += ',';
        m_first = false;
    }
    bool m_first = true;
};

void writeHeader(JsonWriter& w, const TrialHeader& h) {
    w.key("header");
    w.open('{');
    w.field("sceneSha256", h.sceneSha256);
    w.field("seed", h.seed);
    w.key("physics");
    w.open('{');
    w.field("engine", h.physics.engine);
    w.field("stepS", h.physics.stepS);
    w.field("solverIterations", h.physics.solverIterations);
    w.close('}');
    w.field("exercise", std::string(toString(h.exercise)));
    w.key("scope");
    w.open('{');
    w.field("opticDeg", h.scope.opticDeg);
    w.field("diameterMm", h.scope.diameterMm);
    // The optic's values where the trial left them to it (0 in the trial's header): the report says what was used.
    w.field("fieldOfViewDeg", scopeFieldOfViewDeg(h.scope));
    w.field("focusNearMm", scopeFocusNearMm(h.scope));
    w.field("focusFarMm", scopeFocusFarMm(h.scope));
    w.close('}');
    w.key("fluid");
    w.open('{');
    w.field("pumpPressureKpa", h.fluid.pumpPressureKpa);
    w.field("meanArterialPressureKpa", h.fluid.meanArterialPressureKpa);
    w.field("deficitWarningMl", h.fluid.deficitWarningMl);
    w.field("deficitLimitMl", h.fluid.deficitLimitMl);
    w.field("medium", std::string(toString(h.fluid.medium)));
    w.field("elderlyOrComorbid", h.fluid.elderlyOrComorbid);
    w.close('}');
    w.field("device", h.device);
    w.field("startedUtc", h.startedUtc);
    w.close('}');
}

void writeMetrics(JsonWriter& w, const TrialMetrics& m) {
    w.key("metrics");
    w.open('{');
    w.field("timeS", m.timeS);
    w.field("pathLengthMm", m.pathLengthMm);
    w.field("cavitySurfaceVisualizedPercent", m.cavitySurfaceVisualizedPercent);
    w.key("targets");
    w.open('[');
    for (const ExplorationTarget& t : m.targets) {
        w.open('{');
        w.field("name", t.name);
        w.field("visualizedPercent", t.visualizedPercent);
        w.field("seen", t.seen);
        w.field("firstSeenS", t.firstSeenS);
        w.close('}');
    }
    w.close(']');
    w.field("horizonErrorMeanDeg", m.horizonErrorMeanDeg);
    w.field("horizonErrorMaxDeg", m.horizonErrorMaxDeg);
    w.field("wallContacts", m.wallContacts);
    w.field("peakForceN", m.peakForceN);
    w.field("contactTimeS", m.contactTimeS);
    w.key("perforations");
    w.open('[');
    for (const Perforation& p : m.perforations) {
        w.open('{');
        w.field("timeS", p.timeS);
        w.key("locationMm");
        w.open('[');
        w.value(p.locationMm.x);
        w.value(p.locationMm.y);
        w.value(p.locationMm.z);
        w.close(']');
        w.field("depthMm", p.depthMm);
        w.field("region", p.region);
        w.field("falsePassage", p.falsePassage);
        w.close('}');
    }
    w.close(']');
    w.field("timeAboveMeanArterialPressureS", m.timeAboveMeanArterialPressureS);
    w.field("maxPressureKpa", m.maxPressureKpa);
    w.field("inflowMl", m.inflowMl);
    w.field("outflowMl", m.outflowMl);
    w.field("deficitMl", m.deficitMl);
    w.field("intravasationMl", m.intravasationMl);
    w.field("bloodLossMl", m.bloodLossMl);
    w.field("finalPumpPressureKpa", m.finalPumpPressureKpa);
    w.field("deficitWarning", m.deficitWarning);
    w.field("deficitLimitReached", m.deficitLimitReached);
    w.field("redOutTimeS", m.redOutTimeS);
    w.key("pathologies");
    w.open('[');
    for (const PathologyFinding& p : m.pathologies) {
        w.open('{');
        w.field("id", p.id);
        w.field("kind", p.kind);
        w.field("seen", p.seen);
        w.field("found", p.found);
        w.field("foundS", p.foundS);
        w.close('}');
    }
    w.close(']');
    w.field("falseMarks", m.falseMarks);
    const ResectionMetrics& r = m.resection;
    if (!r.pathologies.empty()) {
        // The operative exercises' (docs/simulator.md, "Cutting").
        w.key("resection");
        w.open('{');
        w.key("pathologies");
        w.open('[');
        for (const PathologyResection& p : r.pathologies) {
            w.open('{');
            w.field("id", p.id);
            w.field("kind", p.kind);
            w.field("volumeMl", p.volumeMl);
            w.field("removedMl", p.removedMl);
            w.field("removedPercent", p.removedPercent);
            w.close('}');
        }
        w.close(']');
        w.field("healthyRemovedMl", r.healthyRemovedMl);
        w.field("deepestMyometriumMm", r.deepestMyometriumMm);
        w.field("perforatingCuts", r.perforatingCuts);
        w.field("cutEvents", r.cutEvents);
        w.field("removedTets", r.removedTets);
        w.field("chips", r.chips);
        w.field("chipsMade", r.chipsMade);
        w.field("chipsCarriedOut", r.chipsCarriedOut);
        w.field("chipsLeft", r.chipsLeft);
        w.field("cuttingTimeS", r.cuttingTimeS);
        w.field("resectionTimeS", r.resectionTimeS);
        w.field("firstCutS", r.firstCutS);
        w.field("loopPathMm", r.loopPathMm);
        w.field("coagulationTimeS", r.coagulationTimeS);
        w.close('}');
    }
    w.close('}');
}

// ---- HTML ----

std::string yesNo(bool v) {
    return v ? "yes" : "no";
}

std::string seconds(double s) {
    return s < 0.0 ? std::string("never") : fixedText(s, 1) + " s";
}

/// A two-column table of (name, value) rows.
std::string keyValueTable(const std::vector<std::vector<std::string>>& rows) {
    std::string h = "<table class=\"kv\">\n";
    for (const auto& row : rows)
        h += "<tr><th>" + htmlEscape(row.at(0)) + "</th><td>" + htmlEscape(row.at(1)) + "</td></tr>\n";
    return h + "</table>\n";
}

std::string table(const std::vector<std::string>& head, const std::vector<std::vector<std::string>>& rows) {
    std::string h = "<table>\n<tr>";
    for (const std::string& c : head)
        h += "<th>" + htmlEscape(c) + "</th>";
    h += "</tr>\n";
    for (const auto& row : rows) {
        h += "<tr>";
        for (const std::string& c : row)
            h += "<td>" + htmlEscape(c) + "</td>";
        h += "</tr>\n";
    }
    return h + "</table>\n";
}

std::string pressure(double kpa) {
    return fixedText(kpa, 2) + " kPa (" + fixedText(kpa / units::kKpaPerMmHg, 0) + " mmHg)";
}

using Rows = std::vector<std::vector<std::string>>;

ReportTable keyValues(std::string section, Rows rows) {
    return {std::move(section), {}, std::move(rows)};
}

std::string sectionsHtml(const TrialReport& r) {
    std::string h;
    for (const ReportTable& t : reportTables(r)) {
        if (!t.section.empty())
            h += "<h2>" + htmlEscape(t.section) + "</h2>\n";
        h += t.head.empty() ? keyValueTable(t.rows) : table(t.head, t.rows);
    }
    return h;
}

ordered_json lineChart(const ReportPlot& plot) {
    auto datasets = ordered_json::array();
    for (const ReportLine& line : plot.lines) {
        auto points = ordered_json::array();
        for (const auto& [x, y] : line.points)
            points.push_back({{"x", x}, {"y", y}});
        datasets.push_back({{"label", line.label},
                            {"data", std::move(points)},
                            {"borderColor", io::chartColour(datasets.size())},
                            {"backgroundColor", io::chartColour(datasets.size(), 0.3)},
                            {"pointRadius", 0},
                            {"borderWidth", 1.5}});
    }
    ordered_json options = io::chartOptions(plot.title);
    options["parsing"] = false;
    options["scales"] = {{"x", {{"type", "linear"}, {"title", {{"display", true}, {"text", "time (s)"}}}}},
                         {"y", {{"title", {{"display", true}, {"text", plot.yTitle}}}}}};
    return {{"type", "line"}, {"data", {{"datasets", datasets}}}, {"options", options}};
}

/// (time, value) points of one field of the series.
template <class Get>
std::vector<std::pair<double, double>> points(const std::vector<SeriesPoint>& series, Get get) {
    std::vector<std::pair<double, double>> list;
    list.reserve(series.size());
    for (const SeriesPoint& p : series)
        list.emplace_back(p.timeS, get(p));
    return list;
}

/// A constant line over the trial's time (a limit).
std::vector<std::pair<double, double>> level(const std::vector<SeriesPoint>& series, double value) {
    if (series.empty())
        return {};
    return {{series.front().timeS, value}, {series.back().timeS, value}};
}

ordered_json surfaceChart(const std::vector<SurfaceSample>& surface) {
    auto seen = ordered_json::array(), unseen = ordered_json::array();
    for (const SurfaceSample& face : surface)
        (face.seen ? seen : unseen).push_back({{"x", face.aroundDeg}, {"y", face.alongMm}});
    ordered_json options = io::chartOptions("Cavity surface, unrolled about the canal's axis");
    options["parsing"] = false;
    options["scales"] = {
        {"x",
         {{"type", "linear"},
          {"min", -180},
          {"max", 180},
          {"title", {{"display", true}, {"text", "around the axis (degrees; 0 anterior, +90 the patient's left)"}}}}},
        {"y", {{"title", {{"display", true}, {"text", "from the internal os (mm)"}}}}}};
    return {{"type", "scatter"},
            {"data",
             {{"datasets",
               {{{"label", "seen"}, {"data", seen}, {"pointRadius", 1.5}, {"backgroundColor", io::chartColour(3)}},
                {{"label", "not seen"},
                 {"data", unseen},
                 {"pointRadius", 1.5},
                 {"backgroundColor", io::chartColour(2)}}}}}},
            {"options", options}};
}

ordered_json chartConfigs(const TrialReport& r) {
    auto charts = ordered_json::array();
    for (const ReportPlot& plot : reportPlots(r))
        charts.push_back(lineChart(plot));
    charts.push_back(surfaceChart(plottedSurface(r))); // the last canvas, below the plots over time
    return charts;
}

std::string pageHtml(const TrialReport& r, const std::string& library) {
    const std::string title = "Trial report: " + std::string(toString(r.header.exercise));
    std::string h =
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + htmlEscape(title) +
        "</title>\n<style>body{font-family:sans-serif;margin:1em;max-width:1300px}table{border-collapse:"
        "collapse;font-size:13px;margin-bottom:1em}td,th{border:1px solid #ccc;padding:2px 6px;"
        "text-align:left}table.kv th{background:#f4f4f4;font-weight:normal}.charts{display:flex;"
        "flex-wrap:wrap}.chart{width:620px;height:300px;margin:4px}.wide{width:1240px;height:420px;"
        "margin:4px}</style></head>\n<body>\n<h1>" +
        htmlEscape(title) + "</h1>\n<p>Scene " + htmlEscape(r.header.sceneSha256.substr(0, 12)) + ", seed " +
        std::to_string(r.header.seed) + ", " + fixedText(r.header.scope.opticDeg, 0) + "° optic, " +
        fixedText(r.header.scope.diameterMm, 1) + " mm scope, device " + htmlEscape(r.header.device) +
        (r.header.startedUtc.empty() ? std::string() : ", started " + htmlEscape(r.header.startedUtc)) + ".</p>\n";
    if (library.empty())
        h += "<p>No plots: the chart library (Debian's libjs-chart.js) is not installed.</p>\n";
    const std::size_t plots = reportPlots(r).size();
    h += "<h2>Over time</h2>\n<div class=\"charts\">\n";
    for (std::size_t i = 0; i < plots; ++i)
        h += io::chartCanvas(static_cast<int>(i));
    h += "</div>\n<h2>Visualized surface</h2>\n" + io::chartCanvas(static_cast<int>(plots), "wide");
    h += sectionsHtml(r);
    h += io::chartScripts(library, chartConfigs(r));
    return h + "</body></html>\n";
}

} // namespace

std::vector<ReportTable> reportTables(const TrialReport& r) {
    const TrialMetrics& m = r.metrics;
    std::vector<ReportTable> tables;
    tables.push_back(
        keyValues("Overview", {{"exercise", std::string(toString(r.header.exercise))},
                               {"time", seconds(m.timeS)},
                               {"device samples", std::to_string(r.samples)},
                               {"path length inside the body", fixedText(m.pathLengthMm, 0) + " mm"},
                               {"cavity surface visualized", fixedText(m.cavitySurfaceVisualizedPercent, 1) + " %"},
                               {"horizon error (mean / max)", fixedText(m.horizonErrorMeanDeg, 1) + "° / " +
                                                                  fixedText(m.horizonErrorMaxDeg, 1) + "°"},
                               {"exploration complete", yesNo(r.explorationComplete)},
                               {"diagnosis complete", yesNo(r.diagnosisComplete)}}));
    Rows targets;
    for (const ExplorationTarget& t : m.targets)
        targets.push_back({t.name, fixedText(t.visualizedPercent, 1) + " %", yesNo(t.seen), seconds(t.firstSeenS)});
    tables.push_back({"Exploration", {"target", "visualized", "seen", "first seen"}, std::move(targets)});
    tables.push_back(keyValues("Safety", {{"wall contacts", std::to_string(m.wallContacts)},
                                          {"peak force", fixedText(m.peakForceN, 2) + " N"},
                                          {"time in contact", seconds(m.contactTimeS)},
                                          {"perforations", std::to_string(m.perforations.size())}}));
    if (!m.perforations.empty()) {
        Rows rows;
        for (const Perforation& p : m.perforations)
            rows.push_back({seconds(p.timeS), p.falsePassage ? p.region + " (false passage)" : p.region,
                            fixedText(p.depthMm, 1) + " mm",
                            fixedText(p.locationMm.x, 1) + ", " + fixedText(p.locationMm.y, 1) + ", " +
                                fixedText(p.locationMm.z, 1)});
        tables.push_back({{}, {"time", "region", "depth", "where (mm)"}, std::move(rows)});
    }
    tables.push_back(keyValues(
        "Fluid",
        {{"medium", std::string(toString(r.header.fluid.medium)) +
                        (r.header.fluid.elderlyOrComorbid ? " (elderly or comorbid patient)" : "")},
         {"pump pressure (set at the start / at the end)",
          pressure(r.header.fluid.pumpPressureKpa) + " / " + pressure(m.finalPumpPressureKpa)},
         {"mean arterial pressure", pressure(r.header.fluid.meanArterialPressureKpa)},
         {"highest intrauterine pressure", pressure(m.maxPressureKpa)},
         {"time above mean arterial pressure", seconds(m.timeAboveMeanArterialPressureS)},
         {"inflow / outflow", fixedText(m.inflowMl, 0) + " mL / " + fixedText(m.outflowMl, 0) + " mL"},
         {"deficit", fixedText(m.deficitMl, 0) + " mL (warning at " + fixedText(r.header.fluid.deficitWarningMl, 0) +
                         " mL, limit " + fixedText(r.header.fluid.deficitLimitMl, 0) + " mL)"},
         {"deficit warning / limit reached", yesNo(m.deficitWarning) + " / " + yesNo(m.deficitLimitReached)},
         {"intravasation", fixedText(m.intravasationMl, 0) + " mL"},
         {"blood loss", fixedText(m.bloodLossMl, 1) + " mL"},
         {"red-out time", seconds(m.redOutTimeS)}}));
    Rows findings;
    for (const PathologyFinding& p : m.pathologies)
        findings.push_back({p.id, p.kind, yesNo(p.seen), yesNo(p.found), seconds(p.foundS)});
    tables.push_back({"Diagnosis", {"pathology", "kind", "seen", "marked", "marked at"}, std::move(findings)});
    tables.push_back(keyValues({}, {{"marks on no pathology", std::to_string(m.falseMarks)}}));
    const ResectionMetrics& cut = m.resection;
    if (!cut.pathologies.empty()) {
        Rows removed;
        for (const PathologyResection& p : cut.pathologies)
            removed.push_back({p.id, p.kind, fixedText(p.volumeMl, 3) + " mL", fixedText(p.removedMl, 3) + " mL",
                               fixedText(p.removedPercent, 1) + " %"});
        tables.push_back({"Resection", {"pathology", "kind", "volume", "removed", "removed (%)"}, std::move(removed)});
        tables.push_back(keyValues(
            {}, {{"healthy tissue removed", fixedText(cut.healthyRemovedMl, 3) + " mL"},
                 {"deepest cut into the myometrium", fixedText(cut.deepestMyometriumMm, 1) + " mm"},
                 {"cuts through the serosa", std::to_string(cut.perforatingCuts)},
                 {"resection time (first to last cut)", seconds(cut.resectionTimeS)},
                 {"cutting time (pedal down)", seconds(cut.cuttingTimeS)},
                 {"loop path with the pedal down", fixedText(cut.loopPathMm, 0) + " mm"},
                 {"coagulating time (pedal down)", seconds(cut.coagulationTimeS)},
                 {"cut events / pieces cut free", std::to_string(cut.cutEvents) + " / " + std::to_string(cut.chips)},
                 {"chips made / carried out / left in the cavity", std::to_string(cut.chipsMade) + " / " +
                                                                       std::to_string(cut.chipsCarriedOut) + " / " +
                                                                       std::to_string(cut.chipsLeft)}}));
    }
    return tables;
}

std::vector<SurfaceSample> plottedSurface(const TrialReport& report) {
    const std::vector<SurfaceSample>& surface = report.surface;
    const std::size_t stride = surface.size() / kMaxPlottedSurfaceSamples + 1;
    std::vector<SurfaceSample> plotted;
    plotted.reserve(surface.size() / stride + 1);
    for (std::size_t i = 0; i < surface.size(); i += stride)
        plotted.push_back(surface[i]);
    return plotted;
}

std::vector<ReportPlot> reportPlots(const TrialReport& r) {
    const auto& s = r.series;
    std::vector<ReportPlot> plots;
    plots.push_back({"Contact force", "N", {{"force", points(s, [](const SeriesPoint& p) { return p.forceN; })}}});
    plots.push_back({"Intrauterine pressure",
                     "kPa",
                     {{"pressure", points(s, [](const SeriesPoint& p) { return p.pressureKpa; })},
                      {"mean arterial pressure", level(s, r.header.fluid.meanArterialPressureKpa)},
                      {"pump set pressure", points(s, [](const SeriesPoint& p) { return p.pumpSetKpa; })}}});
    plots.push_back({"Fluid deficit",
                     "mL",
                     {{"deficit", points(s, [](const SeriesPoint& p) { return p.deficitMl; })},
                      {"warning", level(s, r.header.fluid.deficitWarningMl)},
                      {"limit", level(s, r.header.fluid.deficitLimitMl)}}});
    if (!r.metrics.resection.pathologies.empty())
        plots.push_back(
            {"Blood loss", "mL", {{"blood", points(s, [](const SeriesPoint& p) { return p.bloodLossMl; })}}});
    return plots;
}

std::string reportJson(const TrialReport& report) {
    JsonWriter w;
    w.open('{');
    w.field("format", std::string("hysteroscene-trial-report"));
    w.field("version", kReportVersion);
    writeHeader(w, report.header);
    w.field("samples", report.samples);
    w.field("explorationComplete", report.explorationComplete);
    w.field("diagnosisComplete", report.diagnosisComplete);
    writeMetrics(w, report.metrics);
    w.key("series");
    w.open('{');
    w.column("timeS", report.series, [](const SeriesPoint& p) { return p.timeS; });
    w.column("forceN", report.series, [](const SeriesPoint& p) { return p.forceN; });
    w.column("pressureKpa", report.series, [](const SeriesPoint& p) { return p.pressureKpa; });
    w.column("deficitMl", report.series, [](const SeriesPoint& p) { return p.deficitMl; });
    w.column("bloodLossMl", report.series, [](const SeriesPoint& p) { return p.bloodLossMl; });
    w.column("pumpSetKpa", report.series, [](const SeriesPoint& p) { return p.pumpSetKpa; });
    w.close('}');
    w.key("surface");
    w.open('{');
    w.column("aroundDeg", report.surface, [](const SurfaceSample& p) { return p.aroundDeg; });
    w.column("alongMm", report.surface, [](const SurfaceSample& p) { return p.alongMm; });
    w.column("seen", report.surface, [](const SurfaceSample& p) { return p.seen; });
    w.close('}');
    w.close('}');
    return w.text + "\n";
}

Result<std::string> reportHtml(const TrialReport& report, const std::string& chartLibrary) {
    auto library = io::readChartLibrary(chartLibrary);
    if (!library)
        return library.failure();
    return pageHtml(report, *library);
}

Status writeReport(const TrialReport& report, const std::string& jsonPath, const std::string& htmlPath) {
    HS_TRY(io::writeFileAtomically(jsonPath, reportJson(report)));
    if (htmlPath.empty())
        return {};
    auto page = reportHtml(report);
    if (!page)
        return page.failure();
    return io::writeFileAtomically(htmlPath, *page);
}

} // namespace hs::sim
