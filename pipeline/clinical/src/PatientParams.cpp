#include "hs/clinical/PatientParams.h"

#include <tuple>

namespace hs::clinical {

bool operator==(const PatientParams& a, const PatientParams& b) {
    return std::tie(a.ageYears, a.parity, a.gravidity, a.heightCm, a.weightKg, a.menopausal) ==
           std::tie(b.ageYears, b.parity, b.gravidity, b.heightCm, b.weightKg, b.menopausal);
}
bool operator!=(const PatientParams& a, const PatientParams& b) {
    return !(a == b);
}

} // namespace hs::clinical
