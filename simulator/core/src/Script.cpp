// Scripted trials: key frames of the device's degrees of freedom, played at 1 kHz.
#include "hs/sim/Script.h"

#include "hs/io/AtomicFile.h"
#include "hs/scene/JsonText.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace hs::sim {

namespace {

using nlohmann::json;
using nlohmann::ordered_json;

constexpr std::string_view kScriptFormat = "hysteroscene-script";
constexpr int kScriptVersion = 1;
/// A key frame with every member written takes ~200 bytes: the text limit follows from kMaxKeyFrames.
constexpr std::int64_t kMaxScriptBytes = static_cast<std::int64_t>(kMaxKeyFrames) * 400 + 4096;

std::uint64_t tickOf(double timeS) {
    return static_cast<std::uint64_t>(std::llround(timeS * kDeviceRateHz));
}

double lerp(double a, double b, double f) {
    return a + (b - a) * f;
}

/// The range of each sample field, for messages.
struct FieldRange {
    const char* name;
    double DeviceSample::*member;
    double lo, hi;
};
const FieldRange kFields[] = {
    {"insertionMm", &DeviceSample::insertionMm, kMinInsertionMm, kMaxInsertionMm},
    {"pitchDeg", &DeviceSample::pitchDeg, -kMaxPivotDeg, kMaxPivotDeg},
    {"yawDeg", &DeviceSample::yawDeg, -kMaxPivotDeg, kMaxPivotDeg},
    {"rollDeg", &DeviceSample::rollDeg, -kMaxRollDeg, kMaxRollDeg},
    {"cameraRollDeg", &DeviceSample::cameraRollDeg, -kMaxRollDeg, kMaxRollDeg},
    {"inflow", &DeviceSample::inflow, 0.0, 1.0},
    {"outflow", &DeviceSample::outflow, 0.0, 1.0},
    {"workingElementMm", &DeviceSample::workingElementMm, 0.0, kMaxWorkingElementMm},
};

void readKeyFrame(const json& item, const std::string& path, const KeyFrame* previous, KeyFrame& out,
                  scene::JsonIssues& issues) {
    scene::ObjectReader reader(item, path, issues);
    if (previous)
        out.sample = previous->sample;
    out.timeS = std::nan("");
    reader.read("t", out.timeS, true);
    if (const json* t = reader.member("t"); t && std::isfinite(out.timeS)) {
        if (out.timeS < 0.0 || out.timeS > kMaxScriptSeconds)
            issues.push_back({reader.pathOf("t"), scene::formatNumber(out.timeS) + " is outside 0.." +
                                                      scene::formatNumber(kMaxScriptSeconds) + " s"});
        else if (!previous && out.timeS != 0.0)
            issues.push_back({reader.pathOf("t"), "the first key frame must be at 0 s"});
        else if (previous && !(out.timeS > previous->timeS))
            issues.push_back({reader.pathOf("t"), scene::formatNumber(out.timeS) +
                                                      " is not after the previous key "
                                                      "frame's " +
                                                      scene::formatNumber(previous->timeS) + " s"});
    }
    for (const FieldRange& f : kFields) {
        double& value = out.sample.*f.member;
        if (!reader.member(f.name))
            continue;
        reader.read(f.name, value);
        if (!(value >= f.lo && value <= f.hi))
            issues.push_back({reader.pathOf(f.name), scene::formatNumber(value) + " is outside " +
                                                         scene::formatNumber(f.lo) + ".." + scene::formatNumber(f.hi)});
    }
    if (reader.member("buttons")) {
        std::uint64_t buttons = out.sample.buttons;
        reader.read("buttons", buttons);
        if (buttons & ~std::uint64_t{kKnownButtons})
            issues.push_back({reader.pathOf("buttons"),
                              std::to_string(buttons) + " has bits other than " + std::to_string(kKnownButtons) +
                                  " (1 mark, 2 capture, 4 cut, 8 coagulate, 16 pump up, 32 pump down)"});
        else
            out.sample.buttons = static_cast<std::uint32_t>(buttons);
    }
    if (reader.member("instrument")) {
        std::uint64_t instrument = out.sample.instrument;
        reader.read("instrument", instrument);
        if (instrument > kMaxInstrument)
            issues.push_back({reader.pathOf("instrument"), std::to_string(instrument) + " is outside 0.." +
                                                               std::to_string(kMaxInstrument) +
                                                               " (0 none, 1 loop, 2 scissors, 3 grasper)"});
        else
            out.sample.instrument = static_cast<std::uint32_t>(instrument);
    }
    reader.finish();
}

void readScriptFields(const json& document, Script& script, scene::JsonIssues& issues) {
    scene::ObjectReader root(document, "", issues);
    std::string format;
    root.read("format", format, true);
    if (root.member("format") && format != kScriptFormat)
        issues.push_back({"/format", scene::quoteText(format) + " is not \"" + std::string(kScriptFormat) + "\""});
    int version = 0;
    root.read("version", version, true);
    if (root.member("version") && version != kScriptVersion)
        issues.push_back({"/version", std::to_string(version) + " is not the version this build reads (" +
                                          std::to_string(kScriptVersion) + ")"});
    const json* frames = root.member("keyframes", true);
    root.finish();
    if (!frames)
        return;
    if (!frames->is_array()) {
        scene::typeIssue(issues, "/keyframes", "an array", *frames);
        return;
    }
    if (frames->empty() || frames->size() > kMaxKeyFrames) {
        issues.push_back({"/keyframes", std::to_string(frames->size()) + " key frames (allowed: 1.." +
                                            std::to_string(kMaxKeyFrames) + ")"});
        return;
    }
    script.keyframes.reserve(frames->size());
    for (std::size_t i = 0; i < frames->size() && issues.size() < 100; ++i) {
        KeyFrame frame;
        readKeyFrame((*frames)[i], "/keyframes/" + std::to_string(i),
                     script.keyframes.empty() ? nullptr : &script.keyframes.back(), frame, issues);
        script.keyframes.push_back(frame);
    }
}

/// One linear pass over the text that records keys repeated within an object and nesting deeper than `maxDepth`.
/// (The shared strict reader, scene::parseJsonObject, goes through nlohmann's callback parser, which rescans an
/// array at the end of each object in it: quadratic for the 100k key frames a long script may hold.)
class StrictnessCheck final : public nlohmann::json_sax<json> {
public:
    StrictnessCheck(int maxDepth, scene::JsonIssues& issues) : m_maxDepth(maxDepth), m_issues(issues) {}
    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return open(false); }
    bool key(string_t& key) override {
        Level& top = m_levels.back();
        top.key = key;
        if (std::find(top.keys.begin(), top.keys.end(), key) != top.keys.end())
            m_issues.push_back({path(), "duplicate key " + scene::quoteText(key) + " (each field once)"});
        else
            top.keys.push_back(key);
        return true;
    }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(true); }
    bool end_array() override { return close(); }
    bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) override {
        const std::string what = e.what();
        const auto cut = what.find("] ");
        const std::string where = path();
        m_syntax = (where.empty() ? "(root)" : where) + " (byte " + std::to_string(position) +
                   "): not valid JSON: " + (cut == std::string::npos ? what : what.substr(cut + 2));
        return false;
    }
    const std::string& syntaxError() const { return m_syntax; }

private:
    struct Level {
        bool array = false;
        std::size_t index = 0;
        std::string key;
        std::vector<std::string> keys; ///< an object here has a dozen members at most
    };
    std::string path() const {
        std::string p;
        for (const Level& l : m_levels)
            p += "/" + (l.array ? std::to_string(l.index) : scene::escapePointerToken(l.key));
        return p;
    }
    bool value() {
        if (!m_levels.empty() && m_levels.back().array)
            ++m_levels.back().index;
        return true;
    }
    bool open(bool array) {
        if (static_cast<int>(m_levels.size()) >= m_maxDepth) {
            m_syntax = path() + ": nested deeper than " + std::to_string(m_maxDepth);
            return false;
        }
        m_levels.push_back({array, 0, {}, {}});
        return true;
    }
    bool close() {
        m_levels.pop_back();
        return value();
    }
    int m_maxDepth;
    scene::JsonIssues& m_issues;
    std::vector<Level> m_levels;
    std::string m_syntax;
};

} // namespace

std::uint64_t Script::tickCount() const {
    return keyframes.empty() ? 0 : tickOf(keyframes.back().timeS) + 1;
}

DeviceSample Script::sampleAt(std::uint64_t tick) const {
    DeviceSample s;
    if (!keyframes.empty()) {
        const double t = static_cast<double>(std::min(tick, tickCount() - 1)) / kDeviceRateHz;
        // The first key frame after t; the one before it holds the buttons.
        const auto next = std::upper_bound(keyframes.begin(), keyframes.end(), t,
                                           [](double time, const KeyFrame& k) { return time < k.timeS; });
        if (next == keyframes.begin()) {
            s = next->sample;
        } else if (next == keyframes.end()) {
            s = keyframes.back().sample;
        } else {
            const KeyFrame& a = *(next - 1);
            const KeyFrame& b = *next;
            const double f = (t - a.timeS) / (b.timeS - a.timeS);
            s = a.sample;
            for (const FieldRange& field : kFields)
                s.*field.member = lerp(a.sample.*field.member, b.sample.*field.member, f);
        }
    }
    s.tick = tick;
    return s;
}

Result<Script> parseScript(const std::string& text, const std::string& name) {
    if (static_cast<std::int64_t>(text.size()) > kMaxScriptBytes)
        return fail(ErrorCode::LimitExceeded, name + ": " + std::to_string(text.size()) + " bytes, more than the " +
                                                  std::to_string(kMaxScriptBytes) + "-byte limit of a script");
    try {
        scene::JsonIssues issues;
        StrictnessCheck check(4, issues);
        if (!json::sax_parse(text, &check))
            return fail(ErrorCode::InvalidInput, name + ": " + check.syntaxError());
        if (!issues.empty())
            return scene::failWithIssues(name, issues);
        const json document = json::parse(text);
        if (!document.is_object())
            return fail(ErrorCode::InvalidInput, name + ": (root): expected an object (a script)");
        Script script;
        readScriptFields(document, script, issues);
        if (!issues.empty())
            return scene::failWithIssues(name, issues);
        return script;
    } catch (const json::exception& e) { // a reader bug must not throw across the boundary
        return fail(ErrorCode::Internal, name + ": unexpected JSON error: " + std::string(e.what()));
    }
}

Result<Script> readScript(const std::string& path) {
    auto text = io::readFile(path, kMaxScriptBytes);
    if (!text)
        return text.failure();
    return parseScript(*text, path);
}

std::string scriptJson(const Script& script) {
    ordered_json j;
    j["format"] = kScriptFormat;
    j["version"] = kScriptVersion;
    j["keyframes"] = ordered_json::array();
    for (const KeyFrame& k : script.keyframes) {
        ordered_json f;
        f["t"] = k.timeS;
        for (const FieldRange& field : kFields)
            f[field.name] = k.sample.*field.member;
        f["buttons"] = k.sample.buttons;
        f["instrument"] = k.sample.instrument;
        j["keyframes"].push_back(std::move(f));
    }
    return j.dump(1) + "\n";
}

Status writeScript(const Script& script, const std::string& path) {
    // Written scripts must read back: the same rules as parseScript.
    const std::string text = scriptJson(script);
    auto back = parseScript(text, path);
    if (!back)
        return back.failure();
    return io::writeFileAtomically(path, text);
}

} // namespace hs::sim
