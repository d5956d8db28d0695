#include "hs/core/Streams.h"
#include "hs/core/Rng.h"

#include <gtest/gtest.h>

#include <set>

// The seed table's promise: the named streams of one parent never meet each other or its per-element ranges.
TEST(Streams, NamedStreamsOfTheMeshingSeedLieOutsideItsSeedingRanges) {
    using namespace hs::streams;
    const std::uint64_t repair = kMeshingSliverRepair;
    // Surface seeding: (s << 40) ^ v below 2^62; inner seeding: 2^62 ^ v in [2^62, 2^63).
    EXPECT_GE(repair, std::uint64_t{1} << 63);
    EXPECT_GE(kMeshingSeedingInner, std::uint64_t{1} << 62);
    EXPECT_LT(kMeshingSeedingInner ^ ((std::uint64_t{1} << 62) - 1), std::uint64_t{1} << 63);
    // The first surface's voxel 7 and the repair draw from different seeds.
    EXPECT_NE(hs::Rng::deriveSeed(42, (std::uint64_t{0} << 40) ^ 7), hs::Rng::deriveSeed(42, repair));
}

TEST(Streams, StageAndTextureStreamsAreDistinct) {
    using namespace hs::streams;
    std::set<std::uint64_t> caseStreams{kPathology, kMeshing, kTexture, kMaterial};
    EXPECT_EQ(caseStreams.size(), 4u);
    for (std::uint64_t s : caseStreams)
        EXPECT_LT(s, kVariantBase);
    // Up to 100 appearance classes each: exemplars [100, 200), synthesis [200, 300), vessels 300.
    EXPECT_EQ(kTextureSynthesis - kTextureExemplars, 100u);
    EXPECT_EQ(kTextureVessels - kTextureSynthesis, 100u);
}
