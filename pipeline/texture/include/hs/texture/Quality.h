#pragma once
/// Measures of synthesis quality: colour statistics, local statistics and seam visibility.

#include "hs/core/Image.h"
#include "hs/core/Result.h"

#include <cstdint>

namespace hs::texture {

/// Hellinger distance between the per-channel colour histograms (32 bins) of two RGB images, averaged over the
/// channels: 0 for equal distributions, 1 for disjoint ones.
double histogramDistance(const ImageU8& a, const ImageU8& b);

/// The baseline for histogramDistance: the mean distance between `exemplar` and `crops` random crops of it whose
/// sides are `cropFraction` of the exemplar's (seeded).
double cropHistogramDistance(const ImageU8& exemplar, double cropFraction = 0.5, int crops = 8, std::uint64_t seed = 1);

/// Relative Frobenius distance between the Gram matrices of a small filter bank (luminance, two chroma channels,
/// Gaussian derivatives and Laplacians of luminance at two scales): ||G_a - G_b|| / ||G_a||. Texture statistics in the
/// sense of Portilla & Simoncelli / Gatys et al.; 0 for identical statistics.
double gramDistance(const ImageU8& exemplar, const ImageU8& output);

/// Root-mean-square colour distance (0..255) from `samples` seeded 7x7 patches of `output` to their nearest patch
/// in `exemplar`: low when the output is made of exemplar-like pieces.
double nearestPatchDistance(const ImageU8& exemplar, const ImageU8& output, int samples = 200, std::uint64_t seed = 1);

/// Seam visibility of a tiled image: the mean squared colour step across the wrap-around borders (last column to
/// first, last row to first) divided by the mean squared step between neighbouring pixels inside. About 1 when the
/// image tiles seamlessly; far above 1 when the tile border shows.
double tileSeamRatio(const ImageU8& image);

struct SynthesisQuality {
    double histogram = 0.0;        ///< histogramDistance(exemplar, output)
    double cropHistogram = 0.0;    ///< cropHistogramDistance(exemplar): what a piece of the exemplar itself scores
    double histogramRatio = 0.0;   ///< histogram / cropHistogram (bar: <= 1.2)
    double gram = 0.0;             ///< gramDistance
    double nearestPatch = 0.0;     ///< nearestPatchDistance, 0..255
    double tileSeam = 0.0;         ///< tileSeamRatio(output)
    double exemplarTileSeam = 0.0; ///< tileSeamRatio(exemplar), for comparison
};

/// All of the above. InvalidInput for empty images.
Result<SynthesisQuality> measureSynthesis(const ImageU8& exemplar, const ImageU8& output, std::uint64_t seed = 1);

} // namespace hs::texture
