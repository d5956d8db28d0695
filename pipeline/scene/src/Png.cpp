// PNG (ISO/IEC 15948) encoding and decoding of the 8-bit subset the package writes.

#include "Png.h"

#include <zlib.h>

#include <array>
#include <cstdint>
#include <cstdlib>

namespace hs::scene::detail {

namespace {

constexpr std::string_view kSignature{"\x89PNG\r\n\x1a\n", 8};

void putU32(std::string& out, std::uint32_t v) {
    out += static_cast<char>((v >> 24) & 0xff);
    out += static_cast<char>((v >> 16) & 0xff);
    out += static_cast<char>((v >> 8) & 0xff);
    out += static_cast<char>(v & 0xff);
}

std::uint32_t getU32(std::string_view s, std::size_t at) {
    return (std::uint32_t{static_cast<std::uint8_t>(s[at])} << 24) |
           (std::uint32_t{static_cast<std::uint8_t>(s[at + 1])} << 16) |
           (std::uint32_t{static_cast<std::uint8_t>(s[at + 2])} << 8) |
           std::uint32_t{static_cast<std::uint8_t>(s[at + 3])};
}

std::uint32_t crcOf(std::string_view typeAndData) {
    return static_cast<std::uint32_t>(
        crc32(0L, reinterpret_cast<const Bytef*>(typeAndData.data()), static_cast<uInt>(typeAndData.size())));
}

void putChunk(std::string& out, const char* type, std::string_view data) {
    putU32(out, static_cast<std::uint32_t>(data.size()));
    std::string body(type, 4);
    body.append(data.data(), data.size());
    out += body;
    putU32(out, crcOf(body));
}

int colourType(int channels) {
    switch (channels) {
    case 1:
        return 0;
    case 3:
        return 2;
    case 4:
        return 6;
    default:
        return -1;
    }
}

int paeth(int a, int b, int c) {
    const int p = a + b - c;
    const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    if (pa <= pb && pa <= pc)
        return a;
    return pb <= pc ? b : c;
}

/// Reverses the row filters in place; `raw` holds (1 + stride) bytes per row.
Status unfilter(std::string& raw, std::size_t stride, std::size_t rows, std::size_t bpp, const std::string& name,
                std::vector<std::uint8_t>& out) {
    out.assign(stride * rows, 0);
    for (std::size_t y = 0; y < rows; ++y) {
        const auto filter = static_cast<std::uint8_t>(raw[y * (stride + 1)]);
        const auto* in = reinterpret_cast<const std::uint8_t*>(raw.data()) + y * (stride + 1) + 1;
        std::uint8_t* row = out.data() + y * stride;
        const std::uint8_t* up = y > 0 ? row - stride : nullptr;
        for (std::size_t x = 0; x < stride; ++x) {
            const int a = x >= bpp ? row[x - bpp] : 0;
            const int b = up ? up[x] : 0;
            const int c = (up && x >= bpp) ? up[x - bpp] : 0;
            int predicted = 0;
            switch (filter) {
            case 0:
                break;
            case 1:
                predicted = a;
                break;
            case 2:
                predicted = b;
                break;
            case 3:
                predicted = (a + b) / 2;
                break;
            case 4:
                predicted = paeth(a, b, c);
                break;
            default:
                return fail(ErrorCode::InvalidInput,
                            name + ": row " + std::to_string(y) + " has unknown filter " + std::to_string(filter));
            }
            row[x] = static_cast<std::uint8_t>((in[x] + predicted) & 0xff);
        }
    }
    return {};
}

} // namespace

Result<std::string> encodePng(const ImageU8& image) {
    const int type = colourType(image.channels());
    if (image.empty() || type < 0)
        return fail(ErrorCode::InvalidInput, "PNG: need a non-empty image of 1, 3 or 4 channels");
    const auto width = static_cast<std::size_t>(image.width());
    const auto height = static_cast<std::size_t>(image.height());
    const auto bpp = static_cast<std::size_t>(image.channels());
    const std::size_t stride = width * bpp;
    std::string raw(height * (stride + 1), '\0');
    const auto& px = image.data();
    for (std::size_t y = 0; y < height; ++y) {
        raw[y * (stride + 1)] = 1; // Sub
        for (std::size_t x = 0; x < stride; ++x) {
            const int left = x >= bpp ? px[y * stride + x - bpp] : 0;
            raw[y * (stride + 1) + 1 + x] = static_cast<char>((px[y * stride + x] - left) & 0xff);
        }
    }
    // zlib level 6 (its default): level 9 took three times as long on texture maps for a few percent of size.
    uLongf packedSize = compressBound(static_cast<uLong>(raw.size()));
    std::string packed(packedSize, '\0');
    if (compress2(reinterpret_cast<Bytef*>(packed.data()), &packedSize, reinterpret_cast<const Bytef*>(raw.data()),
                  static_cast<uLong>(raw.size()), 6) != Z_OK)
        return fail(ErrorCode::BackendFailure, "PNG: zlib compression failed");
    packed.resize(packedSize);

    std::string out(kSignature);
    std::string header;
    putU32(header, static_cast<std::uint32_t>(width));
    putU32(header, static_cast<std::uint32_t>(height));
    header += static_cast<char>(8); // bit depth
    header += static_cast<char>(type);
    header += std::string(3, '\0'); // deflate, adaptive filtering, no interlace
    putChunk(out, "IHDR", header);
    putChunk(out, "IDAT", packed);
    putChunk(out, "IEND", {});
    return out;
}

Result<ImageU8> decodePng(std::string_view bytes, const std::string& name, int maxSide) {
    if (bytes.substr(0, kSignature.size()) != kSignature)
        return fail(ErrorCode::InvalidInput, name + ": not a PNG file (bad signature)");
    std::size_t at = kSignature.size();
    std::uint32_t width = 0, height = 0;
    int channels = 0;
    std::string packed;
    bool sawEnd = false;
    while (!sawEnd) {
        if (bytes.size() - at < 12)
            return fail(ErrorCode::InvalidInput, name + ": truncated PNG chunk at byte " + std::to_string(at));
        const std::uint32_t length = getU32(bytes, at);
        if (length > bytes.size() - at - 12)
            return fail(ErrorCode::InvalidInput,
                        name + ": PNG chunk at byte " + std::to_string(at) + " runs past the end of the file");
        const std::string_view typeAndData = bytes.substr(at + 4, 4 + std::size_t{length});
        if (crcOf(typeAndData) != getU32(bytes, at + 8 + length))
            return fail(ErrorCode::InvalidInput, name + ": PNG chunk at byte " + std::to_string(at) + " has a bad CRC");
        const std::string_view type = typeAndData.substr(0, 4);
        const std::string_view data = typeAndData.substr(4);
        if (type == "IHDR") {
            if (length != 13)
                return fail(ErrorCode::InvalidInput, name + ": bad PNG header");
            width = getU32(data, 0);
            height = getU32(data, 4);
            const int depth = static_cast<std::uint8_t>(data[8]);
            const int ctype = static_cast<std::uint8_t>(data[9]);
            channels = ctype == 0 ? 1 : ctype == 2 ? 3 : ctype == 6 ? 4 : 0;
            if (depth != 8 || channels == 0 || data[10] != 0 || data[11] != 0 || data[12] != 0)
                return fail(ErrorCode::Unsupported,
                            name + ": only 8-bit grey, RGB or RGBA PNGs without interlacing are read here");
            if (width == 0 || height == 0 || width > static_cast<std::uint32_t>(maxSide) ||
                height > static_cast<std::uint32_t>(maxSide))
                return fail(ErrorCode::LimitExceeded, name + ": image size " + std::to_string(width) + " x " +
                                                          std::to_string(height) + " outside 1.." +
                                                          std::to_string(maxSide));
        } else if (type == "IDAT") {
            if (channels == 0)
                return fail(ErrorCode::InvalidInput, name + ": PNG data before its header");
            packed.append(data.data(), data.size());
        } else if (type == "IEND") {
            sawEnd = true;
        } else if ((static_cast<std::uint8_t>(type[0]) & 0x20) == 0) {
            return fail(ErrorCode::Unsupported, name + ": unknown critical PNG chunk " + std::string(type));
        }
        at += 12 + std::size_t{length};
    }
    if (channels == 0)
        return fail(ErrorCode::InvalidInput, name + ": PNG without a header");
    const std::size_t stride = std::size_t{width} * static_cast<std::size_t>(channels);
    std::string raw((stride + 1) * height, '\0');
    uLongf rawSize = static_cast<uLongf>(raw.size());
    if (uncompress(reinterpret_cast<Bytef*>(raw.data()), &rawSize, reinterpret_cast<const Bytef*>(packed.data()),
                   static_cast<uLong>(packed.size())) != Z_OK ||
        rawSize != raw.size())
        return fail(ErrorCode::InvalidInput, name + ": PNG pixel data is corrupt or has the wrong size");
    auto image = ImageU8::create(static_cast<int>(width), static_cast<int>(height), channels);
    if (!image)
        return image.failure();
    HS_TRY(unfilter(raw, stride, height, static_cast<std::size_t>(channels), name, image->data()));
    return image;
}

} // namespace hs::scene::detail
