#include "hs/texture/Quality.h"

#include "hs/core/Rng.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace hs::texture {
namespace {

constexpr int kBins = 32;

using Histogram = std::array<std::array<double, kBins>, 3>;

int channelOf(const ImageU8& image, int c) {
    return image.channels() >= 3 ? c : 0;
}

Histogram histogram(const ImageU8& image, int x0, int y0, int w, int h) {
    Histogram hist{};
    for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x)
            for (int c = 0; c < 3; ++c)
                hist[static_cast<std::size_t>(c)][image.at(x, y, channelOf(image, c)) * kBins / 256] += 1.0;
    const double n = static_cast<double>(w) * h;
    for (auto& ch : hist)
        for (auto& b : ch)
            b /= n;
    return hist;
}

double hellinger(const Histogram& a, const Histogram& b) {
    double sum = 0.0;
    for (std::size_t c = 0; c < 3; ++c) {
        double bc = 0.0;
        for (std::size_t i = 0; i < kBins; ++i)
            bc += std::sqrt(a[c][i] * b[c][i]);
        sum += std::sqrt(std::max(0.0, 1.0 - bc));
    }
    return sum / 3.0;
}

cv::Mat toMat(const ImageU8& image) {
    cv::Mat mat(image.height(), image.width(), CV_8UC3);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            for (int c = 0; c < 3; ++c)
                mat.at<cv::Vec3b>(y, x)[c] = image.at(x, y, channelOf(image, c));
    return mat;
}

/// Filter responses per pixel: luminance, two opponent chroma channels, and for luminance the x/y Gaussian
/// derivatives and the Laplacian at sigma 1 and 2.
std::vector<cv::Mat> filterBank(const ImageU8& image) {
    cv::Mat rgb;
    toMat(image).convertTo(rgb, CV_32FC3, 1.0 / 255.0);
    std::vector<cv::Mat> ch;
    cv::split(rgb, ch);
    cv::Mat lum = (ch[0] + ch[1] + ch[2]) / 3.0;
    std::vector<cv::Mat> bank{lum, ch[0] - ch[1], 0.5 * (ch[0] + ch[1]) - ch[2]};
    for (double sigma : {1.0, 2.0}) {
        cv::Mat smooth, dx, dy, lap;
        cv::GaussianBlur(lum, smooth, cv::Size(0, 0), sigma, sigma, cv::BORDER_REFLECT);
        cv::Sobel(smooth, dx, CV_32F, 1, 0, 3, sigma, 0, cv::BORDER_REFLECT);
        cv::Sobel(smooth, dy, CV_32F, 0, 1, 3, sigma, 0, cv::BORDER_REFLECT);
        cv::Laplacian(smooth, lap, CV_32F, 1, sigma * sigma, 0, cv::BORDER_REFLECT);
        bank.push_back(dx);
        bank.push_back(dy);
        bank.push_back(lap);
    }
    return bank;
}

cv::Mat gram(const ImageU8& image) {
    const std::vector<cv::Mat> bank = filterBank(image);
    const int n = static_cast<int>(bank.size());
    cv::Mat g(n, n, CV_64F);
    for (int i = 0; i < n; ++i)
        for (int j = i; j < n; ++j) {
            const double v = bank[static_cast<std::size_t>(i)].dot(bank[static_cast<std::size_t>(j)]) /
                             static_cast<double>(image.width() * image.height());
            g.at<double>(i, j) = v;
            g.at<double>(j, i) = v;
        }
    return g;
}

double squaredStep(const ImageU8& image, int x0, int y0, int x1, int y1) {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double d = static_cast<double>(image.at(x0, y0, channelOf(image, c))) -
                         static_cast<double>(image.at(x1, y1, channelOf(image, c)));
        sum += d * d;
    }
    return sum;
}

} // namespace

double histogramDistance(const ImageU8& a, const ImageU8& b) {
    return hellinger(histogram(a, 0, 0, a.width(), a.height()), histogram(b, 0, 0, b.width(), b.height()));
}

double cropHistogramDistance(const ImageU8& exemplar, double cropFraction, int crops, std::uint64_t seed) {
    const Histogram full = histogram(exemplar, 0, 0, exemplar.width(), exemplar.height());
    const int w = std::max(1, static_cast<int>(exemplar.width() * cropFraction));
    const int h = std::max(1, static_cast<int>(exemplar.height() * cropFraction));
    Rng rng(seed);
    double sum = 0.0;
    for (int i = 0; i < crops; ++i) {
        const int x = static_cast<int>(rng.below(static_cast<std::uint64_t>(exemplar.width() - w + 1)));
        const int y = static_cast<int>(rng.below(static_cast<std::uint64_t>(exemplar.height() - h + 1)));
        sum += hellinger(full, histogram(exemplar, x, y, w, h));
    }
    return crops > 0 ? sum / crops : 0.0;
}

double gramDistance(const ImageU8& exemplar, const ImageU8& output) {
    const cv::Mat ga = gram(exemplar), gb = gram(output);
    const double norm = cv::norm(ga);
    return norm > 0.0 ? cv::norm(ga - gb) / norm : 0.0;
}

double nearestPatchDistance(const ImageU8& exemplar, const ImageU8& output, int samples, std::uint64_t seed) {
    constexpr int kPatch = 7;
    if (exemplar.width() < kPatch || exemplar.height() < kPatch || output.width() < kPatch ||
        output.height() < kPatch || samples <= 0)
        return 0.0;
    cv::Mat ex, out;
    toMat(exemplar).convertTo(ex, CV_32FC3);
    toMat(output).convertTo(out, CV_32FC3);
    Rng rng(seed);
    double sum = 0.0;
    for (int i = 0; i < samples; ++i) {
        const int x = static_cast<int>(rng.below(static_cast<std::uint64_t>(output.width() - kPatch + 1)));
        const int y = static_cast<int>(rng.below(static_cast<std::uint64_t>(output.height() - kPatch + 1)));
        cv::Mat response;
        cv::matchTemplate(ex, out(cv::Rect(x, y, kPatch, kPatch)), response, cv::TM_SQDIFF);
        double minVal = 0.0;
        cv::minMaxLoc(response, &minVal);
        sum += std::max(0.0, minVal) / (kPatch * kPatch * 3);
    }
    return std::sqrt(sum / samples);
}

double tileSeamRatio(const ImageU8& image) {
    const int w = image.width(), h = image.height();
    if (w < 2 || h < 2)
        return 0.0;
    double inside = 0.0, border = 0.0;
    std::int64_t insideCount = 0, borderCount = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double sx = squaredStep(image, x, y, (x + 1) % w, y);
            const double sy = squaredStep(image, x, y, x, (y + 1) % h);
            (x == w - 1 ? border : inside) += sx;
            (x == w - 1 ? borderCount : insideCount) += 1;
            (y == h - 1 ? border : inside) += sy;
            (y == h - 1 ? borderCount : insideCount) += 1;
        }
    const double meanInside = inside / static_cast<double>(insideCount);
    const double meanBorder = border / static_cast<double>(borderCount);
    return meanInside > 0.0 ? meanBorder / meanInside : (meanBorder > 0.0 ? 1e9 : 1.0);
}

Result<SynthesisQuality> measureSynthesis(const ImageU8& exemplar, const ImageU8& output, std::uint64_t seed) {
    if (exemplar.empty() || output.empty())
        return fail(ErrorCode::InvalidInput, "quality: empty image");
    SynthesisQuality q;
    q.histogram = histogramDistance(exemplar, output);
    q.cropHistogram = cropHistogramDistance(exemplar, 0.5, 8, seed);
    q.histogramRatio = q.cropHistogram > 0.0 ? q.histogram / q.cropHistogram : (q.histogram > 0.0 ? 1e9 : 0.0);
    q.gram = gramDistance(exemplar, output);
    q.nearestPatch = nearestPatchDistance(exemplar, output, 200, seed);
    q.tileSeam = tileSeamRatio(output);
    q.exemplarTileSeam = tileSeamRatio(exemplar);
    return q;
}

} // namespace hs::texture
