#include "hs/texture/ImageFiles.h"

#include "TestSupport.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
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

void put32(std::string& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8)
        out += static_cast<char>((v >> shift) & 0xff);
}

/// A minimal ICC profile (header, one 'desc' tag of ICC.1:2001's text type) that names itself `description`.
std::string iccProfile(const std::string& description) {
    std::string tag = "desc";
    put32(tag, 0);
    put32(tag, static_cast<std::uint32_t>(description.size() + 1));
    tag += description;
    tag += '\0';
    std::string icc(128, '\0');
    put32(icc, 1);                                      // one tag
    icc += "desc";                                      // its signature,
    put32(icc, 144);                                    // offset (128 + 4 + 12)
    put32(icc, static_cast<std::uint32_t>(tag.size())); // and size
    icc += tag;
    // libpng (1.6.39 as Debian 12 ships it) drops a profile this small as "too short"; real ones are kilobytes.
    icc += std::string(512, '\0');
    while (icc.size() % 4 != 0) // tags start on 4-byte boundaries
        icc += '\0';
    std::string size;
    put32(size, static_cast<std::uint32_t>(icc.size()));
    icc.replace(0, 4, size);
    icc.replace(8, 4, std::string("\x02\x10\x00\x00", 4)); // version 2.1
    icc.replace(12, 4, "mntr");                            // a display's profile,
    icc.replace(16, 4, "RGB ");                            // of RGB data,
    icc.replace(20, 4, "XYZ ");                            // connected through XYZ
    icc.replace(36, 4, "acsp");
    icc.replace(68, 12, std::string("\x00\x00\xf6\xd6\x00\x01\x00\x00\x00\x00\xd3\x2d", 12)); // D50
    return icc;
}

/// The PNG at `path` with an iCCP chunk (PNG 1.2, 11.3.3.3: the profile's name, a zero, method 0 and the zlib-
/// compressed profile) inserted after its IHDR.
void embedProfile(const std::string& path, const std::string& icc) {
    std::ifstream in(path, std::ios::binary);
    std::string png((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    uLongf packedSize = compressBound(static_cast<uLong>(icc.size()));
    std::string packed(packedSize, '\0');
    ASSERT_EQ(compress(reinterpret_cast<Bytef*>(packed.data()), &packedSize, reinterpret_cast<const Bytef*>(icc.data()),
                       static_cast<uLong>(icc.size())),
              Z_OK);
    packed.resize(packedSize);
    std::string body = "iCCP";
    body += std::string("profile") + '\0' + '\0' + packed;
    std::string chunk;
    put32(chunk, static_cast<std::uint32_t>(body.size() - 4));
    chunk += body;
    put32(chunk, static_cast<std::uint32_t>(
                     crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()))));
    const std::size_t afterHeader = 8 + 4 + 4 + 13 + 4; // signature, IHDR's length, type, data and CRC
    png.insert(afterHeader, chunk);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << png;
}

} // namespace

// A user's exemplar may carry alpha or a colour profile: it reads the same when they change nothing (opaque alpha,
// an sRGB profile), and is refused by name when they would (transparent pixels have no colour; nothing here converts
// another profile to sRGB). Grey with alpha reads as grey (it used to put the alpha into green and blue).
TEST(TextureImageFiles, AlphaAndColourProfilesReadOrAreRefusedByName) {
    test::TempDir dir;
    ImageU8 greyAlpha = ImageU8::create(16, 16, 2, 255).value();
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            greyAlpha.at(x, y, 0) = static_cast<std::uint8_t>(10 * x);
    ASSERT_TRUE(writeImage(greyAlpha, dir.file("ga.png")).ok());
    const auto grey = readImageRgb8(dir.file("ga.png"));
    ASSERT_TRUE(grey.ok()) << grey.error().message();
    EXPECT_EQ(grey->at(5, 3, 0), 50);
    EXPECT_EQ(grey->at(5, 3, 1), 50);
    EXPECT_EQ(grey->at(5, 3, 2), 50);

    ImageU8 rgba = ImageU8::create(16, 16, 4, 255).value();
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            rgba.at(x, y, 0) = 200;
            rgba.at(x, y, 1) = static_cast<std::uint8_t>(10 * y);
            rgba.at(x, y, 2) = 30;
        }
    ASSERT_TRUE(writeImage(rgba, dir.file("opaque.png")).ok());
    const auto opaque = readImageRgb8(dir.file("opaque.png"));
    ASSERT_TRUE(opaque.ok()) << opaque.error().message();
    EXPECT_EQ(opaque->at(2, 7, 0), 200);
    EXPECT_EQ(opaque->at(2, 7, 1), 70);
    EXPECT_EQ(opaque->at(2, 7, 2), 30);

    rgba.at(3, 5, 3) = 0;
    rgba.at(9, 9, 3) = 128;
    ASSERT_TRUE(writeImage(rgba, dir.file("holes.png")).ok());
    const auto holes = readImageRgb8(dir.file("holes.png"));
    ASSERT_FALSE(holes.ok());
    EXPECT_EQ(holes.error().code, ErrorCode::InvalidInput);
    EXPECT_NE(holes.error().detail.find("holes.png: 2 of 256 pixels are transparent"), std::string::npos)
        << holes.error().detail;
    EXPECT_NE(holes.error().detail.find("the first at x 3, y 5"), std::string::npos) << holes.error().detail;

    const ImageU8 rgb = gradient(16, 16);
    ASSERT_TRUE(writeImage(rgb, dir.file("srgb.png")).ok());
    embedProfile(dir.file("srgb.png"), iccProfile("sRGB IEC61966-2.1"));
    const auto srgb = readImageRgb8(dir.file("srgb.png"));
    ASSERT_TRUE(srgb.ok()) << srgb.error().message();
    EXPECT_EQ(srgb->data(), rgb.data());

    ASSERT_TRUE(writeImage(rgb, dir.file("p3.png")).ok());
    embedProfile(dir.file("p3.png"), iccProfile("Display P3"));
    const auto p3 = readImageRgb8(dir.file("p3.png"));
    ASSERT_FALSE(p3.ok());
    EXPECT_EQ(p3.error().code, ErrorCode::Unsupported);
    EXPECT_NE(p3.error().detail.find("p3.png: colour profile 'Display P3'"), std::string::npos) << p3.error().detail;
}

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
