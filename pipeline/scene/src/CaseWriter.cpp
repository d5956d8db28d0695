// CaseSpec -> JSON (current schema version), fields in schema order.
#include "CaseWriter.h"

namespace hs::scene::detail {

namespace {

using ojson = nlohmann::ordered_json;

template <class T>
ojson optionalValue(const std::optional<T>& value) {
    return value ? ojson(*value) : ojson(nullptr);
}

ojson vec3(const Vec3& v) {
    return ojson::array({v.x, v.y, v.z});
}

ojson writePathology(const PathologySpec& s) {
    ojson j;
    j["id"] = s.id;
    j["kind"] = std::string(toString(s.kind));
    j["growthModel"] = std::string(toString(s.growthModel));
    j["sizeMm"] = s.sizeMm;
    // Only the fields of the pathology's kind are written (the others must be unset in a valid spec).
    if (s.kind == clinical::PathologyKind::Myoma || s.figo) {
        if (!s.figo)
            j["figo"] = nullptr;
        else if (s.figo->isHybrid())
            j["figo"] = s.figo->toString();
        else
            j["figo"] = s.figo->type;
    }
    if (s.kind == clinical::PathologyKind::Polyp || s.attachment)
        j["attachment"] = s.attachment ? ojson(std::string(toString(*s.attachment))) : ojson(nullptr);
    if (s.kind == clinical::PathologyKind::Polyp || s.stalkLengthMm)
        j["stalkLengthMm"] = optionalValue(s.stalkLengthMm);
    if (const auto* described = std::get_if<clinical::ClinicalPlacement>(&s.placement)) {
        j["placement"] = ojson{{"location", std::string(toString(described->location))}};
    } else {
        const auto& surface = std::get<clinical::SurfacePlacement>(s.placement);
        ojson p;
        p["pointMm"] = vec3(surface.pointMm);
        p["normal"] = vec3(surface.normal);
        j["placement"] = p;
    }
    return j;
}

} // namespace

ojson writeCase(const CaseSpec& spec) {
    ojson j;
    j["format"] = std::string(kCaseFormat);
    j["schemaVersion"] = kCaseSchemaVersion;
    j["title"] = spec.title;
    j["seed"] = spec.seed;

    const clinical::PatientParams& p = spec.patient;
    j["patient"] = ojson{{"ageYears", p.ageYears},
                         {"parity", p.parity},
                         {"gravidity", p.gravidity},
                         {"heightCm", p.heightCm},
                         {"weightKg", p.weightKg},
                         {"menopausal", p.menopausal},
                         {"cyclePhase", p.cyclePhase ? ojson(std::string(toString(*p.cyclePhase))) : ojson(nullptr)}};

    const AnatomyParams& a = spec.anatomy;
    const UterusDimensions& d = a.dimensions;
    ojson anatomy;
    anatomy["shape"] = std::string(toString(a.shape));
    anatomy["modelPath"] = optionalValue(a.modelPath);
    anatomy["versionDeg"] = optionalValue(a.versionDeg);
    anatomy["flexionDeg"] = optionalValue(a.flexionDeg);
    anatomy["dimensions"] = ojson{{"lengthMm", optionalValue(d.lengthMm)},
                                  {"widthMm", optionalValue(d.widthMm)},
                                  {"apMm", optionalValue(d.apMm)},
                                  {"cavityLengthMm", optionalValue(d.cavityLengthMm)},
                                  {"cavityWidthMm", optionalValue(d.cavityWidthMm)},
                                  {"cornualAngleDeg", optionalValue(d.cornualAngleDeg)},
                                  {"fundalWallThicknessMm", optionalValue(d.fundalWallThicknessMm)},
                                  {"cervixLengthMm", optionalValue(d.cervixLengthMm)}};
    anatomy["endometrialThicknessMm"] = optionalValue(a.endometrialThicknessMm);
    j["anatomy"] = anatomy;

    ojson pathologies = ojson::array();
    for (const PathologySpec& s : spec.pathologies)
        pathologies.push_back(writePathology(s));
    j["pathologies"] = pathologies;

    const MeshingParams& m = spec.meshing;
    ojson meshing;
    meshing["method"] = std::string(toString(m.method));
    meshing["targetEdgeLengthMm"] = optionalValue(m.targetEdgeLengthMm);
    meshing["targetVertices"] = optionalValue(m.targetVertices);
    meshing["seeding"] = std::string(toString(m.seeding));
    meshing["particlesPerInnerVoxel"] = optionalValue(m.particlesPerInnerVoxel);
    meshing["relaxationIterations"] = m.relaxationIterations;
    meshing["threads"] = m.threads;
    j["meshing"] = meshing;

    const TextureParams& t = spec.texture;
    ojson texture;
    texture["sizePx"] = t.sizePx;
    texture["exemplars"] = ojson{{"endometrium", optionalValue(t.exemplars.endometrium)},
                                 {"myoma", optionalValue(t.exemplars.myoma)},
                                 {"polyp", optionalValue(t.exemplars.polyp)},
                                 {"cervicalCanal", optionalValue(t.exemplars.cervicalCanal)}};
    texture["vesselDensity"] = t.vesselDensity;
    j["texture"] = texture;

    ojson scene;
    scene["hydrometraPressureKpa"] = spec.scene.hydrometraPressureKpa;
    ojson materials;
    for (const clinical::Tissue tissue : clinical::kTissues) {
        const MaterialOverride& o = spec.scene.materials[static_cast<std::size_t>(tissue)];
        materials[std::string(toString(tissue))] = ojson{{"youngsModulusKpa", optionalValue(o.youngsModulusKpa)},
                                                         {"poissonRatio", optionalValue(o.poissonRatio)},
                                                         {"densityKgPerM3", optionalValue(o.densityKgPerM3)},
                                                         {"heterogeneity", optionalValue(o.heterogeneity)}};
    }
    scene["materials"] = materials;
    j["scene"] = scene;
    return j;
}

} // namespace hs::scene::detail
