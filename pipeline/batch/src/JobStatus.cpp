// Status records: JSON writing and strict reading, file names, time stamps.
#include "hs/batch/JobStatus.h"

#include "hs/batch/Manifest.h"
#include "hs/io/AtomicFile.h"
#include "hs/scene/JsonText.h"

#include <nlohmann/json.hpp>

#include <array>
#include <ctime>
#include <filesystem>
#include <unistd.h>

namespace hs::batch {

namespace {

using nlohmann::json;
using nlohmann::ordered_json;
using scene::JsonIssues;
using scene::ObjectReader;

constexpr std::array<ErrorCode, 8> kErrorCodes{
    ErrorCode::InvalidInput,  ErrorCode::NotFound,  ErrorCode::IoError,        ErrorCode::Unsupported,
    ErrorCode::LimitExceeded, ErrorCode::Cancelled, ErrorCode::BackendFailure, ErrorCode::Internal};

ordered_json sceneJson(const SceneSummary& s) {
    ordered_json j;
    j["organ"] = {{"lengthMm", s.organLengthMm},
                  {"widthMm", s.organWidthMm},
                  {"apMm", s.organApMm},
                  {"uterineVolumeMl", s.uterineVolumeMl}};
    j["mesh"] = {{"vertices", s.vertices},
                 {"tetrahedra", s.tetrahedra},
                 {"meanRadiusRatio", s.meanRadiusRatio},
                 {"minDihedralDeg", s.minDihedralDeg},
                 {"slivers", s.slivers}};
    auto pathologies = ordered_json::array();
    for (const PathologySummary& p : s.pathologies)
        pathologies.push_back(
            {{"id", p.id}, {"kind", p.kind}, {"sizeMm", p.sizeMm}, {"figo", p.figo}, {"lasmar", p.lasmar}});
    j["pathologies"] = pathologies;
    auto stages = ordered_json::array();
    for (const auto& [name, seconds] : s.stageSeconds)
        stages.push_back({{"stage", name}, {"seconds", seconds}});
    j["stages"] = stages;
    j["warnings"] = s.warnings;
    if (s.scopePasses)
        j["scope"] = {{"passes", *s.scopePasses}, {"narrowestMm", s.scopeNarrowestMm}};
    return j;
}

void readScene(const json& v, const std::string& path, SceneSummary& s, JsonIssues& issues) {
    ObjectReader o(v, path, issues);
    if (const json* organ = o.member("organ", true)) {
        ObjectReader r(*organ, o.pathOf("organ"), issues);
        r.read("lengthMm", s.organLengthMm, true);
        r.read("widthMm", s.organWidthMm, true);
        r.read("apMm", s.organApMm, true);
        r.read("uterineVolumeMl", s.uterineVolumeMl, true);
        r.finish();
    }
    if (const json* mesh = o.member("mesh", true)) {
        ObjectReader r(*mesh, o.pathOf("mesh"), issues);
        std::uint64_t vertices = 0, tets = 0, slivers = 0;
        r.read("vertices", vertices, true);
        r.read("tetrahedra", tets, true);
        r.read("meanRadiusRatio", s.meanRadiusRatio, true);
        r.read("minDihedralDeg", s.minDihedralDeg, true);
        r.read("slivers", slivers, true);
        r.finish();
        s.vertices = static_cast<std::size_t>(vertices);
        s.tetrahedra = static_cast<std::size_t>(tets);
        s.slivers = static_cast<std::size_t>(slivers);
    }
    if (const json* list = o.member("pathologies", true); list && list->is_array()) {
        for (std::size_t i = 0; i < list->size(); ++i) {
            ObjectReader r((*list)[i], o.pathOf("pathologies") + "/" + std::to_string(i), issues);
            PathologySummary p;
            r.read("id", p.id, true);
            r.read("kind", p.kind, true);
            r.read("sizeMm", p.sizeMm, true);
            r.read("figo", p.figo, true);
            r.read("lasmar", p.lasmar, true);
            r.finish();
            s.pathologies.push_back(std::move(p));
        }
    }
    if (const json* list = o.member("stages", true); list && list->is_array()) {
        for (std::size_t i = 0; i < list->size(); ++i) {
            ObjectReader r((*list)[i], o.pathOf("stages") + "/" + std::to_string(i), issues);
            std::pair<std::string, double> stage;
            r.read("stage", stage.first, true);
            r.read("seconds", stage.second, true);
            r.finish();
            s.stageSeconds.push_back(std::move(stage));
        }
    }
    if (const json* list = o.member("warnings", false); list && list->is_array()) {
        for (std::size_t i = 0; i < list->size(); ++i) {
            if (!(*list)[i].is_string()) {
                issues.push_back({o.pathOf("warnings") + "/" + std::to_string(i), "expected a string"});
                continue;
            }
            s.warnings.push_back((*list)[i].get<std::string>());
        }
    } else if (list) {
        issues.push_back({o.pathOf("warnings"), "expected an array of strings"});
    }
    if (const json* scope = o.member("scope", false)) {
        ObjectReader r(*scope, o.pathOf("scope"), issues);
        bool passes = false;
        r.read("passes", passes, true);
        r.read("narrowestMm", s.scopeNarrowestMm, true);
        r.finish();
        s.scopePasses = passes;
    }
    o.finish();
}

void readError(const json& v, const std::string& path, Error& error, JsonIssues& issues) {
    ObjectReader o(v, path, issues);
    std::string code;
    o.read("code", code, true);
    o.read("detail", error.detail, true);
    o.finish();
    bool known = false;
    for (ErrorCode c : kErrorCodes) {
        if (errorCodeKey(c) == code) {
            error.code = c;
            known = true;
        }
    }
    if (!known && o.ok())
        issues.push_back({path + "/code", scene::quoteText(code) + " is not an error code"});
}

void readRecord(const json& root, StatusRecord& r, JsonIssues& issues) {
    ObjectReader o(root, "", issues);
    std::string format;
    int version = 0;
    o.read("format", format, true);
    o.read("schemaVersion", version, true);
    if (format != kStatusFormat || version < 1 || version > kStatusSchemaVersion)
        issues.push_back({"/format", "not a status record of this build (expected \"" + std::string(kStatusFormat) +
                                         "\", schema version 1 to " + std::to_string(kStatusSchemaVersion) + ")"});
    o.read("job", r.job, true);
    std::uint64_t index = 0;
    o.read("index", index, true);
    r.index = static_cast<std::size_t>(index);
    o.read("seed", r.seed, true);
    o.read("output", r.output, true);
    std::string state;
    o.read("state", state, true);
    if (state == toString(JobState::Ok))
        r.state = JobState::Ok;
    else if (state == toString(JobState::Failed))
        r.state = JobState::Failed;
    else
        issues.push_back({"/state", scene::quoteText(state) + " is not one of \"ok\", \"failed\""});
    if (const json* error = o.member("error", true); error && !error->is_null()) {
        r.error.emplace();
        readError(*error, "/error", *r.error, issues);
    }
    o.read("seconds", r.seconds, true);
    o.read("peakMemoryMb", r.peakMemoryMb, true);
    o.read("host", r.host, true);
    o.read("finishedUtc", r.finishedUtc, true);
    o.read("reused", r.reused, true);
    o.read("packageManifestSha256", r.packageManifestSha256, true);
    o.read("caseSha256", r.caseSha256, version >= 2);
    o.read("tools", r.tools, version >= 2);
    if (const json* s = o.member("scene", true); s && !s->is_null()) {
        r.scene.emplace();
        readScene(*s, "/scene", *r.scene, issues);
    }
    o.finish();
}

} // namespace

std::string_view toString(JobState state) {
    return state == JobState::Ok ? "ok" : "failed";
}

std::string toJson(const StatusRecord& r) {
    ordered_json j;
    j["format"] = std::string(kStatusFormat);
    j["schemaVersion"] = kStatusSchemaVersion;
    j["job"] = r.job;
    j["index"] = r.index;
    j["seed"] = r.seed;
    j["output"] = r.output;
    j["state"] = std::string(toString(r.state));
    j["error"] = r.error ? ordered_json{{"code", std::string(errorCodeKey(r.error->code))}, {"detail", r.error->detail}}
                         : ordered_json(nullptr);
    j["seconds"] = r.seconds;
    j["peakMemoryMb"] = r.peakMemoryMb;
    j["host"] = r.host;
    j["finishedUtc"] = r.finishedUtc;
    j["reused"] = r.reused;
    j["packageManifestSha256"] = r.packageManifestSha256;
    j["caseSha256"] = r.caseSha256;
    j["tools"] = r.tools;
    j["scene"] = r.scene ? sceneJson(*r.scene) : ordered_json(nullptr);
    return j.dump(4, ' ', false, ordered_json::error_handler_t::replace) + "\n";
}

Result<StatusRecord> parseStatus(std::string_view text, const std::string& sourceName) {
    scene::JsonDocumentLimits limits;
    limits.maxBytes = kMaxStatusFileBytes;
    limits.kind = "status record";
    return scene::parseJsonDocument<StatusRecord>(text, sourceName, limits, readRecord);
}

std::string statusPath(const std::string& batchFolder, const std::string& job) {
    return batchPath(batchFolder, std::string(kStatusFolder) + "/" + job + ".json");
}

Status writeStatus(const std::string& batchFolder, const StatusRecord& record) {
    return io::writeFileAtomically(statusPath(batchFolder, record.job), toJson(record));
}

Result<std::optional<StatusRecord>> readStatus(const std::string& batchFolder, const std::string& job) {
    const std::string path = statusPath(batchFolder, job);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return std::optional<StatusRecord>();
    auto text = io::readFile(path, kMaxStatusFileBytes);
    if (!text)
        return text.failure();
    auto record = parseStatus(*text, path);
    if (!record)
        return record.failure();
    return std::optional<StatusRecord>(std::move(*record));
}

std::string hostName() {
    char name[256] = {};
    if (gethostname(name, sizeof name - 1) != 0)
        return {};
    return name;
}

} // namespace hs::batch
