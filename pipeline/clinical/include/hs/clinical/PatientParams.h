#pragma once
/// The patient parameters a gynaecologist knows, which decide the shape of a healthy uterus (Sierra et al. 2004).
/// The case file's patient block and the shape model's conditioning use this one struct.
///
/// Defaults describe the case's default patient and cite their sources by key (docs/references.md). Ranges are
/// checked where they matter: a case's by scene::checkCase() (hs/scene/CaseSpec.h, limits), the shape model's by
/// anatomy::validatePatient() (hs/anatomy/PatientParams.h).

#include <array>
#include <optional>
#include <string_view>

namespace hs::clinical {

/// Phase of the menstrual cycle on the day of the hysteroscopy; it sets the endometrium's thickness.
enum class CyclePhase {
    Menstrual,     ///< "menstrual": days 1-4
    Proliferative, ///< "proliferative": after menstruation until ovulation; when office hysteroscopy is scheduled
    Secretory,     ///< "secretory": after ovulation
};
constexpr std::array<CyclePhase, 3> kCyclePhases{CyclePhase::Menstrual, CyclePhase::Proliferative,
                                                 CyclePhase::Secretory};
std::string_view toString(CyclePhase value); ///< "menstrual", "proliferative", "secretory"
bool fromString(std::string_view key, CyclePhase& out);

struct PatientParams {
    double ageYears = 35.0;  ///< years; 35: the 35-45 band [FundusMRI]; length peaks at 40 [Verguts2013]
    int parity = 1;          ///< births (>= 20 weeks of gestation); 1: primiparous, length 61.5 mm [IraqParity]
    int gravidity = 1;       ///< pregnancies, including the births (>= parity); raises length, width, AP [Verguts2013]
    double heightCm = 165.0; ///< cm; dimensions correlate with height [Gao2018]; a typical adult woman
    double weightKg = 65.0;  ///< kg; no correlation with BMI [Gao2018]; BMI 23.9 with the default height
    bool menopausal = false; ///< postmenopausal; AP shrinks ~22 % [Sokalska2008]; true needs age >= 40, false age <= 60
    /// Premenopausal patients only (unset after menopause). Proliferative: hysteroscopy is done then, which is also
    /// why the endometrium's default stiffness is the proliferative one [Du2021].
    std::optional<CyclePhase> cyclePhase = CyclePhase::Proliferative;
};

/// The typical endometrial thickness (mm) of a patient, as transvaginal ultrasound measures it: both layers,
/// anterior and posterior, across the cavity in the mid-sagittal plane (docs/anatomy.md, "Tissue layers", cites the
/// sources): menstrual 3 (2-4), proliferative 8 (5-11), secretory 11.5 (7-16), postmenopausal 3 (<= 4).
double typicalEndometrialThicknessMm(const PatientParams& patient);

bool operator==(const PatientParams& a, const PatientParams& b);
bool operator!=(const PatientParams& a, const PatientParams& b);

} // namespace hs::clinical
