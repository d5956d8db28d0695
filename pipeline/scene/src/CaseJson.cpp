// parseCase / loadCase / toJson / saveCase: the case file on disk.

#include "CaseReader.h"
#include "CaseUpgrade.h"
#include "CaseWriter.h"
#include "Format.h"
#include "hs/io/AtomicFile.h"
#include "hs/scene/CaseSpec.h"

#include <nlohmann/json.hpp>

#include <set>

namespace hs::scene {

namespace detail {

namespace {

using nlohmann::json;

constexpr std::size_t kMaxReportedIssues = 20;

/// Follows the parser's events to know the JSON path of each key: records keys repeated within one object
/// (nlohmann keeps the last silently; a case file must not be ambiguous) and tells where a syntax error happened.
class ParseTracker {
public:
    explicit ParseTracker(std::vector<CaseIssue>& issues) : m_issues(issues) {}

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
                if (!top.keys.insert(top.key).second)
                    m_issues.push_back({currentPath(), "duplicate key " + quoteText(top.key) + " (each field once)"});
            }
            break;
        case json::parse_event_t::value:
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

    void elementDone() {
        if (!m_frames.empty() && m_frames.back().array)
            ++m_frames.back().index;
    }

    std::vector<CaseIssue>& m_issues;
    std::vector<Frame> m_frames;
};

/// "[json.exception.parse_error.101] parse error at line 2, ..." -> "parse error at line 2, ...".
std::string parserMessage(const std::string& what) {
    const auto pos = what.find("] ");
    return pos == std::string::npos ? what : what.substr(pos + 2);
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

Result<CaseSpec> parseChecked(std::string_view jsonText, const std::string& sourceName, const CaseUpgradeChain& chain) {
    if (static_cast<std::int64_t>(jsonText.size()) > kMaxCaseFileBytes)
        return fail(ErrorCode::LimitExceeded, sourceName + ": " + std::to_string(jsonText.size()) +
                                                  " bytes, more than the " + std::to_string(kMaxCaseFileBytes) +
                                                  "-byte limit of a case file");
    if (const int depth = nestingDepth(jsonText); depth > kMaxCaseNestingDepth)
        return fail(ErrorCode::InvalidInput, sourceName + ": arrays and objects nested " + std::to_string(depth) +
                                                 " deep (a case file nests at most " +
                                                 std::to_string(kMaxCaseNestingDepth) + ")");

    std::vector<CaseIssue> issues;
    ParseTracker tracker(issues);
    json document;
    try {
        document =
            json::parse(jsonText.begin(), jsonText.end(), [&tracker](int, json::parse_event_t event, json& parsed) {
                return tracker.onEvent(event, parsed);
            });
    } catch (const json::exception& e) { // parse_error, or out_of_range for numbers such as 1e999
        const std::string path = tracker.currentPath();
        return fail(ErrorCode::InvalidInput, sourceName + ": " + (path.empty() ? "(root)" : path) +
                                                 ": not valid JSON: " + parserMessage(e.what()));
    }
    if (!document.is_object())
        return fail(ErrorCode::InvalidInput, sourceName +
                                                 ": (root): expected an object (a case file is a JSON object), got " +
                                                 std::string(document.type_name()));
    HS_TRY(upgradeCaseDocument(document, chain, sourceName));

    CaseSpec spec;
    readCase(document, spec, issues);
    for (CaseIssue& issue : checkCase(spec))
        issues.push_back(std::move(issue));
    if (!issues.empty())
        return failWithIssues(sourceName, issues);
    return spec;
}

} // namespace

Result<CaseSpec> parseCaseWithChain(std::string_view jsonText, const std::string& sourceName,
                                    const CaseUpgradeChain& chain) {
    try {
        return parseChecked(jsonText, sourceName, chain);
    } catch (const json::exception& e) { // a reader bug must not throw across the stage boundary
        return fail(ErrorCode::Internal, sourceName + ": unexpected JSON error: " + std::string(e.what()));
    }
}

} // namespace detail

Result<CaseSpec> parseCase(std::string_view jsonText, const std::string& sourceName) {
    return detail::parseCaseWithChain(jsonText, sourceName, detail::caseUpgradeChain());
}

Result<CaseSpec> loadCase(const std::string& path) {
    auto text = io::readFile(path, kMaxCaseFileBytes);
    if (!text.ok())
        return text.failure();
    return parseCase(*text, path);
}

std::string toJson(const CaseSpec& spec) {
    // Invalid UTF-8 in a string (a title typed in code) is replaced rather than thrown.
    return detail::writeCase(spec).dump(4, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

Status saveCase(const CaseSpec& spec, const std::string& path) {
    const auto issues = checkCase(spec);
    if (!issues.empty())
        return fail(ErrorCode::InvalidInput,
                    path + ": refusing to save an invalid case: " + issues.front().text() +
                        (issues.size() > 1 ? " (and " + std::to_string(issues.size() - 1) + " more problems)" : ""));
    return io::writeFileAtomically(path, toJson(spec));
}

} // namespace hs::scene
