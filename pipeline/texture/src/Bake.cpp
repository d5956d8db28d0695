#include "hs/texture/Bake.h"

#include "BakeSteps.h"

#include "hs/core/Parallel.h"
#include "hs/core/Rng.h"
#include "hs/core/Streams.h"
#include "hs/texture/ImageFiles.h"
#include "hs/texture/Synthesis.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace hs::texture {
namespace {
using namespace detail;

Status checkParams(const BakeParams& p) {
    if (p.size < 64 || p.size > 8192)
        return fail(ErrorCode::LimitExceeded, "bake size " + std::to_string(p.size) + " outside 64..8192 texels");
    if (p.baseTextureSize < 64 || p.baseTextureSize > 4096)
        return fail(ErrorCode::LimitExceeded,
                    "baseTextureSize " + std::to_string(p.baseTextureSize) + " outside 64..4096 pixels");
    if (!(p.tileMm > 0.1 && p.tileMm < 1000.0))
        return fail(ErrorCode::InvalidInput, "tileMm " + std::to_string(p.tileMm) + " outside 0.1..1000 mm");
    if (!(p.blendMm >= 0.0 && p.blendMm <= 50.0))
        return fail(ErrorCode::InvalidInput, "blendMm " + std::to_string(p.blendMm) + " outside 0..50 mm");
    if (!(p.bumpMm >= 0.0 && p.bumpMm <= 5.0))
        return fail(ErrorCode::InvalidInput, "bumpMm " + std::to_string(p.bumpMm) + " outside 0..5 mm");
    if (p.canal) {
        const CanalFrame& c = *p.canal;
        const double length = distance(c.externalOsMm, c.internalOsMm);
        const Vec3 axis = (c.internalOsMm - c.externalOsMm) / std::max(length, 1e-12);
        const double across = norm(c.anterior - axis * dot(c.anterior, axis));
        if (!(length >= 1.0 && length <= 200.0))
            return fail(ErrorCode::InvalidInput, "canal: the external and internal os lie " + std::to_string(length) +
                                                     " mm apart, outside 1..200 mm");
        if (!(across > 1e-3 * std::max(1.0, norm(c.anterior))))
            return fail(ErrorCode::InvalidInput, "canal: the anterior direction runs along the canal's axis");
        if (!(c.radiusMm > 0.0 && c.radiusMm <= 50.0))
            return fail(ErrorCode::InvalidInput,
                        "canal: radiusMm " + std::to_string(c.radiusMm) + " outside 0..50 mm (above 0)");
        if (!(c.wallRadiusMm >= 0.0 && c.wallRadiusMm <= c.radiusMm))
            return fail(ErrorCode::InvalidInput, "canal: wallRadiusMm " + std::to_string(c.wallRadiusMm) +
                                                     " outside 0..radiusMm (" + std::to_string(c.radiusMm) + " mm)");
    }
    return {};
}

Result<ImageU8> exemplarFor(const BakeParams& params, Appearance cls) {
    const std::string& file = params.exemplarFiles[static_cast<std::size_t>(cls)];
    if (file.empty())
        return makeExemplar(cls, 256,
                            Rng::deriveSeed(params.seed, streams::kTextureExemplars + static_cast<std::uint64_t>(cls)),
                            params.endometrium);
    auto image = readExemplarFile(file);
    if (!image.ok())
        return fail(image.error().code, appearanceName(cls) + " exemplar: " + image.error().detail);
    return image;
}

} // namespace

Result<ImageU8> readExemplarFile(const std::string& path) {
    ImageReadLimits limits;
    limits.minSide = SynthesisParams::kMinExemplarSide;
    limits.maxSide = SynthesisParams::kMaxExemplarSide;
    return readImageRgb8(path, limits);
}

std::vector<Appearance> classifyFaces(const SurfaceMesh& surface, const AppearanceLabels& labels) {
    std::vector<Appearance> out(surface.triangles.size(), Appearance::Endometrium);
    const auto labelOf = [&](const std::string& name) -> const std::vector<std::int32_t>* {
        const auto it = surface.faceLabels.find(name);
        return it == surface.faceLabels.end() || it->second.size() != surface.triangles.size() ? nullptr : &it->second;
    };
    const auto contains = [](const std::vector<std::int32_t>& list, std::int32_t v) {
        return std::find(list.begin(), list.end(), v) != list.end();
    };
    const std::vector<std::int32_t>* canal = labels.canalValues.empty() ? nullptr : labelOf(labels.canalLabel);
    const std::vector<std::int32_t>* kind = labelOf(labels.appearanceLabel);
    for (std::size_t f = 0; f < out.size(); ++f) {
        if (kind && contains(labels.polypValues, (*kind)[f]))
            out[f] = Appearance::Polyp;
        else if (kind && contains(labels.myomaValues, (*kind)[f]))
            out[f] = Appearance::Myoma;
        else if (canal && contains(labels.canalValues, (*canal)[f]))
            out[f] = Appearance::CervicalCanal;
    }
    return out;
}

Result<BakeResult> bakeAppearance(const SurfaceMesh& surface, const BakeParams& params, Progress& progress) {
    HS_TRY(checkParams(params));
    HS_TRY(validate(surface));
    if (surface.triangles.empty())
        return fail(ErrorCode::InvalidInput, "bake: the surface has no triangles");
    const int threads = resolveThreads(params.threads);
    BakeResult result;
    result.faceAppearance = classifyFaces(surface, params.labels);
    for (Appearance a : result.faceAppearance)
        ++result.stats.facesPerClass[static_cast<std::size_t>(a)];

    {
        ScopedStepTimer timer(result.timings, "atlas");
        AtlasParams ap;
        ap.size = params.size;
        ap.padding = params.padding;
        Progress::Sub sub = progress.sub(0.0, 0.1);
        auto atlas = buildAtlas(surface, ap, sub);
        if (!atlas.ok())
            return atlas.failure();
        result.atlas = std::move(atlas.value());
        result.timings.step("atlas").counts = {{"charts", result.atlas.stats.charts}};
    }
    std::array<Tile, kAppearanceCount> tiles;
    {
        ScopedStepTimer timer(result.timings, "synthesis");
        for (Appearance cls : kAppearances) {
            const auto c = static_cast<std::size_t>(cls);
            if (result.stats.facesPerClass[c] == 0)
                continue;
            auto exemplar = exemplarFor(params, cls);
            if (!exemplar.ok())
                return exemplar.failure();
            SynthesisParams sp;
            sp.width = sp.height = params.baseTextureSize;
            sp.seed = Rng::deriveSeed(params.seed, streams::kTextureSynthesis + c);
            sp.threads = threads;
            Progress::Sub sub = progress.sub(0.1 + 0.1 * static_cast<double>(c), 0.2 + 0.1 * static_cast<double>(c));
            auto synth = synthesizeTexture(*exemplar, sp, sub);
            if (!synth.ok())
                return fail(synth.error().code, appearanceName(cls) + " base texture: " + synth.error().detail);
            result.baseTextures[c] = std::move(synth->image);
            tiles[c] = toTile(result.baseTextures[c]);
        }
    }
    if (params.vessels) {
        ScopedStepTimer timer(result.timings, "vessels");
        VesselParams vp = params.vesselParams;
        vp.seed = Rng::deriveSeed(params.seed, streams::kTextureVessels);
        vp.perClass[static_cast<std::size_t>(Appearance::Endometrium)].attractorsPerMm2 *=
            endometrialSurface(params.endometrium).vesselDensity;
        Progress::Sub sub = progress.sub(0.4, 0.6);
        auto vessels = growVessels(surface, result.faceAppearance, vp, sub);
        if (!vessels.ok())
            return vessels.failure();
        result.vessels = std::move(vessels.value());
        result.stats.vesselSegments = static_cast<std::int64_t>(result.vessels.segments.size());
        result.timings.step("vessels").counts = {{"segments", result.stats.vesselSegments}};
    }
    HS_TRY(progress.check("bake"));

    const double texelMm = 1.0 / std::max(1e-9, result.atlas.stats.texelsPerMm);
    TexelMap map;
    {
        ScopedStepTimer timer(result.timings, "rasterize");
        map = rasterize(surface, result.atlas, threads);
    }
    progress.report("texture.bake", 0.7);
    Shading shading;
    {
        ScopedStepTimer timer(result.timings, "shade");
        const std::vector<Vec3> normals = vertexNormals(surface);
        const std::vector<Weights3> weights =
            vertexWeights(surface, result.faceAppearance, params.labels, params.blendMm);
        const VesselIndex vessels = indexVessels(result.vessels, texelMm);
        shading = shade(surface, map, normals, weights, tiles, vessels, params, texelMm, threads, progress);
    }
    HS_TRY(progress.check("bake"));
    progress.report("texture.bake", 0.85);
    {
        ScopedStepTimer timer(result.timings, "normals");
        result.normal = normalMap(surface, map, shading, result.atlas, texelMm, params.normalStrength, threads);
    }
    HS_TRY(progress.check("bake", "deriving the normal map"));
    result.albedo = std::move(shading.albedo);
    result.roughness = std::move(shading.roughness);
    result.coverage = ImageU8::create(map.size, map.size, 1).value();
    for (std::size_t i = 0; i < map.face.size(); ++i) {
        result.stats.coveredTexels += shading.covered[i];
        result.coverage.data()[i] = map.face[i] < 0 ? 0 : (map.exact[i] ? 255 : 128);
    }
    {
        std::vector<std::int64_t> owned(surface.triangles.size(), 0);
        for (std::size_t i = 0; i < map.face.size(); ++i)
            if (map.face[i] >= 0)
                ++owned[static_cast<std::size_t>(map.face[i])];
        result.stats.facesWithoutTexels = std::count(owned.begin(), owned.end(), 0);
    }
    {
        ScopedStepTimer timer(result.timings, "gutter");
        std::array<std::int64_t, 4> mean{};
        for (std::size_t i = 0; i < map.face.size(); ++i)
            if (shading.covered[i]) {
                for (std::size_t c = 0; c < 3; ++c)
                    mean[c] += result.albedo.data()[i * 3 + c];
                mean[3] += result.roughness.data()[i];
            }
        const std::int64_t cov = std::max<std::int64_t>(1, result.stats.coveredTexels);
        const std::vector<std::array<std::uint8_t, 4>> fallback{{static_cast<std::uint8_t>(mean[0] / cov),
                                                                 static_cast<std::uint8_t>(mean[1] / cov),
                                                                 static_cast<std::uint8_t>(mean[2] / cov), 0},
                                                                {128, 128, 255, 0},
                                                                {static_cast<std::uint8_t>(mean[3] / cov), 0, 0, 0}};
        fillGutters({&result.albedo, &result.normal, &result.roughness}, shading.covered, map.size,
                    result.atlas.stats.padding + 1, fallback);
    }
    HS_TRY(progress.check("bake", "filling the gutters"));
    {
        ScopedStepTimer timer(result.timings, "seams");
        result.stats.chartSeamRatio = chartSeamRatio(surface, result.atlas, result.albedo, map);
        result.stats.normalSeams = normalSeamAngles(makeTexturedSurface(surface, result.atlas), result.normal);
    }
    result.stats.atlas = result.atlas.stats;
    progress.report("texture.bake", 1.0);
    return result;
}

} // namespace hs::texture