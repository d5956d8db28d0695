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

double modelOpeningMl(const Hydrometra& hydrometra, double pressureKpa) {
    const auto& c = hydrometra.modelCurve;
    if (c.empty())
        return 0.0;
    if (c.size() == 1)
        return c.front().pressureKpa > 0.0 ? c.front().cavityOpeningMl * pressureKpa / c.front().pressureKpa : 0.0;
    std::size_t i = 1;
    while (i + 1 < c.size() && c[i].pressureKpa < pressureKpa)
        ++i;
    const HydrometraPoint& a = c[i - 1];
    const HydrometraPoint& b = c[i];
    const double span = b.pressureKpa - a.pressureKpa;
    return span > 0.0
               ? a.cavityOpeningMl + (b.cavityOpeningMl - a.cavityOpeningMl) * (pressureKpa - a.pressureKpa) / span
               : a.cavityOpeningMl;
}

} // namespace hs::scene
