// parseCurriculum / toJson(Curriculum): the curriculum document. Structure, types, names and choices only; the rules
// about values are checkCurriculum()'s (CurriculumCheck.cpp).
#include "hs/batch/Curriculum.h"
#include "hs/scene/JsonText.h"

#include <nlohmann/json.hpp>

namespace hs::batch {

namespace {

using nlohmann::json;
using scene::JsonIssues;
using scene::ObjectReader;

/// `25`, `{"uniform": [18, 45]}` or `{"oneOf": [0, 1, 2]}`; `integer` fields take integers only.
bool readNumberSampler(const json& v, const std::string& path, bool integer, NumberSampler& out, JsonIssues& issues) {
    auto readOne = [&](const json& item, const std::string& itemPath, double& value) {
        if (!integer)
            return scene::readValue(item, itemPath, value, issues);
        int whole = 0;
        if (!scene::readValue(item, itemPath, whole, issues))
            return false;
        value = whole;
        return true;
    };
    if (!v.is_object()) {
        double value = 0.0;
        if (v.is_array() || !readOne(v, path, value)) {
            if (v.is_array())
                scene::typeIssue(issues, path,
                                 "a number, {\"uniform\": [min, max]} or {\"oneOf\": [values]} (an array is not one)",
                                 v);
            return false;
        }
        out.values = {value};
        return true;
    }
    ObjectReader o(v, path, issues);
    const json* uniform = o.member("uniform");
    const json* oneOf = o.member("oneOf");
    o.finish();
    if ((uniform != nullptr) == (oneOf != nullptr)) {
        issues.push_back({path, "give exactly one of \"uniform\": [min, max] and \"oneOf\": [values]"});
        return false;
    }
    const std::string listPath = path + (uniform ? "/uniform" : "/oneOf");
    const json& list = uniform ? *uniform : *oneOf;
    if (!list.is_array() || list.empty() || (uniform && list.size() != 2)) {
        scene::typeIssue(issues, listPath, uniform ? "an array [min, max]" : "a non-empty array of numbers", list);
        return false;
    }
    std::vector<double> values;
    bool ok = true;
    for (std::size_t i = 0; i < list.size(); ++i) {
        double value = 0.0;
        if (readOne(list[i], listPath + "/" + std::to_string(i), value))
            values.push_back(value);
        else
            ok = false;
    }
    if (!ok)
        return false;
    if (uniform) {
        if (values[0] > values[1]) {
            issues.push_back({listPath, "min " + scene::formatNumber(values[0]) + " is greater than max " +
                                            scene::formatNumber(values[1])});
            return false;
        }
        out.range = scene::Range{values[0], values[1]};
    } else {
        out.values = std::move(values);
    }
    return true;
}

/// `"fundal"` or `{"oneOf": ["fundal", "anterior"]}` (any type scene::readValue reads).
template <class T>
bool readChoiceSampler(const json& v, const std::string& path, ChoiceSampler<T>& out, JsonIssues& issues) {
    if (!v.is_object()) {
        T value{};
        if (!scene::readValue(v, path, value, issues))
            return false;
        out.values = {value};
        return true;
    }
    ObjectReader o(v, path, issues);
    const json* list = o.member("oneOf", true);
    o.finish();
    if (!list)
        return false;
    if (!list->is_array() || list->empty()) {
        scene::typeIssue(issues, path + "/oneOf", "a non-empty array", *list);
        return false;
    }
    std::vector<T> values;
    bool ok = true;
    for (std::size_t i = 0; i < list->size(); ++i) {
        T value{};
        if (scene::readValue((*list)[i], path + "/oneOf/" + std::to_string(i), value, issues))
            values.push_back(value);
        else
            ok = false;
    }
    if (ok)
        out.values = std::move(values);
    return ok;
}

void readNumber(ObjectReader& o, const std::string& key, bool integer, std::optional<NumberSampler>& out,
                bool required = false) {
    if (const json* v = o.member(key, required)) {
        NumberSampler sampler;
        if (readNumberSampler(*v, o.pathOf(key), integer, sampler, o.issues()))
            out = std::move(sampler);
    }
}

template <class T>
void readChoice(ObjectReader& o, const std::string& key, std::optional<ChoiceSampler<T>>& out, bool required = false) {
    if (const json* v = o.member(key, required)) {
        ChoiceSampler<T> sampler;
        if (readChoiceSampler(*v, o.pathOf(key), sampler, o.issues()))
            out = std::move(sampler);
    }
}

void readPatient(const json& v, const std::string& path, PatientSampler& p, JsonIssues& issues) {
    ObjectReader o(v, path, issues);
    readNumber(o, "ageYears", false, p.ageYears);
    readNumber(o, "parity", true, p.parity);
    readNumber(o, "gravidity", true, p.gravidity);
    readNumber(o, "heightCm", false, p.heightCm);
    readNumber(o, "weightKg", false, p.weightKg);
    readChoice(o, "menopausal", p.menopausal);
    readChoice(o, "cyclePhase", p.cyclePhase);
    o.finish();
}

void readPathology(const json& v, const std::string& path, PathologySampler& s, JsonIssues& issues) {
    ObjectReader o(v, path, issues);
    o.read("id", s.id, true);
    o.read("kind", s.kind, true);
    std::optional<ChoiceSampler<clinical::GrowthModel>> growthModel;
    readChoice(o, "growthModel", growthModel);
    if (growthModel)
        s.growthModel = *growthModel;
    std::optional<NumberSampler> size;
    readNumber(o, "sizeMm", false, size, true);
    if (size)
        s.sizeMm = *size;
    std::optional<ChoiceSampler<clinical::FigoType>> figo;
    readChoice(o, "figo", figo);
    if (figo)
        s.figo = *figo;
    std::optional<ChoiceSampler<clinical::PolypAttachment>> attachment;
    readChoice(o, "attachment", attachment);
    if (attachment)
        s.attachment = *attachment;
    readNumber(o, "stalkLengthMm", false, s.stalkLengthMm);
    std::optional<ChoiceSampler<clinical::UterineLocation>> location;
    readChoice(o, "location", location, true);
    if (location)
        s.location = *location;
    o.finish();
}

void readTemplate(const json& v, const std::string& path, CaseTemplate& t, JsonIssues& issues) {
    ObjectReader o(v, path, issues);
    o.read("name", t.name, true);
    o.read("cases", t.cases, true);
    o.read("base", t.base);
    if (const json* patient = o.member("patient"))
        readPatient(*patient, o.pathOf("patient"), t.patient, issues);
    if (const json* list = o.member("pathologies")) {
        if (!list->is_array()) {
            scene::typeIssue(issues, o.pathOf("pathologies"), "an array", *list);
        } else {
            t.pathologies.emplace();
            for (std::size_t i = 0; i < list->size(); ++i) {
                PathologySampler s;
                readPathology((*list)[i], o.pathOf("pathologies") + "/" + std::to_string(i), s, issues);
                t.pathologies->push_back(std::move(s));
            }
        }
    }
    o.finish();
}

void readCurriculum(const json& root, Curriculum& c, JsonIssues& issues) {
    ObjectReader o(root, "", issues);
    std::string format;
    if (const json* v = o.member("format", true);
        v && scene::readValue(*v, "/format", format, issues) && format != kCurriculumFormat)
        issues.push_back({"/format", scene::quoteText(format) + " is not a curriculum (expected \"" +
                                         std::string(kCurriculumFormat) + "\")"});
    int version = 0;
    if (const json* v = o.member("schemaVersion", true);
        v && scene::readValue(*v, "/schemaVersion", version, issues) && version != kCurriculumSchemaVersion)
        issues.push_back({"/schemaVersion", std::to_string(version) + " is not supported by this build (allowed " +
                                                std::to_string(kCurriculumSchemaVersion) + ")"});
    o.read("title", c.title);
    o.read("seed", c.seed, true);
    o.read("variants", c.variants);
    if (const json* list = o.member("templates", true)) {
        if (!list->is_array()) {
            scene::typeIssue(issues, "/templates", "an array", *list);
        } else {
            for (std::size_t i = 0; i < list->size(); ++i) {
                CaseTemplate t;
                readTemplate((*list)[i], "/templates/" + std::to_string(i), t, issues);
                c.templates.push_back(std::move(t));
            }
        }
    }
    o.finish();
}

// ---- Writing ----

/// Integer fields are written as integers, so that the strict reader takes them back.
json numberJson(const NumberSampler& s, bool integer = false) {
    const auto value = [integer](double v) { return integer ? json(static_cast<long long>(v)) : json(v); };
    if (s.range)
        return json{{"uniform", {value(s.range->min), value(s.range->max)}}};
    if (s.values.size() == 1)
        return value(s.values.front());
    json list = json::array();
    for (double v : s.values)
        list.push_back(value(v));
    return json{{"oneOf", list}};
}

json valueJson(bool value) {
    return value;
}
json valueJson(const clinical::FigoType& value) {
    return value.isHybrid() ? json(value.toString()) : json(value.type);
}
template <class E>
json valueJson(const E& value) {
    return std::string(toString(value));
}

template <class T>
json choiceJson(const ChoiceSampler<T>& s) {
    if (s.values.size() == 1)
        return valueJson(s.values.front());
    json list = json::array();
    for (const T& value : s.values)
        list.push_back(valueJson(value));
    return json{{"oneOf", list}};
}

nlohmann::ordered_json patientJson(const PatientSampler& p) {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    auto number = [&j](const char* key, const std::optional<NumberSampler>& s, bool integer = false) {
        if (s)
            j[key] = numberJson(*s, integer);
    };
    number("ageYears", p.ageYears);
    number("parity", p.parity, true);
    number("gravidity", p.gravidity, true);
    number("heightCm", p.heightCm);
    number("weightKg", p.weightKg);
    if (p.menopausal)
        j["menopausal"] = choiceJson(*p.menopausal);
    if (p.cyclePhase)
        j["cyclePhase"] = choiceJson(*p.cyclePhase);
    return j;
}

nlohmann::ordered_json pathologyJson(const PathologySampler& s) {
    nlohmann::ordered_json j;
    j["id"] = s.id;
    j["kind"] = std::string(toString(s.kind));
    j["growthModel"] = choiceJson(s.growthModel);
    j["sizeMm"] = numberJson(s.sizeMm);
    if (!s.figo.values.empty())
        j["figo"] = choiceJson(s.figo);
    if (!s.attachment.values.empty())
        j["attachment"] = choiceJson(s.attachment);
    if (s.stalkLengthMm)
        j["stalkLengthMm"] = numberJson(*s.stalkLengthMm);
    j["location"] = choiceJson(s.location);
    return j;
}

} // namespace

Result<Curriculum> parseCurriculum(std::string_view jsonText, const std::string& sourceName) {
    scene::JsonDocumentLimits limits;
    limits.maxBytes = kMaxCurriculumFileBytes;
    limits.kind = "curriculum";
    return scene::parseJsonDocument<Curriculum>(jsonText, sourceName, limits, readCurriculum);
}

std::string toJson(const Curriculum& curriculum) {
    nlohmann::ordered_json j;
    j["format"] = std::string(kCurriculumFormat);
    j["schemaVersion"] = kCurriculumSchemaVersion;
    j["title"] = curriculum.title;
    j["seed"] = curriculum.seed;
    j["variants"] = curriculum.variants;
    auto templates = nlohmann::ordered_json::array();
    for (const CaseTemplate& t : curriculum.templates) {
        nlohmann::ordered_json tj;
        tj["name"] = t.name;
        tj["cases"] = t.cases;
        if (t.base)
            tj["base"] = *t.base;
        tj["patient"] = patientJson(t.patient);
        if (t.pathologies) {
            auto list = nlohmann::ordered_json::array();
            for (const PathologySampler& s : *t.pathologies)
                list.push_back(pathologyJson(s));
            tj["pathologies"] = list;
        }
        templates.push_back(tj);
    }
    j["templates"] = templates;
    return j.dump(4, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

} // namespace hs::batch
