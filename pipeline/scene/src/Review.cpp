// Review files: a clinician's ratings beside a scene package.
#include "hs/scene/Review.h"

#include "hs/io/AtomicFile.h"
#include "hs/scene/JsonText.h"
#include "hs/scene/Scene.h"
#include "hs/scene/Sha256.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <map>

namespace hs::scene {

namespace {

using nlohmann::json;
using nlohmann::ordered_json;

constexpr std::size_t kMaxReviewerLength = 200;
constexpr int kMaxReviewNesting = 8;
const char* const kAppearances[] = {"endometrium", "myoma", "polyp"};

Error invalid(const std::string& source, const std::string& path, const std::string& what) {
    return Error{ErrorCode::InvalidInput, source + ": " + path + ": " + what};
}

ordered_json ratingJson(const Rating& r) {
    ordered_json j;
    j["score"] = r.score ? ordered_json(*r.score) : ordered_json(nullptr);
    j["comment"] = r.comment;
    return j;
}

/// Reads {"score": 1..5 | null, "comment": "..."} at `path`.
Result<Rating> readRating(const json& j, const std::string& source, const std::string& path) {
    if (!j.is_object())
        return invalid(source, path, "must be an object with score and comment");
    Rating r;
    const auto score = j.find("score");
    if (score == j.end())
        return invalid(source, path + "/score", "is missing (1-5, or null when not rated)");
    if (!score->is_null()) {
        if (!score->is_number_integer() || score->get<long long>() < 1 || score->get<long long>() > 5)
            return invalid(source, path + "/score", score->dump() + " is not an integer in 1-5 (or null)");
        r.score = score->get<int>();
    }
    const auto comment = j.find("comment");
    if (comment != j.end()) {
        if (!comment->is_string())
            return invalid(source, path + "/comment", "must be a string");
        r.comment = comment->get<std::string>();
        if (r.comment.size() > kMaxReviewCommentLength)
            return invalid(source, path + "/comment",
                           "is " + std::to_string(r.comment.size()) + " bytes long (at most " +
                               std::to_string(kMaxReviewCommentLength) + ")");
    }
    return r;
}

Status check(const Review& review, const std::string& source) {
    if (review.packageSha256.size() != 64 ||
        !std::all_of(review.packageSha256.begin(), review.packageSha256.end(),
                     [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); }))
        return invalid(source, "/packageSha256", "must be 64 lower-case hex digits (the manifest's SHA-256)");
    if (review.reviewer.size() > kMaxReviewerLength)
        return invalid(source, "/reviewer", "is longer than " + std::to_string(kMaxReviewerLength) + " bytes");
    if (review.pathologies.size() > kMaxReviewItems || review.textures.size() > kMaxReviewItems)
        return invalid(source, "/pathologies", "more than " + std::to_string(kMaxReviewItems) + " items");
    const auto checkRating = [&](const Rating& r, const std::string& path) -> Status {
        if (r.score && (*r.score < 1 || *r.score > 5))
            return invalid(source, path + "/score", std::to_string(*r.score) + " is outside 1-5");
        if (r.comment.size() > kMaxReviewCommentLength)
            return invalid(source, path + "/comment", "is longer than " + std::to_string(kMaxReviewCommentLength));
        return {};
    };
    for (std::size_t i = 0; i < review.pathologies.size(); ++i)
        HS_TRY(checkRating(review.pathologies[i].rating, "/pathologies/" + std::to_string(i)));
    for (std::size_t i = 0; i < review.textures.size(); ++i)
        HS_TRY(checkRating(review.textures[i].rating, "/textures/" + std::to_string(i)));
    return {};
}

Result<Review> parseChecked(std::string_view text, const std::string& source) {
    // The case files' strict reader: size and nesting checked before parsing, repeated keys refused.
    JsonDocumentLimits limits;
    limits.maxBytes = kMaxReviewFileBytes;
    limits.maxDepth = kMaxReviewNesting;
    limits.kind = "review file";
    std::vector<CaseIssue> issues;
    auto parsed = parseJsonObject(text, source, limits, issues);
    if (!parsed)
        return parsed.failure();
    if (!issues.empty())
        return failWithIssues(source, issues);
    const json& j = *parsed;
    if (j.value("format", std::string()) != kReviewFormat)
        return invalid(source, "/format", "must be \"" + std::string(kReviewFormat) + "\"");
    if (!j.contains("schemaVersion") || !j["schemaVersion"].is_number_integer())
        return invalid(source, "/schemaVersion", "is missing (an integer)");
    if (j["schemaVersion"].get<long long>() != kReviewSchemaVersion)
        return Error{ErrorCode::Unsupported, source + ": /schemaVersion: " + j["schemaVersion"].dump() +
                                                 " is not the version this build reads (" +
                                                 std::to_string(kReviewSchemaVersion) + ")"};
    Review review;
    if (!j.contains("packageSha256") || !j["packageSha256"].is_string())
        return invalid(source, "/packageSha256", "is missing (the manifest's SHA-256)");
    review.packageSha256 = j["packageSha256"].get<std::string>();
    if (j.contains("reviewer")) {
        if (!j["reviewer"].is_string())
            return invalid(source, "/reviewer", "must be a string");
        review.reviewer = j["reviewer"].get<std::string>();
    }
    const auto readList = [&](const char* key) -> Result<const json*> {
        if (!j.contains(key) || !j[key].is_array())
            return invalid(source, std::string("/") + key, "is missing (an array)");
        if (j[key].size() > kMaxReviewItems)
            return invalid(source, std::string("/") + key,
                           "has " + std::to_string(j[key].size()) + " items (at most " +
                               std::to_string(kMaxReviewItems) + ")");
        return &j[key];
    };
    auto pathologies = readList("pathologies");
    if (!pathologies)
        return pathologies.failure();
    for (std::size_t i = 0; i < (*pathologies)->size(); ++i) {
        const json& item = (**pathologies)[i];
        const std::string path = "/pathologies/" + std::to_string(i);
        if (!item.is_object() || !item.contains("id") || !item["id"].is_string())
            return invalid(source, path + "/id", "is missing (the case's pathology id)");
        PathologyRating p;
        p.id = item["id"].get<std::string>();
        if (p.id.size() > kMaxPathologyIdLength)
            return invalid(source, path + "/id", "is longer than " + std::to_string(kMaxPathologyIdLength));
        if (!item.contains("kind") || !item["kind"].is_string() ||
            !clinical::fromString(item["kind"].get<std::string>(), p.kind))
            return invalid(source, path + "/kind", "must be \"myoma\" or \"polyp\"");
        if (!item.contains("growthModel") || !item["growthModel"].is_string() ||
            !clinical::fromString(item["growthModel"].get<std::string>(), p.growthModel))
            return invalid(source, path + "/growthModel", "must be \"ca\", \"skeleton\" or \"particles\"");
        auto rating = readRating(item.value("rating", json()), source, path + "/rating");
        if (!rating)
            return rating.failure();
        p.rating = std::move(rating).value();
        review.pathologies.push_back(std::move(p));
    }
    auto textures = readList("textures");
    if (!textures)
        return textures.failure();
    for (std::size_t i = 0; i < (*textures)->size(); ++i) {
        const json& item = (**textures)[i];
        const std::string path = "/textures/" + std::to_string(i);
        TextureRating t;
        if (!item.is_object() || !item.contains("appearance") || !item["appearance"].is_string() ||
            std::none_of(std::begin(kAppearances), std::end(kAppearances),
                         [&](const char* a) { return item["appearance"].get<std::string>() == a; }))
            return invalid(source, path + "/appearance", "must be \"endometrium\", \"myoma\" or \"polyp\"");
        t.appearance = item["appearance"].get<std::string>();
        auto rating = readRating(item.value("rating", json()), source, path + "/rating");
        if (!rating)
            return rating.failure();
        t.rating = std::move(rating).value();
        review.textures.push_back(std::move(t));
    }
    HS_TRY(check(review, source));
    return review;
}

} // namespace

Review emptyReview(const Scene& scene, const std::string& packageSha256) {
    Review review;
    review.packageSha256 = packageSha256;
    bool myoma = false, polyp = false;
    for (const PathologySpec& p : scene.caseSpec.pathologies) {
        review.pathologies.push_back({p.id, p.kind, p.growthModel, {}});
        myoma = myoma || p.kind == clinical::PathologyKind::Myoma;
        polyp = polyp || p.kind == clinical::PathologyKind::Polyp;
    }
    review.textures.push_back({"endometrium", {}});
    if (myoma)
        review.textures.push_back({"myoma", {}});
    if (polyp)
        review.textures.push_back({"polyp", {}});
    return review;
}

Result<std::string> packageIdentity(const std::string& packageFolder) {
    auto digest = sha256File((std::filesystem::path(packageFolder) / "manifest.json").string(), 1 << 20);
    if (!digest)
        return digest.failure();
    return digest->sha256;
}

std::string reviewPathFor(const std::string& packageFolder) {
    std::string folder = packageFolder;
    while (folder.size() > 1 && (folder.back() == '/' || folder.back() == '\\'))
        folder.pop_back();
    return folder + ".review.json";
}

std::string toJson(const Review& review) {
    ordered_json j;
    j["format"] = kReviewFormat;
    j["schemaVersion"] = kReviewSchemaVersion;
    j["packageSha256"] = review.packageSha256;
    j["reviewer"] = review.reviewer;
    j["pathologies"] = ordered_json::array();
    for (const PathologyRating& p : review.pathologies)
        j["pathologies"].push_back({{"id", p.id},
                                    {"kind", std::string(clinical::toString(p.kind))},
                                    {"growthModel", std::string(clinical::toString(p.growthModel))},
                                    {"rating", ratingJson(p.rating)}});
    j["textures"] = ordered_json::array();
    for (const TextureRating& t : review.textures)
        j["textures"].push_back({{"appearance", t.appearance}, {"rating", ratingJson(t.rating)}});
    return j.dump(4) + "\n";
}

Result<Review> parseReview(std::string_view jsonText, const std::string& sourceName) {
    try {
        return parseChecked(jsonText, sourceName);
    } catch (const nlohmann::json::exception& e) { // a reader bug must not throw across the boundary
        return fail(ErrorCode::Internal, sourceName + ": unexpected JSON error: " + std::string(e.what()));
    }
}

Result<Review> loadReview(const std::string& path) {
    auto text = io::readFile(path, kMaxReviewFileBytes);
    if (!text)
        return text.failure();
    return parseReview(*text, path);
}

Status saveReview(const Review& review, const std::string& path) {
    HS_TRY(check(review, path));
    return io::writeFileAtomically(path, toJson(review));
}

std::vector<RatingSummary> summarize(const std::vector<Review>& reviews) {
    std::map<std::string, std::vector<int>> groups; // ordered: kinds and models, then textures
    std::vector<std::string> order;
    const auto add = [&](const std::string& group, const Rating& r) {
        if (!r.score)
            return;
        if (groups.find(group) == groups.end())
            order.push_back(group);
        groups[group].push_back(*r.score);
    };
    for (const Review& review : reviews)
        for (const PathologyRating& p : review.pathologies)
            add(std::string(clinical::toString(p.kind)) + " / " + std::string(clinical::toString(p.growthModel)),
                p.rating);
    for (const Review& review : reviews)
        for (const TextureRating& t : review.textures)
            add("texture / " + t.appearance, t.rating);
    std::sort(order.begin(), order.end(), [](const std::string& a, const std::string& b) {
        const bool ta = a.rfind("texture", 0) == 0, tb = b.rfind("texture", 0) == 0;
        return ta != tb ? tb : a < b;
    });
    std::vector<RatingSummary> rows;
    for (const std::string& group : order) {
        const std::vector<int>& scores = groups[group];
        RatingSummary row;
        row.group = group;
        row.count = static_cast<int>(scores.size());
        double sum = 0.0;
        for (int s : scores)
            sum += s;
        row.mean = sum / row.count;
        row.lowest = *std::min_element(scores.begin(), scores.end());
        row.highest = *std::max_element(scores.begin(), scores.end());
        rows.push_back(std::move(row));
    }
    return rows;
}

} // namespace hs::scene
