#pragma once
/// Haptic frames for the tests: a flat wall across the canal's axis in front of the pivot.

#include "hs/sim/HapticFrame.h"

#include <memory>

namespace hs::test {

/// Pivot at the origin, canal axis +z, anterior +y, the patient's left -x (Scope.h's frame).
sim::ScopeFrame testPivot();
/// A wall at z = `wallZ` mm, 100 x 100 mm in 10 mm squares, facing the pivot (normals -z), with the given stiffness.
std::shared_ptr<const sim::HapticFrame> wallFrame(double wallZ = 40.0, double stiffnessNPerMm = 0.3);

} // namespace hs::test
