#pragma once
/// A clinician's review of a scene package: how real each pathology and each texture looks (1-5 with a comment).
/// The review is a file beside the package (`<package>.review.json`), never inside it, so the package's checksums
/// stay valid; it names the package by its manifest's SHA-256 so that a review never attaches to another scene.
/// A summary pools many reviews by pathology kind and growth model (docs/workstation.md, "Review").

#include "hs/clinical/Clinical.h"
#include "hs/core/Result.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hs::scene {

struct Scene;

/// Value of the review file's "format" member, and the schema version this build writes and reads.
constexpr std::string_view kReviewFormat = "hysteroscene-review";
constexpr int kReviewSchemaVersion = 1;
/// A review is a few kB; anything above this is refused before parsing.
constexpr std::int64_t kMaxReviewFileBytes = 1024 * 1024;
constexpr std::size_t kMaxReviewCommentLength = 2000;
constexpr std::size_t kMaxReviewItems = 64;

/// One rating: 1 (not realistic) to 5 (indistinguishable from a real one); unset: not rated yet.
struct Rating {
    std::optional<int> score;
    std::string comment;
};

struct PathologyRating {
    std::string id; ///< the case's pathology id
    clinical::PathologyKind kind = clinical::PathologyKind::Myoma;
    clinical::GrowthModel growthModel = clinical::GrowthModel::Particles;
    Rating rating;
};

/// The texture of one appearance: "endometrium", "myoma", "polyp".
struct TextureRating {
    std::string appearance;
    Rating rating;
};

struct Review {
    std::string packageSha256; ///< SHA-256 of the reviewed package's manifest.json
    std::string reviewer;      ///< free text, <= 200 characters
    std::vector<PathologyRating> pathologies;
    std::vector<TextureRating> textures;
};

/// A review with every pathology of `scene` (kind and growth model from its case) and every appearance it shows,
/// none rated yet.
Review emptyReview(const Scene& scene, const std::string& packageSha256);
/// The SHA-256 of `packageFolder`/manifest.json, which names the package in its reviews.
[[nodiscard]] Result<std::string> packageIdentity(const std::string& packageFolder);
/// Where the review of `packageFolder` is kept: beside it, "<folder>.review.json".
std::string reviewPathFor(const std::string& packageFolder);

/// The review file's text: fixed member order, 4-space indent, final newline.
std::string toJson(const Review& review);
/// Parses and validates a review file (format, version, scores 1-5, lengths, counts); errors name the file, the
/// field and the allowed range.
[[nodiscard]] Result<Review> parseReview(std::string_view jsonText, const std::string& sourceName);
[[nodiscard]] Result<Review> loadReview(const std::string& path);
/// Writes atomically; refuses a review that parseReview would refuse.
[[nodiscard]] Status saveReview(const Review& review, const std::string& path);

/// The mean score and count of one group of ratings.
struct RatingSummary {
    std::string group; ///< "myoma / particles", "texture / endometrium"
    int count = 0;
    double mean = 0.0;
    int lowest = 0;
    int highest = 0;
};
/// Pools the rated items of `reviews`: one row per pathology kind and growth model, then one per texture appearance,
/// in a fixed order; groups without a rating are left out.
std::vector<RatingSummary> summarize(const std::vector<Review>& reviews);

} // namespace hs::scene
