#include "CaseReader.h"

#include "Format.h"

#include <cmath>
#include <limits>
#include <set>

namespace hs::scene::detail {

namespace {

using nlohmann::json;
using Issues = std::vector<CaseIssue>;

void readPatient(const json& v, const std::string& path, clinical::PatientParams& p, Issues& issues) {
    ObjectReader o(v, path, issues);
    o.read("ageYears", p.ageYears);
    o.read("parity", p.parity);
    o.read("gravidity", p.gravidity);
    o.read("heightCm", p.heightCm);
    o.read("weightKg", p.weightKg);
    o.read("menopausal", p.menopausal);
    o.read("cyclePhase", p.cyclePhase);
    o.finish();
}

void readDimensions(const json& v, const std::string& path, UterusDimensions& d, Issues& issues) {
    ObjectReader o(v, path, issues);
    o.read("lengthMm", d.lengthMm);
    o.read("widthMm", d.widthMm);
    o.read("apMm", d.apMm);
    o.read("cavityLengthMm", d.cavityLengthMm);
    o.read("cavityWidthMm", d.cavityWidthMm);
    o.read("cornualAngleDeg", d.cornualAngleDeg);
    o.read("fundalWallThicknessMm", d.fundalWallThicknessMm);
    o.read("cervixLengthMm", d.cervixLengthMm);
    o.finish();
}

void readAnatomy(const json& v, const std::string& path, AnatomyParams& a, Issues& issues) {
    ObjectReader o(v, path, issues);
    o.read("shape", a.shape);
    o.read("modelPath", a.modelPath);
    o.read("versionDeg", a.versionDeg);
    o.read("flexionDeg", a.flexionDeg);
    if (const json* d = o.member("dimensions"))
        readDimensions(*d, o.pathOf("dimensions"), a.dimensions, issues);
    o.read("endometrialThicknessMm", a.endometrialThicknessMm);
    o.finish();
}

/// {"location": ...} or {"pointMm": [...], "normal": [...]}: exactly one form.
void readPlacement(const json& v, const std::string& path, clinical::Placement& placement, Issues& issues) {
    ObjectReader o(v, path, issues);
    const json* location = o.member("location");
    const json* point = o.member("pointMm");
    const json* normal = o.member("normal");
    o.finish();
    if (!o.ok())
        return;
    const bool surface = point || normal;
    if (location && surface) {
        issues.push_back({path, "give either a clinical placement {\"location\"} or a surface placement "
                                "{\"pointMm\", \"normal\"}, not both"});
    } else if (location) {
        clinical::ClinicalPlacement described;
        if (readValue(*location, o.pathOf("location"), described.location, issues))
            placement = described;
    } else if (surface) {
        clinical::SurfacePlacement s;
        if (!point)
            issues.push_back({o.pathOf("pointMm"), "required field is missing (a surface placement has pointMm and "
                                                   "normal)"});
        if (!normal)
            issues.push_back({o.pathOf("normal"), "required field is missing (a surface placement has pointMm and "
                                                  "normal)"});
        if (point && normal && readValue(*point, o.pathOf("pointMm"), s.pointMm, issues) &&
            readValue(*normal, o.pathOf("normal"), s.normal, issues))
            placement = s;
    } else {
        issues.push_back({path, "empty placement: give {\"location\": one of " +
                                    choiceList(clinical::kUterineLocations) +
                                    "} or {\"pointMm\": [x, y, z], \"normal\": [x, y, z]}"});
    }
}

void readPathology(const json& v, const std::string& path, PathologySpec& s, Issues& issues) {
    ObjectReader o(v, path, issues);
    o.read("id", s.id, true);
    o.read("kind", s.kind, true);
    o.read("growthModel", s.growthModel);
    o.read("sizeMm", s.sizeMm, true);
    o.read("figo", s.figo);
    o.read("attachment", s.attachment);
    o.read("stalkLengthMm", s.stalkLengthMm);
    if (const json* placement = o.member("placement", true))
        readPlacement(*placement, o.pathOf("placement"), s.placement, issues);
    o.finish();
}

void readPathologies(const json& v, const std::string& path, std::vector<PathologySpec>& list, Issues& issues) {
    if (!v.is_array()) {
        typeIssue(issues, path, "an array of pathologies", v);
        return;
    }
    if (v.size() > kMaxPathologies) { // checked here too, so that a huge list is not read at all
        issues.push_back({path, std::to_string(v.size()) + " pathologies (allowed at most " +
                                    std::to_string(kMaxPathologies) + ")"});
        return;
    }
    list.clear();
    for (std::size_t i = 0; i < v.size(); ++i) {
        PathologySpec s;
        readPathology(v[i], path + "/" + std::to_string(i), s, issues);
        list.push_back(std::move(s));
    }
}

void readMeshing(const json& v, const std::string& path, MeshingParams& m, Issues& issues) {
    ObjectReader o(v, path, issues);
    o.read("method", m.method);
    // Exactly one density control is set. The default (targetVertices) applies only when the document names
    // neither, so that `"targetEdgeLengthMm": 0.5` alone is enough.
    o.read("targetEdgeLengthMm", m.targetEdgeLengthMm);
    if (m.targetEdgeLengthMm && !o.member("targetVertices"))
        m.targetVertices.reset();
    o.read("targetVertices", m.targetVertices);
    o.read("seeding", m.seeding);
    o.read("particlesPerInnerVoxel", m.particlesPerInnerVoxel);
    o.read("relaxationIterations", m.relaxationIterations);
    o.read("threads", m.threads);
    o.finish();
}

void readTexture(const json& v, const std::string& path, TextureParams& t, Issues& issues) {
    ObjectReader o(v, path, issues);
    o.read("sizePx", t.sizePx);
    if (const json* e = o.member("exemplars")) {
        ObjectReader exemplars(*e, o.pathOf("exemplars"), issues);
        exemplars.read("endometrium", t.exemplars.endometrium);
        exemplars.read("myoma", t.exemplars.myoma);
        exemplars.read("polyp", t.exemplars.polyp);
        exemplars.read("cervicalCanal", t.exemplars.cervicalCanal);
        exemplars.finish();
    }
    o.read("vesselDensity", t.vesselDensity);
    o.finish();
}

void readScene(const json& v, const std::string& path, SceneParams& s, Issues& issues) {
    ObjectReader o(v, path, issues);
    o.read("hydrometraPressureKpa", s.hydrometraPressureKpa);
    if (const json* materials = o.member("materials")) {
        ObjectReader tissues(*materials, o.pathOf("materials"), issues);
        for (const clinical::Tissue tissue : clinical::kTissues) {
            const std::string key(toString(tissue));
            if (const json* m = tissues.member(key)) {
                MaterialOverride& out = s.materials[static_cast<std::size_t>(tissue)];
                ObjectReader fields(*m, tissues.pathOf(key), issues);
                fields.read("youngsModulusKpa", out.youngsModulusKpa);
                fields.read("poissonRatio", out.poissonRatio);
                fields.read("densityKgPerM3", out.densityKgPerM3);
                fields.read("heterogeneity", out.heterogeneity);
                fields.finish();
            }
        }
        tissues.finish();
    }
    o.finish();
}

} // namespace

void readCase(const json& root, CaseSpec& spec, std::vector<CaseIssue>& issues) {
    ObjectReader o(root, "", issues);
    o.member("format", true); // checked (with schemaVersion) before the upgrade
    o.member("schemaVersion", true);
    o.read("title", spec.title);
    o.read("seed", spec.seed);
    if (const json* v = o.member("patient"))
        readPatient(*v, "/patient", spec.patient, issues);
    if (const json* v = o.member("anatomy"))
        readAnatomy(*v, "/anatomy", spec.anatomy, issues);
    if (const json* v = o.member("pathologies"))
        readPathologies(*v, "/pathologies", spec.pathologies, issues);
    if (const json* v = o.member("meshing"))
        readMeshing(*v, "/meshing", spec.meshing, issues);
    if (const json* v = o.member("texture"))
        readTexture(*v, "/texture", spec.texture, issues);
    if (const json* v = o.member("scene"))
        readScene(*v, "/scene", spec.scene, issues);
    o.finish();
}

} // namespace hs::scene::detail
