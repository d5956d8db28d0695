#pragma once
/// Procedural blood vessels grown on a surface.
///
/// Branching trees grown by space colonisation (Runions et al., "Modeling trees with a space colonization
/// algorithm", 2007), here restricted to the surface: attraction points are scattered over the faces of each
/// appearance class, trees grow from roots in steps along the surface's tangent plane towards them, and attraction
/// points close to a branch are consumed. Radii follow Murray's law (r_parent^3 = sum of r_child^3, Murray 1926) from
/// a leaf radius up. Per class: a fine capillary network on endometrium, larger tortuous vessels over myomas, a
/// central vessel from the base of each polyp.

#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/Vec3.h"
#include "hs/texture/Exemplars.h"

#include <array>
#include <cstdint>
#include <vector>

namespace hs::texture {

/// Growth parameters of one appearance class.
struct VesselClassParams {
    double attractorsPerMm2 = 0.3; ///< density of attraction points on the class's faces, 1/mm^2
    double rootsPerMm2 = 0.002;    ///< density of roots (at least one per connected patch), 1/mm^2
    double stepMm = 0.6;           ///< growth step, mm
    double influenceMm = 3.0;      ///< attraction radius, mm
    double killMm = 0.8;           ///< an attraction point this close to a node is consumed, mm
    double leafRadiusMm = 0.03;    ///< radius of the terminal segments, mm
    double maxRadiusMm = 0.25;     ///< radius cap near the roots, mm
    double tortuosity = 0.1;       ///< random turn per step relative to the attraction direction (0..1)
    double contrast = 0.6;         ///< how strongly the vessels show in the albedo (0..1)
};

struct VesselParams {
    std::array<VesselClassParams, kAppearanceCount> perClass = defaultVesselClassParams();
    int maxIterations = 400;        ///< growth steps
    std::int64_t maxNodes = 400000; ///< guard against runaway growth
    std::uint64_t seed = 1;

    static std::array<VesselClassParams, kAppearanceCount> defaultVesselClassParams();
};

struct VesselSegment {
    Vec3 a, b;            ///< mm, on the surface
    double radiusA = 0.0; ///< mm at a
    double radiusB = 0.0; ///< mm at b
    Appearance appearance = Appearance::Endometrium;
    float contrast = 0.6f;
};

struct VesselNetwork {
    std::vector<VesselSegment> segments;
    std::array<int, kAppearanceCount> roots{}; ///< trees per class
    std::array<int, kAppearanceCount> nodes{}; ///< nodes per class
};

/// Grows the vessels on `surface`, class by class. `faceAppearance` has one entry per face. InvalidInput when it
/// does not match, Cancelled on request.
[[nodiscard]] Result<VesselNetwork> growVessels(const SurfaceMesh& surface,
                                                const std::vector<Appearance>& faceAppearance,
                                                const VesselParams& params, Progress& progress = Progress::none());

/// A vessel seen through the mucosa over it (docs/texture.md, "Vessels beneath the surface"): the share of the light
/// the mucosa remits that a vessel of `radiusMm`, its axis `distanceMm` beside the point along the surface, takes away,
/// per channel (red, green, blue: 630, 550 and 470 nm), 0..1. The vessel lies with its top kVesselCoverMm under the
/// surface; blood absorbs across its mean chord (whole blood, [Prahl1999]); the light that reaches its depth and comes
/// back falls as exp(-2 mu_eff z) in the diffusion approximation, mu_eff = sqrt(3 mu_a (mu_a + mu_s')) of the mucosa
/// ([Jacques2013]); and the shadow spreads sideways over about the depth of its upper half, as diffuse light does. Red
/// reaches far, green and blue a few tenths of a millimetre: a capillary just under the surface takes green and blue
/// (it shows red), a deeper, wider vessel a little of each and over a wider band (darker, duller, softer), as veins
/// under skin do ([Kienle1996]).
/// `extraSpreadMm` widens the sideways spread in quadrature (a texel's sampling), keeping the shadow's integral.
std::array<double, 3> vesselShadow(double radiusMm, double distanceMm, double extraSpreadMm = 0.0);
/// The vessel's axis under the surface, mm: its radius plus kVesselCoverMm.
double vesselDepthMm(double radiusMm);
/// How far sideways its shadow spreads (the Gaussian's deviation), mm: its cover and half its radius, the depth at
/// which its upper half takes the light.
double vesselSpreadMm(double radiusMm);
/// How far beside its axis a vessel's shadow reaches, mm (its radius and 3.5 spreads: beyond, vesselShadow is below
/// 3e-4 of its peak).
double vesselShadowReachMm(double radiusMm);
/// The tissue over a vessel's top, mm: a choice (a simple columnar epithelium and the stroma's thin layer over the
/// subepithelial capillaries; no measurement of their depth in the endometrium was found).
inline constexpr double kVesselCoverMm = 0.03;

} // namespace hs::texture
