#pragma once
/// The particle mesher: augmented voxel space, particles, relaxation, Delaunay, sliver removal
/// (Sierra, Zátonyi, Bajka, Székely, Harders, "Coherent Scene Generation for Surgical Simulators", 2004).

#include "hs/core/Progress.h"
#include "hs/meshing/MeshTypes.h"

namespace hs::meshing {

using ParticleMeshParams = MeshParams;
using ParticleMeshResult = MeshResult;

/// Fills every region of `body` with near-regular tetrahedra; each tet carries the region id of the region it lies
/// in, interfaces are shared faces. Deterministic: the same body, params and seed give the same mesh for any thread
/// count. Fails with InvalidInput on an invalid body (see validate(const RegionModel&)) or parameters,
/// LimitExceeded when the requested size is above kMaxVertices, Cancelled on request (checked at least every
/// few milliseconds), BackendFailure when CGAL fails.
[[nodiscard]] Result<ParticleMeshResult> meshParticles(const RegionModel& body, const ParticleMeshParams& params,
                                                       Progress& progress = Progress::none());

} // namespace hs::meshing
