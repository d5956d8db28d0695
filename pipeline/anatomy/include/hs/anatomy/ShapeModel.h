#pragma once
/// Statistical shape model of the uterus conditioned on patient parameters (Sierra et al. 2004: a new healthy organ
/// from the standard clinical measurements).
///
/// Build: generalised Procrustes alignment (rotation and translation removed, scale kept: size is what the patient
/// parameters predict, so normalising it away would discard the signal the conditioning needs), PCA truncated by
/// explained variance, then a linear regression of the standardised PCA scores on a fixed feature map of the
/// patient parameters with a Gaussian residual: p(c | patient) = N(B^T f(patient), S). This is the conditional
/// Gaussian of statismo's conditional models written as a regression, so that piecewise relations (growth to 40,
/// atrophy after menopause) can enter through the features. Files use statismo's HDF5 layout.

#include "hs/anatomy/Cohort.h"
#include "hs/anatomy/PatientParams.h"
#include "hs/anatomy/UterusGenerator.h"
#include "hs/core/Progress.h"
#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/Timings.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hs::anatomy {

struct ShapeModelParams {
    double explainedVariance = 0.995; ///< fraction of the total variance the kept modes explain
    int maxModes = 40;                ///< upper bound on kept modes
    bool alignRotation = true;        ///< Procrustes removes rotation (translation always; scale never)
    int procrustesIterations = 30;
    double procrustesToleranceMm = 1e-6;            ///< mm; stop when the mean moves less (RMS per vertex)
    double ridge = 1e-6;                            ///< regression regularisation, relative to the training size
    std::string description = "uterus shape model"; ///< stored in the file's metadata
    std::uint64_t cohortSeed = 0;                   ///< metadata: the seed of the cohort it was built from (0: none)
};

/// The organ's tilt in the pelvis, drawn apart from the shape (version is a pose; the shape model sees organs with
/// version 0). About 20 % of uteri are retroverted (docs/references.md [Retroversion]); the angles are assumptions
/// (docs/anatomy.md).
struct PosePrior {
    double retroversionProbability = 0.2;
    double antevertedMeanDeg = 20.0, antevertedSdDeg = 10.0;    ///< degree
    double retrovertedMeanDeg = -25.0, retrovertedSdDeg = 10.0; ///< degree
};

/// Clinical measurements a supervisor may ask for on top of the patient parameters (as measureUterus measures them:
/// mm, degrees). Unset ones are left to the patient's conditional model.
struct DimensionTargets {
    std::optional<double> lengthMm;
    std::optional<double> widthMm;
    std::optional<double> apDepthMm;
    std::optional<double> cavityLengthMm;
    std::optional<double> cavityWidthMm;
    std::optional<double> fundalWallMm;
    std::optional<double> cervixLengthMm;
    std::optional<double> flexionDeg;
    bool any() const {
        return lengthMm || widthMm || apDepthMm || cavityLengthMm || cavityWidthMm || fundalWallMm || cervixLengthMm ||
               flexionDeg;
    }
};

class ShapeModel {
public:
    struct Data;
    ShapeModel();
    explicit ShapeModel(std::shared_ptr<const Data> data);

    bool empty() const;
    int modeCount() const;
    std::size_t pointCount() const;
    /// Triangles and labels of every instance; points: the unconditional mean in the model frame.
    const SurfaceMesh& reference() const;
    /// The template layout when the model was built from uterus-template instances (measurements, posing).
    const std::optional<TemplateLayout>& layout() const;
    std::vector<double> variances() const; ///< per mode, mm^2, decreasing
    double totalVariance() const;          ///< of the training set, mm^2 (all modes)
    double noiseVariance() const;          ///< mm^2 per coordinate (PPCA estimate from the discarded modes)
    int trainingSize() const;
    const PosePrior& pose() const;

    /// Instance for standardised coefficients (each N(0, 1) under the unconditional model), model frame.
    Result<SurfaceMesh> instance(const std::vector<double>& coefficients) const;
    /// Standardised coefficients of an aligned shape (least squares in the model's span).
    std::vector<double> project(const std::vector<Vec3>& shape) const;

    /// Expected coefficients for a patient; InvalidInput for parameters outside the supported ranges.
    Result<std::vector<double>> conditionalCoefficients(const clinical::PatientParams& patient) const;
    /// The expected organ for a patient, in the anatomical frame with the most common (anteverted) version, or with
    /// `versionDeg` (degrees, + anteverted, - retroverted) when given.
    Result<SurfaceMesh> mean(const clinical::PatientParams& patient,
                             std::optional<double> versionDeg = std::nullopt) const;
    /// A plausible organ for a patient: conditional shape (each residual coefficient truncated at 2.5 SD) and a version
    /// drawn from the pose prior. Draws whose wall is below 5.25 mm or that self-intersect are rejected and redrawn
    /// (at most 64 draws, then InvalidInput naming the seed: never a silent substitute), so the result is the
    /// conditional Gaussian restricted to valid organs. Deterministic in `seed`. A given `versionDeg` replaces the
    /// drawn version (the draw still happens, so the shape for a seed does not depend on it).
    Result<SurfaceMesh> sample(const clinical::PatientParams& patient, std::uint64_t seed,
                               std::optional<double> versionDeg = std::nullopt) const;
    /// The organ for a patient that also has the requested dimensions: starting from the expected organ (or, with a
    /// seed, from a sample), the coefficients are moved by Gauss-Newton to the least change (in standard deviations)
    /// that meets every target within 1 mm (2 degrees for flexion), in the anatomical frame with `versionDeg` (default:
    /// the most common version). Fails with InvalidInput naming the dimension when the model cannot reach it for
    /// this patient without leaving the range of its training shapes (no silent extrapolation), or when the result
    /// would not be a valid organ (wall under 5 mm, self-intersection). Unsupported without a uterus template.
    Result<SurfaceMesh> withDimensions(const clinical::PatientParams& patient, const DimensionTargets& targets,
                                       std::optional<std::uint64_t> seed = std::nullopt,
                                       std::optional<double> versionDeg = std::nullopt) const;
    /// A sample of the unconditional model (model frame, no pose), for specificity.
    SurfaceMesh sampleUnconditional(std::uint64_t seed) const;
    /// Re-expresses a model-frame instance in the anatomical frame of UterusGenerator.h (external os at the origin,
    /// canal along +z) and applies `versionDeg`. Unchanged when the model has no template layout.
    SurfaceMesh pose(SurfaceMesh mesh, double versionDeg) const;

    const Data& data() const { return *m_data; }

private:
    std::shared_ptr<const Data> m_data;
};

struct ShapeModelBuildResult {
    ShapeModel model;
    int procrustesIterations = 0;
    double procrustesChangeMm = 0.0; ///< mm; the last RMS movement of the mean
    StageTimings timings;            ///< align, pca, condition
    std::vector<std::string> warnings;
};

/// Builds the model. Fails with InvalidInput for fewer than 10 shapes, shapes not in correspondence with the
/// reference, missing or out-of-range patient parameters; Cancelled on request.
[[nodiscard]] Result<ShapeModelBuildResult> buildShapeModel(const TrainingSet& training,
                                                            const ShapeModelParams& params = {},
                                                            Progress& progress = Progress::none());

/// Writes the model in statismo's HDF5 layout (/model, /representer, /version, /modelinfo) with the conditioning
/// and metadata under /hysteroscene. Written to a temporary name and renamed into place.
[[nodiscard]] Status saveShapeModel(const ShapeModel& model, const std::string& path);
/// Reads a file written by saveShapeModel. A plain statismo file (no /hysteroscene group) loads as an
/// unconditioned model: mean()/sample() then fail with Unsupported. Every size and value is checked.
[[nodiscard]] Result<ShapeModel> loadShapeModel(const std::string& path);
/// loadShapeModel on the bytes of a file held in memory (HDF5's file image), with the same checks; `name` names
/// it in errors. For models received over the network or embedded, and for fuzzing the reader.
[[nodiscard]] Result<ShapeModel> loadShapeModelImage(const void* bytes, std::size_t size, const std::string& name);

/// Names of the regression features, in order (stored in the file).
const std::vector<std::string>& conditioningFeatureNames();

} // namespace hs::anatomy
