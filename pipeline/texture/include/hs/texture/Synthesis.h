#pragma once
/// Exemplar-based texture synthesis: a larger, tileable texture that looks like the exemplar.
///
/// Method: multi-resolution, coordinate-based synthesis with coherent neighbourhood search (Ashikhmin 2001;
/// Lefebvre & Hoppe, "Parallel controllable texture synthesis", SIGGRAPH 2005). The output is a map of exemplar
/// coordinates, refined from coarse to fine: upsample the coarser map, jitter it, then correct every pixel by the
/// candidate whose 5x5 exemplar neighbourhood best matches the current output neighbourhood (candidates: the
/// coherent continuations of its 3x3 neighbours, plus random ones). The output domain wraps around, so the result
/// tiles seamlessly. Pixels are corrected in four interleaved sub-passes that read only the previous state, so the
/// result does not depend on the number of threads.

#include "hs/core/Image.h"
#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/Timings.h"

#include <cstdint>
#include <vector>

namespace hs::texture {

struct SynthesisParams {
    int width = 1024;         ///< output pixels, kMinOutputSide..kMaxOutputSide
    int height = 1024;        ///< output pixels, kMinOutputSide..kMaxOutputSide
    int correctionPasses = 2; ///< per resolution level, 1..8
    double jitter = 1.0;      ///< exemplar pixels of random displacement after upsampling (0..4); more = more variety
    int randomCandidates = 1; ///< random candidates per pixel and pass besides the coherent ones (0..8)
    int coarseBlock = 8;      ///< pixels of the random blocks that start the coarsest level (2..64)
    std::uint64_t seed = 1;   ///< same seed, same texture
    int threads = 0;          ///< worker threads; 0: all cores. The result does not depend on it.

    static constexpr int kMinOutputSide = 16;
    static constexpr int kMaxOutputSide = 8192;
    static constexpr int kMinExemplarSide = 16;
    static constexpr int kMaxExemplarSide = 4096;
};

struct SynthesisResult {
    ImageU8 image;        ///< RGB, params.width x params.height, tileable
    int levels = 0;       ///< resolution levels used
    StageTimings timings; ///< per level
};

/// Synthesizes a tileable RGB texture from `exemplar` (1, 3 or 4 channels; grey is replicated, alpha ignored).
/// Fails with InvalidInput / LimitExceeded naming the parameter and its allowed range (exemplar sides 16..4096,
/// output sides 16..8192), Cancelled on request.
[[nodiscard]] Result<SynthesisResult> synthesizeTexture(const ImageU8& exemplar, const SynthesisParams& params,
                                                        Progress& progress = Progress::none());

} // namespace hs::texture
