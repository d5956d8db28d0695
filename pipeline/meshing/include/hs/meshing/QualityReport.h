#pragma once
/// Quality of a tetrahedral mesh: element shape, and (given the input body) fidelity to the input surfaces.
/// Works on any TetMesh, also on meshes from other tools read from disk.

#include "hs/core/RegionModel.h"
#include "hs/core/TetMesh.h"
#include "hs/meshing/Geometry.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hs::meshing {

/// Tets whose smallest dihedral angle is below this are slivers (or needles, caps, wedges: all are bad for FEM).
constexpr double kSliverDihedralDeg = 10.0;

struct RegionVolume {
    std::int32_t regionId = 0;
    double meshVolume = 0.0;    ///< mm^3, sum of |tet volume| of the region
    double inputVolume = 0.0;   ///< mm^3, enclosed by the input surfaces (0 when no reference was given)
    double relativeError = 0.0; ///< |mesh - input| / input (0 without a reference)
};

struct QualityReport {
    std::size_t vertexCount = 0;
    std::size_t tetCount = 0;

    double meanRadiusRatio = 0.0; ///< 3 r_in / r_circ: 1 regular, 0 flat
    double minRadiusRatio = 0.0;
    double minDihedralDeg = 0.0; ///< smallest dihedral angle of the mesh, degrees
    double maxDihedralDeg = 0.0; ///< largest dihedral angle of the mesh, degrees
    double meanEdgeRatio = 0.0;  ///< longest / shortest edge per tet, averaged
    double maxEdgeRatio = 0.0;
    /// Tets per radius-ratio bucket [0, 0.1), [0.1, 0.2), ... [0.9, 1.0].
    std::array<std::size_t, 10> radiusRatioHistogram{};
    /// Tets per smallest-dihedral bucket [0, 10), [10, 20), ... [80, 90) degrees (no tet has a larger minimum).
    std::array<std::size_t, 9> minDihedralHistogram{};
    std::size_t sliverCount = 0;     ///< min dihedral < kSliverDihedralDeg
    std::size_t invertedCount = 0;   ///< signed volume < 0
    std::size_t degenerateCount = 0; ///< |volume| <= 1e-12 * (mean edge)^3
    /// The outer boundary (faces of one tet): edges shared by more than two of its faces, vertices whose faces form
    /// more than one fan (two parts of the mesh touching along an edge or at a point).
    std::size_t boundaryNonManifoldEdges = 0;
    std::size_t boundaryNonManifoldVertices = 0;

    /// The following need the input body (hasReference).
    bool hasReference = false;
    double boundingBoxDiagonal = 0.0;  ///< of the input, mm
    double hausdorffDistance = 0.0;    ///< two-sided, mesh boundary (incl. interfaces) vs input surfaces, mm
    double hausdorffRelative = 0.0;    ///< hausdorffDistance / boundingBoxDiagonal
    double volumeError = 0.0;          ///< largest relativeError over the regions
    std::vector<RegionVolume> regions; ///< per region id, ascending
};

/// Shape statistics of every tet; with `reference`, also the boundary Hausdorff distance and the per-region volume
/// errors against the enclosed volumes of the reference (RegionModel semantics: the innermost surface decides).
/// Runs on `threads` threads (0: hardware concurrency); the result does not depend on the thread count.
QualityReport measureQuality(const TetMesh& mesh, const RegionModel* reference = nullptr, int threads = 0);

/// The shape of every tet (what measureQuality summarises), for an inspector that colours or lists tets. Runs on
/// `threads` threads (0: hardware concurrency); the result does not depend on the thread count.
std::vector<TetShape> tetShapes(const TetMesh& mesh, int threads = 0);

/// The indices of the `count` tets with the smallest `value` (e.g. the radius ratios of tetShapes), smallest first,
/// ties by index.
std::vector<std::size_t> worstTets(const std::vector<double>& value, std::size_t count);

/// Volume enclosed per region id by a region model (void regions are left out), mm^3.
std::vector<RegionVolume> inputRegionVolumes(const RegionModel& model);

} // namespace hs::meshing
