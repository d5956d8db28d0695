#pragma once
/// The patient parameters a gynaecologist knows, which decide the shape of a healthy uterus (Sierra et al. 2004).
/// The case file's patient block and the shape model's conditioning use this one struct.
///
/// Defaults describe the case's default patient and cite the domain sheet (UTERUS.md, "line N"). Ranges are
/// checked where they matter: a case's by scene::checkCase() (hs/scene/CaseSpec.h, limits), the shape model's by
/// anatomy::validatePatient() (hs/anatomy/PatientParams.h).

namespace hs::clinical {

struct PatientParams {
    double ageYears = 35.0;  ///< years; 35: the 35-45 band (line 41-42), uterine length near its peak at 40 (line 30)
    int parity = 1;          ///< births (>= 20 weeks of gestation); 1: primiparous, length 61.5 mm (line 34)
    int gravidity = 1;       ///< pregnancies, including the births (>= parity); raises length, width and AP (line 31)
    double heightCm = 165.0; ///< cm; dimensions correlate with height (line 32-33); a typical adult woman
    double weightKg = 65.0;  ///< kg; no correlation with BMI (line 32-33); BMI 23.9 with the default height
    bool menopausal = false; ///< postmenopausal; AP shrinks ~22 % (line 43); true needs age >= 40, false age <= 60
};

bool operator==(const PatientParams& a, const PatientParams& b);
bool operator!=(const PatientParams& a, const PatientParams& b);

} // namespace hs::clinical
