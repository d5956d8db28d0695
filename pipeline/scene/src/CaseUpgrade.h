#pragma once
/// The schema upgrade chain (private to hs::scene; tests include it to exercise the mechanism).
///
/// Rule (docs/case-format.md): a change to the document that an older reader could misread (a field renamed,
/// removed, re-united or re-defaulted, a new required field) bumps kCaseSchemaVersion by one and appends one
/// step to caseUpgradeChain() that rewrites a version N document into version N+1. Loading applies the steps
/// from the file's version to the current one, then validates against the current schema only. Documents newer
/// than this build are refused; nothing is ever downgraded.

#include "hs/core/Result.h"
#include "hs/scene/CaseSpec.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace hs::scene::detail {

/// Rewrites a document of version N into version N+1, in place. It runs before validation, so it must not
/// assume the document is valid (anything unexpected is left for the validator to report) and must not touch
/// "schemaVersion" (the chain sets it). A step fails only when the document cannot be upgraded at all.
using CaseUpgradeStep = std::function<Status(nlohmann::json& document)>;

struct CaseUpgradeChain {
    int oldestVersion = kOldestCaseSchemaVersion;
    int currentVersion = kCaseSchemaVersion;
    std::vector<CaseUpgradeStep> steps; ///< steps[i] upgrades version oldestVersion + i to oldestVersion + i + 1
};

/// The chain of this build. Schema version 1 is the first, so it has no steps yet.
const CaseUpgradeChain& caseUpgradeChain();

/// Checks "format" and "schemaVersion" of `document` (an object) and applies the chain's steps from the
/// document's version up to chain.currentVersion. Unsupported for versions outside [oldest, current]; Internal
/// for a chain whose step count does not match its versions. Errors start with "<sourceName>: ".
Status upgradeCaseDocument(nlohmann::json& document, const CaseUpgradeChain& chain, const std::string& sourceName);

/// parseCase() with an explicit chain; parseCase() passes caseUpgradeChain().
Result<CaseSpec> parseCaseWithChain(std::string_view jsonText, const std::string& sourceName,
                                    const CaseUpgradeChain& chain);

} // namespace hs::scene::detail
