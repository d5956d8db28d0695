#pragma once
// How surface.vtp stores the visual surface's binding to the tets: the vertex label "embedTet" (Int32, the tet) and
// the point array "embedWeights" (Float64, 4 barycentric weights); docs/scene-format.md.

#include "hs/core/TetEmbedding.h"
#include "hs/io/MeshIO.h"

#include <vector>

namespace hs::scene::detail {

inline constexpr const char* kEmbedTetLabel = "embedTet";
inline constexpr const char* kEmbedWeightsArray = "embedWeights";
/// The same for the binding to the simulation mesh (simulation.vtu).
inline constexpr const char* kSimEmbedTetLabel = "simulationTet";
inline constexpr const char* kSimEmbedWeightsArray = "simulationWeights";

/// Adds the embedding to `mesh` (label `tetLabel`) and `arrays` (weights `weightsArray`) for writing.
void splitEmbedding(const std::vector<TetEmbedding>& embedding, SurfaceMesh& mesh, io::PointArrays& arrays,
                    const char* tetLabel = kEmbedTetLabel, const char* weightsArray = kEmbedWeightsArray);
/// Takes the embedding out of a read surface (removing its label); nothing when the file has neither part, an
/// InvalidInput error naming surface.vtp when it has one part only or the wrong shape.
Status joinEmbedding(SurfaceMesh& mesh, const io::PointArrays& arrays, std::vector<TetEmbedding>& embedding,
                     const char* tetLabel = kEmbedTetLabel, const char* weightsArray = kEmbedWeightsArray);

} // namespace hs::scene::detail
