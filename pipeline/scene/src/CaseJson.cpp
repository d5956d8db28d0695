// parseCase / loadCase / toJson / saveCase: the case file on disk.

#include "CaseReader.h"
#include "CaseUpgrade.h"
#include "CaseWriter.h"
#include "Format.h"
#include "hs/io/AtomicFile.h"
#include "hs/scene/CaseSpec.h"

#include <nlohmann/json.hpp>

namespace hs::scene {

namespace detail {

namespace {

using nlohmann::json;

Result<CaseSpec> parseChecked(std::string_view jsonText, const std::string& sourceName, const CaseUpgradeChain& chain) {
    std::vector<CaseIssue> issues;
    auto parsed = parseJsonObject(jsonText, sourceName, JsonDocumentLimits{}, issues);
    if (!parsed)
        return parsed.failure();
    nlohmann::json& document = *parsed;
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
