#include "hs/texture/Synthesis.h"

#include "hs/core/Parallel.h"
#include "hs/core/Rng.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace hs::texture {
namespace {

constexpr int kRadius = 2; // 5x5 neighbourhoods
constexpr int kSide = 2 * kRadius + 1;
constexpr int kTaps = kSide * kSide;
constexpr int kMaxLevels = 5;
constexpr int kMinCoarseExemplar = 32;

struct Coord {
    std::int16_t x = 0, y = 0;
};

/// One level of the exemplar pyramid: RGB as floats 0..255.
struct ExemplarLevel {
    int w = 0, h = 0;
    std::vector<float> rgb;
    const float* at(int x, int y) const { return &rgb[(static_cast<std::size_t>(y) * w + x) * 3]; }
};

/// One level of the output: a map of exemplar coordinates, wrapping around.
struct CoordMap {
    int w = 0, h = 0;
    std::vector<Coord> c;
    Coord& at(int x, int y) { return c[static_cast<std::size_t>(y) * w + x]; }
    const Coord& at(int x, int y) const { return c[static_cast<std::size_t>(y) * w + x]; }
    const Coord& wrapped(int x, int y) const {
        x = x < 0 ? x + w : (x >= w ? x - w : x);
        y = y < 0 ? y + h : (y >= h ? y - h : y);
        return at(x, y);
    }
};

Status checkParams(const ImageU8& exemplar, const SynthesisParams& p) {
    using P = SynthesisParams;
    const auto range = [](int lo, int hi) { return std::to_string(lo) + ".." + std::to_string(hi); };
    if (exemplar.empty())
        return fail(ErrorCode::InvalidInput, "exemplar: empty image");
    if (exemplar.width() < P::kMinExemplarSide || exemplar.height() < P::kMinExemplarSide ||
        exemplar.width() > P::kMaxExemplarSide || exemplar.height() > P::kMaxExemplarSide)
        return fail(ErrorCode::InvalidInput, "exemplar of " + std::to_string(exemplar.width()) + " x " +
                                                 std::to_string(exemplar.height()) + " pixels; each side must be " +
                                                 range(P::kMinExemplarSide, P::kMaxExemplarSide));
    if (p.width < P::kMinOutputSide || p.height < P::kMinOutputSide || p.width > P::kMaxOutputSide ||
        p.height > P::kMaxOutputSide)
        return fail(ErrorCode::LimitExceeded, "output size " + std::to_string(p.width) + " x " +
                                                  std::to_string(p.height) + " outside " +
                                                  range(P::kMinOutputSide, P::kMaxOutputSide) + " pixels per side");
    if (p.correctionPasses < 1 || p.correctionPasses > 8)
        return fail(ErrorCode::InvalidInput,
                    "correctionPasses " + std::to_string(p.correctionPasses) + " outside 1..8");
    if (!(p.jitter >= 0.0 && p.jitter <= 4.0))
        return fail(ErrorCode::InvalidInput, "jitter " + std::to_string(p.jitter) + " outside 0..4");
    if (p.randomCandidates < 0 || p.randomCandidates > 8)
        return fail(ErrorCode::InvalidInput,
                    "randomCandidates " + std::to_string(p.randomCandidates) + " outside 0..8");
    if (p.coarseBlock < 2 || p.coarseBlock > 64)
        return fail(ErrorCode::InvalidInput, "coarseBlock " + std::to_string(p.coarseBlock) + " outside 2..64");
    return {};
}

std::vector<ExemplarLevel> buildPyramid(const ImageU8& exemplar, int levels) {
    std::vector<ExemplarLevel> pyramid(static_cast<std::size_t>(levels));
    ExemplarLevel& finest = pyramid.back();
    finest.w = exemplar.width();
    finest.h = exemplar.height();
    finest.rgb.resize(static_cast<std::size_t>(finest.w) * finest.h * 3);
    const int ch = exemplar.channels();
    for (int y = 0; y < finest.h; ++y)
        for (int x = 0; x < finest.w; ++x)
            for (int c = 0; c < 3; ++c)
                finest.rgb[(static_cast<std::size_t>(y) * finest.w + x) * 3 + c] = exemplar.at(x, y, ch >= 3 ? c : 0);
    for (int l = levels - 2; l >= 0; --l) {
        const ExemplarLevel& fine = pyramid[static_cast<std::size_t>(l + 1)];
        ExemplarLevel& coarse = pyramid[static_cast<std::size_t>(l)];
        coarse.w = fine.w / 2;
        coarse.h = fine.h / 2;
        coarse.rgb.resize(static_cast<std::size_t>(coarse.w) * coarse.h * 3);
        for (int y = 0; y < coarse.h; ++y)
            for (int x = 0; x < coarse.w; ++x)
                for (int c = 0; c < 3; ++c)
                    coarse.rgb[(static_cast<std::size_t>(y) * coarse.w + x) * 3 + c] =
                        0.25f * (fine.at(2 * x, 2 * y)[c] + fine.at(2 * x + 1, 2 * y)[c] +
                                 fine.at(2 * x, 2 * y + 1)[c] + fine.at(2 * x + 1, 2 * y + 1)[c]);
    }
    return pyramid;
}

int levelCount(const ImageU8& exemplar, const SynthesisParams& p) {
    int levels = 1;
    int side = std::min(exemplar.width(), exemplar.height());
    int out = std::min(p.width, p.height);
    while (levels < kMaxLevels && side / 2 >= kMinCoarseExemplar && out / 2 >= SynthesisParams::kMinOutputSide) {
        side /= 2;
        out /= 2;
        ++levels;
    }
    return levels;
}

/// Seed of the random numbers of one row in one step, independent of the threads.
Rng rowRng(std::uint64_t seed, int level, int step, int row) {
    const std::uint64_t index = (static_cast<std::uint64_t>(level) * 64u + static_cast<std::uint64_t>(step)) * 65536u +
                                static_cast<std::uint64_t>(row);
    return Rng(seed).derive(index);
}

std::int16_t clampTo(int v, int lo, int hi) {
    return static_cast<std::int16_t>(std::clamp(v, lo, hi));
}

/// Coarsest level: random exemplar blocks, a quilt that the corrections then stitch.
void initCoarsest(CoordMap& map, const ExemplarLevel& ex, const SynthesisParams& p) {
    const int lo = kRadius, hiX = ex.w - 1 - kRadius, hiY = ex.h - 1 - kRadius;
    const int block = std::min({p.coarseBlock, hiX - lo + 1, hiY - lo + 1});
    // The block grid starts at a random offset, so the wrap-around border is no more a block border than any other
    // line of the output.
    Rng offsetRng = rowRng(p.seed, 0, 61, 0);
    const int shiftX = static_cast<int>(offsetRng.below(static_cast<std::uint64_t>(block)));
    const int shiftY = static_cast<int>(offsetRng.below(static_cast<std::uint64_t>(block)));
    const int bw = (map.w + shiftX + block - 1) / block, bh = (map.h + shiftY + block - 1) / block;
    for (int by = 0; by < bh; ++by) {
        Rng rng = rowRng(p.seed, 0, 63, by);
        for (int bx = 0; bx < bw; ++bx) {
            const int ox = lo + static_cast<int>(rng.below(static_cast<std::uint64_t>(hiX - lo + 2 - block)));
            const int oy = lo + static_cast<int>(rng.below(static_cast<std::uint64_t>(hiY - lo + 2 - block)));
            for (int y = std::max(0, by * block - shiftY); y < std::min(map.h, (by + 1) * block - shiftY); ++y)
                for (int x = std::max(0, bx * block - shiftX); x < std::min(map.w, (bx + 1) * block - shiftX); ++x)
                    map.at(x, y) = {clampTo(ox + x + shiftX - bx * block, lo, hiX),
                                    clampTo(oy + y + shiftY - by * block, lo, hiY)};
        }
    }
}

/// Upsamples the coarser map (children inherit 2 * parent + their offset) and jitters it.
CoordMap upsample(const CoordMap& coarse, int w, int h, const ExemplarLevel& ex, int level, const SynthesisParams& p,
                  int threads) {
    CoordMap fine;
    fine.w = w;
    fine.h = h;
    fine.c.resize(static_cast<std::size_t>(w) * h);
    const int lo = kRadius, hiX = ex.w - 1 - kRadius, hiY = ex.h - 1 - kRadius;
    const bool jitter = p.jitter > 0.0 && level < kMaxLevels; // every level; corrections restore coherence
    parallelChunks(static_cast<std::size_t>(h), evenChunk(static_cast<std::size_t>(h), threads), threads,
                   [&](std::size_t, std::size_t y0Chunk, std::size_t y1Chunk) {
                       const int y0 = static_cast<int>(y0Chunk), y1 = static_cast<int>(y1Chunk);
                       for (int y = y0; y < y1; ++y) {
                           Rng rng = rowRng(p.seed, level, 62, y);
                           for (int x = 0; x < w; ++x) {
                               const Coord& parent =
                                   coarse.at(std::min(x / 2, coarse.w - 1), std::min(y / 2, coarse.h - 1));
                               int cx = 2 * parent.x + (x & 1), cy = 2 * parent.y + (y & 1);
                               if (jitter) {
                                   cx += static_cast<int>(std::lround(p.jitter * rng.uniform(-1.0, 1.0)));
                                   cy += static_cast<int>(std::lround(p.jitter * rng.uniform(-1.0, 1.0)));
                               }
                               fine.at(x, y) = {clampTo(cx, lo, hiX), clampTo(cy, lo, hiY)};
                           }
                       }
                   });
    return fine;
}

struct Weights {
    std::array<float, kTaps> w{};
    Weights() {
        for (int dy = -kRadius; dy <= kRadius; ++dy)
            for (int dx = -kRadius; dx <= kRadius; ++dx)
                w[static_cast<std::size_t>((dy + kRadius) * kSide + dx + kRadius)] =
                    static_cast<float>(std::exp(-(dx * dx + dy * dy) / 8.0));
    }
};

/// Weighted squared distance between the output neighbourhood and the exemplar neighbourhood at (cx, cy), stopping
/// once it exceeds `bound`.
float neighbourhoodCost(const ExemplarLevel& ex, int cx, int cy, const float* out, const Weights& weights,
                        float bound) {
    float sum = 0.0f;
    for (int dy = -kRadius; dy <= kRadius; ++dy) {
        const float* row = ex.at(cx - kRadius, cy + dy);
        const int base = (dy + kRadius) * kSide;
        for (int k = 0; k < kSide; ++k) {
            const float* o = out + (base + k) * 3;
            const float* e = row + k * 3;
            const float d0 = e[0] - o[0], d1 = e[1] - o[1], d2 = e[2] - o[2];
            sum += weights.w[static_cast<std::size_t>(base + k)] * (d0 * d0 + d1 * d1 + d2 * d2);
        }
        if (sum >= bound)
            return sum;
    }
    return sum;
}

/// The best candidate for pixel (x, y) given the current map.
Coord correctPixel(const CoordMap& cur, const ExemplarLevel& ex, int x, int y, Rng& rng, int randomCandidates,
                   const Weights& weights) {
    std::array<float, kTaps * 3> out;
    for (int dy = -kRadius; dy <= kRadius; ++dy)
        for (int dx = -kRadius; dx <= kRadius; ++dx) {
            const Coord& q = cur.wrapped(x + dx, y + dy);
            const float* e = ex.at(q.x, q.y);
            float* o = &out[static_cast<std::size_t>(((dy + kRadius) * kSide + dx + kRadius) * 3)];
            o[0] = e[0];
            o[1] = e[1];
            o[2] = e[2];
        }
    const int lo = kRadius, hiX = ex.w - 1 - kRadius, hiY = ex.h - 1 - kRadius;
    std::array<Coord, 9 + 8> candidates;
    int count = 0;
    const auto add = [&](int cx, int cy) {
        const Coord c{clampTo(cx, lo, hiX), clampTo(cy, lo, hiY)};
        for (int i = 0; i < count; ++i)
            if (candidates[static_cast<std::size_t>(i)].x == c.x && candidates[static_cast<std::size_t>(i)].y == c.y)
                return;
        candidates[static_cast<std::size_t>(count++)] = c;
    };
    add(cur.at(x, y).x, cur.at(x, y).y); // the current coordinate first: ties keep it
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            if (dx != 0 || dy != 0) {
                const Coord& q = cur.wrapped(x + dx, y + dy);
                add(q.x - dx, q.y - dy);
            }
    for (int r = 0; r < randomCandidates; ++r) {
        const int rx = lo + static_cast<int>(rng.below(static_cast<std::uint64_t>(hiX - lo + 1)));
        const int ry = lo + static_cast<int>(rng.below(static_cast<std::uint64_t>(hiY - lo + 1)));
        add(rx, ry);
    }
    Coord best = candidates[0];
    float bestCost = neighbourhoodCost(ex, best.x, best.y, out.data(), weights, 3.4e38f);
    for (int i = 1; i < count; ++i) {
        const Coord& c = candidates[static_cast<std::size_t>(i)];
        const float cost = neighbourhoodCost(ex, c.x, c.y, out.data(), weights, bestCost);
        if (cost < bestCost) {
            bestCost = cost;
            best = c;
        }
    }
    return best;
}

/// One correction pass in four interleaved sub-passes; each reads only the state before it, so the result is the
/// same for any split of the rows over threads.
void correct(CoordMap& map, const ExemplarLevel& ex, int level, int pass, const SynthesisParams& p, int threads,
             const Weights& weights) {
    static constexpr std::array<std::array<int, 2>, 4> kOrder{{{0, 0}, {1, 1}, {1, 0}, {0, 1}}};
    for (int sub = 0; sub < 4; ++sub) {
        const int ox = kOrder[static_cast<std::size_t>(sub)][0], oy = kOrder[static_cast<std::size_t>(sub)][1];
        CoordMap next = map;
        const int rows = (map.h - oy + 1) / 2;
        parallelChunks(static_cast<std::size_t>(rows), evenChunk(static_cast<std::size_t>(rows), threads), threads,
                       [&](std::size_t, std::size_t r0Chunk, std::size_t r1Chunk) {
                           const int r0 = static_cast<int>(r0Chunk), r1 = static_cast<int>(r1Chunk);
                           for (int r = r0; r < r1; ++r) {
                               const int y = 2 * r + oy;
                               Rng rng = rowRng(p.seed, level, pass * 4 + sub, y);
                               for (int x = ox; x < map.w; x += 2)
                                   next.at(x, y) = correctPixel(map, ex, x, y, rng, p.randomCandidates, weights);
                           }
                       });
        map = std::move(next);
    }
}

} // namespace

Result<SynthesisResult> synthesizeTexture(const ImageU8& exemplar, const SynthesisParams& params, Progress& progress) {
    HS_TRY(checkParams(exemplar, params));
    SynthesisResult result;
    result.levels = levelCount(exemplar, params);
    const int threads = resolveThreads(params.threads);
    const std::vector<ExemplarLevel> pyramid = buildPyramid(exemplar, result.levels);
    const Weights weights;

    std::vector<std::array<int, 2>> sizes(static_cast<std::size_t>(result.levels));
    sizes.back() = {params.width, params.height};
    for (int l = result.levels - 2; l >= 0; --l) {
        const auto& f = sizes[static_cast<std::size_t>(l + 1)];
        sizes[static_cast<std::size_t>(l)] = {(f[0] + 1) / 2, (f[1] + 1) / 2};
    }

    CoordMap map;
    for (int l = 0; l < result.levels; ++l) {
        ScopedStepTimer timer(result.timings, "level " + std::to_string(l));
        const ExemplarLevel& ex = pyramid[static_cast<std::size_t>(l)];
        const auto size = sizes[static_cast<std::size_t>(l)];
        if (l == 0) {
            map.w = size[0];
            map.h = size[1];
            map.c.resize(static_cast<std::size_t>(map.w) * map.h);
            initCoarsest(map, ex, params);
        } else {
            map = upsample(map, size[0], size[1], ex, l, params, threads);
        }
        const int passes = params.correctionPasses + (l == 0 ? 2 : 0);
        for (int pass = 0; pass < passes; ++pass) {
            HS_TRY(progress.check("texture synthesis"));
            correct(map, ex, l, pass, params, threads, weights);
            progress.report("texture.synthesis", (l + (pass + 1.0) / passes) / result.levels);
        }
        result.timings.step("level " + std::to_string(l)).counts = {{"pixels", static_cast<std::int64_t>(map.c.size())},
                                                                    {"passes", passes}};
    }

    auto image = ImageU8::create(params.width, params.height, 3);
    if (!image.ok())
        return image.failure();
    result.image = std::move(image.value());
    const int ch = exemplar.channels();
    for (int y = 0; y < params.height; ++y)
        for (int x = 0; x < params.width; ++x) {
            const Coord& c = map.at(x, y);
            for (int k = 0; k < 3; ++k)
                result.image.at(x, y, k) = exemplar.at(c.x, c.y, ch >= 3 ? k : 0);
        }
    return result;
}

} // namespace hs::texture
