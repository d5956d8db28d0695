#pragma once
/// The scene's simulation mesh: the merged body meshed again, coarsely enough for a real-time solver, with the same
/// tissue layers, materials and support as the scene's tets, and the visual surface bound to it (scene::SimulationMesh;
/// docs/scene-format.md, "simulation.vtu"; docs/simulator.md, "Tissue").

#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/generate/CaseStages.h"
#include "hs/merge/Merge.h"
#include "hs/scene/CaseSpec.h"
#include "hs/scene/Scene.h"

#include <cstdint>
#include <optional>
#include <string>

namespace hs::generate {

/// Vertices the simulation mesh aims at. About 2000 vertices give about 9000 tets on the default uterus: a
/// corotational or XPBD solver steps that at 100-250 Hz on one core (SOFA's corotational FEM ~70-170 Hz at ~7k tets;
/// docs/simulator.md), while the particle mesher still keeps the cervical canal open (3.2 mm at its narrowest on the
/// default case, against the 2.9 mm scope).
inline constexpr std::int64_t kSimulationVertices = 2000;

/// The simulation mesh of a case's scene: `merged`'s body meshed with the case's method and seed at
/// kSimulationVertices, split into the wall's tissue layers like the scene's tets, each tet given its region's material
/// from `materials` (Scene::materials), the support (supportLabel with `cervixLengthMm`) and the cavity faces (the
/// boundary the scope sees, scopeSeenFaces) marked, and every point of `visual` bound to it.
[[nodiscard]] Result<scene::SimulationMesh>
simulationMesh(const scene::CaseSpec& spec, const merge::MergeResult& merged,
               const std::vector<scene::SceneMaterial>& materials, double cervixLengthMm, const SurfaceMesh& visual,
               std::optional<int> threads = std::nullopt, Progress& progress = Progress::none());

/// The named warning for the points of `visual` that `sim` binds off their tet (simulationMesh clamps the weights
/// where the coarse mesh is thinner than the surface): "simulation: N of M visual surface points are bound up to X mm
/// off their simulation tet ...", empty when every point lies on its tet (within 1 micrometre).
std::string simulationBindingWarning(const SurfaceMesh& visual, const scene::SimulationMesh& sim);

} // namespace hs::generate
