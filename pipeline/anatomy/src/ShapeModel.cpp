#include "hs/anatomy/ShapeModel.h"

#include "Procrustes.h"
#include "ShapeModelData.h"

#include "hs/anatomy/OrganChecks.h"
#include "hs/core/Rng.h"
#include "hs/core/Units.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hs::anatomy {

namespace detail {

Eigen::VectorXd patientFeatures(const clinical::PatientParams& p) {
    // Piecewise-linear in age like the relations: growth to 30 and to 45, atrophy by years after 51 if menopausal.
    Eigen::VectorXd f(9);
    const double meno = p.menopausal ? 1.0 : 0.0;
    f << 1.0, (std::min(p.ageYears, 30.0) - 30.0) / 10.0, (std::min(p.ageYears, 45.0) - 30.0) / 10.0, meno,
        meno * (p.ageYears - 51.0) / 10.0, std::min(p.parity, 4), std::min(p.parity, 2),
        std::min(p.gravidity - p.parity, 4), (p.heightCm - 164.0) / 10.0;
    return f;
}

double sizeRatio(const ShapeModel::Data& d, const Eigen::VectorXd& coefficients) {
    const Eigen::VectorXd shape = d.mean + d.basis * d.variance.cwiseSqrt().cwiseProduct(coefficients);
    auto size = [](const Eigen::VectorXd& v) {
        const Eigen::Index n = v.size() / 3;
        const Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic>> p(v.data(), 3, n);
        const Eigen::Vector3d c = p.rowwise().mean();
        return std::sqrt((p.colwise() - c).squaredNorm() / static_cast<double>(n));
    };
    return size(shape) / size(d.mean);
}

void roundToFloat(Eigen::MatrixXd& m) {
    m = m.cast<float>().cast<double>();
}
void roundToFloat(Eigen::VectorXd& v) {
    v = v.cast<float>().cast<double>();
}

Eigen::MatrixXd choleskyFactor(const Eigen::MatrixXd& covariance) {
    const auto k = covariance.rows();
    Eigen::LLT<Eigen::MatrixXd> llt(covariance + 1e-10 * Eigen::MatrixXd::Identity(k, k));
    if (llt.info() == Eigen::Success)
        return llt.matrixL();
    // Semi-definite: fall back to the symmetric square root.
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(covariance);
    return eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
}

} // namespace detail

const std::vector<std::string>& conditioningFeatureNames() {
    static const std::vector<std::string> names = {
        "intercept",     "(min(ageYears,30)-30)/10",    "(min(ageYears,45)-30)/10",
        "menopausal",    "menopausal*(ageYears-51)/10", "min(parity,4)",
        "min(parity,2)", "min(gravidity-parity,4)",     "(heightCm-164)/10"};
    return names;
}

namespace {

/// Residual coefficients are drawn within this many standard deviations (the tails of a linear model are where
/// walls thin and bends fold; 2.5 keeps 98.8 % of each normal's mass).
constexpr double kTruncation = 2.5;

Eigen::VectorXd flatten(const std::vector<Vec3>& points) {
    Eigen::VectorXd v(static_cast<Eigen::Index>(3 * points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        const auto k = static_cast<Eigen::Index>(3 * i);
        v(k) = points[i].x;
        v(k + 1) = points[i].y;
        v(k + 2) = points[i].z;
    }
    return v;
}

SurfaceMesh meshFrom(const ShapeModel::Data& d, const Eigen::VectorXd& v) {
    SurfaceMesh mesh = d.reference;
    for (std::size_t i = 0; i < mesh.points.size(); ++i) {
        const auto k = static_cast<Eigen::Index>(3 * i);
        mesh.points[i] = {v(k), v(k + 1), v(k + 2)};
    }
    return mesh;
}

/// An organ for a patient: the model's instance with its canal and cavity opened to the generator's floor, which a
/// linear combination of training organs does not keep (openPassage). The raw instances (`instance`, modes,
/// unconditional samples) stay as the model gives them.
SurfaceMesh organFrom(const ShapeModel::Data& d, const Eigen::VectorXd& v) {
    SurfaceMesh mesh = meshFrom(d, v);
    if (d.layout)
        openPassage(mesh, *d.layout);
    return mesh;
}

/// Standard normal deviates truncated at kTruncation: samples stay where the training shapes are.
Eigen::VectorXd truncatedNormals(Rng& rng, Eigen::Index k) {
    Eigen::VectorXd z(k);
    for (Eigen::Index i = 0; i < k; ++i)
        z(i) = rng.truncatedNormal(0.0, 1.0, -kTruncation, kTruncation);
    return z;
}

/// A draw is kept only if it is a valid solid: the Gaussian's tails can thin the wall below the organ checks' 5 mm
/// or fold the bend. Without a template layout every draw is kept. With the bundled model 416 of 420 draws (ages
/// 20-75, parity 0-4, 20 seeds each) were kept at once and the other 4 at the second draw; after kMaxAttempts the
/// sample is refused rather than replaced by the conditional mean (in a batch, many cases would silently share it).
constexpr int kMaxAttempts = 64;
constexpr double kSampleWallMm = 5.25; ///< mm; 5 mm required plus a margin for the float rounding of files (the
                                       ///< refusal below names it)

bool isPlausible(const SurfaceMesh& shape, const ShapeModel::Data& d) {
    if (!d.layout)
        return true;
    const auto thick = wallAtLeast(shape, *d.layout, kSampleWallMm);
    return thick && *thick && !hasSelfIntersections(shape);
}

Status checkTraining(const TrainingSet& t) {
    if (t.shapes.size() < 10)
        return fail(ErrorCode::InvalidInput,
                    "a shape model needs at least 10 training shapes, got " + std::to_string(t.shapes.size()));
    if (t.patients.size() != t.shapes.size())
        return fail(ErrorCode::InvalidInput, "training set has " + std::to_string(t.shapes.size()) + " shapes but " +
                                                 std::to_string(t.patients.size()) + " patient parameter rows");
    HS_TRY(validate(t.reference));
    for (std::size_t i = 0; i < t.shapes.size(); ++i) {
        if (t.shapes[i].size() != t.reference.points.size())
            return fail(ErrorCode::InvalidInput, "training shape " + std::to_string(i) + " has " +
                                                     std::to_string(t.shapes[i].size()) +
                                                     " points; shapes must be in correspondence with the reference (" +
                                                     std::to_string(t.reference.points.size()) + " points)");
        for (const auto& p : t.shapes[i])
            if (!isFinite(p))
                return fail(ErrorCode::InvalidInput, "training shape " + std::to_string(i) + " has a non-finite point");
        const Status ok = validatePatient(t.patients[i]);
        if (!ok)
            return fail(ErrorCode::InvalidInput, "training shape " + std::to_string(i) + ": " + ok.error().detail);
    }
    return {};
}

} // namespace

ShapeModel::ShapeModel() : m_data(std::make_shared<Data>()) {}
ShapeModel::ShapeModel(std::shared_ptr<const Data> data) : m_data(std::move(data)) {}
bool ShapeModel::empty() const {
    return m_data->mean.size() == 0;
}
int ShapeModel::modeCount() const {
    return static_cast<int>(m_data->variance.size());
}
std::size_t ShapeModel::pointCount() const {
    return m_data->reference.points.size();
}
const SurfaceMesh& ShapeModel::reference() const {
    return m_data->reference;
}
const std::optional<TemplateLayout>& ShapeModel::layout() const {
    return m_data->layout;
}
std::vector<double> ShapeModel::variances() const {
    return {m_data->variance.data(), m_data->variance.data() + m_data->variance.size()};
}
double ShapeModel::totalVariance() const {
    return m_data->totalVariance;
}
double ShapeModel::noiseVariance() const {
    return m_data->noiseVariance;
}
int ShapeModel::trainingSize() const {
    return m_data->trainingSize;
}
const PosePrior& ShapeModel::pose() const {
    return m_data->pose;
}

Result<SurfaceMesh> ShapeModel::instance(const std::vector<double>& coefficients) const {
    const auto& d = *m_data;
    if (coefficients.size() != static_cast<std::size_t>(d.variance.size()))
        return fail(ErrorCode::InvalidInput, "expected " + std::to_string(d.variance.size()) + " coefficients, got " +
                                                 std::to_string(coefficients.size()));
    const Eigen::Map<const Eigen::VectorXd> c(coefficients.data(), static_cast<Eigen::Index>(coefficients.size()));
    return meshFrom(d, d.mean + d.basis * (d.variance.cwiseSqrt().cwiseProduct(c)));
}

std::vector<double> ShapeModel::project(const std::vector<Vec3>& shape) const {
    const auto& d = *m_data;
    const Eigen::VectorXd c = (d.basis.transpose() * (flatten(shape) - d.mean)).cwiseQuotient(d.variance.cwiseSqrt());
    return {c.data(), c.data() + c.size()};
}

Result<std::vector<double>> ShapeModel::conditionalCoefficients(const clinical::PatientParams& patient) const {
    HS_TRY(validatePatient(patient));
    const auto& d = *m_data;
    if (!d.conditioned)
        return fail(ErrorCode::Unsupported, "this shape model has no patient conditioning (a plain statismo file)");
    const Eigen::VectorXd c = d.regression.transpose() * detail::patientFeatures(patient);
    return std::vector<double>(c.data(), c.data() + c.size());
}

Result<SurfaceMesh> ShapeModel::mean(const clinical::PatientParams& patient, std::optional<double> versionDeg) const {
    auto c = conditionalCoefficients(patient);
    if (!c)
        return c.failure();
    auto mesh = instance(*c);
    if (!mesh)
        return mesh.failure();
    if (m_data->layout)
        openPassage(*mesh, *m_data->layout);
    return pose(std::move(mesh).value(), versionDeg.value_or(m_data->pose.antevertedMeanDeg));
}

Result<SurfaceMesh> ShapeModel::sample(const clinical::PatientParams& patient, std::uint64_t seed,
                                       std::optional<double> versionDeg) const {
    auto c = conditionalCoefficients(patient);
    if (!c)
        return c.failure();
    const auto& d = *m_data;
    Rng rng(seed);
    const Eigen::Map<const Eigen::VectorXd> mu(c->data(), static_cast<Eigen::Index>(c->size()));
    const double scale = detail::sizeRatio(d, mu);
    SurfaceMesh shape;
    bool accepted = false;
    for (int attempt = 0; attempt < kMaxAttempts && !accepted; ++attempt) {
        const Eigen::VectorXd z = truncatedNormals(rng, d.variance.size());
        const Eigen::VectorXd coefficients = mu + scale * (d.residualFactor * z);
        shape = organFrom(d, d.mean + d.basis * d.variance.cwiseSqrt().cwiseProduct(coefficients));
        accepted = isPlausible(shape, d);
    }
    if (!accepted)
        return fail(
            ErrorCode::InvalidInput,
            "shape model: no valid organ in " + std::to_string(kMaxAttempts) + " draws for this patient with seed " +
                std::to_string(seed) +
                " (each had a wall under 5.25 mm or crossed itself); try another seed, or the expected organ (--mean)");
    const auto& pp = d.pose;
    double version = rng.bernoulli(pp.retroversionProbability) ? rng.normal(pp.retrovertedMeanDeg, pp.retrovertedSdDeg)
                                                               : rng.normal(pp.antevertedMeanDeg, pp.antevertedSdDeg);
    version = std::clamp(version, -80.0, 80.0);
    return pose(std::move(shape), versionDeg.value_or(version));
}

SurfaceMesh ShapeModel::sampleUnconditional(std::uint64_t seed) const {
    const auto& d = *m_data;
    Rng rng(seed);
    const Eigen::VectorXd z = truncatedNormals(rng, d.variance.size());
    return meshFrom(d, d.mean + d.basis * d.variance.cwiseSqrt().cwiseProduct(z));
}

SurfaceMesh ShapeModel::pose(SurfaceMesh mesh, double versionDeg) const {
    if (!m_data->layout)
        return mesh;
    const TemplateLayout& l = *m_data->layout;
    auto centroid = [&](int ring) {
        Vec3 c;
        for (int j = 0; j < l.around; ++j)
            c += mesh.points[static_cast<std::size_t>(l.vertex(ring, j))];
        return c / l.around;
    };
    const Vec3 origin = centroid(l.firstCanalRing());
    const Vec3 z = normalized(centroid(l.internalOsRing()) - origin);
    const int mid = l.firstCanalRing() + l.canalRings / 2;
    Vec3 x = mesh.points[static_cast<std::size_t>(l.vertex(mid, 0))] -
             mesh.points[static_cast<std::size_t>(l.vertex(mid, l.around / 2))];
    x = normalized(x - z * dot(x, z));
    const Vec3 y = cross(z, x);
    const double v = units::degToRad(versionDeg);
    const double cv = std::cos(v), sv = std::sin(v);
    for (auto& p : mesh.points) {
        const Vec3 q = p - origin;
        const Vec3 local{dot(q, x), dot(q, y), dot(q, z)};
        p = {local.x, local.y * cv + local.z * sv, -local.y * sv + local.z * cv};
    }
    return mesh;
}

Result<ShapeModelBuildResult> buildShapeModel(const TrainingSet& training, const ShapeModelParams& params,
                                              Progress& progress) {
    HS_TRY(checkTraining(training));
    if (!(params.explainedVariance > 0.0 && params.explainedVariance <= 1.0) || params.maxModes < 1)
        return fail(ErrorCode::InvalidInput, "explainedVariance must be in (0, 1] and maxModes >= 1");
    ShapeModelBuildResult result;
    auto data = std::make_shared<ShapeModel::Data>();
    const auto count = static_cast<Eigen::Index>(training.shapes.size());

    detail::ProcrustesResult gpa;
    {
        ScopedStepTimer timer(result.timings, "align");
        gpa = detail::generalizedProcrustes(training.shapes, params.alignRotation, params.procrustesIterations,
                                            params.procrustesToleranceMm);
        result.procrustesIterations = gpa.iterations;
        result.procrustesChangeMm = gpa.changeMm;
    }
    progress.report("anatomy.model.align", 0.3);
    HS_TRY(progress.check("shape model build"));

    Eigen::MatrixXd scores;
    {
        ScopedStepTimer timer(result.timings, "pca");
        const Eigen::VectorXd mean = flatten(gpa.mean);
        Eigen::MatrixXd x(count, mean.size());
        for (Eigen::Index i = 0; i < count; ++i)
            x.row(i) = (flatten(gpa.aligned[static_cast<std::size_t>(i)]) - mean).transpose();
        // Eigen-decomposition of the small Gram matrix (N x N) instead of the 3n x 3n covariance.
        const Eigen::MatrixXd gram = x * x.transpose() / static_cast<double>(count - 1);
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(gram);
        const Eigen::VectorXd values = eig.eigenvalues().reverse().cwiseMax(0.0);
        const Eigen::MatrixXd vectors = eig.eigenvectors().rowwise().reverse();
        data->totalVariance = values.sum();
        int k = 0;
        double kept = 0.0;
        while (k < std::min<Eigen::Index>(params.maxModes, count - 1) && values(k) > 1e-12 * values(0) &&
               kept < params.explainedVariance * data->totalVariance)
            kept += values(k++);
        data->mean = mean;
        data->variance = values.head(k);
        data->basis = x.transpose() * vectors.leftCols(k);
        for (int j = 0; j < k; ++j)
            data->basis.col(j) /= std::sqrt(static_cast<double>(count - 1) * values(j));
        // PPCA noise: the mean discarded variance per remaining dimension (Tipping & Bishop 1999).
        const double rest = data->totalVariance - kept;
        data->noiseVariance = rest / static_cast<double>(mean.size() - k);
        detail::roundToFloat(data->mean);
        detail::roundToFloat(data->basis);
        detail::roundToFloat(data->variance);
        scores = vectors.leftCols(k) * std::sqrt(static_cast<double>(count - 1)); // standardised, N x k
        result.timings.step("pca").counts.push_back({"modes", k});
        if (kept < params.explainedVariance * data->totalVariance)
            result.warnings.push_back("the kept modes explain " + std::to_string(100.0 * kept / data->totalVariance) +
                                      " % of the variance (maxModes reached)");
    }
    progress.report("anatomy.model.pca", 0.8);

    {
        ScopedStepTimer timer(result.timings, "condition");
        const auto p = static_cast<Eigen::Index>(conditioningFeatureNames().size());
        Eigen::MatrixXd f(count, p);
        for (Eigen::Index i = 0; i < count; ++i)
            f.row(i) = detail::patientFeatures(training.patients[static_cast<std::size_t>(i)]).transpose();
        Eigen::MatrixXd normal = f.transpose() * f;
        normal.diagonal().tail(p - 1).array() += params.ridge * static_cast<double>(count);
        data->regression = normal.ldlt().solve(f.transpose() * scores);
        detail::roundToFloat(data->regression);
        // Heteroscedastic residual: natural variation scales with organ size, so residuals are divided by the size
        // of their predicted shape before the covariance is estimated, and samples are scaled back.
        Eigen::MatrixXd residual = scores - f * data->regression;
        for (Eigen::Index i = 0; i < count; ++i)
            residual.row(i) /= detail::sizeRatio(*data, data->regression.transpose() * f.row(i).transpose());
        data->residualCovariance =
            residual.transpose() * residual / static_cast<double>(std::max<Eigen::Index>(1, count - p));
        detail::roundToFloat(data->residualCovariance);
        data->residualFactor = detail::choleskyFactor(data->residualCovariance);
        data->conditioned = true;
    }
    data->reference = training.reference;
    data->reference.points = gpa.mean;
    for (std::size_t i = 0; i < gpa.mean.size(); ++i)
        data->reference.points[i] = {data->mean(static_cast<Eigen::Index>(3 * i)),
                                     data->mean(static_cast<Eigen::Index>(3 * i + 1)),
                                     data->mean(static_cast<Eigen::Index>(3 * i + 2))};
    data->layout = training.layout;
    data->trainingSize = static_cast<int>(count);
    data->description = params.description;
    data->cohortSeed = params.cohortSeed;
    result.model = ShapeModel(std::move(data));
    progress.report("anatomy.model", 1.0);
    return result;
}

} // namespace hs::anatomy
