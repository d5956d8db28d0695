#pragma once
/// The curriculum (curriculum.json): case templates whose patient and pathology fields are fixed, drawn uniformly
/// from a range, or chosen from a list; how many cases each template gives and how many variants each case; one
/// master seed. docs/batch.md describes the document, every field and its rules.
///
/// checkCurriculum() refuses, before anything is generated, every combination a case could never satisfy (a rule of
/// the case format, a FIGO type the placement cannot give, a pathology larger than the expected uterus of a patient
/// the template may draw); sampleCase() then draws each case deterministically from the master seed.

#include "hs/core/Result.h"
#include "hs/scene/CaseSpec.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hs::batch {

/// Value of the document's "format" member.
constexpr std::string_view kCurriculumFormat = "hysteroscene-curriculum";
/// The only schema version this build reads and writes.
constexpr int kCurriculumSchemaVersion = 1;
/// A curriculum is a few kB; larger files are refused before parsing.
constexpr std::int64_t kMaxCurriculumFileBytes = 1024 * 1024;
constexpr std::size_t kMaxTemplates = 64;
constexpr int kMaxCasesPerTemplate = 10000;
constexpr int kMaxVariantsPerCase = 100;
/// Jobs of one plan (templates x cases x variants).
constexpr std::size_t kMaxJobs = 100000;
/// Longest template name (names become file names).
constexpr std::size_t kMaxTemplateNameLength = 32;

/// A number to draw: a list of values (one value: fixed), or a uniform range.
struct NumberSampler {
    std::vector<double> values;        ///< chosen with equal probability; empty when `range` is set
    std::optional<scene::Range> range; ///< uniform in [min, max]; integer fields: every integer in it
    double lowest() const;             ///< smallest value it can give
    double highest() const;            ///< largest value it can give
    bool fixed() const { return !range && values.size() == 1; }
};

/// A choice to draw (enumerations, FIGO types, yes/no): one of `values` with equal probability.
template <class T>
struct ChoiceSampler {
    std::vector<T> values;
};

/// What a template says about the patient; an unset sampler keeps the base case's value.
struct PatientSampler {
    std::optional<NumberSampler> ageYears;
    std::optional<NumberSampler> parity;    ///< integers
    std::optional<NumberSampler> gravidity; ///< integers; must not fall below the parity
    std::optional<NumberSampler> heightCm;
    std::optional<NumberSampler> weightKg;
    std::optional<ChoiceSampler<bool>> menopausal;
    /// Premenopausal cases only; a postmenopausal case has none.
    std::optional<ChoiceSampler<clinical::CyclePhase>> cyclePhase;
};

/// One pathology of a template's cases; every field is drawn independently.
struct PathologySampler {
    std::string id;
    clinical::PathologyKind kind = clinical::PathologyKind::Myoma;
    ChoiceSampler<clinical::GrowthModel> growthModel{{clinical::GrowthModel::Particles}};
    NumberSampler sizeMm;
    ChoiceSampler<clinical::FigoType> figo;              ///< myomas: required; polyps: empty
    ChoiceSampler<clinical::PolypAttachment> attachment; ///< polyps: required; myomas: empty
    std::optional<NumberSampler> stalkLengthMm;          ///< polyps that can be pedunculated
    ChoiceSampler<clinical::UterineLocation> location;   ///< clinical placement
};

struct CaseTemplate {
    std::string name; ///< unique; [A-Za-z0-9][A-Za-z0-9_-]*, <= 32 chars
    int cases = 1;
    /// Case file the template starts from (relative to the curriculum's folder); unset = scene::defaultCase().
    std::optional<std::string> base;
    PatientSampler patient;
    /// Set: the cases' pathologies (an empty list is a healthy uterus); unset: the base case's, unchanged.
    std::optional<std::vector<PathologySampler>> pathologies;
};

struct Curriculum {
    std::string title;
    std::uint64_t seed = 1; ///< master seed: every case's draws and seed derive from it
    int variants = 1;       ///< scenes per case, each with its own seed (generate::variantSeed)
    std::vector<CaseTemplate> templates;
};

/// A curriculum with its templates' base cases loaded.
struct LoadedCurriculum {
    Curriculum curriculum;
    std::vector<scene::CaseSpec> bases; ///< one per template
    std::string sourceName;             ///< the file it was read from
};

/// Parses a curriculum document (structure, types, names, choices). Errors list every problem as
/// "<sourceName>: <JSON pointer>: <message>" (scene::failWithIssues).
[[nodiscard]] Result<Curriculum> parseCurriculum(std::string_view jsonText, const std::string& sourceName);

/// The rules a plan must meet before any case is drawn: counts, template names, each sampler within the case
/// format's limits, the cross-field rules of the case format for every value a template can draw (gravidity against
/// parity, menopause against age, FIGO type against location and kind), what the pathology stage does not model
/// (FIGO type 8, the cervix), and each pathology's largest size against the expected uterus
/// (anatomy::expectedShape) of every extreme patient the template allows. Each issue names the entry by its JSON
/// pointer ("/templates/1/pathologies/0/sizeMm").
std::vector<scene::CaseIssue> checkCurriculum(const Curriculum& curriculum, const std::vector<scene::CaseSpec>& bases);

/// Reads `path`, parses it, loads every template's base case (relative to the curriculum's folder) and checks it
/// with checkCurriculum(); InvalidInput lists every problem.
[[nodiscard]] Result<LoadedCurriculum> loadCurriculum(const std::string& path);

/// The document of `curriculum` (4-space indent, final newline); parseCurriculum() reads it back to the same value.
std::string toJson(const Curriculum& curriculum);

/// Case `caseIndex` of template `templateIndex`: the base case with every sampler drawn, titled
/// "<curriculum title>: <template> <caseIndex>", with its own seed. Deterministic: the draws come from
/// Rng::deriveSeed(curriculum.seed, templateIndex * 2^20 + caseIndex), so adding cases or templates never changes
/// the cases already planned. Seeds stay below 2^53 (docs/case-format.md).
scene::CaseSpec sampleCase(const LoadedCurriculum& loaded, std::size_t templateIndex, std::size_t caseIndex);

} // namespace hs::batch
