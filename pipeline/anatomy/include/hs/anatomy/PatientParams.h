#pragma once
/// The patients the shape model supports (clinical::PatientParams, hs/clinical/PatientParams.h): each field has a
/// supported range, the range the default model's synthetic cohort covers: age [18, 85] years, parity [0, 6]
/// births, gravidity [parity, 10] pregnancies, height [140, 195] cm, weight [35, 160] kg (no published effect on
/// uterine size, Gao 2018); menopausal only from 40 years, premenopausal only up to 60. Values outside are
/// rejected, never extrapolated.

#include "hs/clinical/PatientParams.h"
#include "hs/core/Result.h"

#include <string>
#include <vector>

namespace hs::anatomy {

/// One supported range, for error messages, help texts and the model file's metadata.
struct ParamRange {
    std::string name; ///< field name as in clinical::PatientParams ("ageYears")
    double min = 0.0;
    double max = 0.0;
    std::string unit; ///< "years", "cm", ...
};

/// The supported ranges of the numeric fields, in field order.
const std::vector<ParamRange>& supportedPatientRanges();

/// Checks every field against its supported range (NaN and infinities included) and the cross-field rules
/// (gravidity >= parity; menopausal only from 40 years, premenopausal only up to 60). Fails with InvalidInput
/// naming the first offending parameter, its value and its range.
Status validatePatient(const clinical::PatientParams& patient);

} // namespace hs::anatomy
