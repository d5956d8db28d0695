#pragma once
/// A small, complete Scene made in code for the package tests: a block of tetrahedra (each cube of an n^3 grid
/// split into six Kuhn tets) with a "myoma" region in the middle, its boundary as the visual surface with planar
/// UVs, patterned maps, labels and the default case. Everything is a function of the arguments.

#include "hs/scene/Scene.h"

#include <cstdint>

namespace hs::test {

struct SyntheticSceneOptions {
    int cells = 4;        ///< cubes per axis
    double sizeMm = 40.0; ///< edge of the block, mm
    int mapSize = 16;     ///< pixels per side of each map
    double heterogeneity = 0.0;
    std::uint64_t seed = 7;
};

scene::Scene syntheticScene(const SyntheticSceneOptions& options = {});

} // namespace hs::test
