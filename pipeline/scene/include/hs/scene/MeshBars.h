#pragma once
/// The quality bars a scene's tetrahedral mesh is held to (docs/meshing.md, "Bars"): each one measured on the scene
/// itself, recorded in report.json, and a named warning of the scene and of `validate` when missed.

#include "hs/scene/Scene.h"

#include <string>
#include <vector>

namespace hs::scene {

/// Mean radius ratio (3 r_in / r_circ) of the tets, at least.
inline constexpr double kBarMeanRadiusRatio = 0.90;
/// Smallest dihedral angle of any tet, degrees, at least.
inline constexpr double kBarMinDihedralDeg = 17.0;
/// Two-sided Hausdorff distance between the mesh boundary and the body's surfaces, as a share of the body's
/// bounding-box diagonal, at most.
inline constexpr double kBarHausdorffRelative = 0.01;

struct MeshBar {
    std::string name;    ///< "mesh-radius-ratio", "mesh-min-dihedral", "mesh-slivers", "mesh-inverted",
                         ///< "mesh-hausdorff", "mesh-non-manifold"
    double value = 0.0;  ///< measured
    double limit = 0.0;  ///< the bar
    bool atLeast = true; ///< the value must be >= limit (else <= limit)
    bool met = true;
    std::string detail; ///< one sentence: what was measured against which bar
};

/// Every bar `quality` can be checked against, in a fixed order; the Hausdorff bar needs `hasReference`, the
/// manifold bar the boundary counts (packages written before they were measured lack them), else it is left out.
std::vector<MeshBar> meshBars(const MeshQuality& quality);

/// The bars missed, as "NAME: detail" warnings.
std::vector<std::string> missedMeshBars(const MeshQuality& quality);

} // namespace hs::scene
