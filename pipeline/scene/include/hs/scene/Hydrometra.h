#pragma once
/// Hydrometra: the volume of the uterine cavity distended by fluid at a given pressure.
///
/// Bajka et al. (Surg Endosc 2009) measured the cavity volume at 20 kPa (150 mmHg) in excised uteri: 0.6-11.4 mL,
/// fitted by y = 0.00037 x^2 + 0.036 x (R^2 0.74), x = uterine volume in mL (docs/references.md [Bajka2009]). Only that
/// one pressure was published; below it the volume is interpolated linearly in pressure from 0 mL at 0 kPa (an
/// assumption of this project, documented in docs/scene-format.md; the loading branch of the hysteresis).

#include "hs/core/Result.h"

#include <vector>

namespace hs::scene {

/// The pressure at which the fit was measured, kPa.
constexpr double kHydrometraFitPressureKpa = 20.0;
/// The measured cavity volumes, mL; outside this range the fit extrapolates.
constexpr double kHydrometraMinMeasuredMl = 0.6;
constexpr double kHydrometraMaxMeasuredMl = 11.4;

/// A point of the scene's own tissue model's curve: the cavity's opening over rest at a pressure.
struct HydrometraPoint {
    double pressureKpa = 0.0;     ///< kPa
    double cavityOpeningMl = 0.0; ///< mL over the cavity's rest volume
};

/// The pressures of the model's curve, mmHg: 20-100, the range of the cited distension pressures.
inline constexpr double kHydrometraCurveMmHg[] = {20.0, 40.0, 60.0, 80.0, 100.0};

struct Hydrometra {
    double pressureKpa = 0.0;     ///< kPa, distension pressure (the case's scene.hydrometraPressureKpa)
    double uterineVolumeMl = 0.0; ///< mL, the fit's input
    double cavityVolumeMl = 0.0;  ///< mL, distended cavity volume at pressureKpa
    bool extrapolated = false;    ///< the 20 kPa value lies outside the measured 0.6-11.4 mL
    /// The scene's tissue model's curve (generate: a static solve of hs::mechanics::UterusModel at
    /// kHydrometraCurveMmHg), what the simulator's distension reaches; empty in packages written before it.
    std::vector<HydrometraPoint> modelCurve;
};

/// The model's curve at `pressureKpa`, linear between its points (and beyond its ends along the nearest segment);
/// 0 for an empty curve.
double modelOpeningMl(const Hydrometra& hydrometra, double pressureKpa);

/// Cavity volume at 20 kPa from the quadratic fit, mL.
double hydrometraVolumeAtFitPressureMl(double uterineVolumeMl);

/// The distended cavity at `pressureKpa` (0..20) for a uterus of `uterineVolumeMl` (> 0). InvalidInput outside.
[[nodiscard]] Result<Hydrometra> computeHydrometra(double uterineVolumeMl, double pressureKpa);

} // namespace hs::scene
