#pragma once
/// Baseline meshers behind the particle mesher's interface, for comparison. Each lives in its own optional target:
/// meshTetGen in hs_meshing_tetgen (TetGen 1.5 is AGPL), meshCgal in hs_meshing_cgal (CGAL Mesh_3). Link
/// hs_meshing_methods and call meshWith() to choose at run time.

#include "hs/core/LibraryVersions.h"
#include "hs/core/Progress.h"
#include "hs/meshing/MeshTypes.h"

namespace hs::meshing {

/// TetGen "-pq1.2a<V>A": constrained Delaunay refinement with radius-edge ratio 1.2, volume bound from the target
/// edge length, region attributes. Seed and threads are ignored (TetGen is deterministic and serial).
[[nodiscard]] Result<MeshResult> meshTetGen(const RegionModel& body, const MeshParams& params,
                                            Progress& progress = Progress::none());

/// CGAL Mesh_3 on a polyhedral complex (one patch per surface, with sharp features protected), then ODT, Lloyd,
/// perturbation and exudation. Deterministic for a seed; single-threaded.
[[nodiscard]] Result<MeshResult> meshCgal(const RegionModel& body, const MeshParams& params,
                                          Progress& progress = Progress::none());

/// Whether this build has `method`.
bool methodAvailable(MeshMethod method);

/// The libraries `method` adds to hs::meshing's own (meshing::libraryVersions): "tetgen" for TetGen (read from
/// tetgen.h at build time, which has no version macro); nothing for the others or when this build lacks the method.
LibraryVersions methodLibraryVersions(MeshMethod method);

/// Runs `method` (Unsupported when this build lacks it).
[[nodiscard]] Result<MeshResult> meshWith(MeshMethod method, const RegionModel& body, const MeshParams& params,
                                          Progress& progress = Progress::none());

} // namespace hs::meshing
