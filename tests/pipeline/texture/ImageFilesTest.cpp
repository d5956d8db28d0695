#include "hs/texture/ImageFiles.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace hs;
using namespace hs::texture;

namespace {

ImageU8 gradient(int w, int h) {
    ImageU8 img = ImageU8::create(w, h, 3).value();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            img.at(x, y, 0) = static_cast<std::uint8_t>(x * 255 / (w - 1));
            img.at(x, y, 1) = static_cast<std::uint8_t>(y * 255 / (h - 1));
            img.at(x, y, 2) = 77;
        }
    return img;
}

} // namespace

TEST(TextureImageFiles, PngRoundTripsExactly) {
    test::TempDir dir;
    const ImageU8 img = gradient(40, 30);
    ASSERT_TRUE(writeImage(img, dir.file("g.png")).ok());
    const auto back = readImageRgb8(dir.file("g.png"));
    ASSERT_TRUE(back.ok()) << back.error().message();
    EXPECT_EQ(back->data(), img.data());
}

TEST(TextureImageFiles, JpegExrAndTiffRoundTripApproximately) {
    test::TempDir dir;
    const ImageU8 img = gradient(32, 32);
    for (const char* name : {"g.jpg", "g.exr", "g.tif"}) {
        ASSERT_TRUE(writeImage(img, dir.file(name)).ok()) << name;
        const auto back = readImageRgb8(dir.file(name));
        ASSERT_TRUE(back.ok()) << name << ": " << back.error().message();
        double err = 0;
        for (std::size_t i = 0; i < img.data().size(); ++i)
            err += std::abs(int(img.data()[i]) - int(back->data()[i]));
        EXPECT_LT(err / static_cast<double>(img.data().size()), 3.0) << name;
    }
}

TEST(TextureImageFiles, KnowsTheFormatByItsContentAndReadsOnlyTheFourItWrites) {
    test::TempDir dir;
    const ImageU8 img = ImageU8::create(20, 20, 3, 100).value();
    ASSERT_TRUE(writeImage(img, dir.file("real-png.png")).ok());
    std::filesystem::rename(dir.file("real-png.png"), dir.file("named-wrongly.jpg"));
    const auto byContent = readImageRgb8(dir.file("named-wrongly.jpg"));
    ASSERT_TRUE(byContent.ok()) << byContent.error().message();
    EXPECT_EQ(byContent->width(), 20);
    {
        // A GIF (a format OpenImageIO has a reader for): refused before any decoder sees it.
        std::ofstream gif(dir.file("picture.gif"), std::ios::binary);
        gif << "GIF89a\x14\x00\x14\x00\x00\x00\x00;";
    }
    const auto other = readImageRgb8(dir.file("picture.gif"));
    ASSERT_FALSE(other.ok());
    EXPECT_EQ(other.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(other.error().detail.find("picture.gif"), std::string::npos);
    EXPECT_NE(other.error().detail.find("PNG, JPEG, OpenEXR, TIFF"), std::string::npos) << other.error().detail;
}

TEST(TextureImageFiles, RejectsUnreadableMissingAndTinyFilesNamingThem) {
    test::TempDir dir;
    {
        std::ofstream garbage(dir.file("bad.png"), std::ios::binary);
        garbage << "this is not an image";
    }
    const auto bad = readImageRgb8(dir.file("bad.png"));
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(bad.error().detail.find("bad.png"), std::string::npos);

    const auto missing = readImageRgb8(dir.file("missing.png"));
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::NotFound);

    ASSERT_TRUE(writeImage(ImageU8::create(1, 1, 3, 9).value(), dir.file("one.png")).ok());
    ImageReadLimits limits;
    limits.minSide = 16;
    limits.maxSide = 4096;
    const auto tiny = readImageRgb8(dir.file("one.png"), limits);
    ASSERT_FALSE(tiny.ok());
    EXPECT_EQ(tiny.error().code, ErrorCode::LimitExceeded);
    EXPECT_NE(tiny.error().detail.find("one.png"), std::string::npos);
    EXPECT_NE(tiny.error().detail.find("16..4096"), std::string::npos);
}

TEST(TextureImageFiles, RefusesUnknownExtensionAndLeavesNoFile) {
    test::TempDir dir;
    const auto s = writeImage(gradient(8, 8), dir.file("x.xyz"));
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().code, ErrorCode::Unsupported);
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}
