// bench_texture: timings and quality measures of hs::texture, printed as a table (docs/texture.md quotes it).
//   bench_texture                      synthesis 1024^2 from 256^2, histogram bars, bake of a ~30k-vertex surface
//   bench_texture --docs DIR [ORGAN]   also writes the side-by-side images and a baked demo organ (ORGAN: a surface
//                                      file, subdivided twice and given a myoma and a polyp bump) for render_texture
#include "TextureTestMeshes.h"

#include "hs/core/Rng.h"
#include "hs/io/MeshIO.h"
#include "hs/texture/Bake.h"
#include "hs/texture/Exemplars.h"
#include "hs/texture/ImageFiles.h"
#include "hs/texture/Quality.h"
#include "hs/texture/Synthesis.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

using namespace hs;
using namespace hs::texture;

namespace {

double seconds(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

ImageU8 crop(const ImageU8& img, int x0, int y0, int side) {
    ImageU8 out = ImageU8::create(side, side, 3).value();
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            for (int c = 0; c < 3; ++c)
                out.at(x, y, c) = img.at(x0 + x, y0 + y, c);
    return out;
}

/// Box-downsamples by an integer factor.
ImageU8 shrink(const ImageU8& img, int factor) {
    ImageU8 out = ImageU8::create(img.width() / factor, img.height() / factor, 3).value();
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                int s = 0;
                for (int dy = 0; dy < factor; ++dy)
                    for (int dx = 0; dx < factor; ++dx)
                        s += img.at(x * factor + dx, y * factor + dy, c);
                out.at(x, y, c) = static_cast<std::uint8_t>(s / (factor * factor));
            }
    return out;
}

/// Exemplar (left) next to a synthesized texture of the same pixel size (right; pass it shrunk to show more).
ImageU8 sideBySide(const ImageU8& exemplar, const ImageU8& synth) {
    const int s = synth.width(), gap = 6;
    ImageU8 out = ImageU8::create(2 * s + gap, s, 3, 255).value();
    for (int y = 0; y < s; ++y)
        for (int x = 0; x < s; ++x)
            for (int c = 0; c < 3; ++c) {
                out.at(x, y, c) = exemplar.at(x * exemplar.width() / s, y * exemplar.height() / s, c);
                out.at(s + gap + x, y, c) = synth.at(x, y, c);
            }
    return out;
}

void synthesisTable(const std::string& docsDir) {
    std::printf("\n## Synthesis (1024^2 from the 256^2 default exemplars)\n");
    std::printf("| exemplar | threads | levels | time s | histogram | crop baseline | ratio | Gram | nearest patch | "
                "tile seam |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for (Appearance a : kAppearances) {
        const ImageU8 exemplar = makeExemplar(a, 512, 1).value();
        const ImageU8 ex256 = crop(exemplar, 61, 97, 256); // a crop: not tileable, like a photograph
        for (int threads : {1, 2}) {
            SynthesisParams p;
            p.width = p.height = 1024;
            p.threads = threads;
            const auto t0 = std::chrono::steady_clock::now();
            const auto out = synthesizeTexture(ex256, p);
            const double t = seconds(t0);
            if (!out.ok()) {
                std::printf("failed: %s\n", out.error().message().c_str());
                return;
            }
            const auto q = measureSynthesis(ex256, out->image).value();
            std::printf("| %s 256^2 | %d | %d | %.2f | %.4f | %.4f | %.2f | %.3f | %.1f | %.2f (exemplar %.2f) |\n",
                        appearanceName(a).c_str(), threads, out->levels, t, q.histogram, q.cropHistogram,
                        q.histogramRatio, q.gram, q.nearestPatch, q.tileSeam, q.exemplarTileSeam);
            if (!docsDir.empty() && threads == 2) {
                // Right: 512 x 512 of the output at half scale, so it shows four exemplars' worth of area.
                const ImageU8 piece = crop(out->image, 0, 0, 512);
                (void)writeImage(sideBySide(ex256, shrink(piece, 2)),
                                 docsDir + "/texture-synth-" + appearanceName(a) + ".png");
            }
        }
    }
    std::printf("\n## Histogram bar (128^2 exemplar crops, 512^2 output; bar: ratio <= 1.2)\n");
    std::printf(
        "| exemplar | seed | histogram | crop baseline | ratio | Gram | tile seam |\n|---|---|---|---|---|---|---|\n");
    for (Appearance a : kAppearances)
        for (std::uint64_t seed : {1u, 2u, 3u}) {
            const ImageU8 ex128 = crop(makeExemplar(a, 256, seed).value(), 37, 53, 128);
            SynthesisParams p;
            p.width = p.height = 512;
            p.seed = seed;
            const auto out = synthesizeTexture(ex128, p).value();
            const auto q = measureSynthesis(ex128, out.image, seed).value();
            std::printf("| %s | %llu | %.4f | %.4f | %.2f | %.3f | %.2f |\n", appearanceName(a).c_str(),
                        static_cast<unsigned long long>(seed), q.histogram, q.cropHistogram, q.histogramRatio, q.gram,
                        q.tileSeam);
        }
}

void bakeRow(const char* name, const SurfaceMesh& surface, int size, const std::string& outDir) {
    BakeParams p;
    p.size = size;
    p.labels.myomaValues = {1};
    p.labels.polypValues = {2};
    const auto t0 = std::chrono::steady_clock::now();
    const auto bake = bakeAppearance(surface, p);
    const double t = seconds(t0);
    if (!bake.ok()) {
        std::printf("failed: %s\n", bake.error().message().c_str());
        return;
    }
    const auto& s = bake->stats;
    std::printf("| %s | %zu | %d^2 | %.2f | %d | %.3f | %.2f | %.1f | %.2f | %lld | %.3f |\n", name,
                surface.points.size(), size, t, s.atlas.charts, s.atlas.l2Stretch, s.atlas.maxStretch,
                s.atlas.texelsPerMm, s.atlas.fill, static_cast<long long>(s.vesselSegments), s.chartSeamRatio);
    std::printf("|   steps: ");
    for (const auto& step : bake->timings.steps)
        std::printf("%s %.2f s; ", step.name.c_str(), step.seconds);
    std::printf("| | | | | | | | | | |\n");
    if (!outDir.empty()) {
        const auto written = writeBakeOutputs(surface, *bake, outDir);
        if (!written.ok())
            std::printf("failed: %s\n", written.error().message().c_str());
    }
}

} // namespace

int main(int argc, char** argv) {
    std::string docsDir, organPath;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--docs" && i + 1 < argc)
            docsDir = argv[++i];
        else
            organPath = arg;
    }
    std::printf("# bench_texture\n");
    synthesisTable(docsDir);

    std::printf("\n## Bake (albedo, normal, roughness; labelled geodesic organ with a myoma and a polyp bump)\n");
    std::printf("| surface | vertices | size | time s | charts | L2 stretch | max stretch | texels/mm | fill | vessel "
                "segments | chart seam ratio |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
    bakeRow("geodesic f=55", test::makeLabelledOrgan(55), 2048, "");
    if (!docsDir.empty() && !organPath.empty()) {
        auto organ = io::readSurface(organPath);
        if (!organ.ok()) {
            std::printf("failed: %s\n", organ.error().message().c_str());
            return 1;
        }
        SurfaceMesh demo = test::subdivideMidpoint(test::subdivideMidpoint(*organ));
        test::addPathologyBumps(demo, Vec3(0.2, 1, 0.6), 9.0, 5.0, Vec3(-0.6, 0.8, 0.4), 3.5, 6.0);
        bakeRow("demo organ", demo, 2048, docsDir + "/bake");
    }
    return 0;
}
