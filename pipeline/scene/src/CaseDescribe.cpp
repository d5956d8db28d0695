// describe(): the short summary `hysteroscene-cli info` and `validate` print for a case.

#include "Format.h"
#include "hs/core/Units.h"
#include "hs/scene/CaseSpec.h"

#include <cmath>

namespace hs::scene {

namespace {

using detail::formatNumber;

/// "label       text": labels padded to 12 columns, like the CLI's own lines.
std::string line(std::string_view label, const std::string& text) {
    std::string out(label);
    out.resize(std::max<std::size_t>(out.size() + 1, 12), ' ');
    return out + text;
}

/// One decimal at most: 23.875 -> "23.9", 60 -> "60".
std::string rounded(double value) {
    return formatNumber(std::round(value * 10.0) / 10.0);
}

std::string describePatient(const clinical::PatientParams& p) {
    const double heightM = p.heightCm / 100.0;
    return rounded(p.ageYears) + " years, gravida " + std::to_string(p.gravidity) + " para " +
           std::to_string(p.parity) + ", " + rounded(p.heightCm) + " cm, " + rounded(p.weightKg) + " kg (BMI " +
           rounded(p.weightKg / (heightM * heightM)) + "), " + (p.menopausal ? "postmenopausal" : "premenopausal") +
           (p.cyclePhase ? ", " + std::string(clinical::toString(*p.cyclePhase)) + " phase" : std::string());
}

std::string describeAnatomy(const AnatomyParams& a) {
    std::string text = a.shape == ShapeMode::Mean ? "model mean for the patient" : "seeded sample for the patient";
    text += a.modelPath ? ", model " + *a.modelPath : ", bundled model";
    if (a.versionDeg)
        text += ", version " + formatNumber(*a.versionDeg) + " deg";
    if (a.flexionDeg)
        text += ", flexion " + formatNumber(*a.flexionDeg) + " deg";
    const UterusDimensions& d = a.dimensions;
    const std::optional<double>* fields[] = {&d.lengthMm,
                                             &d.widthMm,
                                             &d.apMm,
                                             &d.cavityLengthMm,
                                             &d.cavityWidthMm,
                                             &d.cornualAngleDeg,
                                             &d.fundalWallThicknessMm,
                                             &d.cervixLengthMm};
    int overrides = 0;
    for (const auto* f : fields)
        overrides += f->has_value() ? 1 : 0;
    text += overrides ? ", " + std::to_string(overrides) + " dimension overrides" : "";
    return text;
}

std::string describePlacement(const clinical::Placement& placement) {
    if (const auto* described = std::get_if<clinical::ClinicalPlacement>(&placement))
        return std::string(toString(described->location));
    const auto& s = std::get<clinical::SurfacePlacement>(placement);
    return "at (" + formatNumber(s.pointMm.x) + ", " + formatNumber(s.pointMm.y) + ", " + formatNumber(s.pointMm.z) +
           ") mm";
}

std::string describePathology(const PathologySpec& s) {
    std::string text = s.id + ": " + std::string(toString(s.kind));
    if (s.figo) {
        text += " FIGO " + s.figo->toString();
        if (!s.figo->isHybrid() && !clinical::figoDefinition(s.figo->type).empty())
            text += " (" + std::string(clinical::figoDefinition(s.figo->type)) + ")";
    }
    if (s.attachment)
        text += " " + std::string(toString(*s.attachment));
    if (s.stalkLengthMm)
        text += " (stalk " + formatNumber(*s.stalkLengthMm) + " mm)";
    return text + ", " + formatNumber(s.sizeMm) + " mm, " + describePlacement(s.placement) + ", growth " +
           std::string(toString(s.growthModel));
}

std::string describeMeshing(const MeshingParams& m) {
    std::string text(toString(m.method));
    if (m.targetEdgeLengthMm)
        text += ", edge " + formatNumber(*m.targetEdgeLengthMm) + " mm";
    if (m.targetVertices)
        text += ", ~" + std::to_string(*m.targetVertices) + " vertices";
    text += m.seeding == MeshingSeeding::Random
                ? ", random seeding, " + std::to_string(m.particlesPerInnerVoxel.value_or(0)) + " per inner voxel"
                : ", lattice seeding";
    return text + ", " + std::to_string(m.relaxationIterations) + " relaxation iterations, threads " +
           (m.threads == 0 ? "auto" : std::to_string(m.threads));
}

std::string describeTexture(const TextureParams& t) {
    const bool custom = t.exemplars.endometrium || t.exemplars.myoma || t.exemplars.polyp || t.exemplars.cervicalCanal;
    return std::to_string(t.sizePx) + " px maps, " + (custom ? "custom" : "procedural") +
           " exemplars, vessel density " + formatNumber(t.vesselDensity);
}

std::string describeScene(const SceneParams& s) {
    std::string text = "hydrometra " + formatNumber(s.hydrometraPressureKpa) + " kPa (" +
                       rounded(s.hydrometraPressureKpa / units::kKpaPerMmHg) + " mmHg)";
    std::string overridden;
    for (const clinical::Tissue tissue : clinical::kTissues) {
        const MaterialOverride& o = s.materials[static_cast<std::size_t>(tissue)];
        if (o.youngsModulusKpa || o.poissonRatio || o.densityKgPerM3 || o.heterogeneity)
            overridden += (overridden.empty() ? "" : ", ") + std::string(toString(tissue));
    }
    return text + ", materials " + (overridden.empty() ? "default" : "overridden for " + overridden);
}

} // namespace

std::vector<std::string> describe(const CaseSpec& spec) {
    std::vector<std::string> lines;
    if (!spec.title.empty())
        lines.push_back(line("title", spec.title));
    lines.push_back(line("schema", std::string(kCaseFormat) + " version " + std::to_string(kCaseSchemaVersion)));
    lines.push_back(line("seed", std::to_string(spec.seed)));
    lines.push_back(line("patient", describePatient(spec.patient)));
    lines.push_back(line("anatomy", describeAnatomy(spec.anatomy)));
    if (spec.pathologies.empty())
        lines.push_back(line("pathology", "none (healthy uterus)"));
    for (const PathologySpec& s : spec.pathologies)
        lines.push_back(line("pathology", describePathology(s)));
    lines.push_back(line("meshing", describeMeshing(spec.meshing)));
    lines.push_back(line("texture", describeTexture(spec.texture)));
    lines.push_back(line("scene", describeScene(spec.scene)));
    return lines;
}

} // namespace hs::scene
