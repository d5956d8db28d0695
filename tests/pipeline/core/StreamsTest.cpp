#include "hs/core/Streams.h"
#include "hs/core/Rng.h"

#include <gtest/gtest.h>

#include <set>

// The seed table's promise: the named streams of one parent never meet each other or its per-element ranges.
TEST(Streams, TheMeshingSeedingRangesDoNotMeet) {
    using namespace hs::streams;
    // Surface seeding: (s << 40) ^ v below 2^62; inner seeding: kMeshingSeedingInner ^ v in [2^62, 2^63).
    EXPECT_EQ(kMeshingSeedingInner, std::uint64_t{1} << 62);
    EXPECT_LT(kMeshingSeedingInner ^ ((std::uint64_t{1} << 62) - 1), std::uint64_t{1} << 63);
    EXPECT_LT((std::uint64_t{(1 << 22) - 1} << 40) ^ ((std::uint64_t{1} << 40) - 1), kMeshingSeedingInner);
    // The sliver repair derives per vertex from its stream; the voxel that shares its index draws from it directly.
    const hs::Rng voxel(hs::Rng::deriveSeed(42, kMeshingSliverRepair));
    const hs::Rng repairVertex = hs::Rng(hs::Rng::deriveSeed(42, kMeshingSliverRepair)).derive(0);
    hs::Rng a = voxel, b = repairVertex;
    EXPECT_NE(a.next(), b.next());
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
