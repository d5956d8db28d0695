// Review files: written beside a package and read back, validated as untrusted input, summarised by kind and model.
#include "hs/scene/Review.h"
#include "hs/scene/Scene.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <fstream>

using namespace hs;
using namespace hs::scene;

namespace {

const std::string kSha(64, 'a');

Review sampleReview() {
    Scene scene;
    scene.caseSpec = defaultCase(); // a FIGO 2 myoma and a sessile polyp, both grown by skeletons
    Review review = emptyReview(scene, kSha);
    review.reviewer = "Dr. A";
    review.pathologies[0].rating = {4, "firm, well demarcated"};
    review.pathologies[1].rating = {2, ""};
    review.textures[0].rating = {5, "vessels convincing"};
    return review;
}

} // namespace

TEST(Review, ListsEveryPathologyAndTheAppearancesTheSceneShows) {
    Scene scene;
    scene.caseSpec = defaultCase();
    const Review review = emptyReview(scene, kSha);
    ASSERT_EQ(review.pathologies.size(), scene.caseSpec.pathologies.size());
    EXPECT_EQ(review.pathologies[0].id, scene.caseSpec.pathologies[0].id);
    EXPECT_EQ(review.pathologies[0].growthModel, scene.caseSpec.pathologies[0].growthModel);
    ASSERT_EQ(review.textures.size(), 3u); // endometrium, myoma, polyp
    EXPECT_FALSE(review.pathologies[0].rating.score.has_value());
}

TEST(Review, RoundTripsThroughItsFileBesideThePackage) {
    test::TempDir tmp;
    const std::string package = tmp.file("scene");
    EXPECT_EQ(reviewPathFor(package + "/"), package + ".review.json");
    const Review review = sampleReview();
    ASSERT_TRUE(saveReview(review, reviewPathFor(package)).ok());
    auto read = loadReview(reviewPathFor(package));
    ASSERT_TRUE(read.ok()) << read.error().message();
    EXPECT_EQ(toJson(*read), toJson(review));
    EXPECT_EQ(*read->pathologies[0].rating.score, 4);
    EXPECT_EQ(read->pathologies[0].rating.comment, "firm, well demarcated");
}

TEST(Review, RefusesABadFileNamingTheField) {
    const std::string good = toJson(sampleReview());
    const auto refused = [&](std::string text, const std::string& field) {
        auto r = parseReview(text, "r.json");
        ASSERT_FALSE(r.ok()) << text;
        EXPECT_NE(r.error().detail.find("r.json: " + field), std::string::npos) << r.error().detail;
    };
    std::string score = good;
    score.replace(score.find("\"score\": 4"), 10, "\"score\": 9");
    refused(score, "/pathologies/0/rating/score");
    std::string kind = good;
    kind.replace(kind.find("\"myoma\""), 7, "\"cyst\"");
    refused(kind, "/pathologies/0/kind");
    std::string sha = good;
    sha.replace(sha.find(kSha), 64, "xyz");
    refused(sha, "/packageSha256");
    refused("[[[[[[[[[[[[[[[[[[[[]]]]]]]]]]]]]]]]]]]]", "");
    refused("not json", "");
    std::string version = good;
    version.replace(version.find("\"schemaVersion\": 1"), 18, "\"schemaVersion\": 7");
    auto newer = parseReview(version, "r.json");
    ASSERT_FALSE(newer.ok());
    EXPECT_EQ(newer.error().code, ErrorCode::Unsupported);
    Review tooLong = sampleReview();
    tooLong.pathologies[0].rating.comment.assign(kMaxReviewCommentLength + 1, 'x');
    EXPECT_FALSE(saveReview(tooLong, "/nonexistent/never-written.json").ok());
}

TEST(Review, SummarisesRatingsByKindAndGrowthModelThenTexture) {
    Review a = sampleReview();
    Review b = sampleReview();
    b.pathologies[0].rating.score = 2;
    b.pathologies[1].rating.score.reset(); // not rated: left out
    const std::vector<RatingSummary> rows = summarize({a, b});
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[0].group, "myoma / skeleton");
    EXPECT_EQ(rows[0].count, 2);
    EXPECT_DOUBLE_EQ(rows[0].mean, 3.0);
    EXPECT_EQ(rows[0].lowest, 2);
    EXPECT_EQ(rows[0].highest, 4);
    EXPECT_EQ(rows[1].group.rfind("polyp / ", 0), 0u);
    EXPECT_EQ(rows[1].count, 1);
    EXPECT_EQ(rows[2].group, "texture / endometrium");
}
