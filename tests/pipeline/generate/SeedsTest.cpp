#include "hs/generate/Seeds.h"

#include "hs/core/Rng.h"

#include <gtest/gtest.h>

#include <set>

using namespace hs::generate;

TEST(Seeds, StageKeysRoundTrip) {
    for (int i = 0; i < kStageCount; ++i) {
        const auto stage = static_cast<Stage>(i);
        Stage back = Stage::Scene;
        ASSERT_TRUE(fromString(toString(stage), back)) << toString(stage);
        EXPECT_EQ(back, stage);
    }
    Stage unused = Stage::Organ;
    EXPECT_FALSE(fromString("package", unused));
    EXPECT_EQ(toString(Stage::Meshing), "meshing");
}

TEST(Seeds, StageStreamsKeepTheirIndicesSoScenesStayTheSame) {
    // The streams are part of every scene ever generated: changing one changes every scene of that stage.
    EXPECT_EQ(organSeed(42), 42u);
    EXPECT_EQ(streamSeed(42, Stream::Pathology), hs::Rng::deriveSeed(42, 5));
    EXPECT_EQ(streamSeed(42, Stream::Meshing), hs::Rng::deriveSeed(42, 7));
    EXPECT_EQ(streamSeed(42, Stream::Texture), hs::Rng::deriveSeed(42, 11));
    EXPECT_EQ(streamSeed(42, Stream::Material), hs::Rng::deriveSeed(42, 13));
}

TEST(Seeds, VariantSeedsNeverMeetTheBaseCaseStageStreams) {
    // Before the seed plan, variant 5's seed was the base case's pathology stream.
    EXPECT_EQ(hs::Rng::deriveSeed(1, 5), streamSeed(1, Stream::Pathology));
    const Stream streams[] = {Stream::Pathology, Stream::Meshing, Stream::Texture, Stream::Material};
    for (std::uint64_t base = 0; base < 50; ++base) {
        std::set<std::uint64_t> stageSeeds{organSeed(base)};
        for (auto s : streams)
            stageSeeds.insert(streamSeed(base, s));
        std::set<std::uint64_t> variants;
        for (std::size_t v = 0; v < 2000; ++v) {
            const auto seed = variantSeed(base, v);
            EXPECT_EQ(stageSeeds.count(seed), 0u) << "base " << base << " variant " << v;
            variants.insert(seed);
        }
        EXPECT_EQ(variants.size(), 2000u) << "base " << base;
    }
}

TEST(Seeds, VariantSeedsAreAFunctionOfTheBaseSeedAndIndex) {
    EXPECT_EQ(variantSeed(7, 3), variantSeed(7, 3));
    EXPECT_NE(variantSeed(7, 3), variantSeed(8, 3));
    EXPECT_NE(variantSeed(7, 3), variantSeed(7, 4));
}

TEST(Seeds, ExportsNameVariantFoldersAndKeepTheBaseSeedForOne) {
    EXPECT_EQ(variantFolderName(7), "variant-007");
    EXPECT_EQ(variantFolderName(1234), "variant-1234");
    EXPECT_EQ(exportSeed(42, 0, 1), 42u);
    EXPECT_EQ(exportSeed(42, 3, 5), variantSeed(42, 3));
}
