#pragma once
/// A 2-D image with interleaved channels of uint8 or float samples.

#include "hs/core/Result.h"

#include <cstdint>
#include <string>
#include <vector>

namespace hs {

template <class T>
class Image {
public:
    /// Largest image this project allocates: 16384 x 16384 pixels (textures up to 16k).
    static constexpr int kMaxSide = 16384;
    static constexpr int kMaxChannels = 4;

    Image() = default;

    static Result<Image> create(int width, int height, int channels, T fill = T{}) {
        if (width <= 0 || height <= 0 || width > kMaxSide || height > kMaxSide)
            return fail(ErrorCode::LimitExceeded, "image size " + std::to_string(width) + " x " +
                                                      std::to_string(height) + " outside 1.." +
                                                      std::to_string(kMaxSide) + " pixels per side");
        if (channels < 1 || channels > kMaxChannels)
            return fail(ErrorCode::InvalidInput, "image channel count " + std::to_string(channels) + " outside 1..4");
        Image image;
        image.m_width = width;
        image.m_height = height;
        image.m_channels = channels;
        image.m_data.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                                static_cast<std::size_t>(channels),
                            fill);
        return image;
    }

    int width() const { return m_width; }
    int height() const { return m_height; }
    int channels() const { return m_channels; }
    bool empty() const { return m_data.empty(); }

    /// Row-major from the top-left pixel.
    T& at(int x, int y, int c = 0) { return m_data[index(x, y, c)]; }
    const T& at(int x, int y, int c = 0) const { return m_data[index(x, y, c)]; }
    std::vector<T>& data() { return m_data; }
    const std::vector<T>& data() const { return m_data; }

private:
    std::size_t index(int x, int y, int c) const {
        return (static_cast<std::size_t>(y) * static_cast<std::size_t>(m_width) + static_cast<std::size_t>(x)) *
                   static_cast<std::size_t>(m_channels) +
               static_cast<std::size_t>(c);
    }
    int m_width = 0;
    int m_height = 0;
    int m_channels = 0;
    std::vector<T> m_data;
};

using ImageU8 = Image<std::uint8_t>;
using ImageF32 = Image<float>;

} // namespace hs
