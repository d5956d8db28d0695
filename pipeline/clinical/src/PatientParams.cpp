#include "hs/clinical/PatientParams.h"

#include "EnumKey.h"

#include <tuple>

namespace hs::clinical {

std::string_view toString(CyclePhase value) {
    switch (value) {
    case CyclePhase::Menstrual:
        return "menstrual";
    case CyclePhase::Proliferative:
        return "proliferative";
    case CyclePhase::Secretory:
        return "secretory";
    }
    return "proliferative";
}

bool fromString(std::string_view key, CyclePhase& out) {
    return detail::enumFromKey(key, kCyclePhases, out);
}

double typicalEndometrialThicknessMm(const PatientParams& patient) {
    if (patient.menopausal || !patient.cyclePhase)
        return 3.0; // <= 4 mm without hormone therapy (ACOG 2018); mean 3.8 +- 2.3 mm (Hebbar et al. 2014)
    switch (*patient.cyclePhase) {
    case CyclePhase::Menstrual:
        return 3.0; // 2-4 mm
    case CyclePhase::Proliferative:
        return 8.0; // 5-7 mm early, up to 11 mm late
    case CyclePhase::Secretory:
        return 11.5; // 7-16 mm
    }
    return 8.0;
}

bool operator==(const PatientParams& a, const PatientParams& b) {
    return std::tie(a.ageYears, a.parity, a.gravidity, a.heightCm, a.weightKg, a.menopausal, a.cyclePhase) ==
           std::tie(b.ageYears, b.parity, b.gravidity, b.heightCm, b.weightKg, b.menopausal, b.cyclePhase);
}
bool operator!=(const PatientParams& a, const PatientParams& b) {
    return !(a == b);
}

} // namespace hs::clinical
