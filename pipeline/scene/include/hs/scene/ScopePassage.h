#pragma once
/// Can a rigid hysteroscope get in? The free space of a scene's tetrahedral body (the canal and the cavity are not
/// meshed) is measured along the widest route from outside the external os, up the cervical canal, through the
/// internal os to the fundus of the cavity. docs/scene-format.md ("Scope passage") describes the method.
///
/// Office hysteroscopes are 2.9-5 mm across; the internal os of a real uterus is 4-11 mm wide (docs/references.md
/// [Bradley], [Chen2020]), so a scene whose canal is narrower than the thinnest scope cannot be used for a
/// diagnostic exploration.

#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/TetMesh.h"
#include "hs/core/Vec3.h"
#include "hs/core/VoxelGrid.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hs::scene {

struct Scene;

/// Where the scope enters and where it has to go, mm, in the frame of the tet mesh.
struct ScopeLandmarks {
    Vec3 externalOsMm; ///< centre of the external os (the canal's outer opening)
    Vec3 internalOsMm; ///< centre of the internal os (where the canal opens into the cavity)
    Vec3 fundusMm;     ///< a point of the cavity near its fundus (between the tubal ostia)
    /// findScopeLandmarks: 2, or 1 when the ostium faces form a single cluster (a pathology covers the other
    /// ostium), and the fundus point is then that ostium's cornu. Not read by checkScopePassage.
    int ostiaFound = 2;
};

struct ScopePassageParams {
    double scopeDiameterMm = 2.9;     ///< mm, 1-10; 2.9 is the thinnest rigid office hysteroscope
    double voxelFraction = 0.2;       ///< voxel edge as a fraction of the diameter, 0.05-0.5 (0.58 mm for 2.9 mm)
    double straightLengthMm = 10.0;   ///< mm, 0-100: the straight stretch of scope ahead of the tip that must fit
    double startOffsetMm = 5.0;       ///< mm, 1-50: the route starts this far outside the external os, on the axis
    double fundusReachMm = 5.0;       ///< mm, 0.5-30: the route ends at any voxel this close to the fundus point
    std::int64_t maxVoxels = 1 << 24; ///< 1 to VoxelGrid's 2^31; a finer grid fails with LimitExceeded
};

/// Which part of the passage a point lies in, by its position along the canal axis (external -> internal os).
/// The os are short funnels, not planes: each is the zone within 2 mm of its landmark along the axis.
enum class PassagePart {
    Outside,    ///< more than 2 mm before the external os
    ExternalOs, ///< within 2 mm of the external os along the axis
    Canal,      ///< the cervical canal between the two os zones
    InternalOs, ///< within 2 mm of the internal os along the axis
    Cavity,     ///< more than 2 mm beyond the internal os
};
/// "outside", "external-os", "canal", "internal-os", "cavity".
std::string_view toString(PassagePart part);

/// One point of the route.
struct PassagePoint {
    Vec3 positionMm;
    double freeWidthMm = 0.0; ///< mm, twice the distance to the nearest tissue; 0 inside tissue
    double arcLengthMm = 0.0; ///< mm along the route from its start
    PassagePart part = PassagePart::Outside;
};

struct ScopePassage {
    double scopeDiameterMm = 0.0;
    ScopeLandmarks landmarks; ///< as given
    /// True when a free route reaches the fundus. False: the route ends where the free space reachable from the
    /// start comes nearest to the free space around the fundus; `narrowest` is that dead end (width 0) and
    /// `closedGapMm` the tissue between the two, about the thickness of the closure.
    bool open = false;
    double closedGapMm = 0.0; ///< mm (0 when open)
    /// A ball of the scope's diameter can be swept along the route: the narrowest free width >= the diameter.
    bool ballPasses = false;
    /// Also the straight stretch of `straightLengthMm` ahead of the tip fits everywhere along the route.
    bool straightPasses = false;
    PassagePoint narrowest; ///< the narrowest point of the route (first one from the start on a tie)
    /// The same for the route up to the cavity (outside, external os, canal, internal os): the canal alone, whatever
    /// pathologies narrow the cavity. canalOpen and canalPasses are open and ballPasses for this part; the canal is
    /// closed when the route's dead end lies before the cavity.
    PassagePoint narrowestCanal;
    bool canalOpen = false;
    bool canalPasses = false;
    double canalClosedGapMm = 0.0;  ///< mm, closedGapMm when the dead end is before the cavity
    PassagePoint narrowestStraight; ///< the tip position whose straight stretch ahead has the least room
    double straightWidthMm = 0.0;   ///< mm, free width along that stretch (twice its least clearance)
    /// From outside the external os to the fundus: voxel centres, each moved within a voxel across the route to
    /// where it has the most room.
    std::vector<PassagePoint> route;
    double voxelSizeMm = 0.0;
    Index3 gridDims{0, 0, 0};
    std::vector<std::string> warnings; ///< the start or the fundus point lies in tissue
};

/// Sweeps a rigid scope of `params.scopeDiameterMm` through the free space of `tets` from `startOffsetMm` outside
/// the external os to the fundus (docs/scene-format.md, "Scope passage"). Fails with InvalidInput for an invalid or
/// empty mesh, landmarks that are not finite, coincide or lie outside the mesh's box, or a parameter out of range (the
/// detail names it and its range); LimitExceeded when the voxel grid would be larger than `maxVoxels`; Cancelled on
/// request.
[[nodiscard]] Result<ScopePassage> checkScopePassage(const TetMesh& tets, const ScopeLandmarks& landmarks,
                                                     const ScopePassageParams& params = {},
                                                     Progress& progress = Progress::none());

/// The landmarks of a scene from its labels: the "cervical-canal" faces of the visual surface give the canal axis
/// (principal direction of the faces) and its two ends; the end nearer the "ostia" faces is the internal os; the
/// fundus point is the midpoint of the two ostia. InvalidInput naming the missing or degenerate label.
[[nodiscard]] Result<ScopeLandmarks> findScopeLandmarks(const Scene& scene);

/// The same from a surface and the indices of its canal and ostium faces.
[[nodiscard]] Result<ScopeLandmarks> findScopeLandmarks(const SurfaceMesh& surface,
                                                        const std::vector<std::int32_t>& canalFaces,
                                                        const std::vector<std::int32_t>& ostiumFaces);

} // namespace hs::scene
