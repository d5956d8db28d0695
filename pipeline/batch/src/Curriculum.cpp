// checkCurriculum, loadCurriculum and sampleCase: what a curriculum may ask for, and drawing its cases.
//
// A template is checked through the cases it can give: its extreme cases (every numeric sampler at its lowest and
// highest, every choice at each value) are built exactly as sampleCase() builds a drawn case and held to
// scene::checkCase(), so the case format's rules live in one place; an issue found in such a case is reported at
// the template entry that produced the field.
#include "hs/batch/Curriculum.h"

#include "hs/anatomy/Cohort.h"
#include "hs/core/Rng.h"
#include "hs/io/AtomicFile.h"
#include "hs/pathology/Pathology.h"
#include "hs/scene/JsonText.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

namespace hs::batch {

double NumberSampler::lowest() const {
    if (range)
        return range->min;
    return values.empty() ? 0.0 : *std::min_element(values.begin(), values.end());
}

double NumberSampler::highest() const {
    if (range)
        return range->max;
    return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

namespace {

using scene::CaseIssue;
using scene::formatNumber;
using scene::formatRange;
using scene::quoteText;

/// Case titles are "<curriculum title>: <template> <case>"; this leaves room for the suffix.
constexpr std::size_t kMaxCurriculumTitleLength = scene::kMaxTitleLength - kMaxTemplateNameLength - 12;
/// Draws of case `c` of template `t` come from stream t * 2^20 + c (c < kMaxCasesPerTemplate < 2^20).
constexpr std::uint64_t kTemplateStreamStride = std::uint64_t{1} << 20;

// ---- Building a case from concrete values (shared by sampling and by the checks). ----

struct PatientValues {
    double ageYears = 0.0;
    int parity = 0;
    int gravidity = 0;
    double heightCm = 0.0;
    double weightKg = 0.0;
    bool menopausal = false;
    std::optional<clinical::CyclePhase> cyclePhase; ///< as drawn; dropped for a postmenopausal patient
};

struct PathologyValues {
    clinical::GrowthModel growthModel = clinical::GrowthModel::Particles;
    double sizeMm = 0.0;
    std::optional<clinical::FigoType> figo;
    std::optional<clinical::PolypAttachment> attachment;
    std::optional<double> stalkLengthMm;
    clinical::UterineLocation location = clinical::UterineLocation::Fundal;
};

void applyPatient(const PatientSampler& s, const PatientValues& v, clinical::PatientParams& p) {
    if (s.ageYears)
        p.ageYears = v.ageYears;
    if (s.parity)
        p.parity = v.parity;
    if (s.gravidity)
        p.gravidity = v.gravidity;
    if (s.heightCm)
        p.heightCm = v.heightCm;
    if (s.weightKg)
        p.weightKg = v.weightKg;
    if (s.menopausal)
        p.menopausal = v.menopausal;
    if (s.cyclePhase)
        p.cyclePhase = v.cyclePhase;
    if (p.menopausal)
        p.cyclePhase.reset();
    else if (!p.cyclePhase) // a postmenopausal base drawn premenopausal: the case format's default phase
        p.cyclePhase = clinical::PatientParams{}.cyclePhase;
}

scene::PathologySpec makePathology(const PathologySampler& s, const PathologyValues& v) {
    scene::PathologySpec p;
    p.id = s.id;
    p.kind = s.kind;
    p.growthModel = v.growthModel;
    p.sizeMm = v.sizeMm;
    p.figo = v.figo;
    p.attachment = v.attachment;
    if (v.attachment == clinical::PolypAttachment::Pedunculated)
        p.stalkLengthMm = v.stalkLengthMm;
    p.placement = clinical::ClinicalPlacement{v.location};
    return p;
}

template <class T>
std::optional<T> firstOf(const ChoiceSampler<T>& s) {
    return s.values.empty() ? std::nullopt : std::optional<T>(s.values.front());
}

PathologyValues firstValues(const PathologySampler& s) {
    PathologyValues v;
    v.growthModel = s.growthModel.values.empty() ? v.growthModel : s.growthModel.values.front();
    v.sizeMm = s.sizeMm.lowest();
    v.figo = firstOf(s.figo);
    v.attachment = firstOf(s.attachment);
    if (s.stalkLengthMm)
        v.stalkLengthMm = s.stalkLengthMm->lowest();
    v.location = s.location.values.empty() ? v.location : s.location.values.front();
    return v;
}

// ---- Drawing ----

double drawNumber(Rng& rng, const NumberSampler& s, bool integer) {
    if (!s.range)
        return s.values[static_cast<std::size_t>(rng.below(s.values.size()))];
    if (integer)
        return static_cast<double>(rng.between(static_cast<std::int64_t>(std::ceil(s.range->min)),
                                               static_cast<std::int64_t>(std::floor(s.range->max))));
    // One decimal reads better in case files and reports; kept only where it stays inside the range.
    const double x = rng.uniform(s.range->min, s.range->max);
    const double rounded = std::round(x * 10.0) / 10.0;
    return s.range->contains(rounded) ? rounded : x;
}

double drawNumber(Rng& rng, const std::optional<NumberSampler>& s, bool integer, double otherwise) {
    return s ? drawNumber(rng, *s, integer) : otherwise;
}

template <class T>
std::optional<T> drawChoice(Rng& rng, const ChoiceSampler<T>& s) {
    if (s.values.empty())
        return std::nullopt;
    return s.values[static_cast<std::size_t>(rng.below(s.values.size()))];
}

PatientValues drawPatient(Rng& rng, const PatientSampler& s, const clinical::PatientParams& base) {
    PatientValues v;
    v.ageYears = drawNumber(rng, s.ageYears, false, base.ageYears);
    v.parity = static_cast<int>(drawNumber(rng, s.parity, true, base.parity));
    v.gravidity = static_cast<int>(drawNumber(rng, s.gravidity, true, base.gravidity));
    v.heightCm = drawNumber(rng, s.heightCm, false, base.heightCm);
    v.weightKg = drawNumber(rng, s.weightKg, false, base.weightKg);
    v.menopausal = s.menopausal ? drawChoice(rng, *s.menopausal).value_or(base.menopausal) : base.menopausal;
    v.cyclePhase = s.cyclePhase ? drawChoice(rng, *s.cyclePhase) : base.cyclePhase;
    return v;
}

PathologyValues drawPathology(Rng& rng, const PathologySampler& s) {
    PathologyValues v;
    v.growthModel = drawChoice(rng, s.growthModel).value_or(v.growthModel);
    v.sizeMm = drawNumber(rng, s.sizeMm, false);
    v.figo = drawChoice(rng, s.figo);
    v.attachment = drawChoice(rng, s.attachment);
    if (s.stalkLengthMm)
        v.stalkLengthMm = drawNumber(rng, *s.stalkLengthMm, false);
    v.location = drawChoice(rng, s.location).value_or(v.location);
    return v;
}

// ---- Checks ----

bool isName(const std::string& name) {
    if (name.empty() || name.size() > kMaxTemplateNameLength)
        return false;
    for (std::size_t i = 0; i < name.size(); ++i) {
        const char c = name[i];
        const bool alnum = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
        if (!alnum && (i == 0 || (c != '-' && c != '_')))
            return false;
    }
    return true;
}

/// The lowest and highest value of a numeric sampler, or the base's value when the template does not sample it.
std::vector<double> extremes(const std::optional<NumberSampler>& s, double base) {
    if (!s)
        return {base};
    if (s->lowest() == s->highest())
        return {s->lowest()};
    return {s->lowest(), s->highest()};
}

template <class T>
std::vector<T> choices(const std::optional<ChoiceSampler<T>>& s, T base) {
    return s ? s->values : std::vector<T>{base};
}

/// Every extreme patient a template can draw: each numeric field at its lowest and highest, each choice at each
/// value (at most 2^5 x 2 x 3 = 192 patients).
std::vector<PatientValues> extremePatients(const PatientSampler& s, const clinical::PatientParams& base) {
    std::vector<PatientValues> all;
    const auto phases = s.cyclePhase ? std::vector<std::optional<clinical::CyclePhase>>(s.cyclePhase->values.begin(),
                                                                                        s.cyclePhase->values.end())
                                     : std::vector<std::optional<clinical::CyclePhase>>{base.cyclePhase};
    for (double age : extremes(s.ageYears, base.ageYears))
        for (double parity : extremes(s.parity, base.parity))
            for (double gravidity : extremes(s.gravidity, base.gravidity))
                for (double height : extremes(s.heightCm, base.heightCm))
                    for (double weight : extremes(s.weightKg, base.weightKg))
                        for (bool menopausal : choices(s.menopausal, base.menopausal))
                            for (const auto& phase : phases)
                                all.push_back({age, static_cast<int>(parity), static_cast<int>(gravidity), height,
                                               weight, menopausal, phase});
    return all;
}

std::vector<PathologyValues> extremePathologies(const PathologySampler& s) {
    std::vector<PathologyValues> all;
    const PathologyValues first = firstValues(s);
    const auto figos = s.figo.values.empty()
                           ? std::vector<std::optional<clinical::FigoType>>{std::nullopt}
                           : std::vector<std::optional<clinical::FigoType>>(s.figo.values.begin(), s.figo.values.end());
    const auto attachments = s.attachment.values.empty()
                                 ? std::vector<std::optional<clinical::PolypAttachment>>{std::nullopt}
                                 : std::vector<std::optional<clinical::PolypAttachment>>(s.attachment.values.begin(),
                                                                                         s.attachment.values.end());
    const std::vector<double> stalks = s.stalkLengthMm ? extremes(s.stalkLengthMm, 0.0) : std::vector<double>{0.0};
    for (clinical::GrowthModel model : s.growthModel.values)
        for (double size : extremes(s.sizeMm, 0.0))
            for (const auto& figo : figos)
                for (const auto& attachment : attachments)
                    for (double stalk : stalks)
                        for (clinical::UterineLocation location : s.location.values) {
                            PathologyValues v = first;
                            v.growthModel = model;
                            v.sizeMm = size;
                            v.figo = figo;
                            v.attachment = attachment;
                            v.stalkLengthMm = s.stalkLengthMm ? std::optional<double>(stalk) : std::nullopt;
                            v.location = location;
                            all.push_back(v);
                        }
    return all;
}

/// Collects the issues of one template, each once (extreme cases often repeat the same problem).
class TemplateIssues {
public:
    TemplateIssues(std::vector<CaseIssue>& issues, std::string prefix)
        : m_issues(issues), m_prefix(std::move(prefix)) {}

    void add(const std::string& path, const std::string& message) {
        if (m_seen.insert(path + "\n" + message).second)
            m_issues.push_back({m_prefix + path, message});
    }

    /// An issue of a case built from this template, at the template entry that gave the field: "/patient/x" and
    /// "/pathologies/j/x" keep their paths ("location" for the clinical placement); anything else belongs to the
    /// base case, named by `baseName`.
    void addCaseIssue(const CaseIssue& issue, const PatientSampler& patient, bool templatePathologies,
                      const std::string& baseName) {
        std::string path = issue.path;
        const auto replace = [&path](const std::string& from, const std::string& to) {
            if (const auto at = path.find(from); at != std::string::npos)
                path.replace(at, from.size(), to);
        };
        replace("/placement/location", "/location");
        const bool fromPatient = path.rfind("/patient/", 0) == 0 && patientSamples(patient, path.substr(9));
        const bool fromPathologies = path.rfind("/pathologies", 0) == 0 && templatePathologies;
        if (fromPatient || fromPathologies)
            add(path, issue.message);
        else
            add("/base", baseName + ": " + issue.text());
    }

private:
    static bool patientSamples(const PatientSampler& p, const std::string& field) {
        return (field == "ageYears" && p.ageYears) || (field == "parity" && p.parity) ||
               (field == "gravidity" && p.gravidity) || (field == "heightCm" && p.heightCm) ||
               (field == "weightKg" && p.weightKg) || (field == "menopausal" && p.menopausal) ||
               (field == "cyclePhase" && p.cyclePhase);
    }

    std::vector<CaseIssue>& m_issues;
    std::string m_prefix;
    std::set<std::string> m_seen;
};

void checkSamplerRanges(const CaseTemplate& t, TemplateIssues& issues) {
    const auto integerBounds = [&issues](const std::string& path, const std::optional<NumberSampler>& s) {
        if (s && s->range && (std::floor(s->range->min) != s->range->min || std::floor(s->range->max) != s->range->max))
            issues.add(path + "/uniform", "bounds " + formatRange(*s->range) + " must be whole numbers");
    };
    integerBounds("/patient/parity", t.patient.parity);
    integerBounds("/patient/gravidity", t.patient.gravidity);
    if (!t.pathologies)
        return;
    for (std::size_t j = 0; j < t.pathologies->size(); ++j) {
        const PathologySampler& s = (*t.pathologies)[j];
        const std::string p = "/pathologies/" + std::to_string(j);
        for (const clinical::FigoType& figo : s.figo.values)
            if (!figo.isHybrid() && figo.type == 8)
                issues.add(p + "/figo", "FIGO type 8 (cervical, parasitic) is not modelled by the pathology stage");
        for (clinical::UterineLocation location : s.location.values)
            if (location == clinical::UterineLocation::Cervical)
                issues.add(p + "/location", "\"cervical\" is not modelled by the pathology stage");
        if (s.kind == clinical::PathologyKind::Polyp && s.stalkLengthMm &&
            std::find(s.attachment.values.begin(), s.attachment.values.end(),
                      clinical::PolypAttachment::Pedunculated) == s.attachment.values.end())
            issues.add(p + "/stalkLengthMm", "given, but the attachment is never \"pedunculated\"");
    }
}

std::string describePatient(const clinical::PatientParams& p) {
    return std::string(p.menopausal ? "postmenopausal " : "premenopausal ") + formatNumber(p.ageYears) +
           "-year-old (parity " + std::to_string(p.parity) + ", gravidity " + std::to_string(p.gravidity) + ", " +
           formatNumber(p.heightCm) + " cm)";
}

std::string mm(double value) {
    return formatNumber(std::round(value));
}

/// The largest size of each pathology against the expected uterus (anatomy::expectedShape) of every extreme
/// patient: the pathology stage's own limits (pathology::kMaxMyomaToCorpus, kMaxPolypToCavity) on that organ.
void checkSizesAgainstUterus(const CaseTemplate& t, const std::vector<clinical::PatientParams>& patients,
                             TemplateIssues& issues) {
    if (!t.pathologies)
        return;
    for (std::size_t j = 0; j < t.pathologies->size(); ++j) {
        const PathologySampler& s = (*t.pathologies)[j];
        const double largest = s.sizeMm.highest();
        for (const clinical::PatientParams& patient : patients) {
            const anatomy::UterusShapeParams shape = anatomy::expectedShape(patient);
            const double corpusLength = shape.lengthMm - shape.cervixLengthMm;
            std::string problem;
            if (s.kind == clinical::PathologyKind::Myoma) {
                const double room =
                    pathology::kMaxMyomaToCorpus * std::min({shape.widthMm, shape.apDepthMm, corpusLength});
                if (largest > room)
                    problem = "up to " + formatNumber(largest) + " mm, but the expected uterus of a " +
                              describePatient(patient) + " has a corpus of " + mm(shape.widthMm) + " x " +
                              mm(shape.apDepthMm) + " x " + mm(corpusLength) +
                              " mm (width x depth x length): room for a myoma of at most " + mm(room) + " mm";
            } else {
                const double room = pathology::kMaxPolypToCavity * shape.cavityLengthMm;
                if (largest > room)
                    problem = "up to " + formatNumber(largest) + " mm, but the expected uterus of a " +
                              describePatient(patient) + " has a cavity " + mm(shape.cavityLengthMm) +
                              " mm long: room for a polyp head of at most " + mm(room) + " mm";
            }
            if (!problem.empty()) {
                issues.add("/pathologies/" + std::to_string(j) + "/sizeMm", problem);
                break;
            }
        }
    }
}

void checkTemplate(const CaseTemplate& t, const scene::CaseSpec& base, TemplateIssues& issues) {
    if (t.cases < 1 || t.cases > kMaxCasesPerTemplate)
        issues.add("/cases", std::to_string(t.cases) + " is outside the supported range (allowed 1.." +
                                 std::to_string(kMaxCasesPerTemplate) + ")");
    const std::string baseName = t.base ? *t.base : "the default case";
    checkSamplerRanges(t, issues);

    // Every extreme patient, with the pathologies at their first values.
    scene::CaseSpec typical = base;
    if (t.pathologies) {
        typical.pathologies.clear();
        for (const PathologySampler& s : *t.pathologies)
            typical.pathologies.push_back(makePathology(s, firstValues(s)));
    }
    std::vector<clinical::PatientParams> validPatients;
    for (const PatientValues& v : extremePatients(t.patient, base.patient)) {
        scene::CaseSpec c = typical;
        applyPatient(t.patient, v, c.patient);
        bool validPatient = true;
        for (const CaseIssue& issue : scene::checkCase(c)) {
            issues.addCaseIssue(issue, t.patient, t.pathologies.has_value(), baseName);
            validPatient = validPatient && issue.path.rfind("/patient/", 0) != 0;
        }
        if (validPatient) // the sizes are checked against the uterus of every patient the case format accepts
            validPatients.push_back(c.patient);
    }
    // Every extreme of each pathology, the others at their first values.
    if (t.pathologies) {
        for (std::size_t j = 0; j < t.pathologies->size(); ++j) {
            for (const PathologyValues& v : extremePathologies((*t.pathologies)[j])) {
                scene::CaseSpec c = typical;
                c.pathologies[j] = makePathology((*t.pathologies)[j], v);
                for (const CaseIssue& issue : scene::checkCase(c))
                    issues.addCaseIssue(issue, t.patient, true, baseName);
            }
        }
    }
    checkSizesAgainstUterus(t, validPatients, issues);
}

std::size_t jobCount(const Curriculum& c) {
    std::size_t cases = 0;
    for (const CaseTemplate& t : c.templates)
        cases += static_cast<std::size_t>(std::clamp(t.cases, 0, kMaxCasesPerTemplate));
    return cases * static_cast<std::size_t>(std::clamp(c.variants, 0, kMaxVariantsPerCase));
}

} // namespace

std::vector<CaseIssue> checkCurriculum(const Curriculum& curriculum, const std::vector<scene::CaseSpec>& bases) {
    std::vector<CaseIssue> issues;
    if (curriculum.title.size() > kMaxCurriculumTitleLength)
        issues.push_back({"/title", quoteText(curriculum.title) + " is " + std::to_string(curriculum.title.size()) +
                                        " bytes long (allowed at most " + std::to_string(kMaxCurriculumTitleLength) +
                                        ")"});
    if (curriculum.variants < 1 || curriculum.variants > kMaxVariantsPerCase)
        issues.push_back({"/variants", std::to_string(curriculum.variants) +
                                           " is outside the supported range (allowed 1.." +
                                           std::to_string(kMaxVariantsPerCase) + ")"});
    if (curriculum.templates.empty() || curriculum.templates.size() > kMaxTemplates)
        issues.push_back({"/templates", std::to_string(curriculum.templates.size()) + " templates (allowed 1.." +
                                            std::to_string(kMaxTemplates) + ")"});
    if (const std::size_t jobs = jobCount(curriculum); jobs > kMaxJobs)
        issues.push_back({"/templates", std::to_string(jobs) + " jobs (cases x variants; allowed at most " +
                                            std::to_string(kMaxJobs) + ")"});
    std::map<std::string, std::size_t> firstIndexOfName;
    for (std::size_t i = 0; i < curriculum.templates.size() && i < bases.size(); ++i) {
        const CaseTemplate& t = curriculum.templates[i];
        const std::string prefix = "/templates/" + std::to_string(i);
        if (!isName(t.name))
            issues.push_back({prefix + "/name", quoteText(t.name) + " is not a valid name (1-" +
                                                    std::to_string(kMaxTemplateNameLength) +
                                                    " characters: letters, digits, '-' and '_', starting with a "
                                                    "letter or digit)"});
        const auto [it, inserted] = firstIndexOfName.emplace(t.name, i);
        if (!inserted)
            issues.push_back({prefix + "/name", quoteText(t.name) + " repeats the name of /templates/" +
                                                    std::to_string(it->second) + " (names must be unique)"});
        TemplateIssues templateIssues(issues, prefix);
        checkTemplate(t, bases[i], templateIssues);
    }
    return issues;
}

Result<LoadedCurriculum> loadCurriculum(const std::string& path) {
    auto text = io::readFile(path, kMaxCurriculumFileBytes);
    if (!text)
        return text.failure();
    auto parsed = parseCurriculum(*text, path);
    if (!parsed)
        return parsed.failure();
    LoadedCurriculum loaded{std::move(*parsed), {}, path};
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    std::vector<CaseIssue> issues;
    for (std::size_t i = 0; i < loaded.curriculum.templates.size(); ++i) {
        const auto& base = loaded.curriculum.templates[i].base;
        if (!base) {
            loaded.bases.push_back(scene::defaultCase());
            continue;
        }
        const std::filesystem::path basePath =
            std::filesystem::path(*base).is_absolute() ? std::filesystem::path(*base) : folder / *base;
        auto spec = scene::loadCase(basePath.string());
        if (!spec) {
            issues.push_back({"/templates/" + std::to_string(i) + "/base", spec.error().detail});
            loaded.bases.push_back(scene::defaultCase());
            continue;
        }
        // The drawn cases are saved in the batch folder: the base's relative paths must keep pointing where they did.
        const std::filesystem::path baseFolder = basePath.parent_path();
        const auto absolute = [&baseFolder](std::optional<std::string>& file) {
            if (file && std::filesystem::path(*file).is_relative())
                file = std::filesystem::absolute(baseFolder / *file).lexically_normal().string();
        };
        absolute(spec->anatomy.modelPath);
        absolute(spec->texture.exemplars.endometrium);
        absolute(spec->texture.exemplars.myoma);
        absolute(spec->texture.exemplars.polyp);
        absolute(spec->texture.exemplars.cervicalCanal);
        loaded.bases.push_back(std::move(*spec));
    }
    for (CaseIssue& issue : checkCurriculum(loaded.curriculum, loaded.bases))
        issues.push_back(std::move(issue));
    if (!issues.empty())
        return scene::failWithIssues(path, issues);
    return loaded;
}

scene::CaseSpec sampleCase(const LoadedCurriculum& loaded, std::size_t templateIndex, std::size_t caseIndex) {
    const Curriculum& c = loaded.curriculum;
    const CaseTemplate& t = c.templates[templateIndex];
    scene::CaseSpec spec = loaded.bases[templateIndex];
    Rng rng(Rng::deriveSeed(c.seed, templateIndex * kTemplateStreamStride + caseIndex));
    applyPatient(t.patient, drawPatient(rng, t.patient, spec.patient), spec.patient);
    if (t.pathologies) {
        spec.pathologies.clear();
        for (const PathologySampler& s : *t.pathologies)
            spec.pathologies.push_back(makePathology(s, drawPathology(rng, s)));
    }
    spec.seed = rng.next() >> 11; // below 2^53: JSON tools that read numbers as doubles keep it
    spec.title = (c.title.empty() ? std::string() : c.title + ": ") + t.name + " " + std::to_string(caseIndex);
    return spec;
}

} // namespace hs::batch
