#pragma once
/// Parameters and results shared by every tetrahedral meshing method (particle, TetGen, CGAL Mesh_3).

#include "hs/core/RegionModel.h"
#include "hs/core/Result.h"
#include "hs/core/TetMesh.h"
#include "hs/core/Timings.h"
#include "hs/meshing/QualityReport.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hs::meshing {

enum class MeshMethod {
    Particle, ///< this project's particle mesher (Sierra et al. 2004)
    TetGen,   ///< TetGen 1.5 "-pq" (optional backend, AGPL)
    Cgal,     ///< CGAL Mesh_3 with ODT, Lloyd, perturbation and exudation (optional backend)
};

/// "particle", "tetgen", "cgal".
std::string_view methodName(MeshMethod method);
std::optional<MeshMethod> parseMethod(std::string_view name);

/// How the particle seeds are placed in inner voxels.
enum class Seeding {
    Lattice, ///< body-centred cubic: a voxel corner and the voxel centre, jittered (default: Delaunay of BCC points
             ///< is a mesh of identical tets with 60/90 degree dihedral angles, so relaxation only has to fix the
             ///< boundary layer)
    Random,  ///< `particlesPerVoxel` uniformly random positions per voxel, as in Sierra et al. 2004
};

/// Largest mesh a request may ask for; beyond it meshing fails with LimitExceeded instead of allocating.
constexpr std::int64_t kMaxVertices = 20'000'000;

struct MeshParams {
    double targetEdgeLength = 0.0;   ///< mm; <= 0: derived from targetVertices, else 1/25 of the bbox diagonal
    std::int64_t targetVertices = 0; ///< approximate vertex count, used when targetEdgeLength <= 0 (0: unused)
    std::uint64_t seed = 1;          ///< same seed, same mesh (byte for byte)
    int threads = 0;                 ///< worker threads, 0: all cores; never changes the result

    // Particle method only.
    Seeding seeding = Seeding::Lattice;
    int particlesPerVoxel = 2;     ///< Seeding::Random, per inner voxel; surface voxels get their own sampling
    double latticeJitter = 0.0;    ///< Seeding::Lattice: seeded random offset, fraction of the voxel size
    int relaxationIterations = 20; ///< cap; relaxation stops earlier when particles no longer move
    double featureAngleDeg = 45.0; ///< surface edges whose normals differ by more are feature edges (kept sharp)
    /// Particle method: check the boundary against the input surfaces and add surface particles where it strays
    /// (docs/meshing.md, step 9). Off: the mesh as before the check (scenes, for now: "Bars on every scene").
    bool surfaceFidelity = true;
};

/// Output of every method.
struct MeshResult {
    TetMesh mesh;          ///< positive tets, region id per tet
    QualityReport quality; ///< measured against the input body
    StageTimings timings;  ///< per step (validate, voxelize, seed, relax, tetrahedralize, clean, improve, ...)
    std::vector<std::string> warnings;
    std::vector<double> relaxationEnergy; ///< particle method: interaction energy before each iteration
    double targetEdgeLength = 0.0;        ///< mm, the edge length used
};

/// The edge length the methods aim at: params.targetEdgeLength when > 0, else the one giving about
/// params.targetVertices vertices for this body (volume and surface area), else 1/25 of the bbox diagonal.
/// Fails with InvalidInput on a non-finite or negative value and LimitExceeded above kMaxVertices.
Result<double> resolveEdgeLength(const RegionModel& body, const MeshParams& params);

/// Expected vertex count of a mesh of `body` with edge length `edge` (mm).
double estimateVertexCount(const RegionModel& body, double edge);

} // namespace hs::meshing
