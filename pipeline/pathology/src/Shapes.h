#pragma once
/// The three growth models. Each returns a closed, outward-oriented surface around `center`, before scaling to the
/// requested size (done by the caller).

#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/Rng.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/pathology/Pathology.h"

namespace hs::pathology::detail {

constexpr double kPi = 3.14159265358979323846;

/// Where and how big, in the organ frame (mm).
struct ShapeSpec {
    bool polyp = false;
    bool pedunculated = false; ///< a stalk from `base` to the head
    Vec3 center;               ///< myoma centre, or centre of the head
    Vec3 base;                 ///< stalk root, sunk into the wall (pedunculated and polyps)
    Vec3 intoWall;             ///< unit direction from the surface it grows from into the wall
    double radius = 10.0;      ///< nominal radius of the myoma or head
    double stalkRadius = 2.0;  ///< mm
    bool transmural = false;   ///< a hybrid myoma: reaches both the endometrium and the serosa
};

/// Skeleton + revolved contours: a skeleton curve (stalk and head axis, or the myoma's axis) and a planar contour
/// (smooth union of a capsule and a circle, or an ellipse) revolved around it with seeded lobulation.
SurfaceMesh skeletonShape(const ShapeSpec& spec, Rng& rng);

/// Parameters shared by the two field-based models.
struct GrowthTuning {
    double tissueResistance = 1.0;      ///< relative; the wall resists
    double yieldResistance = 0.35;      ///< relative; cavity and outside yield (grow about 3x as easily)
    double anisotropy = 0.3;            ///< extra proliferation along the wall's tangent plane
    double transmuralAnisotropy = 1.0;  ///< extra proliferation across the wall (hybrid myomas, which span it)
    int cellsPerDiameter = 26;          ///< CA voxels across the requested size
    double surfaceCellsPerRadius = 5.5; ///< CA surface: polygonization cells per nominal radius (about 4000 triangles)
    int particleCount = 1500;           ///< particles at the target volume
    const GrowthObserver* observe = nullptr; ///< shown the growth as it happens; never changes it
    std::size_t pathology = 0;               ///< the index the observer is told
};

/// Tells the observer (if any) one step of pathology `tuning.pathology`'s growth.
void emitFrame(const GrowthTuning& tuning, clinical::GrowthModel model, int step, bool last, std::vector<Vec3> points);
/// The skeleton model's frames: its finished surface's points, swept from the skeleton's root in four steps.
void emitSweptFrames(const GrowthTuning& tuning, const SurfaceMesh& shape, const ShapeSpec& spec);

/// Cellular automaton (Eden-type growth with surface tension): every step each empty face-neighbour of the tumour
/// becomes tumour with probability p0 (1 + 2 q) / r * (1 + a (d.t)^2), q the fraction of its neighbours already
/// tumour (fills concavities), r the local resistance (tissue or cavity), d the growth direction, t the wall's
/// tangent plane (a only in the wall: the fibres guide growth there); stops at the target volume. Surface: the
/// occupancy closed with a 2-voxel ball (no crevices), blurred, resampled to `surfaceCellsPerRadius`, marching
/// tetrahedra, Taubin smoothing and tangential relaxation; centred (volume centroid) on `center` unless stalked.
Result<SurfaceMesh> cellularAutomatonShape(const ShapeSpec& spec, const SurfaceMesh& organ, const GrowthTuning& tuning,
                                           Rng& rng, Progress& progress);

/// Particle growth: cells divide (faster where the tissue yields), push each other apart (short-range repulsion)
/// and are held together by a confinement that is strong in the wall and weak in the cavity. Surface from the
/// particle cloud as above.
Result<SurfaceMesh> particleShape(const ShapeSpec& spec, const SurfaceMesh& organ, const GrowthTuning& tuning, Rng& rng,
                                  Progress& progress);

/// Largest diameter of the head (points beyond the stalk, when there is one along `axis` from `base`).
double headDiameter(const std::vector<Vec3>& points, const Vec3& base, const Vec3& axis, double* stalkLength = nullptr);

} // namespace hs::pathology::detail
