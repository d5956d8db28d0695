#pragma once
/// The standard measures of a statistical shape model (Styner et al. 2003; Davies 2002): compactness,
/// generalisation, specificity, plus the conditioning error of the patient-driven model.

#include "hs/anatomy/Cohort.h"
#include "hs/anatomy/ShapeModel.h"
#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/Timings.h"

#include <cstdint>
#include <string>
#include <vector>

namespace hs::anatomy {

struct ModelEvaluationParams {
    int specificitySamples = 1000;  ///< unconditional samples compared with the training set
    int generalizationFolds = 0;    ///< leave-one-out folds, spread over the training set; 0: every shape
    int conditioningPatients = 200; ///< patients drawn from the cohort population for the conditioning error
    std::uint64_t seed = 7;
};

/// Error of one clinical dimension of mean(patient) against the dimension the published relations request.
struct ConditioningError {
    std::string dimension;  ///< "lengthMm", "widthMm", ...
    double meanAbsMm = 0.0; ///< mean |predicted - requested|, mm
    double biasMm = 0.0;    ///< mean (predicted - requested), mm
    double maxAbsMm = 0.0;
};

struct ModelEvaluation {
    std::vector<double> modeVariance;        ///< compactness: variance per kept mode, mm^2
    std::vector<double> cumulativeExplained; ///< fraction of the training variance explained by modes 1..i
    double generalizationMm = 0.0;           ///< leave-one-out: mean vertex distance of the reconstruction, mm
    double generalizationSdMm = 0.0;         ///< over folds
    int folds = 0;
    double specificityMm = 0.0;   ///< mean vertex distance of a sample to its nearest training shape, mm
    double specificitySdMm = 0.0; ///< over samples
    int specificitySamples = 0;
    std::vector<ConditioningError> conditioning; ///< empty without a template layout or conditioning
    StageTimings timings;
};

/// Evaluates `model` against the training set it was built from (aligned once by Procrustes; the folds re-run only
/// the PCA). The conditioning error needs the uterus template; for other models it is left empty.
[[nodiscard]] Result<ModelEvaluation> evaluateShapeModel(const ShapeModel& model, const TrainingSet& training,
                                                         const ModelEvaluationParams& params = {},
                                                         Progress& progress = Progress::none());

} // namespace hs::anatomy
