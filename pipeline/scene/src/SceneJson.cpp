// scene.json, labels.json and report.json: writing and reading.

#include "SceneJson.h"
#include "hs/scene/JsonText.h"
#include "hs/scene/MeshBars.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace hs::scene::detail {

namespace {

using nlohmann::json;
using ordered = nlohmann::ordered_json;

constexpr std::string_view kSceneDoc = "hysteroscene-scene-model";
constexpr std::string_view kLabelsDoc = "hysteroscene-labels";
constexpr std::string_view kReportDoc = "hysteroscene-report";

std::string dump(const ordered& j) {
    return j.dump(2) + "\n";
}

ordered rangeJson(const Range& r) {
    return ordered{{"min", r.min}, {"max", r.max}};
}

ordered materialJson(const SceneMaterial& m) {
    ordered j;
    j["id"] = m.id;
    j["regionId"] = m.regionId;
    j["name"] = m.name;
    j["tissue"] = std::string(toString(m.tissue));
    j["youngsModulusKpa"] = m.material.youngsModulusKpa;
    j["poissonRatio"] = m.material.poissonRatio;
    j["densityKgPerM3"] = m.material.densityKgPerM3;
    j["youngsModulusRangeKpa"] = rangeJson(m.youngsModulusRangeKpa);
    j["heterogeneity"] = m.heterogeneity;
    return j;
}

ordered pathologyJson(const PathologyDescriptor& p) {
    ordered j;
    j["id"] = p.id;
    j["kind"] = std::string(toString(p.kind));
    j["regionId"] = p.regionId;
    j["sizeMm"] = p.sizeMm;
    j["volumeMl"] = p.volumeMl;
    j["figo"] = p.figo ? json(p.figo->toString()) : json(nullptr);
    if (p.lasmar) {
        j["lasmar"] = ordered{{"size", p.lasmar->size},           {"topography", p.lasmar->topography},
                              {"extension", p.lasmar->extension}, {"penetration", p.lasmar->penetration},
                              {"wall", p.lasmar->wall},           {"total", p.lasmar->total()}};
    } else {
        j["lasmar"] = nullptr;
    }
    j["location"] = p.location;
    if (p.tissueContactFraction)
        j["tissueContactFraction"] = *p.tissueContactFraction;
    return j;
}

/// Reading helpers: every access goes through these, so a wrong type or a missing member becomes an error naming
/// the file and the JSON pointer instead of an exception.
struct Reader {
    const std::string& name;
    std::string error;

    const json* member(const json& j, const char* key, const std::string& path) {
        if (!error.empty())
            return nullptr;
        if (!j.is_object() || !j.contains(key)) {
            error = name + ": " + path + "/" + key + " is missing";
            return nullptr;
        }
        return &j.at(key);
    }
    double number(const json& j, const char* key, const std::string& path) {
        const json* v = member(j, key, path);
        if (!v)
            return 0.0;
        if (!v->is_number()) {
            error = name + ": " + path + "/" + key + " must be a number";
            return 0.0;
        }
        return v->get<double>();
    }
    std::int64_t integer(const json& j, const char* key, const std::string& path) {
        const json* v = member(j, key, path);
        if (!v)
            return 0;
        if (!v->is_number_integer()) {
            error = name + ": " + path + "/" + key + " must be an integer";
            return 0;
        }
        return v->get<std::int64_t>();
    }
    std::int32_t int32(const json& j, const char* key, const std::string& path) {
        const std::int64_t v = integer(j, key, path);
        if (v < INT32_MIN || v > INT32_MAX) {
            error = name + ": " + path + "/" + key + " is out of range";
            return 0;
        }
        return static_cast<std::int32_t>(v);
    }
    std::string text(const json& j, const char* key, const std::string& path) {
        const json* v = member(j, key, path);
        if (!v)
            return {};
        if (!v->is_string()) {
            error = name + ": " + path + "/" + key + " must be a string";
            return {};
        }
        return v->get<std::string>();
    }
    bool boolean(const json& j, const char* key, const std::string& path) {
        const json* v = member(j, key, path);
        if (!v)
            return false;
        if (!v->is_boolean()) {
            error = name + ": " + path + "/" + key + " must be true or false";
            return false;
        }
        return v->get<bool>();
    }
    const json* array(const json& j, const char* key, const std::string& path) {
        const json* v = member(j, key, path);
        if (v && !v->is_array()) {
            error = name + ": " + path + "/" + key + " must be an array";
            return nullptr;
        }
        return v;
    }
    template <class E>
    E choice(const json& j, const char* key, const std::string& path) {
        E out{};
        const std::string key_ = text(j, key, path);
        if (error.empty() && !fromString(key_, out))
            error = name + ": " + path + "/" + key + " has the unknown value \"" + key_.substr(0, 40) + "\"";
        return out;
    }
};

Result<json> parseDocument(std::string_view text, const std::string& name, std::string_view format) {
    if (const int depth = jsonNestingDepth(text); depth > kMaxCaseNestingDepth)
        return fail(ErrorCode::InvalidInput, name + ": arrays and objects nested " + std::to_string(depth) +
                                                 " deep (at most " + std::to_string(kMaxCaseNestingDepth) + ")");
    json j = json::parse(text.begin(), text.end(), nullptr, false);
    if (j.is_discarded())
        return fail(ErrorCode::InvalidInput, name + ": not valid JSON");
    if (!j.is_object() || !j.contains("format") || j["format"] != std::string(format))
        return fail(ErrorCode::InvalidInput, name + ": \"format\" must be \"" + std::string(format) + "\"");
    return j;
}

void readMaterials(Reader& r, const json& j, Scene& scene) {
    const json* materials = r.array(j, "materials", "");
    if (!materials)
        return;
    for (std::size_t i = 0; i < materials->size() && r.error.empty(); ++i) {
        const json& m = (*materials)[i];
        const std::string path = "/materials/" + std::to_string(i);
        SceneMaterial out;
        out.id = r.int32(m, "id", path);
        out.regionId = r.int32(m, "regionId", path);
        out.name = r.text(m, "name", path);
        out.tissue = r.choice<clinical::Tissue>(m, "tissue", path);
        out.material.youngsModulusKpa = r.number(m, "youngsModulusKpa", path);
        out.material.poissonRatio = r.number(m, "poissonRatio", path);
        out.material.densityKgPerM3 = r.number(m, "densityKgPerM3", path);
        const json* range = r.member(m, "youngsModulusRangeKpa", path);
        if (range) {
            out.youngsModulusRangeKpa.min = r.number(*range, "min", path + "/youngsModulusRangeKpa");
            out.youngsModulusRangeKpa.max = r.number(*range, "max", path + "/youngsModulusRangeKpa");
        }
        out.heterogeneity = r.number(m, "heterogeneity", path);
        scene.materials.push_back(std::move(out));
    }
}

void readRegions(Reader& r, const json& j, Scene& scene) {
    const json* regions = r.array(j, "regions", "");
    if (!regions)
        return;
    for (std::size_t i = 0; i < regions->size() && r.error.empty(); ++i) {
        const json& g = (*regions)[i];
        const std::string path = "/regions/" + std::to_string(i);
        SceneRegion out;
        out.id = r.int32(g, "id", path);
        out.name = r.text(g, "name", path);
        out.tissue = r.choice<clinical::Tissue>(g, "tissue", path);
        out.pathologyId = r.text(g, "pathologyId", path);
        scene.regions.push_back(std::move(out));
    }
}

void readClinical(Reader& r, const json& j, Scene& scene) {
    const json* clinical = r.member(j, "clinical", "");
    if (!clinical)
        return;
    const json* organ = r.member(*clinical, "organ", "/clinical");
    if (organ) {
        auto& o = scene.clinical.organ;
        const std::string path = "/clinical/organ";
        o.lengthMm = r.number(*organ, "lengthMm", path);
        o.widthMm = r.number(*organ, "widthMm", path);
        o.apMm = r.number(*organ, "apMm", path);
        o.cavityLengthMm = r.number(*organ, "cavityLengthMm", path);
        o.cavityWidthMm = r.number(*organ, "cavityWidthMm", path);
        o.uterineVolumeMl = r.number(*organ, "uterineVolumeMl", path);
    }
    const json* list = r.array(*clinical, "pathologies", "/clinical");
    for (std::size_t i = 0; list && i < list->size() && r.error.empty(); ++i) {
        const json& p = (*list)[i];
        const std::string path = "/clinical/pathologies/" + std::to_string(i);
        PathologyDescriptor out;
        out.id = r.text(p, "id", path);
        out.kind = r.choice<clinical::PathologyKind>(p, "kind", path);
        out.regionId = r.int32(p, "regionId", path);
        out.sizeMm = r.number(p, "sizeMm", path);
        out.volumeMl = r.number(p, "volumeMl", path);
        const json* figo = r.member(p, "figo", path);
        if (figo && !figo->is_null()) {
            out.figo = figo->is_string() ? clinical::FigoType::parse(figo->get<std::string>()) : std::nullopt;
            if (!out.figo || !out.figo->isValid())
                r.error = r.name + ": " + path + "/figo is not a FIGO type";
        }
        const json* lasmar = r.member(p, "lasmar", path);
        if (lasmar && !lasmar->is_null()) {
            clinical::LasmarScore s;
            s.size = r.int32(*lasmar, "size", path + "/lasmar");
            s.topography = r.int32(*lasmar, "topography", path + "/lasmar");
            s.extension = r.int32(*lasmar, "extension", path + "/lasmar");
            s.penetration = r.int32(*lasmar, "penetration", path + "/lasmar");
            s.wall = r.int32(*lasmar, "wall", path + "/lasmar");
            out.lasmar = s;
        }
        out.location = r.text(p, "location", path);
        if (p.is_object() && p.contains("tissueContactFraction")) {
            const double f = r.number(p, "tissueContactFraction", path);
            if (!(f >= 0.0 && f <= 1.0) && r.error.empty())
                r.error = r.name + ": " + path + "/tissueContactFraction must be in 0..1";
            out.tissueContactFraction = f;
        }
        scene.clinical.pathologies.push_back(std::move(out));
    }
}

} // namespace

std::string sceneJson(const Scene& scene) {
    ordered j;
    j["format"] = std::string(kSceneDoc);
    j["units"] = ordered{
        {"length", "mm"}, {"youngsModulus", "kPa"}, {"density", "kg/m^3"}, {"volume", "mL"}, {"pressure", "kPa"}};
    ordered regions = ordered::array();
    for (const auto& r : scene.regions)
        regions.push_back(ordered{{"id", r.id},
                                  {"name", r.name},
                                  {"tissue", std::string(toString(r.tissue))},
                                  {"pathologyId", r.pathologyId}});
    j["regions"] = regions;
    ordered materials = ordered::array();
    for (const auto& m : scene.materials)
        materials.push_back(materialJson(m));
    j["materials"] = materials;
    j["hydrometra"] = ordered{{"pressureKpa", scene.hydrometra.pressureKpa},
                              {"uterineVolumeMl", scene.hydrometra.uterineVolumeMl},
                              {"cavityVolumeMl", scene.hydrometra.cavityVolumeMl},
                              {"extrapolated", scene.hydrometra.extrapolated},
                              {"source", "Bajka et al., Surg Endosc 2009: y = 0.00037 x^2 + 0.036 x at 20 kPa, "
                                         "linear in pressure below"}};
    if (!scene.hydrometra.modelCurve.empty()) {
        ordered curve = ordered::array();
        for (const auto& p : scene.hydrometra.modelCurve)
            curve.push_back(ordered{{"pressureKpa", p.pressureKpa}, {"cavityOpeningMl", p.cavityOpeningMl}});
        j["hydrometra"]["modelCurve"] = curve;
        j["hydrometra"]["modelSource"] = "static solve of the scene's tissue model (corotational FEM on the simulation "
                                         "mesh), the cavity's opening over rest";
    }
    const auto& o = scene.clinical.organ;
    ordered pathologies = ordered::array();
    for (const auto& p : scene.clinical.pathologies)
        pathologies.push_back(pathologyJson(p));
    j["clinical"] = ordered{{"organ", ordered{{"lengthMm", o.lengthMm},
                                              {"widthMm", o.widthMm},
                                              {"apMm", o.apMm},
                                              {"cavityLengthMm", o.cavityLengthMm},
                                              {"cavityWidthMm", o.cavityWidthMm},
                                              {"uterineVolumeMl", o.uterineVolumeMl}}},
                            {"pathologies", pathologies}};
    ordered tools = ordered::object();
    for (const auto& [tool, version] : scene.toolVersions)
        tools[tool] = version;
    j["toolVersions"] = tools;
    return dump(j);
}

std::string labelsJson(const Scene& scene) {
    ordered j;
    j["format"] = std::string(kLabelsDoc);
    ordered labels = ordered::array();
    for (const auto& l : scene.labels)
        labels.push_back(ordered{{"name", l.name},
                                 {"kind", std::string(toString(l.kind))},
                                 {"element", std::string(toString(l.element))},
                                 {"pathologyId", l.pathologyId},
                                 {"count", l.indices.size()},
                                 {"indices", l.indices}});
    j["labels"] = labels;
    return dump(j);
}

std::string reportJson(const Scene& scene) {
    const auto& q = scene.quality;
    ordered j;
    j["format"] = std::string(kReportDoc);
    j["counts"] = ordered{{"points", scene.tets.vertexCount()},
                          {"tets", scene.tets.tetCount()},
                          {"surfacePoints", scene.surface.mesh.vertexCount()},
                          {"surfaceTriangles", scene.surface.mesh.faceCount()},
                          {"regions", scene.regions.size()},
                          {"labels", scene.labels.size()}};
    j["quality"] = ordered{{"vertexCount", q.vertexCount},
                           {"tetCount", q.tetCount},
                           {"meanRadiusRatio", q.meanRadiusRatio},
                           {"minRadiusRatio", q.minRadiusRatio},
                           {"minDihedralDeg", q.minDihedralDeg},
                           {"maxDihedralDeg", q.maxDihedralDeg},
                           {"meanEdgeRatio", q.meanEdgeRatio},
                           {"maxEdgeRatio", q.maxEdgeRatio},
                           {"radiusRatioHistogram", q.radiusRatioHistogram},
                           {"minDihedralHistogram", q.minDihedralHistogram},
                           {"sliverCount", q.sliverCount},
                           {"invertedCount", q.invertedCount},
                           {"degenerateCount", q.degenerateCount},
                           {"hasReference", q.hasReference},
                           {"hausdorffDistanceMm", q.hausdorffDistanceMm},
                           {"hausdorffRelative", q.hausdorffRelative},
                           {"volumeError", q.volumeError}};
    if (q.boundaryNonManifoldEdges)
        j["quality"]["boundaryNonManifoldEdges"] = *q.boundaryNonManifoldEdges;
    if (q.boundaryNonManifoldVertices)
        j["quality"]["boundaryNonManifoldVertices"] = *q.boundaryNonManifoldVertices;
    j["quality"]["bars"] = ordered::array();
    for (const auto& b : meshBars(q))
        j["quality"]["bars"].push_back(
            ordered{{"name", b.name}, {"value", b.value}, {"bar", b.limit}, {"atLeast", b.atLeast}, {"met", b.met}});
    j["warnings"] = scene.warnings;
    return dump(j);
}

Status parseSceneJson(std::string_view text, const std::string& name, Scene& scene) {
    auto doc = parseDocument(text, name, kSceneDoc);
    if (!doc)
        return doc.failure();
    const json& j = *doc;
    Reader r{name, {}};
    readRegions(r, j, scene);
    readMaterials(r, j, scene);
    if (const json* h = r.member(j, "hydrometra", "")) {
        scene.hydrometra.pressureKpa = r.number(*h, "pressureKpa", "/hydrometra");
        scene.hydrometra.uterineVolumeMl = r.number(*h, "uterineVolumeMl", "/hydrometra");
        scene.hydrometra.cavityVolumeMl = r.number(*h, "cavityVolumeMl", "/hydrometra");
        scene.hydrometra.extrapolated = r.boolean(*h, "extrapolated", "/hydrometra");
        if (h->is_object() && h->contains("modelCurve"))
            if (const json* curve = r.array(*h, "modelCurve", "/hydrometra")) {
                double last = -1.0;
                for (std::size_t i = 0; i < curve->size() && r.error.empty(); ++i) {
                    const std::string path = "/hydrometra/modelCurve/" + std::to_string(i);
                    HydrometraPoint p;
                    p.pressureKpa = r.number((*curve)[i], "pressureKpa", path);
                    p.cavityOpeningMl = r.number((*curve)[i], "cavityOpeningMl", path);
                    if (r.error.empty() &&
                        (!std::isfinite(p.pressureKpa) || p.pressureKpa <= last || p.pressureKpa > 40.0 ||
                         !std::isfinite(p.cavityOpeningMl) || std::abs(p.cavityOpeningMl) > 1000.0))
                        r.error = name + ": " + path +
                                  " must have pressureKpa ascending in 0-40 and cavityOpeningMl in -1000..1000";
                    last = p.pressureKpa;
                    scene.hydrometra.modelCurve.push_back(p);
                }
            }
    }
    readClinical(r, j, scene);
    if (const json* tools = r.member(j, "toolVersions", "")) {
        if (!tools->is_object())
            r.error = name + ": /toolVersions must be an object";
        for (auto it = tools->begin(); r.error.empty() && it != tools->end(); ++it) {
            if (!it.value().is_string())
                r.error = name + ": /toolVersions/" + it.key() + " must be a string";
            else
                scene.toolVersions[it.key()] = it.value().get<std::string>();
        }
    }
    if (!r.error.empty())
        return fail(ErrorCode::InvalidInput, r.error);
    return {};
}

Status parseLabelsJson(std::string_view text, const std::string& name, Scene& scene) {
    auto doc = parseDocument(text, name, kLabelsDoc);
    if (!doc)
        return doc.failure();
    Reader r{name, {}};
    const json* labels = r.array(*doc, "labels", "");
    for (std::size_t i = 0; labels && i < labels->size() && r.error.empty(); ++i) {
        const json& l = (*labels)[i];
        const std::string path = "/labels/" + std::to_string(i);
        SceneLabel out;
        out.name = r.text(l, "name", path);
        out.kind = r.choice<LabelKind>(l, "kind", path);
        out.element = r.choice<LabelElement>(l, "element", path);
        out.pathologyId = r.text(l, "pathologyId", path);
        const json* indices = r.array(l, "indices", path);
        for (std::size_t k = 0; indices && k < indices->size() && r.error.empty(); ++k) {
            const json& v = (*indices)[k];
            if (!v.is_number_integer() || v.get<std::int64_t>() < 0 || v.get<std::int64_t>() > INT32_MAX)
                r.error = name + ": " + path + "/indices/" + std::to_string(k) + " must be a non-negative integer";
            else
                out.indices.push_back(static_cast<std::int32_t>(v.get<std::int64_t>()));
        }
        scene.labels.push_back(std::move(out));
    }
    if (!r.error.empty())
        return fail(ErrorCode::InvalidInput, r.error);
    return {};
}

Status parseReportJson(std::string_view text, const std::string& name, Scene& scene) {
    auto doc = parseDocument(text, name, kReportDoc);
    if (!doc)
        return doc.failure();
    Reader r{name, {}};
    auto& q = scene.quality;
    if (const json* j = r.member(*doc, "quality", "")) {
        const std::string path = "/quality";
        const auto count = [&](const char* key) {
            const std::int64_t v = r.integer(*j, key, path);
            return static_cast<std::size_t>(v < 0 ? 0 : v);
        };
        q.vertexCount = count("vertexCount");
        q.tetCount = count("tetCount");
        q.meanRadiusRatio = r.number(*j, "meanRadiusRatio", path);
        q.minRadiusRatio = r.number(*j, "minRadiusRatio", path);
        q.minDihedralDeg = r.number(*j, "minDihedralDeg", path);
        q.maxDihedralDeg = r.number(*j, "maxDihedralDeg", path);
        q.meanEdgeRatio = r.number(*j, "meanEdgeRatio", path);
        q.maxEdgeRatio = r.number(*j, "maxEdgeRatio", path);
        for (const char* key : {"radiusRatioHistogram", "minDihedralHistogram"}) {
            const json* h = r.array(*j, key, path);
            auto& out = std::string(key) == "radiusRatioHistogram" ? q.radiusRatioHistogram : q.minDihedralHistogram;
            for (std::size_t k = 0; h && k < h->size() && r.error.empty(); ++k) {
                if (!(*h)[k].is_number_unsigned())
                    r.error = name + ": " + path + "/" + key + " must hold counts";
                else
                    out.push_back((*h)[k].get<std::size_t>());
            }
        }
        q.sliverCount = count("sliverCount");
        q.invertedCount = count("invertedCount");
        q.degenerateCount = count("degenerateCount");
        q.hasReference = r.boolean(*j, "hasReference", path);
        q.hausdorffDistanceMm = r.number(*j, "hausdorffDistanceMm", path);
        q.hausdorffRelative = r.number(*j, "hausdorffRelative", path);
        q.volumeError = r.number(*j, "volumeError", path);
        // Measured since the mesh bars were recorded; older reports lack them.
        if (j->contains("boundaryNonManifoldEdges"))
            q.boundaryNonManifoldEdges = count("boundaryNonManifoldEdges");
        if (j->contains("boundaryNonManifoldVertices"))
            q.boundaryNonManifoldVertices = count("boundaryNonManifoldVertices");
    }
    if (const json* w = r.array(*doc, "warnings", "")) {
        for (const auto& item : *w)
            if (item.is_string())
                scene.warnings.push_back(item.get<std::string>());
    }
    if (!r.error.empty())
        return fail(ErrorCode::InvalidInput, r.error);
    return {};
}

} // namespace hs::scene::detail
