#pragma once
/// Where a rigid hysteroscope looks from and to: the pose of its camera for a given insertion along the cervical
/// canal, optic angle and roll (the workstation's hysteroscopic preview; the simulator's scope kinematics use the
/// same convention), and a view of a region from inside the cavity (a clinician's review visits each pathology).
///
/// Frame: the scene's (the organ's) mm frame, in which +y is anterior. The shaft runs from the external os through
/// the internal os. An oblique optic looks `opticDeg` off the shaft; at roll 0 it looks towards anterior, and the
/// roll turns that direction about the shaft (the light post's rotation). Optics 0/12/15/30/70 degrees,
/// office scopes typically 30 degrees and 2.9 mm (docs/references.md [Bradley]).

#include "hs/core/Result.h"
#include "hs/core/Vec3.h"
#include "hs/scene/ScopePassage.h"

#include <cstdint>

namespace hs::scene {

struct Scene;

struct ScopeView {
    Vec3 eyeMm;     ///< the lens at the scope's tip
    Vec3 direction; ///< unit, where the optic looks
    Vec3 up;        ///< unit, perpendicular to `direction`: the image's up (the light post's side at roll 0)
    Vec3 shaft;     ///< unit, along the scope from its handle to its tip
};

/// The view of a scope whose tip is `insertionMm` beyond the external os along the canal axis (negative: outside
/// it), with a `opticDeg` optic (0-90) turned by `rollDeg` about the shaft. InvalidInput for landmarks whose os
/// coincide or an optic outside 0-90 degrees.
[[nodiscard]] Result<ScopeView> scopeView(const ScopeLandmarks& landmarks, double insertionMm, double opticDeg,
                                          double rollDeg);

/// A view of region `regionId` of `scene` from inside the cavity: the eye `distanceMm` from the region's centre
/// (the mean of its tets' centres) on the line towards the cavity's middle (between the internal os and the
/// fundus point), looking at that centre. InvalidInput when the region has no tets.
[[nodiscard]] Result<ScopeView> viewOfRegion(const Scene& scene, const ScopeLandmarks& landmarks, std::int32_t regionId,
                                             double distanceMm);

} // namespace hs::scene
