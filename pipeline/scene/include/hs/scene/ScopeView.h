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
#include <string>
#include <vector>

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

/// A tubal ostium as the scope sees it from a point in the cavity.
struct OstiumSight {
    std::string side;             ///< "left" or "right": the patient's side, -x or +x of the viewpoint
    Vec3 centreMm;                ///< area-weighted centre of the ostium's faces
    std::size_t faces = 0;        ///< its "ostium" faces on the visual surface
    double visibleFraction = 0.0; ///< of its faces' area: those whose centre the sight line reaches before any face
    /// What hides the rest, the most first: the id of a pathology (its "contact" faces are in the way) or "wall".
    std::vector<std::string> hiddenBy;
};

/// Where the scope looks round the cavity from: the cavity's middle (halfway from the internal os to the fundus
/// point) when it lies in no tet of `scene` and at least half the scope's diameter from its visual surface; else
/// (a pathology on a stalk may hang in the middle of the cavity) the point of the passage's route inside the cavity,
/// with room for the scope, nearest the middle; the middle when the route has none.
[[nodiscard]] Vec3 cavityViewpoint(const Scene& scene, const ScopePassage& passage);

/// The ostia of `scene` (its visual surface's "ostium" faces, split by side) and how much of each is in sight from
/// `eyeMm`: a sight line to a face's centre is blocked when it crosses a face of the visual surface other than an
/// ostium's more than 0.2 mm before it (a pathology in the way, or the lip of a deep recess; the funnel's own rim,
/// seen obliquely, still shows the opening). Zero, one or two entries, left first: an ostium a pathology covers has
/// no faces left. InvalidInput when the scene has no ostium label.
[[nodiscard]] Result<std::vector<OstiumSight>> ostiaInSight(const Scene& scene, const Vec3& eyeMm);

} // namespace hs::scene
