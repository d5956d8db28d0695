// Distended cavity volume from the Bajka et al. 2009 fit.

#include "hs/scene/Hydrometra.h"

#include "Format.h"
#include "hs/scene/CaseSpec.h"

#include <cmath>

namespace hs::scene {

double hydrometraVolumeAtFitPressureMl(double uterineVolumeMl) {
    // Bajka et al., Surg Endosc 2009: y = 0.00037 x^2 + 0.036 x (R^2 0.74), the better of the two published fits.
    return 0.00037 * uterineVolumeMl * uterineVolumeMl + 0.036 * uterineVolumeMl;
}

Result<Hydrometra> computeHydrometra(double uterineVolumeMl, double pressureKpa) {
    if (!std::isfinite(uterineVolumeMl) || uterineVolumeMl <= 0.0)
        return fail(ErrorCode::InvalidInput,
                    "uterine volume " + detail::formatNumber(uterineVolumeMl) + " mL must be a positive number");
    if (!limits::kHydrometraPressureKpa.contains(pressureKpa))
        return fail(ErrorCode::InvalidInput, "hydrometra pressure " + detail::formatNumber(pressureKpa) +
                                                 " kPa is outside " +
                                                 detail::formatRange(limits::kHydrometraPressureKpa));
    Hydrometra h;
    h.pressureKpa = pressureKpa;
    h.uterineVolumeMl = uterineVolumeMl;
    const double atFit = hydrometraVolumeAtFitPressureMl(uterineVolumeMl);
    h.cavityVolumeMl = atFit * (pressureKpa / kHydrometraFitPressureKpa);
    h.extrapolated = atFit < kHydrometraMinMeasuredMl || atFit > kHydrometraMaxMeasuredMl;
    return h;
}

} // namespace hs::scene
