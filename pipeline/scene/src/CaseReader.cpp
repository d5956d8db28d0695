#include "CaseReader.h"

#include "Format.h"

#include <cmath>
#include <limits>
#include <set>

namespace hs::scene::detail {

namespace {

using nlohmann::json;
using Issues = std::vector<CaseIssue>;

/// "an integer 3", "a string \"x\"", "an object": what was found, for type errors.
std::string describeValue(const json& value) {
    switch (value.type()) {
    case json::value_t::null:
        return "null";
    case json::value_t::boolean:
        return value.get<bool>() ? "true" : "false";
    case json::value_t::string:
        return "string " + quoteText(value.get_ref<const std::string&>());
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
        return "integer " + value.dump();
    case json::value_t::number_float:
        return "number " + formatNumber(value.get<double>());
    case json::value_t::array:
        return "an array";
    case json::value_t::object:
        return "an object";
    default:
        return value.type_name();
    }
}

void typeIssue(Issues& issues, const std::string& path, std::string_view expected, const json& value) {
    issues.push_back({path, "expected " + std::string(expected) + ", got " + describeValue(value)});
}

// ---- Scalar readers: return false (and record an issue) when the value has the wrong type. ----

bool readValue(const json& v, const std::string& path, double& out, Issues& issues) {
    if (!v.is_number()) {
        typeIssue(issues, path, "a number", v);
        return false;
    }
    const double d = v.get<double>();
    if (!std::isfinite(d)) { // e.g. 1e999, which the parser turns into infinity
        issues.push_back({path, "non-finite value " + formatNumber(d) + " (numbers must be finite)"});
        return false;
    }
    out = d;
    return true;
}

bool readValue(const json& v, const std::string& path, int& out, Issues& issues) {
    if (!v.is_number_integer()) {
        typeIssue(issues, path, "an integer", v);
        return false;
    }
    const bool fits = v.is_number_unsigned() ? v.get<unsigned long long>() <=
                                                   static_cast<unsigned long long>(std::numeric_limits<int>::max())
                                             : v.get<long long>() >= std::numeric_limits<int>::min();
    if (!fits) {
        issues.push_back({path, v.dump() + " is too large for this field"});
        return false;
    }
    out = v.get<int>();
    return true;
}

bool readValue(const json& v, const std::string& path, std::uint64_t& out, Issues& issues) {
    if (!v.is_number_unsigned()) { // negative integers are number_integer
        typeIssue(issues, path, "an unsigned integer 0..18446744073709551615", v);
        return false;
    }
    out = v.get<std::uint64_t>();
    return true;
}

bool readValue(const json& v, const std::string& path, bool& out, Issues& issues) {
    if (!v.is_boolean()) {
        typeIssue(issues, path, "true or false", v);
        return false;
    }
    out = v.get<bool>();
    return true;
}

bool readValue(const json& v, const std::string& path, std::string& out, Issues& issues) {
    if (!v.is_string()) {
        typeIssue(issues, path, "a string", v);
        return false;
    }
    out = v.get<std::string>();
    return true;
}

template <class E, std::size_t N>
bool readEnum(const json& v, const std::string& path, E& out, const std::array<E, N>& values, Issues& issues) {
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

bool readValue(const json& v, const std::string& path, clinical::PathologyKind& out, Issues& issues) {
    return readEnum(v, path, out, clinical::kPathologyKinds, issues);
}
bool readValue(const json& v, const std::string& path, clinical::GrowthModel& out, Issues& issues) {
    return readEnum(v, path, out, clinical::kGrowthModels, issues);
}
bool readValue(const json& v, const std::string& path, clinical::UterineLocation& out, Issues& issues) {
    return readEnum(v, path, out, clinical::kUterineLocations, issues);
}
bool readValue(const json& v, const std::string& path, clinical::PolypAttachment& out, Issues& issues) {
    return readEnum(v, path, out, clinical::kPolypAttachments, issues);
}
bool readValue(const json& v, const std::string& path, ShapeMode& out, Issues& issues) {
    return readEnum(v, path, out, kShapeModes, issues);
}
bool readValue(const json& v, const std::string& path, MeshingMethod& out, Issues& issues) {
    return readEnum(v, path, out, kMeshingMethods, issues);
}
bool readValue(const json& v, const std::string& path, MeshingSeeding& out, Issues& issues) {
    return readEnum(v, path, out, kMeshingSeedings, issues);
}
bool readValue(const json& v, const std::string& path, clinical::CyclePhase& out, Issues& issues) {
    return readEnum(v, path, out, clinical::kCyclePhases, issues);
}

/// A FIGO type: an integer (2) or a string ("2", "2-5"). Range rules are checkCase()'s.
bool readValue(const json& v, const std::string& path, clinical::FigoType& out, Issues& issues) {
    constexpr std::string_view kExpected = "a FIGO type: an integer 0..8 or a string such as \"2-5\"";
    if (v.is_number_integer()) {
        int type = 0;
        if (!readValue(v, path, type, issues))
            return false;
        out = clinical::FigoType{type, -1};
        return true;
    }
    if (v.is_string()) {
        if (auto figo = clinical::FigoType::parse(v.get_ref<const std::string&>())) {
            out = *figo;
            return true;
        }
        issues.push_back({path, quoteText(v.get_ref<const std::string&>()) + " is not " + std::string(kExpected)});
        return false;
    }
    typeIssue(issues, path, kExpected, v);
    return false;
}

bool readValue(const json& v, const std::string& path, Vec3& out, Issues& issues) {
    if (!v.is_array() || v.size() != 3) {
        typeIssue(issues, path, "an array of 3 numbers", v);
        return false;
    }
    Vec3 result;
    for (int i = 0; i < 3; ++i) {
        if (!readValue(v[static_cast<std::size_t>(i)], path + "/" + std::to_string(i), result[i], issues))
            return false;
    }
    out = result;
    return true;
}

/// Optional fields: null means "not set".
template <class T>
bool readValue(const json& v, const std::string& path, std::optional<T>& out, Issues& issues) {
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
    ObjectReader(const json& value, std::string path, Issues& issues)
        : m_value(value), m_path(std::move(path)), m_issues(issues) {
        if (!value.is_object())
            typeIssue(issues, m_path.empty() ? "(root)" : m_path, "an object", value);
    }
    ObjectReader(const ObjectReader&) = delete;
    ObjectReader& operator=(const ObjectReader&) = delete;

    bool ok() const { return m_value.is_object(); }
    std::string pathOf(const std::string& key) const { return m_path + "/" + escapePointerToken(key); }
    Issues& issues() { return m_issues; }

    /// The member `key`, or nullptr when absent (recorded as an issue when `required`).
    const json* member(const std::string& key, bool required = false) {
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
        if (const json* v = member(key, required))
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

    const json& m_value;
    std::string m_path;
    Issues& m_issues;
    std::vector<std::string> m_known;
};

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
