#pragma once
/// Reading untrusted JSON documents the way case files are read, and the text of their error messages. The case
/// reader uses it, and so do other documents that hold cases (batch curricula): one set of rules for limits,
/// repeated keys, syntax errors and how values and ranges are quoted.
///
/// This header uses nlohmann-json (header-only); a target that includes it links nlohmann_json::nlohmann_json.

#include "hs/core/Result.h"
#include "hs/core/Vec3.h"
#include "hs/scene/CaseSpec.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hs::scene {

/// Limits checked before a document is parsed, and the name of the kind of document for messages.
struct JsonDocumentLimits {
    std::int64_t maxBytes = kMaxCaseFileBytes; ///< larger text is refused (LimitExceeded) before parsing
    int maxDepth = kMaxCaseNestingDepth;       ///< deeper nesting of arrays and objects is refused (InvalidInput)
    /// Longer strings and keys are refused (an issue at their path); fields have tighter limits of their own.
    std::size_t maxStringBytes = 64 * 1024;
    std::string_view kind = "case file"; ///< "case file", "curriculum": "... a case file nests at most 32"
};

/// Parses `text` into a JSON object. Sizes and nesting are checked first; a key repeated within one object is
/// appended to `issues` (path and message; the document keeps the last value); a syntax error fails at once,
/// naming `sourceName` and the JSON pointer where the parser was; a root that is not an object fails too.
[[nodiscard]] Result<nlohmann::json> parseJsonObject(std::string_view text, const std::string& sourceName,
                                                     const JsonDocumentLimits& limits, std::vector<CaseIssue>& issues);

/// How deeply arrays and objects nest in `text` (brackets inside strings do not count), read without parsing, so
/// that a document can be refused before a parser meets it.
int jsonNestingDepth(std::string_view text);

/// InvalidInput listing up to 20 issues, one per line, each "<sourceName>: <path>: <message>", then "... and N more
/// problems".
Failure failWithIssues(const std::string& sourceName, const std::vector<CaseIssue>& issues);

/// Shortest text that reads back to the same double ("25", "0.47", "1e+300"); "nan"/"inf" for non-finite values.
std::string formatNumber(double value);
/// "18..80" (each bound through formatNumber).
std::string formatRange(const Range& range);
/// "\"text\"" with quotes and backslashes escaped, control characters as \uXXXX, long text cut at 60 bytes.
std::string quoteText(std::string_view text);
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

// ---- Reading the fields of a document: each reader records an issue (path, message) instead of throwing. ----

using JsonIssues = std::vector<CaseIssue>;

/// "integer 3", "string \"x\"", "an object": what was found, for type errors.
/// "an integer 3", "a string \"x\"", "an object": what was found, for type errors.
std::string describeValue(const nlohmann::json& value);
/// Records "expected <expected>, got <what was found>" at `path`.
void typeIssue(JsonIssues& issues, const std::string& path, std::string_view expected, const nlohmann::json& value);
/// Each reader sets `out` and returns true, or records an issue (wrong type, non-finite number, integer too large,
/// unknown choice) and returns false leaving `out` unchanged. Integers are numbers; numbers are never integers.
bool readValue(const nlohmann::json& v, const std::string& path, double& out, JsonIssues& issues);
bool readValue(const nlohmann::json& v, const std::string& path, int& out, JsonIssues& issues);
bool readValue(const nlohmann::json& v, const std::string& path, std::uint64_t& out, JsonIssues& issues);
bool readValue(const nlohmann::json& v, const std::string& path, bool& out, JsonIssues& issues);
bool readValue(const nlohmann::json& v, const std::string& path, std::string& out, JsonIssues& issues);
bool readValue(const nlohmann::json& v, const std::string& path, clinical::PathologyKind& out, JsonIssues& issues);
bool readValue(const nlohmann::json& v, const std::string& path, clinical::GrowthModel& out, JsonIssues& issues);
bool readValue(const nlohmann::json& v, const std::string& path, clinical::UterineLocation& out, JsonIssues& issues);
bool readValue(const nlohmann::json& v, const std::string& path, clinical::PolypAttachment& out, JsonIssues& issues);
bool readValue(const nlohmann::json& v, const std::string& path, ShapeMode& out, JsonIssues& issues);
bool readValue(const nlohmann::json& v, const std::string& path, MeshingMethod& out, JsonIssues& issues);
bool readValue(const nlohmann::json& v, const std::string& path, MeshingSeeding& out, JsonIssues& issues);
bool readValue(const nlohmann::json& v, const std::string& path, clinical::CyclePhase& out, JsonIssues& issues);
/// A FIGO type: an integer (2) or a string ("2", "2-5"). Range rules are checkCase()'s.
bool readValue(const nlohmann::json& v, const std::string& path, clinical::FigoType& out, JsonIssues& issues);
bool readValue(const nlohmann::json& v, const std::string& path, Vec3& out, JsonIssues& issues);

template <class E, std::size_t N>
bool readEnum(const nlohmann::json& v, const std::string& path, E& out, const std::array<E, N>& values,
              JsonIssues& issues) {
    if (!v.is_string()) {
        typeIssue(issues, path, "one of " + choiceList(values), v);
        return false;
    }
    if (!fromString(v.get_ref<const std::string&>(), out)) {
        issues.push_back({path, quoteText(v.get_ref<const std::string&>()) + " is not one of " + choiceList(values)});
        return false;
    }
    return true;
}

/// Optional fields: null means "not set".
template <class T>
bool readValue(const nlohmann::json& v, const std::string& path, std::optional<T>& out, JsonIssues& issues) {
    if (v.is_null()) {
        out.reset();
        return true;
    }
    T value{};
    if (!readValue(v, path, value, issues))
        return false;
    out = std::move(value);
    return true;
}

// ---- Objects ----

/// Reads the members of one JSON object. Every member the schema knows is asked for by name; finish() reports
/// the rest as unknown, naming the allowed ones.
class ObjectReader {
public:
    ObjectReader(const nlohmann::json& value, std::string path, JsonIssues& issues)
        : m_value(value), m_path(std::move(path)), m_issues(issues) {
        if (!value.is_object())
            typeIssue(issues, m_path.empty() ? "(root)" : m_path, "an object", value);
    }
    ObjectReader(const ObjectReader&) = delete;
    ObjectReader& operator=(const ObjectReader&) = delete;

    bool ok() const { return m_value.is_object(); }
    std::string pathOf(const std::string& key) const { return m_path + "/" + escapePointerToken(key); }
    JsonIssues& issues() { return m_issues; }

    /// The member `key`, or nullptr when absent (recorded as an issue when `required`).
    const nlohmann::json* member(const std::string& key, bool required = false) {
        m_known.push_back(key);
        if (!ok())
            return nullptr;
        const auto it = m_value.find(key);
        if (it == m_value.end()) {
            if (required)
                m_issues.push_back({pathOf(key), "required field is missing"});
            return nullptr;
        }
        return &*it;
    }

    template <class T>
    void read(const std::string& key, T& out, bool required = false) {
        if (const nlohmann::json* v = member(key, required))
            readValue(*v, pathOf(key), out, m_issues);
    }

    void finish() {
        if (!ok())
            return;
        for (const auto& item : m_value.items()) {
            bool known = false;
            for (const std::string& k : m_known)
                known = known || item.key() == k;
            if (!known)
                m_issues.push_back({m_path + "/" + escapePointerToken(item.key()),
                                    "unknown field " + quoteText(item.key()) + " (allowed: " + knownList() + ")"});
        }
    }

private:
    std::string knownList() const {
        std::string text;
        for (std::size_t i = 0; i < m_known.size(); ++i)
            text += (i ? ", " : "") + m_known[i];
        return text;
    }

    const nlohmann::json& m_value;
    std::string m_path;
    JsonIssues& m_issues;
    std::vector<std::string> m_known;
};

/// parseJsonObject, then `read(document, value, issues)` fills a T: the whole reading of a strict document. Fails
/// with every issue found (failWithIssues); a JSON exception escaping a reader (a bug) becomes Internal.
template <class T, class Read>
Result<T> parseJsonDocument(std::string_view text, const std::string& sourceName, const JsonDocumentLimits& limits,
                            Read read) {
    try {
        JsonIssues issues;
        auto document = parseJsonObject(text, sourceName, limits, issues);
        if (!document)
            return document.failure();
        T value{};
        read(*document, value, issues);
        if (!issues.empty())
            return failWithIssues(sourceName, issues);
        return value;
    } catch (const nlohmann::json::exception& e) {
        return fail(ErrorCode::Internal, sourceName + ": unexpected JSON error: " + std::string(e.what()));
    }
}

} // namespace hs::scene
