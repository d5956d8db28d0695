#pragma once
/// Haptic frames for the tests: a flat wall across the canal's axis in front of the pivot, as the physics would
/// publish it with the scope touching it.

#include "hs/sim/HapticFrame.h"

#include <memory>

namespace hs::test {

/// Pivot at the origin, canal axis +z, anterior +y, the patient's left -x (Scope.h's frame).
sim::ScopeFrame testPivot();
/// A wall at z = `wallZ` mm facing the pivot, with the given stiffness under the tip (its compliance, in the frame),
/// the physics' scope's tip just touching it (insertion wallZ - radius) with no force: one contact at the tip whose
/// gap falls 1 mm per mm of insertion.
std::shared_ptr<const sim::HapticFrame> wallFrame(double wallZ = 40.0, double stiffnessNPerMm = 0.3);

} // namespace hs::test
