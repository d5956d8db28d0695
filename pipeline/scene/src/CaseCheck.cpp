// checkCase(): the range and consistency rules of the current schema, on the in-memory spec. The JSON reader
// checks only syntax, types and field names; every rule about values lives here, so a spec built in code (GUI)
// and a spec read from a file are held to the same rules.

#include "Format.h"
#include "hs/scene/CaseSpec.h"

#include <cmath>
#include <map>

namespace hs::scene {

namespace {

using detail::choiceList;
using detail::formatNumber;
using detail::formatRange;
using detail::quoteText;

class Checker {
public:
    explicit Checker(std::vector<CaseIssue>& issues) : m_issues(issues) {}

    void add(std::string path, std::string message) { m_issues.push_back({std::move(path), std::move(message)}); }

    /// Rejects NaN, infinities and values outside `range`; `unit` is appended to the range ("mm").
    void range(const std::string& path, double value, const Range& range, std::string_view unit) {
        const std::string allowed = "allowed " + formatRange(range) + (unit.empty() ? "" : " ") + std::string(unit);
        if (!std::isfinite(value))
            add(path, "non-finite value " + formatNumber(value) + " (" + allowed + ")");
        else if (!range.contains(value))
            add(path, formatNumber(value) + " is outside the supported range (" + allowed + ")");
    }
    void range(const std::string& path, const std::optional<double>& value, const Range& r, std::string_view unit) {
        if (value)
            range(path, *value, r, unit);
    }
    void range(const std::string& path, int value, const Range& r, std::string_view unit) {
        range(path, static_cast<double>(value), r, unit);
    }

    void text(const std::string& path, const std::string& value, std::size_t maxLength) {
        if (value.size() > maxLength)
            add(path, quoteText(value) + " is " + std::to_string(value.size()) + " bytes long (allowed at most " +
                          std::to_string(maxLength) + ")");
        if (value.find('\0') != std::string::npos)
            add(path, quoteText(value) + " contains a NUL character");
    }
    void filePath(const std::string& path, const std::optional<std::string>& value) {
        if (!value)
            return;
        if (value->empty())
            add(path, "\"\" is not a file path (write null for the default)");
        text(path, *value, kMaxPathLength);
    }

private:
    std::vector<CaseIssue>& m_issues;
};

void checkPatient(Checker& c, const clinical::PatientParams& p) {
    c.range("/patient/ageYears", p.ageYears, limits::kAgeYears, "years");
    c.range("/patient/parity", p.parity, limits::kParity, "births");
    c.range("/patient/gravidity", p.gravidity, limits::kGravidity, "pregnancies");
    if (p.gravidity < p.parity && p.parity >= 0)
        c.add("/patient/gravidity", std::to_string(p.gravidity) + " is less than the parity " +
                                        std::to_string(p.parity) + " (every birth follows a pregnancy)");
    if (p.menopausal && p.ageYears < limits::kMenopausalMinAgeYears)
        c.add("/patient/menopausal", "true needs ageYears >= " + formatNumber(limits::kMenopausalMinAgeYears) +
                                         " years, got " + formatNumber(p.ageYears) +
                                         " (premature ovarian insufficiency is not modelled)");
    if (!p.menopausal && p.ageYears > limits::kPremenopausalMaxAgeYears)
        c.add("/patient/menopausal", "false needs ageYears <= " + formatNumber(limits::kPremenopausalMaxAgeYears) +
                                         " years, got " + formatNumber(p.ageYears) +
                                         " (beyond the shape model's ages at menopause)");
    if (p.menopausal && p.cyclePhase)
        c.add("/patient/cyclePhase", "\"" + std::string(clinical::toString(*p.cyclePhase)) +
                                         "\" given for a postmenopausal patient, who has no cycle: write null");
    if (!p.menopausal && !p.cyclePhase)
        c.add("/patient/cyclePhase",
              "null for a premenopausal patient: give one of " + choiceList(clinical::kCyclePhases));
    c.range("/patient/heightCm", p.heightCm, limits::kHeightCm, "cm");
    c.range("/patient/weightKg", p.weightKg, limits::kWeightKg, "kg");
}

void checkAnatomy(Checker& c, const AnatomyParams& a) {
    c.filePath("/anatomy/modelPath", a.modelPath);
    c.range("/anatomy/versionDeg", a.versionDeg, limits::kVersionDeg, "degrees");
    c.range("/anatomy/flexionDeg", a.flexionDeg, limits::kFlexionDeg, "degrees");
    c.range("/anatomy/endometrialThicknessMm", a.endometrialThicknessMm, limits::kEndometrialThicknessMm,
            "mm (both layers)");
    const UterusDimensions& d = a.dimensions;
    const std::string p = "/anatomy/dimensions/";
    c.range(p + "lengthMm", d.lengthMm, limits::kLengthMm, "mm");
    c.range(p + "widthMm", d.widthMm, limits::kWidthMm, "mm");
    c.range(p + "apMm", d.apMm, limits::kApMm, "mm");
    c.range(p + "cavityLengthMm", d.cavityLengthMm, limits::kCavityLengthMm, "mm");
    c.range(p + "cavityWidthMm", d.cavityWidthMm, limits::kCavityWidthMm, "mm");
    c.range(p + "cornualAngleDeg", d.cornualAngleDeg, limits::kCornualAngleDeg, "degrees");
    c.range(p + "fundalWallThicknessMm", d.fundalWallThicknessMm, limits::kFundalWallThicknessMm, "mm");
    c.range(p + "cervixLengthMm", d.cervixLengthMm, limits::kCervixLengthMm, "mm");
    if (d.cavityLengthMm && d.lengthMm && !(*d.cavityLengthMm < *d.lengthMm))
        c.add(p + "cavityLengthMm", formatNumber(*d.cavityLengthMm) + " mm is not less than lengthMm " +
                                        formatNumber(*d.lengthMm) + " mm (the cavity lies inside the uterus)");
    if (d.cavityWidthMm && d.widthMm && !(*d.cavityWidthMm < *d.widthMm))
        c.add(p + "cavityWidthMm", formatNumber(*d.cavityWidthMm) + " mm is not less than widthMm " +
                                       formatNumber(*d.widthMm) + " mm (the cavity lies inside the uterus)");
}

bool isIdCharacter(char ch, bool first) {
    const bool alnum = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9');
    return alnum || (!first && (ch == '-' || ch == '_'));
}

void checkId(Checker& c, const std::string& path, const std::string& id) {
    bool valid = !id.empty() && id.size() <= kMaxPathologyIdLength;
    for (std::size_t i = 0; valid && i < id.size(); ++i)
        valid = isIdCharacter(id[i], i == 0);
    if (!valid)
        c.add(path, quoteText(id) + " is not a valid id (1-" + std::to_string(kMaxPathologyIdLength) +
                        " characters: letters, digits, '-' and '_', starting with a letter or digit)");
}

void checkMyoma(Checker& c, const std::string& p, const PathologySpec& s) {
    c.range(p + "/sizeMm", s.sizeMm, limits::kMyomaSizeMm, "mm");
    if (!s.figo)
        c.add(p + "/figo", "a myoma needs a FIGO type (0..8 or a hybrid such as \"2-5\")");
    else if (!s.figo->isValid())
        c.add(p + "/figo", quoteText(s.figo->toString()) +
                               " is not a FIGO type (allowed 0..8, or a hybrid X-Y with X in 1..3 and Y in 5..6)");
    if (s.attachment)
        c.add(p + "/attachment",
              quoteText(toString(*s.attachment)) + " is not allowed: attachment applies to polyps only");
    if (s.stalkLengthMm)
        c.add(p + "/stalkLengthMm",
              formatNumber(*s.stalkLengthMm) + " is not allowed: a stalk applies to pedunculated polyps only");
    if (const auto* described = std::get_if<clinical::ClinicalPlacement>(&s.placement);
        described && s.figo && s.figo->isValid()) {
        const bool cervical = described->location == clinical::UterineLocation::Cervical;
        const bool type8 = !s.figo->isHybrid() && s.figo->type == 8;
        if (cervical && !type8)
            c.add(p + "/figo", quoteText(s.figo->toString()) +
                                   " does not fit location \"cervical\" (a cervical myoma is "
                                   "FIGO type 8)");
        if (type8 && !cervical)
            c.add(p + "/placement/location",
                  quoteText(toString(described->location)) +
                      " does not fit FIGO type 8 (allowed \"cervical\"; parasitic myomas lie outside the uterus)");
    }
}

void checkPolyp(Checker& c, const std::string& p, const PathologySpec& s) {
    c.range(p + "/sizeMm", s.sizeMm, limits::kPolypSizeMm, "mm");
    if (s.figo)
        c.add(p + "/figo",
              quoteText(s.figo->toString()) + " is not allowed: a polyp has no FIGO type (FIGO classifies myomas)");
    if (s.growthModel == clinical::GrowthModel::CellularAutomaton)
        c.add(p + "/growthModel", "\"ca\" grows myomas only (allowed for polyps: \"skeleton\", \"particles\")");
    if (!s.attachment) {
        c.add(p + "/attachment", "a polyp needs an attachment (allowed: \"sessile\", \"pedunculated\")");
    } else if (*s.attachment == clinical::PolypAttachment::Pedunculated) {
        if (!s.stalkLengthMm)
            c.add(p + "/stalkLengthMm",
                  "a pedunculated polyp needs a stalk length (allowed " + formatRange(limits::kStalkLengthMm) + " mm)");
        else
            c.range(p + "/stalkLengthMm", *s.stalkLengthMm, limits::kStalkLengthMm, "mm");
    } else if (s.stalkLengthMm) {
        c.add(p + "/stalkLengthMm",
              formatNumber(*s.stalkLengthMm) + " is not allowed: a sessile polyp has no stalk (write null)");
    }
    if (const auto* described = std::get_if<clinical::ClinicalPlacement>(&s.placement);
        described && described->location == clinical::UterineLocation::Cervical)
        c.add(p + "/placement/location", "\"cervical\" is not allowed for a polyp (endometrial polyps grow in the "
                                         "uterine cavity)");
}

void checkSurfacePlacement(Checker& c, const std::string& p, const clinical::SurfacePlacement& s) {
    for (int i = 0; i < 3; ++i)
        c.range(p + "/pointMm/" + std::to_string(i), s.pointMm[i], limits::kSurfaceCoordinateMm, "mm");
    bool finite = true;
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(s.normal[i])) {
            c.add(p + "/normal/" + std::to_string(i), "non-finite value " + formatNumber(s.normal[i]));
            finite = false;
        }
    }
    if (finite && !(norm(s.normal) >= 1e-6))
        c.add(p + "/normal", "the normal has length " + formatNumber(norm(s.normal)) + " (must be at least 1e-06)");
}

void checkPathologies(Checker& c, const std::vector<PathologySpec>& list) {
    if (list.size() > kMaxPathologies)
        c.add("/pathologies",
              std::to_string(list.size()) + " pathologies (allowed at most " + std::to_string(kMaxPathologies) + ")");
    std::map<std::string, std::size_t> firstIndexOfId;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const PathologySpec& s = list[i];
        const std::string p = "/pathologies/" + std::to_string(i);
        checkId(c, p + "/id", s.id);
        const auto [it, inserted] = firstIndexOfId.emplace(s.id, i);
        if (!inserted)
            c.add(p + "/id", quoteText(s.id) + " repeats the id of /pathologies/" + std::to_string(it->second) +
                                 " (ids must be unique)");
        if (s.kind == clinical::PathologyKind::Myoma)
            checkMyoma(c, p, s);
        else
            checkPolyp(c, p, s);
        if (const auto* surface = std::get_if<clinical::SurfacePlacement>(&s.placement))
            checkSurfacePlacement(c, p + "/placement", *surface);
    }
}

void checkMeshing(Checker& c, const MeshingParams& m) {
    if (m.targetEdgeLengthMm && m.targetVertices)
        c.add("/meshing/targetVertices", "set either targetEdgeLengthMm or targetVertices, not both (write null for "
                                         "the other)");
    if (!m.targetEdgeLengthMm && !m.targetVertices)
        c.add("/meshing/targetVertices", "null, and targetEdgeLengthMm is null too: set one of them");
    c.range("/meshing/targetEdgeLengthMm", m.targetEdgeLengthMm, limits::kTargetEdgeLengthMm, "mm");
    if (m.targetVertices)
        c.range("/meshing/targetVertices", *m.targetVertices, limits::kTargetVertices, "vertices");
    if (m.seeding == MeshingSeeding::Random && !m.particlesPerInnerVoxel)
        c.add("/meshing/particlesPerInnerVoxel", "null with \"random\" seeding: give the particles per inner voxel (" +
                                                     formatRange(limits::kParticlesPerVoxel) + ")");
    if (m.seeding == MeshingSeeding::Lattice && m.particlesPerInnerVoxel)
        c.add("/meshing/particlesPerInnerVoxel", std::to_string(*m.particlesPerInnerVoxel) +
                                                     " does nothing with \"lattice\" seeding (the lattice sets the "
                                                     "points): write null, or \"seeding\": \"random\"");
    if (m.particlesPerInnerVoxel)
        c.range("/meshing/particlesPerInnerVoxel", *m.particlesPerInnerVoxel, limits::kParticlesPerVoxel, "");
    if (m.method != MeshingMethod::Particle && m.seeding == MeshingSeeding::Random)
        c.add("/meshing/seeding", "\"random\" applies to the particle method only (method is \"" +
                                      std::string(toString(m.method)) + "\"): write \"lattice\"");
    c.range("/meshing/relaxationIterations", m.relaxationIterations, limits::kRelaxationIterations, "");
    c.range("/meshing/threads", m.threads, limits::kThreads, "(0 = all hardware threads)");
}

void checkTexture(Checker& c, const TextureParams& t) {
    const bool powerOfTwo = t.sizePx > 0 && (t.sizePx & (t.sizePx - 1)) == 0;
    if (!limits::kTextureSizePx.contains(t.sizePx) || !powerOfTwo)
        c.add("/texture/sizePx", std::to_string(t.sizePx) + " is not a supported size (allowed a power of two in " +
                                     formatRange(limits::kTextureSizePx) + " px)");
    c.filePath("/texture/exemplars/endometrium", t.exemplars.endometrium);
    c.filePath("/texture/exemplars/myoma", t.exemplars.myoma);
    c.filePath("/texture/exemplars/polyp", t.exemplars.polyp);
    c.filePath("/texture/exemplars/cervicalCanal", t.exemplars.cervicalCanal);
    c.range("/texture/vesselDensity", t.vesselDensity, limits::kVesselDensity, "");
}

void checkScene(Checker& c, const SceneParams& s) {
    c.range("/scene/hydrometraPressureKpa", s.hydrometraPressureKpa, limits::kHydrometraPressureKpa, "kPa");
    for (const clinical::Tissue tissue : clinical::kTissues) {
        const MaterialOverride& m = s.materials[static_cast<std::size_t>(tissue)];
        const std::string p = "/scene/materials/" + std::string(toString(tissue)) + "/";
        c.range(p + "youngsModulusKpa", m.youngsModulusKpa, youngsModulusRangeKpa(tissue), "kPa");
        c.range(p + "poissonRatio", m.poissonRatio, limits::kPoissonRatio, "");
        c.range(p + "densityKgPerM3", m.densityKgPerM3, limits::kDensityKgPerM3, "kg/m^3");
        c.range(p + "heterogeneity", m.heterogeneity, limits::kHeterogeneity, "(coefficient of variation)");
    }
}

} // namespace

std::vector<CaseIssue> checkCase(const CaseSpec& spec) {
    std::vector<CaseIssue> issues;
    Checker c(issues);
    c.text("/title", spec.title, kMaxTitleLength);
    checkPatient(c, spec.patient);
    checkAnatomy(c, spec.anatomy);
    checkPathologies(c, spec.pathologies);
    checkMeshing(c, spec.meshing);
    checkTexture(c, spec.texture);
    checkScene(c, spec.scene);
    return issues;
}

} // namespace hs::scene
