#pragma once
/// Synthetic cohort: patients drawn from realistic distributions, organ shapes from the published morphometric
/// relations (docs/anatomy.md lists the source of every relation) plus natural variation within the published
/// spread. The default statistical shape model is learned from it; users with segmented data learn from theirs.

#include "hs/anatomy/PatientParams.h"
#include "hs/anatomy/UterusGenerator.h"
#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/Rng.h"
#include "hs/core/Timings.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hs::anatomy {

struct CohortParams {
    int size = 400;                ///< members (>= 300 for the default model)
    std::uint64_t seed = 20040101; ///< same seed, same cohort
    TemplateLayout layout{};       ///< template resolution of every member
};

struct CohortMember {
    clinical::PatientParams patient;
    double menopauseAgeYears = 51.0; ///< years; the age at which this woman's menopause happens (hidden variable)
    UterusShapeParams shape;         ///< including version and flexion
};

/// Shapes in correspondence, with the patient parameters of each: the input of the shape model.
struct TrainingSet {
    SurfaceMesh reference;                ///< triangles and labels shared by all shapes (points: the first shape)
    std::optional<TemplateLayout> layout; ///< set when the shapes are instances of the uterus template
    std::vector<std::vector<Vec3>> shapes;
    std::vector<clinical::PatientParams> patients;
};

struct CohortResult {
    std::vector<CohortMember> members;
    /// Organ of each member with version 0: version is a pose (the organ's tilt in the pelvis), not a shape; the
    /// model draws it separately (see ShapeModel::sample).
    TrainingSet training;
    StageTimings timings;
    std::vector<std::string> warnings; ///< e.g. how many cavities the wall rule narrowed
};

/// A patient from the cohort's population (ages of women undergoing hysteroscopy, parity by age, height, weight).
/// Also returns her age at menopause (the cohort decides menopausal status from it).
clinical::PatientParams samplePatient(Rng& rng, double* menopauseAgeYears = nullptr);

/// A patient drawn uniformly over the supported ranges (menopausal status by age: never below 40, always above 60,
/// in between with a probability rising linearly). For checks over the whole supported range.
clinical::PatientParams sampleSupportedPatient(Rng& rng);

/// The expected shape for a patient by the published relations, without natural variation (version 0, the
/// population's mean flexion; menopause assumed at 51 years). The reference of the conditioning error.
UterusShapeParams expectedShape(const clinical::PatientParams& patient);

/// A dimension as the published relations expect it for a patient: the mean and the standard deviation of the
/// natural variation around it (mm). mean +- 1.96 sd is the patient's 95 % range.
struct ExpectedDimension {
    double mean = 0.0;
    double sd = 0.0;
    double low() const { return mean - 1.96 * sd; }
    double high() const { return mean + 1.96 * sd; }
};

/// The clinical dimensions of a patient's uterus by the published relations, with the spread of the natural
/// variation that sampleShape() draws (menopause assumed at 51 years, as expectedShape()).
struct ExpectedDimensions {
    ExpectedDimension lengthMm;
    ExpectedDimension widthMm;
    ExpectedDimension apDepthMm;
    ExpectedDimension cavityLengthMm;
    ExpectedDimension cavityWidthMm;
    ExpectedDimension fundalWallMm;
    ExpectedDimension cervixLengthMm;
};
ExpectedDimensions expectedDimensions(const clinical::PatientParams& patient);

/// A shape for a patient: the relations plus natural variation.
UterusShapeParams sampleShape(const clinical::PatientParams& patient, double menopauseAgeYears, Rng& rng);

/// Draws `params.size` members and builds their organs. Fails with InvalidInput for size < 10, Cancelled on
/// request.
[[nodiscard]] Result<CohortResult> generateCohort(const CohortParams& params, Progress& progress = Progress::none());

} // namespace hs::anatomy
