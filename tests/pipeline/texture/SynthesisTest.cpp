#include "hs/texture/Synthesis.h"
#include "hs/texture/Exemplars.h"
#include "hs/texture/ImageFiles.h"
#include "hs/texture/Quality.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

using namespace hs;
using namespace hs::texture;

namespace {

std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A crop of a procedural exemplar: not tileable itself, like a photograph.
ImageU8 croppedExemplar(Appearance a, int side, std::uint64_t seed = 7) {
    const ImageU8 big = makeExemplar(a, 2 * side, seed).value();
    ImageU8 crop = ImageU8::create(side, side, 3).value();
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            for (int c = 0; c < 3; ++c)
                crop.at(x, y, c) = big.at(x + side / 3, y + side / 5, c);
    return crop;
}

SynthesisParams smallParams(int side, std::uint64_t seed) {
    SynthesisParams p;
    p.width = p.height = side;
    p.seed = seed;
    return p;
}

} // namespace

TEST(TextureSynthesis, SameSeedGivesByteIdenticalPngsWhateverTheThreadCount) {
    const ImageU8 exemplar = croppedExemplar(Appearance::Endometrium, 64);
    SynthesisParams p = smallParams(128, 42);
    p.threads = 1;
    const auto a = synthesizeTexture(exemplar, p);
    p.threads = 3;
    const auto b = synthesizeTexture(exemplar, p);
    ASSERT_TRUE(a.ok()) << a.error().message();
    ASSERT_TRUE(b.ok()) << b.error().message();
    EXPECT_EQ(a->image.data(), b->image.data());
    test::TempDir dir;
    ASSERT_TRUE(writeImage(a->image, dir.file("a.png")).ok());
    ASSERT_TRUE(writeImage(b->image, dir.file("b.png")).ok());
    EXPECT_EQ(fileBytes(dir.file("a.png")), fileBytes(dir.file("b.png")));
    EXPECT_FALSE(fileBytes(dir.file("a.png")).empty());
}

TEST(TextureSynthesis, DifferentSeedsGiveDifferentTextures) {
    const ImageU8 exemplar = croppedExemplar(Appearance::Endometrium, 64);
    const auto a = synthesizeTexture(exemplar, smallParams(96, 1));
    const auto b = synthesizeTexture(exemplar, smallParams(96, 2));
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_NE(a->image.data(), b->image.data());
}

TEST(TextureSynthesis, OutputTilesWithoutVisibleSeam) {
    const ImageU8 exemplar = croppedExemplar(Appearance::Myoma, 96);
    const auto out = synthesizeTexture(exemplar, smallParams(192, 5));
    ASSERT_TRUE(out.ok());
    const double exemplarSeam = tileSeamRatio(exemplar);
    const double outSeam = tileSeamRatio(out->image);
    EXPECT_GT(exemplarSeam, 1.5) << "the exemplar crop itself should not tile";
    EXPECT_LT(outSeam, 1.3);
}

TEST(TextureSynthesis, HistogramDistanceFrom128ExemplarIsWithin1_2TimesThatOfACrop) {
    for (Appearance a : kAppearances) {
        const ImageU8 exemplar = croppedExemplar(a, 128);
        const auto out = synthesizeTexture(exemplar, smallParams(256, 11));
        ASSERT_TRUE(out.ok());
        const auto q = measureSynthesis(exemplar, out->image);
        ASSERT_TRUE(q.ok());
        EXPECT_LE(q->histogramRatio, 1.2)
            << appearanceName(a) << ": output " << q->histogram << ", crop " << q->cropHistogram;
        EXPECT_LT(q->gram, 0.5) << appearanceName(a);
    }
}

TEST(TextureSynthesis, RejectsOnePixelExemplarAndHugeRequestNamingTheRange) {
    const ImageU8 tiny = ImageU8::create(1, 1, 3, 128).value();
    const auto a = synthesizeTexture(tiny, smallParams(64, 1));
    ASSERT_FALSE(a.ok());
    EXPECT_EQ(a.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(a.error().detail.find("16..4096"), std::string::npos) << a.error().detail;

    const ImageU8 exemplar = croppedExemplar(Appearance::Polyp, 32);
    const auto b = synthesizeTexture(exemplar, smallParams(100000, 1));
    ASSERT_FALSE(b.ok());
    EXPECT_EQ(b.error().code, ErrorCode::LimitExceeded);
    EXPECT_NE(b.error().detail.find("100000"), std::string::npos) << b.error().detail;
    EXPECT_NE(b.error().detail.find("16..8192"), std::string::npos) << b.error().detail;
}

TEST(TextureSynthesis, StopsWhenCancelled) {
    Progress progress;
    progress.requestCancel();
    const auto r = synthesizeTexture(croppedExemplar(Appearance::Polyp, 32), smallParams(64, 1), progress);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::Cancelled);
}

TEST(TextureExemplars, AreDeterministicAndLookDifferentPerTissue) {
    const ImageU8 e1 = makeExemplar(Appearance::Endometrium, 64, 3).value();
    const ImageU8 e2 = makeExemplar(Appearance::Endometrium, 64, 3).value();
    EXPECT_EQ(e1.data(), e2.data());
    const auto meanOf = [](const ImageU8& img, int c) {
        double s = 0;
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x)
                s += img.at(x, y, c);
        return s / (img.width() * img.height());
    };
    const ImageU8 myoma = makeExemplar(Appearance::Myoma, 64, 3).value();
    // The myoma is paler (more green and blue at similar red) than the red-pink endometrium.
    EXPECT_GT(meanOf(myoma, 1), meanOf(e1, 1) + 30);
    EXPECT_FALSE(makeExemplar(Appearance::Myoma, 8, 1).ok());
}
