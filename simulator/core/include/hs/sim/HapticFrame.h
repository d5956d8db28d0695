#pragma once
/// What the physics hands to the haptics loop after each step: the tissue surface the scope may touch (the
/// simulation mesh's boundary as the step left it), the contact stiffness to render, and the pivot. The haptics
/// loop computes forces at 1 kHz against the newest frame without waiting for the next (docs/simulator.md,
/// "Haptics"); frames are immutable once published (shared through std::shared_ptr<const HapticFrame>).

#include "hs/core/SurfaceMesh.h"
#include "hs/core/Vec3.h"
#include "hs/sim/Scope.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace hs::sim {

struct HapticFrame {
    std::uint64_t step = 0; ///< the physics step that produced it
    double timeS = 0.0;     ///< s, simulated time at that step
    ScopeFrame pivot;       ///< the cervical pivot and its axes
    ScopeConfig scope;      ///< the scope in use (diameter: the contact radius)
    /// The surface: points in mm and triangles wound outward from the tissue (on the cavity, pointing into it).
    /// The topology is shared between frames; only the points change.
    std::shared_ptr<const std::vector<Triangle>> triangles;
    std::vector<Vec3> pointsMm;
    double contactStiffnessNPerMm = 0.3;  ///< N/mm, the wall's local stiffness against the tip (from the materials)
    double pivotStiffnessNmmPerDeg = 2.0; ///< N*mm/degree, the cervix resisting the shaft's turn off the canal axis
    bool perforated = false;              ///< the tip has gone through the wall: no wall force at the tip
};

} // namespace hs::sim
