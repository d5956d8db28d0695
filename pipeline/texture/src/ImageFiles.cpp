#include "hs/texture/ImageFiles.h"

#include "hs/io/AtomicFile.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace hs::texture {
namespace {

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (auto& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

/// OpenImageIO's format name for an extension we write, empty for others.
std::string outputFormatFor(const std::string& ext) {
    if (ext == ".png")
        return "png";
    if (ext == ".jpg" || ext == ".jpeg")
        return "jpeg";
    if (ext == ".exr")
        return "openexr";
    if (ext == ".tif" || ext == ".tiff")
        return "tiff";
    return {};
}

/// The format of an image file by its first bytes: one of the formats writeImage writes (PNG, JPEG, OpenEXR, TIFF),
/// empty for anything else. Images come from users: only these decoders see them. Left to itself, OpenImageIO
/// tries every reader it has on a file the one its extension names refuses (FFmpeg's, LibRaw's and DICOM's among
/// them), which widens what a damaged file reaches and costs tens of milliseconds a file.
std::string sniffFormat(const std::string& path) {
    unsigned char head[8] = {};
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f)
        return {};
    const std::size_t n = std::fread(head, 1, sizeof head, f);
    std::fclose(f);
    const auto starts = [&](std::initializer_list<unsigned char> magic) {
        if (n < magic.size())
            return false;
        std::size_t i = 0;
        for (const unsigned char b : magic)
            if (head[i++] != b)
                return false;
        return true;
    };
    if (starts({0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a}))
        return "png";
    if (starts({0xff, 0xd8, 0xff}))
        return "jpeg";
    if (starts({0x76, 0x2f, 0x31, 0x01}))
        return "openexr";
    if (starts({'I', 'I', 0x2a, 0x00}) || starts({'M', 'M', 0x00, 0x2a}) || starts({'I', 'I', 0x2b, 0x00}) ||
        starts({'M', 'M', 0x00, 0x2b}))
        return "tiff";
    return {};
}

std::uint32_t bigEndian32(const std::uint8_t* p) {
    return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]};
}

/// The description of an ICC profile (its 'desc' tag: ICC.1:2001 'desc' text or ICC.1:2010 'mluc', the first
/// record's ASCII characters), empty when it has none or the bytes do not hold one.
std::string iccDescription(const std::uint8_t* icc, std::size_t size) {
    if (size < 132)
        return {};
    const std::uint32_t tags = bigEndian32(icc + 128);
    for (std::uint32_t i = 0; i < tags && 132 + 12 * (std::size_t{i} + 1) <= size; ++i) {
        const std::uint8_t* entry = icc + 132 + 12 * std::size_t{i};
        if (std::string(reinterpret_cast<const char*>(entry), 4) != "desc")
            continue;
        const std::size_t offset = bigEndian32(entry + 4), length = bigEndian32(entry + 8);
        if (offset > size || length > size - offset || length < 12)
            return {};
        const std::uint8_t* tag = icc + offset;
        const std::string type(reinterpret_cast<const char*>(tag), 4);
        std::string text;
        if (type == "desc") {
            const std::size_t count = std::min<std::size_t>(bigEndian32(tag + 8), length - 12);
            for (std::size_t k = 0; k < count && tag[12 + k] != 0; ++k)
                text += static_cast<char>(tag[12 + k]);
        } else if (type == "mluc" && length >= 28) {
            const std::size_t bytes = bigEndian32(tag + 20), at = bigEndian32(tag + 24);
            if (at > length || bytes > length - at)
                return {};
            for (std::size_t k = 0; k + 1 < bytes; k += 2) // UTF-16BE: keep the ASCII ones
                if (tag[at + k] == 0 && tag[at + k + 1] != 0)
                    text += static_cast<char>(tag[at + k + 1]);
        }
        for (auto& c : text)
            if (!std::isprint(static_cast<unsigned char>(c)))
                c = '?';
        return text;
    }
    return {};
}

/// Refuses an embedded colour profile other than sRGB (the textures are sRGB, and nothing here converts): empty
/// when there is none or it describes itself as sRGB.
std::string foreignProfile(const OIIO::ImageSpec& spec) {
    const OIIO::ParamValue* icc = spec.find_attribute("ICCProfile");
    if (!icc || icc->type().basetype != OIIO::TypeDesc::UINT8 || icc->datasize() == 0)
        return {};
    const std::string description = iccDescription(static_cast<const std::uint8_t*>(icc->data()), icc->datasize());
    std::string lower = description;
    for (auto& c : lower)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower.find("srgb") != std::string::npos)
        return {};
    return description.empty() ? std::string("(no description)") : "'" + description + "'";
}

std::string sideRange(const ImageReadLimits& limits) {
    return std::to_string(limits.minSide) + ".." + std::to_string(limits.maxSide);
}

} // namespace

Result<ImageU8> readImageRgb8(const std::string& path, const ImageReadLimits& limits) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return fail(ErrorCode::NotFound, path + ": no such image file");
    const std::string format = sniffFormat(path);
    if (format.empty())
        return fail(ErrorCode::InvalidInput, path + ": not an image of a format read here (PNG, JPEG, OpenEXR, TIFF)");
    auto input = OIIO::ImageInput::create(format);
    OIIO::ImageSpec opened;
    if (!input || !input->open(path, opened)) {
        std::string why = input ? input->geterror() : std::string();
        const std::string global = OIIO::geterror();
        if (why.empty())
            why = global.empty() ? "unknown error" : global;
        return fail(ErrorCode::InvalidInput, path + ": not a readable " + format + " image: " + why);
    }
    // OpenImageIO keeps messages (of formats tried before the one that opened it, of warnings while decoding) until
    // they are read: read them on every path, or they leak.
    (void)OIIO::geterror();
    struct Drain {
        OIIO::ImageInput& input;
        ~Drain() { (void)input.geterror(); }
    } drain{*input};
    const OIIO::ImageSpec spec = input->spec();
    if (spec.width < limits.minSide || spec.height < limits.minSide || spec.width > limits.maxSide ||
        spec.height > limits.maxSide || spec.depth > 1)
        return fail(ErrorCode::LimitExceeded, path + ": image of " + std::to_string(spec.width) + " x " +
                                                  std::to_string(spec.height) + " pixels; each side must be " +
                                                  sideRange(limits));
    if (spec.nchannels < 1 || spec.nchannels > 4)
        return fail(ErrorCode::InvalidInput, path + ": " + std::to_string(spec.nchannels) +
                                                 " channels; expected 1 to 4 (grey, grey and alpha, RGB, RGBA)");
    if (const std::string profile = foreignProfile(spec); !profile.empty())
        return fail(ErrorCode::Unsupported, path + ": colour profile " + profile +
                                                " is not sRGB; the textures are sRGB and nothing here converts: "
                                                "save the image in sRGB (or without a profile, read as sRGB)");
    // Grey and alpha, or RGBA: the colour is the channels before the alpha (OpenImageIO names it; otherwise the
    // last of 2 or 4).
    const int channels = spec.nchannels;
    const int alpha =
        spec.alpha_channel >= 0 ? spec.alpha_channel : (channels == 2 || channels == 4 ? channels - 1 : -1);
    const int colours = alpha >= 0 ? channels - 1 : channels;
    if (alpha >= 0 && alpha != channels - 1)
        return fail(ErrorCode::Unsupported, path + ": the alpha channel is channel " + std::to_string(alpha) + " of " +
                                                std::to_string(channels) + "; expected the last");
    const std::size_t count = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
    std::vector<std::uint8_t> pixels(count * static_cast<std::size_t>(channels));
    if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels.data())) {
        return fail(ErrorCode::InvalidInput, path + ": cannot decode the image: " + input->geterror());
    }
    input->close();
    // Transparent pixels have no colour of their own (often black or white): as texture they would be drawn, so an
    // image with any is refused rather than read; an opaque alpha is dropped.
    if (alpha >= 0) {
        std::size_t transparent = 0, first = count;
        for (std::size_t i = 0; i < count; ++i)
            if (pixels[i * static_cast<std::size_t>(channels) + static_cast<std::size_t>(alpha)] < 255) {
                ++transparent;
                first = std::min(first, i);
            }
        if (transparent > 0)
            return fail(ErrorCode::InvalidInput,
                        path + ": " + std::to_string(transparent) + " of " + std::to_string(count) +
                            " pixels are transparent (alpha below 1; the first at x " +
                            std::to_string(first % static_cast<std::size_t>(spec.width)) + ", y " +
                            std::to_string(first / static_cast<std::size_t>(spec.width)) +
                            "): crop to the opaque part or flatten the image onto the tissue's colour");
    }
    auto image = ImageU8::create(spec.width, spec.height, 3);
    if (!image.ok())
        return fail(image.error().code, path + ": " + image.error().detail);
    auto& out = image->data();
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t c = 0; c < 3; ++c)
            out[i * 3 + c] =
                pixels[i * static_cast<std::size_t>(channels) + std::min(c, static_cast<std::size_t>(colours - 1))];
    return image;
}

Status writeImage(const ImageU8& image, const std::string& path) {
    if (image.empty())
        return fail(ErrorCode::InvalidInput, path + ": refusing to write an empty image");
    const std::string ext = lowerExtension(path);
    const std::string format = outputFormatFor(ext);
    if (format.empty())
        return fail(ErrorCode::Unsupported, path + ": unknown image extension '" + ext + "' (use .png .jpg .exr .tif)");
    if (format == "jpeg" && image.channels() == 4)
        return fail(ErrorCode::Unsupported, path + ": JPEG has no alpha channel");
    return io::writeAtomically(path, [&](const std::string& tmpPath) -> Status {
        auto output = OIIO::ImageOutput::create(format);
        if (!output)
            return fail(ErrorCode::BackendFailure, path + ": no " + format + " writer: " + OIIO::geterror());
        OIIO::ImageSpec spec(image.width(), image.height(), image.channels(),
                             format == "openexr" ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::UINT8);
        if (format == "jpeg")
            spec.attribute("Compression", "jpeg:95");
        if (format == "png")
            spec.attribute("png:compressionLevel", 6);
        if (!output->open(tmpPath, spec))
            return fail(ErrorCode::IoError, path + ": cannot write: " + output->geterror());
        if (!output->write_image(OIIO::TypeDesc::UINT8, image.data().data())) {
            const std::string why = output->geterror();
            output->close();
            return fail(ErrorCode::IoError, path + ": cannot write: " + why);
        }
        if (!output->close())
            return fail(ErrorCode::IoError, path + ": cannot finish: " + output->geterror());
        return {};
    });
}

} // namespace hs::texture
