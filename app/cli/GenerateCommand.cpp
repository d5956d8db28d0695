// `generate CASE.json -o SCENE`: the whole pipeline (organ, pathologies, merge, meshing, texture, scene) into a
// scene package, with a progress bar and per-stage timings; --variants N makes N scenes with derived seeds.
#include "CaseStages.h"
#include "CliCommon.h"
#include "Commands.h"

#include "hs/core/LabelTransfer.h"
#include "hs/core/Rng.h"
#include "hs/core/Timings.h"
#include "hs/core/Units.h"
#include "hs/merge/Merge.h"
#include "hs/meshing/BaselineMeshers.h"
#include "hs/scene/Scene.h"
#include "hs/scene/ScenePackage.h"
#include "hs/texture/Bake.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <unistd.h>

namespace hs::cli {
namespace {

// Sub-seeds of the case seed, one per stage, so that changing one stage's randomness leaves the others alone.
constexpr std::uint64_t kMeshingStream = 7;
constexpr std::uint64_t kTextureStream = 11;
constexpr std::uint64_t kMaterialStream = 13;

/// Face label on the visual surface: 0 wall (endometrium, serosa), 1 over a myoma, 2 over a polyp.
constexpr const char* kAppearanceLabel = "appearance";
/// Tissue label values of the organ surface (hs/anatomy/UterusGenerator.h).
constexpr std::int32_t kTissueCervicalCanal = 3;
constexpr std::int32_t kTissueOstium = 4;

struct GenerateOptions {
    std::string casePath;
    std::string output;
    int variants = 1;
    std::optional<std::uint64_t> seed;
    int jobs = 1;
    std::optional<int> threads;
    bool zip = false;
    CommonOptions common;
};

struct VariantReport {
    int index = 0;
    std::uint64_t seed = 0;
    std::string folder;
    std::optional<Error> error;
    StageTimings timings;
    std::size_t vertices = 0;
    std::size_t tets = 0;
    scene::MeshQuality quality;
    std::vector<scene::PathologyDescriptor> pathologies;
    scene::OrganDimensions organ;
    std::vector<std::string> warnings;
};

meshing::MeshMethod methodOf(scene::MeshingMethod m) {
    switch (m) {
    case scene::MeshingMethod::Particle:
        return meshing::MeshMethod::Particle;
    case scene::MeshingMethod::TetGen:
        return meshing::MeshMethod::TetGen;
    case scene::MeshingMethod::Cgal:
        return meshing::MeshMethod::Cgal;
    }
    return meshing::MeshMethod::Particle;
}

meshing::MeshParams meshParamsFor(const scene::CaseSpec& spec, std::optional<int> threads) {
    meshing::MeshParams p;
    p.targetEdgeLength = spec.meshing.targetEdgeLengthMm.value_or(0.0);
    p.targetVertices = spec.meshing.targetVertices.value_or(0);
    p.seed = Rng::deriveSeed(spec.seed, kMeshingStream);
    p.threads = threads.value_or(spec.meshing.threads);
    p.particlesPerVoxel = spec.meshing.particlesPerInnerVoxel;
    p.relaxationIterations = spec.meshing.relaxationIterations;
    return p;
}

texture::BakeParams bakeParamsFor(const scene::CaseSpec& spec, std::optional<int> threads) {
    texture::BakeParams p;
    p.size = spec.texture.sizePx;
    p.seed = Rng::deriveSeed(spec.seed, kTextureStream);
    p.threads = threads.value_or(spec.meshing.threads);
    p.labels.appearanceLabel = kAppearanceLabel;
    p.labels.myomaValues = {1};
    p.labels.polypValues = {2};
    p.exemplarFiles[static_cast<std::size_t>(texture::Appearance::Endometrium)] =
        spec.texture.exemplars.endometrium.value_or("");
    p.exemplarFiles[static_cast<std::size_t>(texture::Appearance::Myoma)] = spec.texture.exemplars.myoma.value_or("");
    p.exemplarFiles[static_cast<std::size_t>(texture::Appearance::Polyp)] = spec.texture.exemplars.polyp.value_or("");
    p.vessels = spec.texture.vesselDensity > 0.0;
    for (auto& c : p.vesselParams.perClass)
        c.attractorsPerMm2 *= spec.texture.vesselDensity;
    return p;
}

scene::MeshQuality qualityOf(const meshing::QualityReport& q) {
    scene::MeshQuality m;
    m.vertexCount = q.vertexCount;
    m.tetCount = q.tetCount;
    m.meanRadiusRatio = q.meanRadiusRatio;
    m.minRadiusRatio = q.minRadiusRatio;
    m.minDihedralDeg = q.minDihedralDeg;
    m.maxDihedralDeg = q.maxDihedralDeg;
    m.meanEdgeRatio = q.meanEdgeRatio;
    m.maxEdgeRatio = q.maxEdgeRatio;
    m.radiusRatioHistogram.assign(q.radiusRatioHistogram.begin(), q.radiusRatioHistogram.end());
    m.minDihedralHistogram.assign(q.minDihedralHistogram.begin(), q.minDihedralHistogram.end());
    m.sliverCount = q.sliverCount;
    m.invertedCount = q.invertedCount;
    m.degenerateCount = q.degenerateCount;
    m.hasReference = q.hasReference;
    m.hausdorffDistanceMm = q.hausdorffDistance;
    m.hausdorffRelative = q.hausdorffRelative;
    m.volumeError = q.volumeError;
    return m;
}

/// Indices of the faces whose `label` equals `value`, ascending.
std::vector<std::int32_t> facesWith(const SurfaceMesh& mesh, const std::string& label, std::int32_t value) {
    std::vector<std::int32_t> faces;
    const auto it = mesh.faceLabels.find(label);
    if (it == mesh.faceLabels.end())
        return faces;
    for (std::size_t f = 0; f < it->second.size(); ++f)
        if (it->second[f] == value)
            faces.push_back(static_cast<std::int32_t>(f));
    return faces;
}

/// The ostia are smaller than the mesh's triangles, so no boundary face may be nearest to an ostium face: carry
/// them the other way too, marking the boundary face nearest to each ostium face of the organ.
Status keepSmallTissueFeatures(const SurfaceMesh& outline, SurfaceMesh& boundary, double reach) {
    SurfaceMesh probe = outline;
    std::vector<std::int32_t> index(boundary.triangles.size());
    for (std::size_t f = 0; f < index.size(); ++f)
        index[f] = static_cast<std::int32_t>(f);
    boundary.faceLabels["faceIndex"] = std::move(index);
    const Status status = transferFaceLabels(boundary, probe, {"faceIndex"}, reach, -1);
    boundary.faceLabels.erase("faceIndex");
    HS_TRY(status);
    const auto& tissue = outline.faceLabels.at("tissue");
    const auto& nearest = probe.faceLabels.at("faceIndex");
    auto& boundaryTissue = boundary.faceLabels.at("tissue");
    for (std::size_t f = 0; f < tissue.size(); ++f)
        if (tissue[f] == kTissueOstium && nearest[f] >= 0)
            boundaryTissue[static_cast<std::size_t>(nearest[f])] = kTissueOstium;
    return {};
}

/// Tets of region `region` that share a face with a tet of region `other`, ascending: where a pathology sits on the
/// myometrium (a polyp's base, a myoma's intramural interface).
std::vector<std::int32_t> tetsTouching(const TetMesh& mesh, std::int32_t region, std::int32_t other) {
    std::map<std::array<std::int32_t, 3>, std::int32_t> otherFaces; // sorted face -> 1
    constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    auto faceOf = [&mesh](std::size_t t, const int* f) {
        std::array<std::int32_t, 3> key{mesh.tets[t][static_cast<std::size_t>(f[0])],
                                        mesh.tets[t][static_cast<std::size_t>(f[1])],
                                        mesh.tets[t][static_cast<std::size_t>(f[2])]};
        std::sort(key.begin(), key.end());
        return key;
    };
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
        if (mesh.regionOf(t) == other)
            for (const auto& f : kFaces)
                otherFaces.emplace(faceOf(t, f), 1);
    std::vector<std::int32_t> out;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
        if (mesh.regionOf(t) != region)
            continue;
        for (const auto& f : kFaces)
            if (otherFaces.count(faceOf(t, f))) {
                out.push_back(static_cast<std::int32_t>(t));
                break;
            }
    }
    return out;
}

std::string locationKey(const scene::PathologySpec& p) {
    if (const auto* c = std::get_if<scene::ClinicalPlacement>(&p.placement))
        return std::string(scene::toString(c->location));
    return "";
}

/// Runs every stage for one variant and writes its package. `spec` already carries the variant's seed.
Status generateVariant(const scene::CaseSpec& spec, const std::string& caseFile, const GenerateOptions& options,
                       VariantReport& report, Progress& progress) {
    StageTimings& t = report.timings;
    auto checkCancel = [&progress]() -> Status {
        if (progress.cancelled())
            return fail(ErrorCode::Cancelled, "generation cancelled");
        return {};
    };

    // 1. Organ from the shape model.
    std::optional<OrganInstance> organ;
    {
        ScopedStepTimer timer(t, "organ");
        auto request = organRequestFor(spec, caseFile);
        if (!request)
            return request.failure();
        auto model = anatomy::loadShapeModel(modelPathFor(spec, caseFile));
        if (!model)
            return model.failure();
        auto made = makeOrgan(*model, *request);
        if (!made)
            return made.failure();
        organ = std::move(made).value();
    }
    progress.report("organ", 0.05);
    HS_TRY(checkCancel());

    // 2. Pathologies grown in the organ, 3. merged into one body.
    auto pathologySub = progress.sub(0.05, 0.15);
    std::optional<pathology::PathologyResult> grown;
    {
        ScopedStepTimer timer(t, "pathology");
        auto result = pathology::growPathologies(organ->mesh, pathologyParamsFor(spec), pathologySub);
        if (!result)
            return fail(result.error().code, caseFile + ": " + result.error().detail);
        grown = std::move(result).value();
    }
    auto mergeSub = progress.sub(0.15, 0.25);
    std::optional<merge::MergeResult> merged;
    {
        ScopedStepTimer timer(t, "merge");
        auto result = merge::mergeBody(*grown, {}, mergeSub);
        if (!result)
            return fail(result.error().code, caseFile + ": " + result.error().detail);
        merged = std::move(result).value();
    }
    HS_TRY(checkCancel());

    // 4. Tetrahedral mesh. Scene region ids start at 1 (Gmsh physical tags must be positive): body region r -> r + 1.
    auto meshSub = progress.sub(0.25, 0.65);
    std::optional<meshing::MeshResult> meshed;
    {
        ScopedStepTimer timer(t, "meshing");
        auto result = meshing::meshWith(methodOf(spec.meshing.method), merged->body,
                                        meshParamsFor(spec, options.threads), meshSub);
        if (!result)
            return result.failure();
        meshed = std::move(result).value();
    }
    scene::Scene s;
    s.tets = std::move(meshed->mesh);
    for (auto& r : s.tets.regions)
        r += 1;
    s.regions.push_back({1, "myometrium", scene::Tissue::Myometrium, ""});
    for (std::size_t i = 0; i < spec.pathologies.size(); ++i) {
        const auto& p = spec.pathologies[i];
        s.regions.push_back({static_cast<std::int32_t>(i + 2), p.id,
                             p.kind == scene::PathologyKind::Myoma ? scene::Tissue::Myoma : scene::Tissue::Polyp,
                             p.id});
    }
    HS_TRY(checkCancel());

    // 5. Visual surface: the mesh's boundary, with the organ's tissue and pathology labels carried over.
    auto bakeSub = progress.sub(0.65, 0.85);
    {
        ScopedStepTimer timer(t, "texture");
        SurfaceMesh boundary = extractBoundary(s.tets);
        const double reach = 3.0 * std::max(meshed->targetEdgeLength, 0.5);
        HS_TRY(transferFaceLabels(merged->body.surfaces.front().surface, boundary, {"tissue", merge::kPathologyLabel},
                                  reach));
        HS_TRY(keepSmallTissueFeatures(merged->body.surfaces.front().surface, boundary, reach));
        std::vector<std::int32_t> appearance(boundary.triangles.size(), 0);
        const auto& over = boundary.faceLabels.at(merge::kPathologyLabel);
        for (std::size_t f = 0; f < appearance.size(); ++f) {
            const auto p = over[f] - 1; // 1 + index of the pathology a face is draped over
            if (p >= 0 && static_cast<std::size_t>(p) < spec.pathologies.size())
                appearance[f] =
                    spec.pathologies[static_cast<std::size_t>(p)].kind == scene::PathologyKind::Myoma ? 1 : 2;
        }
        boundary.faceLabels[kAppearanceLabel] = std::move(appearance);
        auto baked = texture::bakeAppearance(boundary, bakeParamsFor(spec, options.threads), bakeSub);
        if (!baked)
            return baked.failure();
        texture::TexturedSurface textured = texture::makeTexturedSurface(boundary, baked->atlas);
        s.surface.mesh = std::move(textured.mesh);
        s.surface.uvs = std::move(textured.uv);
        s.surface.albedo = std::move(baked->albedo);
        s.surface.normal = std::move(baked->normal);
        s.surface.roughness = std::move(baked->roughness);
        for (const auto& w : baked->warnings)
            s.warnings.push_back("texture: " + w);
    }
    HS_TRY(checkCancel());

    // 6. Materials, labels, descriptors, hydrometra.
    {
        ScopedStepTimer timer(t, "scene");
        scene::MaterialOptions materialOptions;
        materialOptions.seed = Rng::deriveSeed(spec.seed, kMaterialStream);
        auto materials = scene::assignMaterials(s.tets, s.regions, spec.scene, materialOptions);
        if (!materials)
            return materials.failure();
        s.materials = std::move(materials).value();

        for (std::size_t i = 0; i < spec.pathologies.size(); ++i) {
            auto faces = facesWith(s.surface.mesh, merge::kPathologyLabel, static_cast<std::int32_t>(i + 1));
            if (!faces.empty())
                s.labels.push_back({"contact:" + spec.pathologies[i].id, scene::LabelKind::Contact,
                                    scene::LabelElement::SurfaceFace, spec.pathologies[i].id, std::move(faces)});
        }
        for (std::size_t i = 0; i < spec.pathologies.size(); ++i) {
            auto base = tetsTouching(s.tets, static_cast<std::int32_t>(i + 2), 1);
            if (!base.empty())
                s.labels.push_back({"base:" + spec.pathologies[i].id, scene::LabelKind::PathologyBase,
                                    scene::LabelElement::Tet, spec.pathologies[i].id, std::move(base)});
        }
        if (auto ostia = facesWith(s.surface.mesh, "tissue", kTissueOstium); !ostia.empty())
            s.labels.push_back(
                {"ostia", scene::LabelKind::Ostium, scene::LabelElement::SurfaceFace, "", std::move(ostia)});
        if (auto canal = facesWith(s.surface.mesh, "tissue", kTissueCervicalCanal); !canal.empty())
            s.labels.push_back({"cervical-canal", scene::LabelKind::CervicalCanal, scene::LabelElement::SurfaceFace, "",
                                std::move(canal)});

        const auto& d = organ->dimensions;
        s.clinical.organ = {d.lengthMm, d.widthMm, d.apDepthMm, d.cavityLengthMm, d.cavityWidthMm, d.ellipsoidVolumeMl};
        const auto volumes = regionVolumes(s.tets);
        for (std::size_t i = 0; i < grown->pathologies.size() && i < spec.pathologies.size(); ++i) {
            const auto& g = grown->pathologies[i];
            scene::PathologyDescriptor pd;
            pd.id = g.id;
            pd.kind = spec.pathologies[i].kind;
            pd.regionId = static_cast<std::int32_t>(i + 2);
            pd.sizeMm = g.descriptors.sizeMm;
            const auto v = volumes.find(pd.regionId);
            pd.volumeMl = v == volumes.end() ? 0.0 : units::mlFromMm3(v->second);
            if (g.kind == pathology::Kind::Myoma) {
                pd.figo = scene::FigoType{g.descriptors.figo.type, g.descriptors.figo.serosal};
                const auto& l = g.descriptors.lasmar;
                pd.lasmar = scene::LasmarScore{l.size, l.topography, l.extension, l.penetration, l.wall};
            }
            pd.location = locationKey(spec.pathologies[i]);
            s.clinical.pathologies.push_back(pd);
        }
        auto hydrometra = scene::computeHydrometra(d.ellipsoidVolumeMl, spec.scene.hydrometraPressureKpa);
        if (!hydrometra)
            return hydrometra.failure();
        s.hydrometra = *hydrometra;
        s.quality = qualityOf(meshed->quality);
        s.caseSpec = spec;
        s.toolVersions = scene::defaultToolVersions();
        for (const auto& w : grown->warnings)
            s.warnings.push_back("pathology: " + w);
        for (const auto& w : merged->warnings)
            s.warnings.push_back("merge: " + w);
        for (const auto& w : meshed->warnings)
            s.warnings.push_back("meshing: " + w);
        HS_TRY(scene::checkScene(s));
    }

    // 7. The package, written atomically.
    auto writeSub = progress.sub(0.85, 1.0);
    {
        ScopedStepTimer timer(t, "package");
        auto written = scene::writeScenePackage(s, report.folder, {}, writeSub);
        if (!written)
            return written.failure();
        if (options.zip)
            HS_TRY(scene::zipScenePackage(report.folder, report.folder + ".zip"));
    }
    progress.report("done", 1.0);
    report.vertices = s.tets.points.size();
    report.tets = s.tets.tets.size();
    report.quality = s.quality;
    report.pathologies = s.clinical.pathologies;
    report.organ = s.clinical.organ;
    report.warnings = s.warnings;
    return {};
}

/// Terminal progress: one bar over all variants on a terminal, a line per stage change otherwise.
class ProgressPrinter {
public:
    ProgressPrinter(std::size_t variants, bool quiet)
        : m_fractions(variants, 0.0), m_quiet(quiet), m_tty(isatty(STDERR_FILENO) != 0) {}

    void update(std::size_t variant, std::string_view stage, double fraction) {
        if (m_quiet)
            return;
        std::lock_guard<std::mutex> lock(m_mutex);
        m_fractions[variant] = fraction;
        double total = 0.0;
        for (double f : m_fractions)
            total += f;
        total /= static_cast<double>(m_fractions.size());
        const int percent = static_cast<int>(total * 100.0);
        const std::string key(stage.substr(0, stage.find('.')));
        if (m_tty) {
            if (percent == m_lastPercent && key == m_lastKey)
                return;
            const int filled = percent * 30 / 100;
            std::fprintf(stderr, "\r[%-30s] %3d%% %-12s", std::string(static_cast<std::size_t>(filled), '#').c_str(),
                         percent, key.c_str());
            std::fflush(stderr);
        } else if (key != m_lastKey) {
            std::fprintf(stderr, "[%3d%%] %s\n", percent, key.c_str());
        }
        m_lastPercent = percent;
        m_lastKey = key;
    }
    void finish() {
        if (!m_quiet && m_tty)
            std::fprintf(stderr, "\n");
    }

private:
    std::mutex m_mutex;
    std::vector<double> m_fractions;
    bool m_quiet;
    bool m_tty;
    int m_lastPercent = -1;
    std::string m_lastKey;
};

nlohmann::ordered_json reportJson(const VariantReport& r) {
    nlohmann::ordered_json j;
    j["variant"] = r.index;
    j["seed"] = r.seed;
    j["folder"] = r.folder;
    j["ok"] = !r.error.has_value();
    if (r.error) {
        j["error"] = {{"code", std::string(errorCodeKey(r.error->code))}, {"detail", r.error->detail}};
        return j;
    }
    auto steps = nlohmann::ordered_json::array();
    for (const auto& s : r.timings.steps)
        steps.push_back({{"stage", s.name}, {"seconds", s.seconds}});
    j["timings"] = steps;
    j["seconds"] = r.timings.totalSeconds();
    j["vertices"] = r.vertices;
    j["tetrahedra"] = r.tets;
    j["quality"] = {{"meanRadiusRatio", r.quality.meanRadiusRatio},
                    {"minDihedralDeg", r.quality.minDihedralDeg},
                    {"slivers", r.quality.sliverCount},
                    {"inverted", r.quality.invertedCount},
                    {"hausdorffRelative", r.quality.hausdorffRelative},
                    {"volumeError", r.quality.volumeError}};
    j["organ"] = {{"lengthMm", r.organ.lengthMm},
                  {"widthMm", r.organ.widthMm},
                  {"apMm", r.organ.apMm},
                  {"uterineVolumeMl", r.organ.uterineVolumeMl}};
    auto pathologies = nlohmann::ordered_json::array();
    for (const auto& p : r.pathologies) {
        nlohmann::ordered_json pj{{"id", p.id}, {"sizeMm", p.sizeMm}, {"volumeMl", p.volumeMl}};
        if (p.figo)
            pj["figo"] = p.figo->toString();
        if (p.lasmar)
            pj["lasmar"] = p.lasmar->total();
        pathologies.push_back(pj);
    }
    j["pathologies"] = pathologies;
    j["warnings"] = r.warnings;
    return j;
}

void printReport(const VariantReport& r) {
    if (r.error) {
        std::printf("variant %d (seed %llu): failed: %s\n", r.index, static_cast<unsigned long long>(r.seed),
                    r.error->message().c_str());
        return;
    }
    std::printf("wrote       %s (seed %llu)\n", r.folder.c_str(), static_cast<unsigned long long>(r.seed));
    std::printf("organ       %.1f x %.1f x %.1f mm (L x W x AP), %.1f mL\n", r.organ.lengthMm, r.organ.widthMm,
                r.organ.apMm, r.organ.uterineVolumeMl);
    for (const auto& p : r.pathologies)
        std::printf("pathology   %-10s %.1f mm, %.2f mL%s%s\n", p.id.c_str(), p.sizeMm, p.volumeMl,
                    p.figo ? (", FIGO " + p.figo->toString()).c_str() : "",
                    p.lasmar ? (", Lasmar " + std::to_string(p.lasmar->total())).c_str() : "");
    std::printf("mesh        %zu vertices, %zu tetrahedra, mean radius ratio %.3f, min dihedral %.1f deg, "
                "%zu slivers\n",
                r.vertices, r.tets, r.quality.meanRadiusRatio, r.quality.minDihedralDeg, r.quality.sliverCount);
    std::printf("timings    ");
    for (const auto& s : r.timings.steps)
        std::printf(" %s %.2f s,", s.name.c_str(), s.seconds);
    std::printf(" total %.2f s\n", r.timings.totalSeconds());
    for (const auto& w : r.warnings)
        std::printf("warning     %s\n", w.c_str());
}

int runGenerate(const GenerateOptions& options) {
    auto loaded = scene::loadCase(options.casePath);
    if (!loaded)
        return reportError("generate", loaded.error());
    const std::uint64_t baseSeed = options.seed.value_or(loaded->seed);
    const auto n = static_cast<std::size_t>(options.variants);
    std::vector<VariantReport> reports(n);
    for (std::size_t i = 0; i < n; ++i) {
        reports[i].index = static_cast<int>(i);
        reports[i].seed = n == 1 ? baseSeed : Rng::deriveSeed(baseSeed, i);
        char name[32];
        std::snprintf(name, sizeof name, "variant-%03zu", i);
        reports[i].folder = n == 1 ? options.output : (std::filesystem::path(options.output) / name).string();
    }
    { // the folder that will hold the package (or the variants)
        std::error_code ec;
        const std::filesystem::path out(options.output);
        const std::filesystem::path holder = n > 1 ? out : out.parent_path();
        if (!holder.empty())
            std::filesystem::create_directories(holder, ec);
        if (ec)
            return reportError("generate", Error{ErrorCode::IoError, options.output + ": " + ec.message()});
    }

    ProgressPrinter printer(n, options.common.json);
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t i = next++; i < n; i = next++) {
            scene::CaseSpec spec = *loaded;
            spec.seed = reports[i].seed;
            Progress progress([&printer, i](std::string_view stage, double f) { printer.update(i, stage, f); });
            const Status status = generateVariant(spec, options.casePath, options, reports[i], progress);
            if (!status.ok())
                reports[i].error = status.error();
            printer.update(i, "done", 1.0);
        }
    };
    const auto jobs = std::min<std::size_t>(static_cast<std::size_t>(std::max(options.jobs, 1)), n);
    std::vector<std::thread> threads;
    for (std::size_t j = 1; j < jobs; ++j)
        threads.emplace_back(worker);
    worker();
    for (auto& th : threads)
        th.join();
    printer.finish();

    int exitCode = kExitOk;
    for (const auto& r : reports)
        if (r.error && exitCode == kExitOk)
            exitCode = exitCodeFor(*r.error);
    if (options.common.json) {
        nlohmann::ordered_json j;
        j["case"] = options.casePath;
        j["output"] = options.output;
        auto variants = nlohmann::ordered_json::array();
        for (const auto& r : reports)
            variants.push_back(reportJson(r));
        j["variants"] = variants;
        printJson(std::cout, j);
    } else {
        for (const auto& r : reports)
            printReport(r);
        for (const auto& r : reports)
            if (r.error)
                reportError("generate",
                            Error{r.error->code, "variant " + std::to_string(r.index) + ": " + r.error->detail});
    }
    return exitCode;
}

} // namespace

void addGenerateCommand(CLI::App& app, int& exitCode) {
    auto o = std::make_shared<GenerateOptions>();
    auto* sub = app.add_subcommand("generate", "Run the whole pipeline on a case and write the scene package");
    sub->add_option("CASE", o->casePath, "case file")->required();
    sub->add_option("-o,--output", o->output, "scene package folder (with --variants: folder of variant-NNN)")
        ->required();
    sub->add_option("--variants", o->variants, "number of scenes, each with a seed derived from the case's")
        ->check(CLI::Range(1, 10000));
    sub->add_option("--seed", o->seed, "seed instead of the case's");
    sub->add_option("--jobs", o->jobs, "variants generated at the same time")->check(CLI::Range(1, 256));
    sub->add_option("--threads", o->threads, "threads per stage instead of the case's (never changes the result)")
        ->check(CLI::Range(0, 256));
    sub->add_flag("--zip", o->zip, "also write SCENE.zip");
    sub->add_flag("--json", o->common.json, "print a JSON summary (and no progress bar)");
    sub->callback([o, &exitCode] { exitCode = runGenerate(*o); });
}

} // namespace hs::cli
