#pragma once
/// The patient parameters a gynaecologist knows, which decide the shape of a healthy uterus (Sierra et al. 2004).
///
/// The scene's CaseSpec maps its patient block onto this struct. Each field has a supported range: the range the
/// default model's synthetic cohort covers. Values outside it are rejected, never extrapolated.

#include "hs/core/Result.h"

#include <string>
#include <vector>

namespace hs::anatomy {

struct PatientParams {
    double ageYears = 35.0;  ///< years; supported [18, 85]
    int parity = 0;          ///< births (>= 20 weeks of gestation); supported [0, 6]
    int gravidity = 0;       ///< pregnancies, including the births; supported [parity, 10]
    double heightCm = 164.0; ///< cm; supported [140, 195]
    double weightKg = 65.0;  ///< kg; supported [35, 160]; no published effect on uterine size (Gao 2018)
    bool menopausal = false; ///< postmenopausal; supported for ageYears >= 40 (premenopausal for ageYears <= 60)
};

/// One supported range, for error messages, help texts and the model file's metadata.
struct ParamRange {
    std::string name; ///< field name as in PatientParams ("ageYears")
    double min = 0.0;
    double max = 0.0;
    std::string unit; ///< "years", "cm", ...
};

/// The supported ranges of the numeric fields, in field order.
const std::vector<ParamRange>& supportedPatientRanges();

/// Checks every field against its supported range (NaN and infinities included) and the cross-field rules
/// (gravidity >= parity; menopausal only from 40 years, premenopausal only up to 60). Fails with InvalidInput
/// naming the first offending parameter, its value and its range.
Status validatePatient(const PatientParams& patient);

} // namespace hs::anatomy
