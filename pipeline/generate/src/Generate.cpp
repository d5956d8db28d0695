#include "hs/generate/Generate.h"

#include "hs/anatomy/ShapeModel.h"
#include "hs/core/Subdivision.h"
#include "hs/core/Units.h"
#include "hs/generate/Simulation.h"
#include "hs/mechanics/UterusModel.h"
#include "hs/meshing/BaselineMeshers.h"
#include "hs/scene/Hydrometra.h"
#include "hs/texture/Bake.h"

#include <algorithm>
#include <array>
#include <utility>

namespace hs::generate {
namespace {

/// Where each stage starts in generateScene's progress range, by cost on the default case (the mesh takes about
/// half the time, the texture and the scene, with its simulation mesh, a sixth each); the last entry closes the range.
constexpr std::array<double, kStageCount + 1> kStageStart{0.0, 0.05, 0.15, 0.24, 0.64, 0.66, 0.84, 1.0};

std::size_t indexOf(Stage stage) {
    return static_cast<std::size_t>(stage);
}

/// A stage's error, prefixed with the case file where the stage itself does not name it.
Error inCase(const GenerateParams& params, Error error) {
    if (!params.caseFile.empty())
        error.detail = params.caseFile + ": " + error.detail;
    return error;
}

Status runOrgan(Generated& g, const GenerateParams& params) {
    auto request = organRequestFor(g.spec, params.caseFile);
    if (!request)
        return request.failure();
    auto model = anatomy::loadShapeModel(modelPathFor(g.spec, params.caseFile));
    if (!model)
        return model.failure();
    auto made = makeOrgan(*model, *request);
    if (!made)
        return made.failure();
    g.organ = std::move(made).value();
    return {};
}

Status runPathology(Generated& g, const GenerateParams& params, Progress& progress) {
    auto result =
        pathology::growPathologies(g.organ->mesh, pathologyParamsFor(g.spec), progress, params.growthObserver);
    if (!result)
        return inCase(params, result.error());
    g.pathologies = std::move(result).value();
    return {};
}

Status runMerge(Generated& g, const GenerateParams& params, Progress& progress) {
    auto result = merge::mergeBody(*g.pathologies, {}, progress);
    if (!result)
        return inCase(params, result.error());
    g.body = std::move(result).value();
    return {};
}

Status runMeshing(Generated& g, const GenerateParams& params, Progress& progress) {
    auto result =
        meshing::meshWith(meshMethodFor(g.spec), g.body->body, meshParamsFor(g.spec, params.threads), progress);
    if (!result)
        return result.failure();
    g.mesh = std::move(result).value();
    return {};
}

Status runTissue(Generated& g) {
    auto tissue = tissueStage(g.spec, *g.body, *g.mesh, tissueLayerParamsFor(g.spec));
    if (!tissue)
        return tissue.failure();
    g.tissue = std::move(tissue).value();
    return {};
}

/// The visual surface: the mesh's labelled boundary, baked, refined for close-ups (visualSurfaceLevels), split along
/// chart seams and bound to the tets.
Status runTexture(Generated& g, const GenerateParams& params, Progress& progress) {
    const SurfaceMesh& boundary = g.tissue->boundary;
    const auto ostia = ostiumOpenings(boundary);
    texture::BakeParams bake = bakeParamsFor(g.spec, params.caseFile, params.threads);
    bake.darkSpots = ostiumDarkSpots(ostia);
    bake.canal = canalFrame(boundary);
    // The maps are baked on the faired surface that the close-up surface subdivides: the relief is then drawn on the
    // shape it is seen on, so its slopes meet across the charts' seams.
    texture::CloseUpParams closeUp = closeUpParamsFor(boundary, ostia);
    const SurfaceMesh faired =
        closeUp.smoothing.iterations > 0 ? taubinSmooth(boundary, closeUp.seen, closeUp.smoothing) : boundary;
    closeUp.smoothing.iterations = 0;
    auto baked = texture::bakeAppearance(faired, bake, progress);
    if (!baked)
        return baked.failure();
    // The close-up surface and its binding take no progress of their own: a cancel is checked between them.
    progress.report("texture.closeUp", 1.0);
    HS_TRY(progress.check("texture", "refining the close-up surface"));
    texture::TexturedSurface textured = texture::makeCloseUpSurface(faired, baked->atlas, closeUp);
    progress.report("texture.bind", 1.0);
    HS_TRY(progress.check("texture", "binding the visual surface to the tets"));
    Appearance a;
    a.surface.embedding =
        embedPoints(g.tissue->tets, textured.mesh.points, params.threads.value_or(g.spec.meshing.threads));
    a.surface.normals = std::move(textured.normals);
    a.surface.mesh = std::move(textured.mesh);
    // The scene's UVs have their origin at the maps' top left (as glTF's), the atlas's at their bottom left.
    a.surface.uvs = std::move(textured.uv);
    for (auto& uv : a.surface.uvs)
        uv[1] = 1.0f - uv[1];
    a.surface.albedo = std::move(baked->albedo);
    a.surface.normal = std::move(baked->normal);
    a.surface.roughness = std::move(baked->roughness);
    a.stats = baked->stats;
    a.warnings = std::move(baked->warnings);
    g.appearance = std::move(a);
    return {};
}

/// The scene, with its simulation mesh (generate/Simulation.h).
Status runScene(Generated& g, const GenerateParams& params, Progress& progress) {
    auto s = assembleScene(g.spec, *g.organ, *g.pathologies, *g.body, *g.mesh, *g.tissue, *g.appearance);
    if (!s)
        return s.failure();
    // The simulation mesh and the hydrometra's static solves take about half of the stage each.
    auto simProgress = progress.sub(0.0, 0.5);
    auto sim = simulationMesh(g.spec, *g.body, s->materials, g.organ->dimensions.cervixLengthMm, s->surface.mesh,
                              params.threads, simProgress);
    if (!sim)
        return sim.failure();
    s->simulation = std::move(sim).value();
    if (const std::string w = simulationBindingWarning(s->surface.mesh, *s->simulation); !w.empty())
        s->warnings.push_back(w);
    HS_TRY(progress.check("scene"));
    // The hydrometra curve of the scene's own tissue model (the simulator's distension reaches it).
    auto curveProgress = progress.sub(0.5, 1.0);
    curveProgress.report("scene.hydrometra", 0.0);
    mechanics::UterusModel model;
    HS_TRY(mechanics::buildUterusModel(*s, mechanics::FemSettings{}, model));
    std::vector<double> pressures;
    for (const double mmHg : scene::kHydrometraCurveMmHg)
        pressures.push_back(mmHg * units::kKpaPerMmHg);
    auto curve = mechanics::hydrometraCurve(model, pressures, curveProgress);
    if (!curve && curve.error().code == ErrorCode::Cancelled)
        return curve.failure();
    if (!curve)
        return fail(curve.error().code, "hydrometra curve: " + curve.error().detail);
    for (std::size_t i = 0; i < pressures.size(); ++i)
        s->hydrometra.modelCurve.push_back({pressures[i], (*curve)[i]});
    HS_TRY(scene::checkScene(*s));
    g.scene = std::move(s).value();
    return {};
}

Status runStage(Stage stage, Generated& g, const GenerateParams& params, Progress& progress) {
    switch (stage) {
    case Stage::Organ:
        return runOrgan(g, params);
    case Stage::Pathology:
        return runPathology(g, params, progress);
    case Stage::Merge:
        return runMerge(g, params, progress);
    case Stage::Meshing:
        return runMeshing(g, params, progress);
    case Stage::Tissue:
        return runTissue(g);
    case Stage::Texture:
        return runTexture(g, params, progress);
    case Stage::Scene:
        return runScene(g, params, progress);
    }
    return fail(ErrorCode::InvalidInput, "unknown stage");
}

void clearFrom(Stage from, Generated& g) {
    const auto i = indexOf(from);
    if (i <= indexOf(Stage::Organ))
        g.organ.reset();
    if (i <= indexOf(Stage::Pathology))
        g.pathologies.reset();
    if (i <= indexOf(Stage::Merge))
        g.body.reset();
    if (i <= indexOf(Stage::Meshing))
        g.mesh.reset();
    if (i <= indexOf(Stage::Tissue))
        g.tissue.reset();
    if (i <= indexOf(Stage::Texture))
        g.appearance.reset();
    g.scene.reset();
}

/// Runs `from` through `last`; the results of the stages before `from` must be set. The results after `last` are
/// cleared: they were made from the stages that rerun.
Status runFrom(Stage from, Stage last, Generated& g, const GenerateParams& params, Progress& progress) {
    if (auto issues = scene::checkCase(g.spec); !issues.empty()) {
        std::string detail;
        for (const auto& issue : issues)
            detail += (detail.empty() ? "" : "\n") + (params.caseFile.empty() ? "case" : params.caseFile) + ": " +
                      issue.text();
        return fail(ErrorCode::InvalidInput, detail);
    }
    clearFrom(from, g);
    g.timings = {};
    // The stages that run share the whole range: a rerun from the texture goes from 0 to 1 too.
    const double first = kStageStart[indexOf(from)];
    const double end = kStageStart[indexOf(last) + 1];
    const auto scaled = [first, end](double f) { return first < end ? (f - first) / (end - first) : 1.0; };
    for (auto i = indexOf(from); i <= indexOf(last); ++i) {
        const auto stage = static_cast<Stage>(i);
        HS_TRY(progress.check("generation"));
        auto sub = progress.sub(scaled(kStageStart[i]), scaled(kStageStart[i + 1]));
        {
            ScopedStepTimer timer(g.timings, std::string(toString(stage)));
            HS_TRY(runStage(stage, g, params, sub));
        }
        progress.report(toString(stage), scaled(kStageStart[i + 1]));
    }
    return {};
}

} // namespace

bool Generated::has(Stage stage) const {
    switch (stage) {
    case Stage::Organ:
        return organ.has_value();
    case Stage::Pathology:
        return pathologies.has_value();
    case Stage::Merge:
        return body.has_value();
    case Stage::Meshing:
        return mesh.has_value();
    case Stage::Tissue:
        return tissue.has_value();
    case Stage::Texture:
        return appearance.has_value();
    case Stage::Scene:
        return scene.has_value();
    }
    return false;
}

Result<Generated> generateScene(const scene::CaseSpec& spec, const GenerateParams& params, Progress& progress) {
    Generated g;
    g.spec = spec;
    HS_TRY(runFrom(Stage::Organ, Stage::Scene, g, params, progress));
    return g;
}

std::optional<CaseChange> firstChangedStage(const scene::CaseSpec& before, const scene::CaseSpec& after) {
    if (before.seed != after.seed)
        return CaseChange{Stage::Organ, "/seed"};
    // The cycle phase and the endometrial thickness shape only the tissue layers, not the organ.
    clinical::PatientParams patientBefore = before.patient;
    patientBefore.cyclePhase = after.patient.cyclePhase;
    if (!(patientBefore == after.patient))
        return CaseChange{Stage::Organ, "/patient"};
    scene::AnatomyParams anatomyBefore = before.anatomy;
    anatomyBefore.endometrialThicknessMm = after.anatomy.endometrialThicknessMm;
    if (!(anatomyBefore == after.anatomy))
        return CaseChange{Stage::Organ, "/anatomy"};
    if (!(before.pathologies == after.pathologies))
        return CaseChange{Stage::Pathology, "/pathologies"};
    // The lining a myoma is kept clear of (placementLiningMm) is the case's thickness when it gives one.
    if (!after.pathologies.empty() && placementLiningMm(before) != placementLiningMm(after))
        return CaseChange{Stage::Pathology, "/anatomy/endometrialThicknessMm"};
    scene::MeshingParams meshingBefore = before.meshing;
    meshingBefore.threads = after.meshing.threads; // the thread count never changes a result
    if (!(meshingBefore == after.meshing))
        return CaseChange{Stage::Meshing, "/meshing"};
    if (before.patient.cyclePhase != after.patient.cyclePhase)
        return CaseChange{Stage::Tissue, "/patient/cyclePhase"};
    if (before.anatomy.endometrialThicknessMm != after.anatomy.endometrialThicknessMm)
        return CaseChange{Stage::Tissue, "/anatomy/endometrialThicknessMm"};
    if (!(before.texture == after.texture))
        return CaseChange{Stage::Texture, "/texture"};
    if (!(before.scene == after.scene))
        return CaseChange{Stage::Scene, "/scene"};
    if (before.title != after.title)
        return CaseChange{Stage::Scene, "/title"};
    return std::nullopt;
}

Result<Generated> regenerateFrom(Stage from, Generated previous, const scene::CaseSpec& edited,
                                 const GenerateParams& params, Progress& progress) {
    if (const auto change = firstChangedStage(previous.spec, edited); change && indexOf(change->stage) < indexOf(from))
        return fail(ErrorCode::InvalidInput,
                    (params.caseFile.empty() ? std::string("case") : params.caseFile) + ": " + change->field +
                        " changed, which the " + std::string(toString(change->stage)) +
                        " stage reads: regenerate from '" + std::string(toString(change->stage)) +
                        "' or earlier, not from '" + std::string(toString(from)) + "'");
    for (auto i = indexOf(Stage::Organ); i < indexOf(from); ++i)
        if (!previous.has(static_cast<Stage>(i)))
            return fail(ErrorCode::InvalidInput, "regenerating from '" + std::string(toString(from)) +
                                                     "' needs the result of the " +
                                                     std::string(toString(static_cast<Stage>(i))) +
                                                     " stage, which the previous run does not have");
    previous.spec = edited;
    HS_TRY(runFrom(from, Stage::Scene, previous, params, progress));
    return previous;
}

Result<Generated> updateThrough(Stage last, Generated previous, const scene::CaseSpec& edited,
                                const GenerateParams& params, Progress& progress) {
    // The first stage to run: the earliest one the edit touches or whose result is missing.
    const auto change = firstChangedStage(previous.spec, edited);
    std::size_t from = change ? indexOf(change->stage) : static_cast<std::size_t>(kStageCount);
    for (std::size_t i = 0; i < from; ++i)
        if (!previous.has(static_cast<Stage>(i))) {
            from = i;
            break;
        }
    previous.spec = edited;
    if (from > indexOf(last)) {
        // Nothing through `last` to rerun; what the edit touches after it is no longer valid.
        if (change)
            clearFrom(change->stage, previous);
        progress.report(toString(last), 1.0);
        return previous;
    }
    HS_TRY(runFrom(static_cast<Stage>(from), last, previous, params, progress));
    return previous;
}

} // namespace hs::generate
