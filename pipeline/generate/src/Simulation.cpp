#include "hs/generate/Simulation.h"

#include "hs/core/TetEmbedding.h"
#include "hs/generate/Assembly.h"
#include "hs/meshing/BaselineMeshers.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <string>

namespace hs::generate {

Result<scene::SimulationMesh> simulationMesh(const scene::CaseSpec& spec, const merge::MergeResult& merged,
                                             const std::vector<scene::SceneMaterial>& materials, double cervixLengthMm,
                                             const SurfaceMesh& visual, std::optional<int> threads,
                                             Progress& progress) {
    meshing::MeshParams params = meshParamsFor(spec, threads);
    params.targetEdgeLength = 0.0;
    params.targetVertices = kSimulationVertices;
    // The surface fidelity check (docs/meshing.md, step 9) is the scene mesh's: each particle it adds is a point more
    // in the real-time loop, and this coarse mesh has no Hausdorff bar (its surface is the visual surface's job).
    params.surfaceFidelity = false;
    auto meshed = meshing::meshWith(meshMethodFor(spec), merged.body, params, progress);
    if (!meshed)
        return fail(meshed.error().code, "simulation mesh: " + meshed.error().detail);
    // The scene's mesh covers a pathology on the cavity with endometrium one tet deep (about a millimetre there); one
    // tet of this coarse mesh is about 4 mm deep, and a scope pressing a myoma would feel that lining and not the
    // myoma. The simulation mesh leaves pathologies uncovered: their cover is the visual surface's.
    TissueLayerParams layers = tissueLayerParamsFor(spec);
    layers.coverPathologies = false;
    auto tissue = tissueStage(spec, merged, *meshed, layers);
    if (!tissue)
        return fail(tissue.error().code, "simulation mesh: " + tissue.error().detail);

    scene::SimulationMesh sim;
    sim.tets = std::move(tissue->tets);
    std::map<std::int32_t, std::int32_t> materialOfRegion;
    for (const auto& m : materials)
        materialOfRegion[m.regionId] = m.id;
    auto& materialIds = sim.tets.tetLabels[scene::kMaterialLabel];
    materialIds.resize(sim.tets.tetCount());
    for (std::size_t t = 0; t < sim.tets.tetCount(); ++t) {
        const auto it = materialOfRegion.find(sim.tets.regionOf(t));
        if (it == materialOfRegion.end())
            return fail(ErrorCode::Internal, "simulation mesh: tet " + std::to_string(t) + " lies in region " +
                                                 std::to_string(sim.tets.regionOf(t)) + ", which the scene has not");
        materialIds[t] = it->second;
    }
    auto& support = sim.tets.tetLabels[scene::kSupportTetLabel];
    support.assign(sim.tets.tetCount(), 0);
    for (const std::int32_t t : supportLabel(sim.tets, cervixLengthMm).indices)
        support[static_cast<std::size_t>(t)] = 1;
    auto& cavity = sim.tets.pointLabels[scene::kCavityPointLabel];
    cavity.assign(sim.tets.vertexCount(), 0);
    const auto sourceLabel = tissue->boundary.vertexLabels.find("sourcePoint");
    if (sourceLabel == tissue->boundary.vertexLabels.end())
        return fail(ErrorCode::Internal, "simulation mesh: its boundary does not name its points in the tets");
    const auto& source = sourceLabel->second;
    const auto seen = scopeSeenFaces(tissue->boundary);
    for (std::size_t f = 0; f < tissue->boundary.faceCount(); ++f) {
        if (seen[f] == 0)
            continue;
        for (const std::int32_t v : tissue->boundary.triangles[f])
            cavity[static_cast<std::size_t>(source[static_cast<std::size_t>(v)])] = 1;
    }
    sim.surfaceEmbedding = embedPoints(sim.tets, visual.points, threads.value_or(spec.meshing.threads));
    // Where the coarse mesh is thinner than the surface (a thin stalk, a cornual recess), a point's weights would
    // extrapolate too far: move them towards the tet's centre (weights 1/4 each) just far enough to lie in the allowed
    // range; they still sum to 1, and the point then moves with its tet, a little off it
    // (scene::kMaxSimulationEmbeddingOffsetMm bounds how far).
    const double lo = -scene::kMaxEmbeddingExtrapolation, hi = 1.0 + scene::kMaxEmbeddingExtrapolation;
    for (TetEmbedding& e : sim.surfaceEmbedding) {
        double t = 0.0; // the blend towards the centre that every weight needs
        for (const double w : e.weights) {
            if (w < lo)
                t = std::max(t, (lo - w) / (0.25 - w));
            if (w > hi)
                t = std::max(t, (w - hi) / (w - 0.25));
        }
        if (t > 0.0)
            for (double& w : e.weights)
                w = w + (0.25 - w) * t;
    }
    return sim;
}

std::string simulationBindingWarning(const SurfaceMesh& visual, const scene::SimulationMesh& sim) {
    constexpr double kOnTetMm = 1e-3;
    std::size_t off = 0;
    double farthest = 0.0;
    for (std::size_t i = 0; i < visual.points.size() && i < sim.surfaceEmbedding.size(); ++i) {
        if (sim.surfaceEmbedding[i].tet < 0)
            continue;
        const double d = distance(embeddedPoint(sim.tets, sim.surfaceEmbedding[i]), visual.points[i]);
        if (d > kOnTetMm) {
            ++off;
            farthest = std::max(farthest, d);
        }
    }
    if (off == 0)
        return {};
    std::ostringstream text;
    text.setf(std::ios::fixed);
    text.precision(2);
    text << "simulation: " << off << " of " << visual.points.size() << " visual surface points are bound up to "
         << farthest
         << " mm off their simulation tet (the coarse mesh is thinner than the surface there: a thin stalk, a cornual "
            "recess); they move with that tet";
    return text.str();
}

} // namespace hs::generate
