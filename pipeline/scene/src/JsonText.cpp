// Text of values and ranges in messages, and the strict reading of untrusted JSON documents (hs/scene/JsonText.h).
#include "Format.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

namespace hs::scene {

namespace {

using nlohmann::json;

constexpr std::size_t kMaxReportedIssues = 20;

} // namespace

/// Scanned before parsing so that "[[[[..." never reaches the parser.
int jsonNestingDepth(std::string_view text) {
    int depth = 0;
    int deepest = 0;
    bool inString = false;
    bool escaped = false;
    for (const char c : text) {
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return deepest;
}

namespace {

/// Follows the parser's events to know the JSON path of each key: records keys repeated within one object
/// (nlohmann keeps the last silently; a case file must not be ambiguous) and tells where a syntax error happened.
class ParseTracker {
public:
    ParseTracker(std::vector<CaseIssue>& issues, std::size_t maxStringBytes)
        : m_issues(issues), m_maxStringBytes(maxStringBytes) {}

    bool onEvent(json::parse_event_t event, json& parsed) {
        switch (event) {
        case json::parse_event_t::object_start:
            m_frames.push_back({false, 0, {}, {}});
            break;
        case json::parse_event_t::array_start:
            m_frames.push_back({true, 0, {}, {}});
            break;
        case json::parse_event_t::key:
            if (!m_frames.empty()) {
                Frame& top = m_frames.back();
                top.key = parsed.get<std::string>();
                checkLength(top.key, "key");
                if (!top.keys.insert(top.key).second)
                    m_issues.push_back({currentPath(), "duplicate key " + quoteText(top.key) + " (each field once)"});
            }
            break;
        case json::parse_event_t::value:
            if (parsed.is_string())
                checkLength(parsed.get_ref<const std::string&>(), "string");
            elementDone();
            break;
        case json::parse_event_t::object_end:
        case json::parse_event_t::array_end:
            if (!m_frames.empty())
                m_frames.pop_back();
            elementDone();
            break;
        }
        return true;
    }

    /// Path of the value being read ("" at the root).
    std::string currentPath() const {
        std::string path;
        for (const Frame& f : m_frames)
            path += "/" + (f.array ? std::to_string(f.index) : escapePointerToken(f.key));
        return path;
    }

private:
    struct Frame {
        bool array;
        std::size_t index;
        std::string key;
        std::set<std::string> keys;
    };

    void checkLength(const std::string& text, const char* what) {
        if (text.size() > m_maxStringBytes)
            m_issues.push_back({currentPath(), std::string(what) + " of " + std::to_string(text.size()) +
                                                   " bytes, above the limit of " + std::to_string(m_maxStringBytes)});
    }

    void elementDone() {
        if (!m_frames.empty() && m_frames.back().array)
            ++m_frames.back().index;
    }

    std::vector<CaseIssue>& m_issues;
    std::size_t m_maxStringBytes;
    std::vector<Frame> m_frames;
};

/// "[json.exception.parse_error.101] parse error at line 2, ..." -> "parse error at line 2, ...".
std::string parserMessage(const std::string& what) {
    const auto pos = what.find("] ");
    return pos == std::string::npos ? what : what.substr(pos + 2);
}

} // namespace

Result<json> parseJsonObject(std::string_view text, const std::string& sourceName, const JsonDocumentLimits& limits,
                             std::vector<CaseIssue>& issues) {
    const std::string kind(limits.kind);
    if (static_cast<std::int64_t>(text.size()) > limits.maxBytes)
        return fail(ErrorCode::LimitExceeded, sourceName + ": " + std::to_string(text.size()) +
                                                  " bytes, more than the " + std::to_string(limits.maxBytes) +
                                                  "-byte limit of a " + kind);
    if (const int depth = jsonNestingDepth(text); depth > limits.maxDepth)
        return fail(ErrorCode::InvalidInput, sourceName + ": arrays and objects nested " + std::to_string(depth) +
                                                 " deep (a " + kind + " nests at most " +
                                                 std::to_string(limits.maxDepth) + ")");
    ParseTracker tracker(issues, limits.maxStringBytes);
    json document;
    try {
        document = json::parse(text.begin(), text.end(), [&tracker](int, json::parse_event_t event, json& parsed) {
            return tracker.onEvent(event, parsed);
        });
    } catch (const json::exception& e) { // parse_error, or out_of_range for numbers such as 1e999
        const std::string path = tracker.currentPath();
        return fail(ErrorCode::InvalidInput, sourceName + ": " + (path.empty() ? "(root)" : path) +
                                                 ": not valid JSON: " + parserMessage(e.what()));
    }
    if (!document.is_object())
        return fail(ErrorCode::InvalidInput, sourceName + ": (root): expected an object (a " + kind +
                                                 " is a JSON object), got " + std::string(document.type_name()));
    return document;
}

Failure failWithIssues(const std::string& sourceName, const std::vector<CaseIssue>& issues) {
    std::string detail;
    const std::size_t shown = std::min(issues.size(), kMaxReportedIssues);
    for (std::size_t i = 0; i < shown; ++i)
        detail += (i ? "\n" : "") + sourceName + ": " + issues[i].text();
    if (issues.size() > shown)
        detail += "\n" + sourceName + ": ... and " + std::to_string(issues.size() - shown) + " more problems";
    return fail(ErrorCode::InvalidInput, detail);
}

std::string formatNumber(double value) {
    if (std::isnan(value))
        return "nan";
    if (std::isinf(value))
        return value > 0 ? "inf" : "-inf";
    char buffer[32];
    // Whole numbers in plain digits (1000000000, not 1e+09): limits and counts read better that way.
    if (std::floor(value) == value && std::fabs(value) < 1e15) {
        const auto whole = std::to_chars(buffer, buffer + sizeof buffer, static_cast<long long>(value));
        return std::string(buffer, whole.ptr);
    }
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string formatRange(const Range& range) {
    return formatNumber(range.min) + ".." + formatNumber(range.max);
}

std::string quoteText(std::string_view text) {
    constexpr std::size_t kMaxShown = 60;
    std::string out = "\"";
    const bool cut = text.size() > kMaxShown;
    for (const char c : text.substr(0, kMaxShown)) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
            out += escaped;
        } else {
            out += c;
        }
    }
    out += cut ? "...\"" : "\"";
    return out;
}

std::string escapePointerToken(std::string_view token) {
    std::string out;
    for (const char c : token) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

/// "an integer 3", "a string \"x\"", "an object": what was found, for type errors.
std::string describeValue(const json& value) {
    switch (value.type()) {
    case json::value_t::null:
        return "null";
    case json::value_t::boolean:
        return value.get<bool>() ? "true" : "false";
    case json::value_t::string:
        return "string " + quoteText(value.get_ref<const std::string&>());
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
        return "integer " + value.dump();
    case json::value_t::number_float:
        return "number " + formatNumber(value.get<double>());
    case json::value_t::array:
        return "an array";
    case json::value_t::object:
        return "an object";
    default:
        return value.type_name();
    }
}

void typeIssue(JsonIssues& issues, const std::string& path, std::string_view expected, const json& value) {
    issues.push_back({path, "expected " + std::string(expected) + ", got " + describeValue(value)});
}

// ---- Scalar readers: return false (and record an issue) when the value has the wrong type. ----

bool readValue(const json& v, const std::string& path, double& out, JsonIssues& issues) {
    if (!v.is_number()) {
        typeIssue(issues, path, "a number", v);
        return false;
    }
    const double d = v.get<double>();
    if (!std::isfinite(d)) { // e.g. 1e999, which the parser turns into infinity
        issues.push_back({path, "non-finite value " + formatNumber(d) + " (numbers must be finite)"});
        return false;
    }
    out = d;
    return true;
}

bool readValue(const json& v, const std::string& path, int& out, JsonIssues& issues) {
    if (!v.is_number_integer()) {
        typeIssue(issues, path, "an integer", v);
        return false;
    }
    const bool fits = v.is_number_unsigned() ? v.get<unsigned long long>() <=
                                                   static_cast<unsigned long long>(std::numeric_limits<int>::max())
                                             : v.get<long long>() >= std::numeric_limits<int>::min();
    if (!fits) {
        issues.push_back({path, v.dump() + " is too large for this field"});
        return false;
    }
    out = v.get<int>();
    return true;
}

bool readValue(const json& v, const std::string& path, std::uint64_t& out, JsonIssues& issues) {
    if (!v.is_number_unsigned()) { // negative integers are number_integer
        typeIssue(issues, path, "an unsigned integer 0..18446744073709551615", v);
        return false;
    }
    out = v.get<std::uint64_t>();
    return true;
}

bool readValue(const json& v, const std::string& path, bool& out, JsonIssues& issues) {
    if (!v.is_boolean()) {
        typeIssue(issues, path, "true or false", v);
        return false;
    }
    out = v.get<bool>();
    return true;
}

bool readValue(const json& v, const std::string& path, std::string& out, JsonIssues& issues) {
    if (!v.is_string()) {
        typeIssue(issues, path, "a string", v);
        return false;
    }
    out = v.get<std::string>();
    return true;
}

bool readValue(const json& v, const std::string& path, clinical::PathologyKind& out, JsonIssues& issues) {
    return readEnum(v, path, out, clinical::kPathologyKinds, issues);
}
bool readValue(const json& v, const std::string& path, clinical::GrowthModel& out, JsonIssues& issues) {
    return readEnum(v, path, out, clinical::kGrowthModels, issues);
}
bool readValue(const json& v, const std::string& path, clinical::UterineLocation& out, JsonIssues& issues) {
    return readEnum(v, path, out, clinical::kUterineLocations, issues);
}
bool readValue(const json& v, const std::string& path, clinical::PolypAttachment& out, JsonIssues& issues) {
    return readEnum(v, path, out, clinical::kPolypAttachments, issues);
}
bool readValue(const json& v, const std::string& path, ShapeMode& out, JsonIssues& issues) {
    return readEnum(v, path, out, kShapeModes, issues);
}
bool readValue(const json& v, const std::string& path, MeshingMethod& out, JsonIssues& issues) {
    return readEnum(v, path, out, kMeshingMethods, issues);
}
bool readValue(const json& v, const std::string& path, MeshingSeeding& out, JsonIssues& issues) {
    return readEnum(v, path, out, kMeshingSeedings, issues);
}
bool readValue(const json& v, const std::string& path, clinical::CyclePhase& out, JsonIssues& issues) {
    return readEnum(v, path, out, clinical::kCyclePhases, issues);
}

/// A FIGO type: an integer (2) or a string ("2", "2-5"). Range rules are checkCase()'s.
bool readValue(const json& v, const std::string& path, clinical::FigoType& out, JsonIssues& issues) {
    constexpr std::string_view kExpected = "a FIGO type: an integer 0..8 or a string such as \"2-5\"";
    if (v.is_number_integer()) {
        int type = 0;
        if (!readValue(v, path, type, issues))
            return false;
        out = clinical::FigoType{type, -1};
        return true;
    }
    if (v.is_string()) {
        if (auto figo = clinical::FigoType::parse(v.get_ref<const std::string&>())) {
            out = *figo;
            return true;
        }
        issues.push_back({path, quoteText(v.get_ref<const std::string&>()) + " is not " + std::string(kExpected)});
        return false;
    }
    typeIssue(issues, path, kExpected, v);
    return false;
}

bool readValue(const json& v, const std::string& path, Vec3& out, JsonIssues& issues) {
    if (!v.is_array() || v.size() != 3) {
        typeIssue(issues, path, "an array of 3 numbers", v);
        return false;
    }
    Vec3 result;
    for (int i = 0; i < 3; ++i) {
        if (!readValue(v[static_cast<std::size_t>(i)], path + "/" + std::to_string(i), result[i], issues))
            return false;
    }
    out = result;
    return true;
}

} // namespace hs::scene
