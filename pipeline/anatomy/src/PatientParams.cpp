#include "hs/anatomy/PatientParams.h"

#include <cmath>
#include <sstream>

namespace hs::anatomy {

namespace {

constexpr double kMenopauseMinAge = 40.0;    ///< years; earlier menopause is premature ovarian insufficiency
constexpr double kPremenopauseMaxAge = 60.0; ///< years; beyond the cohort's range of ages at menopause

std::string formatValue(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

Status checkRange(const ParamRange& range, double value) {
    if (std::isfinite(value) && value >= range.min && value <= range.max)
        return {};
    return fail(ErrorCode::InvalidInput, "patient parameter " + range.name + " = " + formatValue(value) +
                                             " is outside the supported range [" + formatValue(range.min) + ", " +
                                             formatValue(range.max) + "] " + range.unit);
}

} // namespace

const std::vector<ParamRange>& supportedPatientRanges() {
    static const std::vector<ParamRange> ranges = {
        {"ageYears", 18.0, 85.0, "years"}, {"parity", 0.0, 6.0, "births"},  {"gravidity", 0.0, 10.0, "pregnancies"},
        {"heightCm", 140.0, 195.0, "cm"},  {"weightKg", 35.0, 160.0, "kg"},
    };
    return ranges;
}

Status validatePatient(const clinical::PatientParams& patient) {
    const auto& r = supportedPatientRanges();
    HS_TRY(checkRange(r[0], patient.ageYears));
    HS_TRY(checkRange(r[1], patient.parity));
    HS_TRY(checkRange(r[2], patient.gravidity));
    HS_TRY(checkRange(r[3], patient.heightCm));
    HS_TRY(checkRange(r[4], patient.weightKg));
    if (patient.gravidity < patient.parity)
        return fail(ErrorCode::InvalidInput, "patient parameter gravidity = " + std::to_string(patient.gravidity) +
                                                 " is below parity = " + std::to_string(patient.parity) +
                                                 " (every birth is a pregnancy)");
    if (patient.menopausal && patient.ageYears < kMenopauseMinAge)
        return fail(ErrorCode::InvalidInput, "patient parameter menopausal = yes needs ageYears in [" +
                                                 formatValue(kMenopauseMinAge) + ", 85] years, got " +
                                                 formatValue(patient.ageYears));
    if (!patient.menopausal && patient.ageYears > kPremenopauseMaxAge)
        return fail(ErrorCode::InvalidInput, "patient parameter menopausal = no needs ageYears in [18, " +
                                                 formatValue(kPremenopauseMaxAge) + "] years, got " +
                                                 formatValue(patient.ageYears));
    return {};
}

} // namespace hs::anatomy
