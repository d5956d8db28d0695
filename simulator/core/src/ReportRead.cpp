// Reading a trial report back (the workstation's review of a trial). A report is an external file like any other:
// every member is checked for its type and range, and an error names the file, the member's JSON pointer and what is
// allowed (docs/file-formats.md, "Trial reports").
#include "TrialJson.h"
#include "hs/io/AtomicFile.h"
#include "hs/scene/JsonText.h"
#include "hs/sim/Metrics.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <initializer_list>
#include <type_traits>
#include <utility>

namespace hs::sim {

namespace {

using nlohmann::json;
using scene::JsonIssues;
using scene::ObjectReader;

constexpr std::string_view kFormat = "hysteroscene-trial-report";
constexpr int kOldestVersion = 1; // 1: no pump column in the series
constexpr int kVersion = 2;
/// The longest trial a report may describe, s (a trial file holds at most four hours of samples).
constexpr double kMaxTrialS = 4.0 * 3600.0;
constexpr std::size_t kMaxNameBytes = 256;

/// Records an issue when `v` is outside [lo, hi]; `range` says the allowed range in the message.
void inRange(JsonIssues& issues, const std::string& path, double v, double lo, double hi, const std::string& range) {
    if (!(v >= lo && v <= hi))
        issues.push_back({path, scene::formatNumber(v) + " is outside " + range});
}

/// The member `key` read as a double within [lo, hi].
void readBounded(ObjectReader& o, const char* key, double& out, double lo, double hi, const std::string& range,
                 bool required = true) {
    if (const json* v = o.member(key, required))
        if (scene::readValue(*v, o.pathOf(key), out, o.issues()))
            inRange(o.issues(), o.pathOf(key), out, lo, hi, range);
}

const std::string kTimeRange = "0-14400 s";
const std::string kWhenRange = "-1 (never) or 0-14400 s";
const std::string kPercentRange = "0-100 %";
const std::string kVolumeRange = "0-100000 mL";
const std::string kPressureRange = "-100-100 kPa";

void readTime(ObjectReader& o, const char* key, double& out) {
    readBounded(o, key, out, 0.0, kMaxTrialS, kTimeRange);
}
/// A moment that may never have come (-1).
void readWhen(ObjectReader& o, const char* key, double& out) {
    readBounded(o, key, out, -1.0, kMaxTrialS, kWhenRange);
    if (out < 0.0 && out != -1.0)
        o.issues().push_back({o.pathOf(key), scene::formatNumber(out) + " is outside " + kWhenRange});
}
void readVolume(ObjectReader& o, const char* key, double& out) {
    readBounded(o, key, out, 0.0, 1e5, kVolumeRange);
}
void readName(ObjectReader& o, const char* key, std::string& out) {
    o.read(key, out, true);
    if (out.size() > kMaxNameBytes)
        o.issues().push_back({o.pathOf(key), "is longer than " + std::to_string(kMaxNameBytes) + " bytes"});
}

/// The array member `key` of at most `maxCount` entries, or nullptr (an issue recorded where it is not one).
const json* arrayMember(ObjectReader& o, const char* key, std::size_t maxCount, bool required = true) {
    const json* v = o.member(key, required);
    if (!v)
        return nullptr;
    if (!v->is_array()) {
        scene::typeIssue(o.issues(), o.pathOf(key), "an array", *v);
        return nullptr;
    }
    if (v->size() > maxCount) {
        o.issues().push_back({o.pathOf(key), std::to_string(v->size()) + " entries, more than the " +
                                                 std::to_string(maxCount) + " a report may hold"});
        return nullptr;
    }
    return v;
}

/// The array member `key` (at most `maxCount` entries), each read by `each(element, path)`.
template <class Each>
void readList(ObjectReader& o, const char* key, std::size_t maxCount, Each each) {
    if (const json* v = arrayMember(o, key, maxCount))
        for (std::size_t i = 0; i < v->size(); ++i)
            each((*v)[i], o.pathOf(key) + "/" + std::to_string(i));
}

/// A column of numbers within [lo, hi]; one issue for the first bad entry (a column may hold millions).
template <class T>
void readColumn(ObjectReader& o, const char* key, std::vector<T>& out, std::size_t maxCount, double lo, double hi,
                const std::string& range, bool required = true) {
    const json* v = arrayMember(o, key, maxCount, required);
    if (!v)
        return;
    const std::string path = o.pathOf(key);
    out.reserve(v->size());
    for (std::size_t i = 0; i < v->size(); ++i) {
        T value{};
        if (!scene::readValue((*v)[i], path + "/" + std::to_string(i), value, o.issues()))
            return;
        if constexpr (std::is_floating_point_v<T>) {
            if (!(value >= lo && value <= hi)) {
                inRange(o.issues(), path + "/" + std::to_string(i), value, lo, hi, range);
                return;
            }
        }
        out.push_back(value);
    }
}

void readTargets(ObjectReader& m, std::vector<ExplorationTarget>& targets, const ReportReadLimits& limits) {
    readList(m, "targets", limits.maxListed, [&](const json& v, const std::string& path) {
        ObjectReader o(v, path, m.issues());
        ExplorationTarget t;
        readName(o, "name", t.name);
        readBounded(o, "visualizedPercent", t.visualizedPercent, 0.0, 100.0, kPercentRange);
        o.read("seen", t.seen, true);
        readWhen(o, "firstSeenS", t.firstSeenS);
        o.finish();
        targets.push_back(std::move(t));
    });
}

void readPerforations(ObjectReader& m, std::vector<Perforation>& perforations, const ReportReadLimits& limits) {
    readList(m, "perforations", limits.maxListed, [&](const json& v, const std::string& path) {
        ObjectReader o(v, path, m.issues());
        Perforation p;
        readTime(o, "timeS", p.timeS);
        o.read("locationMm", p.locationMm, true);
        for (double c : {p.locationMm.x, p.locationMm.y, p.locationMm.z})
            inRange(o.issues(), o.pathOf("locationMm"), c, -1e4, 1e4, "-10000-10000 mm");
        readBounded(o, "depthMm", p.depthMm, 0.0, 1e4, "0-10000 mm");
        readName(o, "region", p.region);
        o.read("falsePassage", p.falsePassage);
        o.finish();
        perforations.push_back(std::move(p));
    });
}

void readFindings(ObjectReader& m, std::vector<PathologyFinding>& findings, const ReportReadLimits& limits) {
    readList(m, "pathologies", limits.maxListed, [&](const json& v, const std::string& path) {
        ObjectReader o(v, path, m.issues());
        PathologyFinding p;
        readName(o, "id", p.id);
        readName(o, "kind", p.kind);
        o.read("seen", p.seen, true);
        o.read("found", p.found, true);
        readWhen(o, "foundS", p.foundS);
        o.finish();
        findings.push_back(std::move(p));
    });
}

void readCount(ObjectReader& o, const char* key, int& out) {
    o.read(key, out, true);
    if (out < 0)
        o.issues().push_back({o.pathOf(key), std::to_string(out) + " is negative (a count)"});
}

void readResection(ObjectReader& m, ResectionMetrics& r, const ReportReadLimits& limits) {
    const json* v = m.member("resection");
    if (!v)
        return; // not an operative exercise
    ObjectReader o(*v, m.pathOf("resection"), m.issues());
    readList(o, "pathologies", limits.maxListed, [&](const json& e, const std::string& path) {
        ObjectReader p(e, path, o.issues());
        PathologyResection item;
        readName(p, "id", item.id);
        readName(p, "kind", item.kind);
        readVolume(p, "volumeMl", item.volumeMl);
        readVolume(p, "removedMl", item.removedMl);
        readBounded(p, "removedPercent", item.removedPercent, 0.0, 100.0, kPercentRange);
        p.finish();
        r.pathologies.push_back(std::move(item));
    });
    readVolume(o, "healthyRemovedMl", r.healthyRemovedMl);
    readBounded(o, "deepestMyometriumMm", r.deepestMyometriumMm, 0.0, 1e4, "0-10000 mm");
    readCount(o, "perforatingCuts", r.perforatingCuts);
    o.read("cutEvents", r.cutEvents, true);
    o.read("removedTets", r.removedTets, true);
    o.read("chips", r.chips, true);
    o.read("chipsMade", r.chipsMade, true);
    o.read("chipsCarriedOut", r.chipsCarriedOut, true);
    o.read("chipsLeft", r.chipsLeft, true);
    readTime(o, "cuttingTimeS", r.cuttingTimeS);
    readTime(o, "resectionTimeS", r.resectionTimeS);
    readWhen(o, "firstCutS", r.firstCutS);
    readBounded(o, "loopPathMm", r.loopPathMm, 0.0, 1e7, "0-10000000 mm");
    readTime(o, "coagulationTimeS", r.coagulationTimeS);
    o.finish();
}

void readMetrics(ObjectReader& root, TrialMetrics& m, const ReportReadLimits& limits) {
    const json* v = root.member("metrics", true);
    if (!v)
        return;
    ObjectReader o(*v, root.pathOf("metrics"), root.issues());
    readTime(o, "timeS", m.timeS);
    readBounded(o, "pathLengthMm", m.pathLengthMm, 0.0, 1e7, "0-10000000 mm");
    readBounded(o, "cavitySurfaceVisualizedPercent", m.cavitySurfaceVisualizedPercent, 0.0, 100.0, kPercentRange);
    readTargets(o, m.targets, limits);
    readBounded(o, "horizonErrorMeanDeg", m.horizonErrorMeanDeg, 0.0, 180.0, "0-180°");
    readBounded(o, "horizonErrorMaxDeg", m.horizonErrorMaxDeg, 0.0, 180.0, "0-180°");
    readCount(o, "wallContacts", m.wallContacts);
    readBounded(o, "peakForceN", m.peakForceN, 0.0, 1e4, "0-10000 N");
    readTime(o, "contactTimeS", m.contactTimeS);
    readPerforations(o, m.perforations, limits);
    readTime(o, "timeAboveMeanArterialPressureS", m.timeAboveMeanArterialPressureS);
    readBounded(o, "maxPressureKpa", m.maxPressureKpa, -100.0, 100.0, kPressureRange);
    readVolume(o, "inflowMl", m.inflowMl);
    readVolume(o, "outflowMl", m.outflowMl);
    readBounded(o, "deficitMl", m.deficitMl, -1e5, 1e5, "-100000-100000 mL");
    readVolume(o, "intravasationMl", m.intravasationMl);
    readVolume(o, "bloodLossMl", m.bloodLossMl);
    readBounded(o, "finalPumpPressureKpa", m.finalPumpPressureKpa, 0.0, 100.0, "0-100 kPa");
    o.read("deficitWarning", m.deficitWarning, true);
    o.read("deficitLimitReached", m.deficitLimitReached, true);
    readTime(o, "redOutTimeS", m.redOutTimeS);
    readFindings(o, m.pathologies, limits);
    readCount(o, "falseMarks", m.falseMarks);
    readResection(o, m.resection, limits);
    o.finish();
}

/// Every column of `columns` has `n` entries.
void sameLengths(ObjectReader& o, std::initializer_list<std::pair<const char*, std::size_t>> columns, std::size_t n) {
    for (const auto& [key, size] : columns)
        if (size != n && o.member(key))
            o.issues().push_back({o.pathOf(key), std::to_string(size) + " entries where the first column has " +
                                                     std::to_string(n) + " (the columns must have equal lengths)"});
}

void readSeries(ObjectReader& root, TrialReport& r, int version, const ReportReadLimits& limits) {
    const json* v = root.member("series", true);
    if (!v)
        return;
    ObjectReader o(*v, root.pathOf("series"), root.issues());
    std::vector<double> time, force, pressure, deficit, blood, pump;
    const std::size_t n = limits.maxSeries;
    readColumn(o, "timeS", time, n, 0.0, kMaxTrialS, kTimeRange);
    readColumn(o, "forceN", force, n, 0.0, 1e4, "0-10000 N");
    readColumn(o, "pressureKpa", pressure, n, -100.0, 100.0, kPressureRange);
    readColumn(o, "deficitMl", deficit, n, -1e5, 1e5, "-100000-100000 mL");
    readColumn(o, "bloodLossMl", blood, n, 0.0, 1e5, kVolumeRange);
    // Reports of version 1 have no pump column: their pump stayed at the header's pressure as far as they tell.
    readColumn(o, "pumpSetKpa", pump, n, 0.0, 100.0, "0-100 kPa", version >= 2);
    o.finish();
    if (version < 2 && !o.member("pumpSetKpa"))
        pump.assign(time.size(), r.header.fluid.pumpPressureKpa);
    sameLengths(o,
                {{"forceN", force.size()},
                 {"pressureKpa", pressure.size()},
                 {"deficitMl", deficit.size()},
                 {"bloodLossMl", blood.size()},
                 {"pumpSetKpa", pump.size()}},
                time.size());
    for (std::size_t i = 1; i < time.size(); ++i)
        if (!(time[i] > time[i - 1])) {
            o.issues().push_back(
                {o.pathOf("timeS") + "/" + std::to_string(i), "times must increase (" + scene::formatNumber(time[i]) +
                                                                  " after " + scene::formatNumber(time[i - 1]) + ")"});
            return;
        }
    if (time.size() != force.size() || time.size() != pressure.size() || time.size() != deficit.size() ||
        time.size() != blood.size() || time.size() != pump.size())
        return;
    r.series.resize(time.size());
    for (std::size_t i = 0; i < time.size(); ++i)
        r.series[i] = {time[i], force[i], pressure[i], deficit[i], blood[i], pump[i]};
}

void readSurface(ObjectReader& root, TrialReport& r, const ReportReadLimits& limits) {
    const json* v = root.member("surface", true);
    if (!v)
        return;
    ObjectReader o(*v, root.pathOf("surface"), root.issues());
    std::vector<double> around, along;
    std::vector<bool> seen;
    const std::size_t n = limits.maxSurface;
    readColumn(o, "aroundDeg", around, n, -360.0, 360.0, "-360-360°");
    readColumn(o, "alongMm", along, n, -1e4, 1e4, "-10000-10000 mm");
    readColumn(o, "seen", seen, n, 0.0, 1.0, {});
    o.finish();
    sameLengths(o, {{"alongMm", along.size()}, {"seen", seen.size()}}, around.size());
    if (around.size() != along.size() || around.size() != seen.size())
        return;
    r.surface.resize(around.size());
    for (std::size_t i = 0; i < around.size(); ++i)
        r.surface[i] = {around[i], along[i], seen[i]};
}

void readReportFields(const json& document, TrialReport& r, JsonIssues& issues, const ReportReadLimits& limits,
                      int& version) {
    ObjectReader root(document, "", issues);
    std::string format;
    root.read("format", format, true);
    if (root.member("format") && format != kFormat)
        issues.push_back({"/format", scene::quoteText(format) + " is not \"" + std::string(kFormat) + "\""});
    root.read("version", version, true);
    if (root.member("version") && (version < kOldestVersion || version > kVersion))
        issues.push_back({"/version", std::to_string(version) + " is not a version this build reads (" +
                                          std::to_string(kOldestVersion) + "-" + std::to_string(kVersion) + ")"});
    if (const json* h = root.member("header", true)) {
        ObjectReader header(*h, root.pathOf("header"), issues);
        detail::readHeaderMembers(header, r.header);
        header.finish();
    }
    root.read("samples", r.samples, true);
    root.read("explorationComplete", r.explorationComplete, true);
    root.read("diagnosisComplete", r.diagnosisComplete, true);
    readMetrics(root, r.metrics, limits);
    readSeries(root, r, version, limits);
    readSurface(root, r, limits);
    root.finish();
}

} // namespace

Result<TrialReport> parseReport(std::string_view text, const std::string& name, const ReportReadLimits& limits) {
    scene::JsonDocumentLimits documentLimits;
    documentLimits.maxBytes = limits.maxBytes;
    documentLimits.maxDepth = 6;
    documentLimits.maxStringBytes = 4096;
    documentLimits.kind = "trial report";
    int version = 0;
    auto report = scene::parseJsonDocument<TrialReport>(text, name, documentLimits,
                                                        [&](const json& document, TrialReport& r, JsonIssues& issues) {
                                                            readReportFields(document, r, issues, limits, version);
                                                        });
    if (!report)
        return report.failure();
    HS_TRY(detail::checkHeader(report->header, name));
    return report;
}

Result<TrialReport> readReport(const std::string& path, const ReportReadLimits& limits) {
    auto text = io::readFile(path, limits.maxBytes);
    if (!text)
        return text.failure();
    return parseReport(*text, path, limits);
}

} // namespace hs::sim
