#include "hs/texture/Synthesis.h"
#include "hs/texture/Exemplars.h"
#include "hs/texture/ImageFiles.h"
#include "hs/texture/Quality.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
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

namespace hs::texture {
namespace {

/// Mean luma, the green-to-red ratio, the saturation and the share of deep red pixels of an exemplar.
struct Look {
    double luma = 0.0, greenPerRed = 0.0, saturation = 0.0, darkRed = 0.0;
};
Look lookOf(const ImageU8& img) {
    Look l;
    double r = 0.0, g = 0.0;
    const double n = double(img.width()) * img.height();
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const double R = img.at(x, y, 0), G = img.at(x, y, 1), B = img.at(x, y, 2);
            l.luma += (0.2126 * R + 0.7152 * G + 0.0722 * B) / 255.0 / n;
            l.saturation += (R - std::min(G, B)) / std::max(1.0, R) / n;
            l.darkRed += G < 0.55 * R ? 1.0 / n : 0.0; // red well beyond the mucosa's own (petechiae on pale)
            r += R;
            g += G;
        }
    l.greenPerRed = g / r;
    return l;
}

TEST(TextureExemplars, TheEndometriumFollowsTheCycleAndTheMenopause) {
    // As hysteroscopy describes it (docs/texture.md): proliferative pink-red; secretory paler and yellowish pink;
    // menstrual dark red; atrophic pale and less saturated, with petechiae.
    std::array<Look, 4> look;
    for (const EndometrialState s : kEndometrialStates)
        look[static_cast<std::size_t>(s)] = lookOf(makeExemplar(Appearance::Endometrium, 256, 3, s).value());
    const Look& pro = look[0];
    const Look& sec = look[1];
    const Look& men = look[2];
    const Look& atr = look[3];
    for (std::size_t k = 0; k < look.size(); ++k)
        std::printf("%-13s luma %.3f  G/R %.3f  saturation %.3f  dark red %.4f\n",
                    endometrialStateName(kEndometrialStates[k]).c_str(), look[k].luma, look[k].greenPerRed,
                    look[k].saturation, look[k].darkRed);
    EXPECT_LT(men.luma, pro.luma - 0.05);
    EXPECT_GT(sec.luma, pro.luma + 0.05);
    EXPECT_GT(sec.greenPerRed, pro.greenPerRed + 0.1); // yellower
    EXPECT_GT(atr.luma, pro.luma + 0.1);               // paler
    EXPECT_LT(atr.saturation, pro.saturation - 0.1);
    EXPECT_GT(atr.darkRed, 0.002); // petechiae on the pale mucosa
    // The default look is the proliferative one, as before; the other tissues do not depend on the state.
    EXPECT_EQ(makeExemplar(Appearance::Endometrium, 64, 3).value().data(),
              makeExemplar(Appearance::Endometrium, 64, 3, EndometrialState::Proliferative).value().data());
    EXPECT_EQ(makeExemplar(Appearance::Myoma, 64, 3).value().data(),
              makeExemplar(Appearance::Myoma, 64, 3, EndometrialState::Atrophic).value().data());
    // Vessels: hidden by the secretory oedema, showing through the atrophic mucosa.
    EXPECT_LT(endometrialSurface(EndometrialState::Secretory).vesselDensity, 0.5);
    EXPECT_GT(endometrialSurface(EndometrialState::Atrophic).vesselDensity, 1.0);
    EXPECT_EQ(endometrialStateName(EndometrialState::Atrophic), "atrophic");
}

TEST(TextureExemplars, TheEndocervixIsWhitishPinkBesideTheEndometrium) {
    // "The endocervical mucosa is whitish pink" (docs/texture.md, "The cervical canal"): paler and less saturated
    // than the proliferative endometrium, still pink (red above green and blue).
    const Look canal = lookOf(makeExemplar(Appearance::CervicalCanal, 256, 3).value());
    const Look endometrium = lookOf(makeExemplar(Appearance::Endometrium, 256, 3).value());
    std::printf("cervical canal luma %.3f  G/R %.3f  saturation %.3f\n", canal.luma, canal.greenPerRed,
                canal.saturation);
    EXPECT_GT(canal.luma, endometrium.luma + 0.05);
    EXPECT_LT(canal.saturation, endometrium.saturation - 0.05);
    EXPECT_LT(canal.greenPerRed, 0.9); // pink, not white
    EXPECT_EQ(appearanceName(Appearance::CervicalCanal), "cervical-canal");
    EXPECT_EQ(makeExemplar(Appearance::CervicalCanal, 64, 3).value().data(),
              makeExemplar(Appearance::CervicalCanal, 64, 3, EndometrialState::Atrophic).value().data());
}

} // namespace
} // namespace hs::texture
