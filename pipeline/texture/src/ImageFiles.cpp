#include "hs/texture/ImageFiles.h"

#include "hs/io/AtomicFile.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
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
    if (spec.nchannels < 1 || spec.nchannels > 64)
        return fail(ErrorCode::InvalidInput,
                    path + ": " + std::to_string(spec.nchannels) + " channels; expected 1 to 4 (grey, RGB, RGBA)");
    const int inChannels = std::min(spec.nchannels, 3);
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) *
                                     static_cast<std::size_t>(inChannels));
    if (!input->read_image(0, 0, 0, inChannels, OIIO::TypeDesc::UINT8, pixels.data())) {
        return fail(ErrorCode::InvalidInput, path + ": cannot decode the image: " + input->geterror());
    }
    input->close();
    auto image = ImageU8::create(spec.width, spec.height, 3);
    if (!image.ok())
        return fail(image.error().code, path + ": " + image.error().detail);
    auto& out = image->data();
    const std::size_t count = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t c = 0; c < 3; ++c)
            out[i * 3 + c] = pixels[i * static_cast<std::size_t>(inChannels) +
                                    std::min(c, static_cast<std::size_t>(inChannels - 1))];
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
