#include "CaseUpgrade.h"

#include "Format.h"

namespace hs::scene::detail {

namespace {

/// Version 1 -> 2: the wall's tissue layers and the fields that did nothing.
///  - meshing.particlesPerSurfaceVoxel is removed (no seeding read it);
///  - meshing.seeding is added, "lattice" (what version 1 used), and particlesPerInnerVoxel, which the lattice
///    ignores, becomes null;
///  - patient.cyclePhase is added: "proliferative" for a premenopausal patient (what the endometrium's default
///    stiffness already assumed), null after menopause; anatomy.endometrialThicknessMm and each material's
///    heterogeneity are added as null (derived / homogeneous, as before).
/// Anything unexpected (a member of the wrong type) is left for the validator.
Status upgradeV1ToV2(nlohmann::json& document) {
    if (auto meshing = document.find("meshing"); meshing != document.end() && meshing->is_object()) {
        meshing->erase("particlesPerSurfaceVoxel");
        if (!meshing->contains("seeding")) {
            (*meshing)["seeding"] = "lattice";
            (*meshing)["particlesPerInnerVoxel"] = nullptr;
        }
    }
    if (auto patient = document.find("patient"); patient != document.end() && patient->is_object()) {
        const auto menopausal = patient->find("menopausal");
        const bool post = menopausal != patient->end() && menopausal->is_boolean() && menopausal->get<bool>();
        if (!patient->contains("cyclePhase"))
            (*patient)["cyclePhase"] = post ? nlohmann::json(nullptr) : nlohmann::json("proliferative");
    }
    return {};
}

/// Version 2 -> 3: texture.exemplars.cervicalCanal is new; unset, the canal takes the bundled exemplar, as before.
/// Nothing to rewrite (the step exists because the strict reader of version 2 refuses the new member).
Status upgradeV2ToV3(nlohmann::json&) {
    return {};
}

} // namespace

const CaseUpgradeChain& caseUpgradeChain() {
    static const CaseUpgradeChain chain{kOldestCaseSchemaVersion, kCaseSchemaVersion, {upgradeV1ToV2, upgradeV2ToV3}};
    return chain;
}

namespace {

Failure invalid(const std::string& sourceName, const std::string& path, const std::string& message) {
    return fail(ErrorCode::InvalidInput, sourceName + ": " + path + ": " + message);
}

std::string typeName(const nlohmann::json& value) {
    return value.type_name();
}

} // namespace

Status upgradeCaseDocument(nlohmann::json& document, const CaseUpgradeChain& chain, const std::string& sourceName) {
    const auto expectedSteps = static_cast<long long>(chain.currentVersion) - chain.oldestVersion;
    if (expectedSteps < 0 || static_cast<long long>(chain.steps.size()) != expectedSteps)
        return fail(ErrorCode::Internal,
                    sourceName + ": the upgrade chain from version " + std::to_string(chain.oldestVersion) + " to " +
                        std::to_string(chain.currentVersion) + " has " + std::to_string(chain.steps.size()) + " steps");

    const auto format = document.find("format");
    if (format == document.end())
        return invalid(sourceName, "/format",
                       "required field is missing (a case file has \"format\": " + quoteText(kCaseFormat) + ")");
    if (!format->is_string() || format->get_ref<const std::string&>() != kCaseFormat)
        return invalid(sourceName, "/format",
                       (format->is_string() ? quoteText(format->get_ref<const std::string&>()) : typeName(*format)) +
                           " is not a case file format (allowed " + quoteText(kCaseFormat) + ")");

    const auto version = document.find("schemaVersion");
    if (version == document.end())
        return invalid(sourceName, "/schemaVersion", "required field is missing");
    if (!version->is_number_integer())
        return invalid(sourceName, "/schemaVersion", "expected an integer, got " + typeName(*version));
    // Parsed non-negative integers are stored unsigned; compare without narrowing either way.
    const bool newer = version->is_number_unsigned()
                           ? version->get<unsigned long long>() > static_cast<unsigned long long>(chain.currentVersion)
                           : version->get<long long>() > chain.currentVersion;
    const std::string allowed =
        "allowed " + std::to_string(chain.oldestVersion) + ".." + std::to_string(chain.currentVersion);
    if (newer)
        return fail(ErrorCode::Unsupported, sourceName + ": /schemaVersion: " + version->dump() +
                                                " is newer than this build supports (" + allowed +
                                                "); open it with a newer hysteroscene");
    const auto v = version->get<long long>();
    if (v < chain.oldestVersion)
        return fail(ErrorCode::Unsupported, sourceName + ": /schemaVersion: " + std::to_string(v) +
                                                " is older than this build can upgrade (" + allowed + ")");

    for (auto from = static_cast<int>(v); from < chain.currentVersion; ++from) {
        const auto& step = chain.steps[static_cast<std::size_t>(from - chain.oldestVersion)];
        const Status upgraded = step(document);
        if (!upgraded.ok())
            return fail(upgraded.error().code, sourceName + ": upgrading from schema version " + std::to_string(from) +
                                                   " to " + std::to_string(from + 1) +
                                                   " failed: " + upgraded.error().detail);
        document["schemaVersion"] = from + 1;
    }
    return {};
}

} // namespace hs::scene::detail
