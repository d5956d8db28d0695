#include "hs/anatomy/ModelEvaluation.h"

#include "Procrustes.h"
#include "ShapeModelData.h"

#include "hs/core/Rng.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace hs::anatomy {

namespace {

double meanVertexDistance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    const Eigen::Index n = a.size() / 3;
    double sum = 0.0;
    for (Eigen::Index i = 0; i < n; ++i)
        sum += (a.segment<3>(3 * i) - b.segment<3>(3 * i)).norm();
    return sum / static_cast<double>(n);
}

void meanAndSd(const std::vector<double>& v, double& mean, double& sd) {
    mean = 0.0;
    for (const double x : v)
        mean += x;
    mean /= static_cast<double>(v.size());
    double ss = 0.0;
    for (const double x : v)
        ss += (x - mean) * (x - mean);
    sd = v.size() > 1 ? std::sqrt(ss / static_cast<double>(v.size() - 1)) : 0.0;
}

/// Leave-one-out through the Gram matrix: each fold re-runs PCA on N-1 shapes with the model's number of modes.
Status generalization(const Eigen::MatrixXd& x, int modes, int folds, Progress& progress, ModelEvaluation& out) {
    const Eigen::Index n = x.rows();
    const Eigen::MatrixXd gram = x * x.transpose();
    std::vector<double> errors;
    const int count = folds <= 0 ? static_cast<int>(n) : std::min<int>(folds, static_cast<int>(n));
    for (int f = 0; f < count; ++f) {
        HS_TRY(progress.check("model evaluation"));
        const Eigen::Index left = static_cast<Eigen::Index>(f) * n / count;
        std::vector<Eigen::Index> keep;
        for (Eigen::Index i = 0; i < n; ++i)
            if (i != left)
                keep.push_back(i);
        const auto m = static_cast<Eigen::Index>(keep.size());
        Eigen::MatrixXd k(m, m);
        Eigen::VectorXd ky(m);
        for (Eigen::Index i = 0; i < m; ++i) {
            ky(i) = gram(keep[static_cast<std::size_t>(i)], left);
            for (Eigen::Index j = 0; j < m; ++j)
                k(i, j) = gram(keep[static_cast<std::size_t>(i)], keep[static_cast<std::size_t>(j)]);
        }
        // Centre the Gram matrix and the left-out shape's inner products on the fold's mean.
        const Eigen::VectorXd rowMean = k.rowwise().mean();
        const double allMean = rowMean.mean();
        const Eigen::MatrixXd kc =
            (k.colwise() - rowMean).rowwise() - rowMean.transpose() + Eigen::MatrixXd::Constant(m, m, allMean);
        const Eigen::VectorXd kyc = (ky - rowMean).array() - ky.mean() + allMean;
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(kc);
        const Eigen::Index use = std::min<Eigen::Index>(modes, m - 1);
        const Eigen::VectorXd values = eig.eigenvalues().reverse().head(use).cwiseMax(1e-12);
        const Eigen::MatrixXd vectors = eig.eigenvectors().rowwise().reverse().leftCols(use);
        // Reconstruction = mean + Xc^T w with w = V diag(1/lambda) V^T (Xc y_c).
        const Eigen::VectorXd w = vectors * (vectors.transpose() * kyc).cwiseQuotient(values);
        Eigen::VectorXd mean = Eigen::VectorXd::Zero(x.cols());
        for (const auto i : keep)
            mean += x.row(i).transpose();
        mean /= static_cast<double>(m);
        Eigen::VectorXd recon = mean;
        for (Eigen::Index i = 0; i < m; ++i)
            recon += w(i) * (x.row(keep[static_cast<std::size_t>(i)]).transpose() - mean);
        errors.push_back(meanVertexDistance(recon, x.row(left).transpose()));
        progress.report("anatomy.evaluate.generalization", static_cast<double>(f + 1) / count);
    }
    out.folds = count;
    meanAndSd(errors, out.generalizationMm, out.generalizationSdMm);
    return {};
}

Status specificity(const ShapeModel& model, const Eigen::MatrixXd& x, const ModelEvaluationParams& params,
                   Progress& progress, ModelEvaluation& out) {
    std::vector<double> nearest;
    for (int s = 0; s < params.specificitySamples; ++s) {
        HS_TRY(progress.check("model evaluation"));
        const SurfaceMesh sample =
            model.sampleUnconditional(Rng::deriveSeed(params.seed, static_cast<std::uint64_t>(s)));
        Eigen::VectorXd v(x.cols());
        for (std::size_t i = 0; i < sample.points.size(); ++i)
            v.segment<3>(static_cast<Eigen::Index>(3 * i)) << sample.points[i].x, sample.points[i].y,
                sample.points[i].z;
        double best = 1e300;
        for (Eigen::Index t = 0; t < x.rows(); ++t)
            best = std::min(best, meanVertexDistance(v, x.row(t).transpose()));
        nearest.push_back(best);
        progress.report("anatomy.evaluate.specificity", static_cast<double>(s + 1) / params.specificitySamples);
    }
    out.specificitySamples = params.specificitySamples;
    meanAndSd(nearest, out.specificityMm, out.specificitySdMm);
    return {};
}

Status conditioningError(const ShapeModel& model, const ModelEvaluationParams& params, ModelEvaluation& out) {
    if (!model.layout() || !model.data().conditioned)
        return {};
    const TemplateLayout& layout = *model.layout();
    const char* names[] = {"lengthMm",      "widthMm",      "apDepthMm",     "cavityLengthMm",
                           "cavityWidthMm", "fundalWallMm", "cervixLengthMm"};
    auto pick = [](const UterusDimensions& d) {
        return std::vector<double>{d.lengthMm,      d.widthMm,      d.apDepthMm,     d.cavityLengthMm,
                                   d.cavityWidthMm, d.fundalWallMm, d.cervixLengthMm};
    };
    std::vector<ConditioningError> errors(std::size(names));
    for (std::size_t i = 0; i < errors.size(); ++i)
        errors[i].dimension = names[i];
    Rng rng(Rng::deriveSeed(params.seed, 0xC0D1));
    for (int p = 0; p < params.conditioningPatients; ++p) {
        const clinical::PatientParams patient = samplePatient(rng);
        auto predicted = model.mean(patient);
        auto requested = generateUterus(expectedShape(patient), layout);
        if (!predicted)
            return predicted.failure();
        if (!requested)
            return requested.failure();
        auto dp = measureUterus(*predicted, layout);
        auto dr = measureUterus(requested->mesh, layout);
        if (!dp || !dr)
            return fail(ErrorCode::Internal, "measuring a model instance failed");
        const auto a = pick(*dp), b = pick(*dr);
        for (std::size_t i = 0; i < errors.size(); ++i) {
            const double e = a[i] - b[i];
            errors[i].meanAbsMm += std::abs(e) / params.conditioningPatients;
            errors[i].biasMm += e / params.conditioningPatients;
            errors[i].maxAbsMm = std::max(errors[i].maxAbsMm, std::abs(e));
        }
    }
    out.conditioning = std::move(errors);
    return {};
}

} // namespace

Result<ModelEvaluation> evaluateShapeModel(const ShapeModel& model, const TrainingSet& training,
                                           const ModelEvaluationParams& params, Progress& progress) {
    if (model.empty())
        return fail(ErrorCode::InvalidInput, "cannot evaluate an empty shape model");
    if (training.shapes.size() < 3 || training.shapes.front().size() != model.pointCount())
        return fail(ErrorCode::InvalidInput, "the training set is not in correspondence with the model");
    ModelEvaluation out;
    const auto variances = model.variances();
    out.modeVariance = variances;
    double cumulative = 0.0;
    for (const double v : variances) {
        cumulative += v;
        out.cumulativeExplained.push_back(cumulative / model.totalVariance());
    }
    // Align the training shapes onto the model's mean once.
    Eigen::MatrixXd x(static_cast<Eigen::Index>(training.shapes.size()),
                      static_cast<Eigen::Index>(3 * model.pointCount()));
    {
        ScopedStepTimer timer(out.timings, "align");
        for (std::size_t t = 0; t < training.shapes.size(); ++t) {
            std::vector<Vec3> s = training.shapes[t];
            detail::rigidAlign(s, model.reference().points, true);
            for (std::size_t i = 0; i < s.size(); ++i)
                x.row(static_cast<Eigen::Index>(t)).segment<3>(static_cast<Eigen::Index>(3 * i)) << s[i].x, s[i].y,
                    s[i].z;
        }
    }
    {
        ScopedStepTimer timer(out.timings, "generalization");
        auto sub = progress.sub(0.0, 0.5);
        HS_TRY(generalization(x, model.modeCount(), params.generalizationFolds, sub, out));
    }
    {
        ScopedStepTimer timer(out.timings, "specificity");
        auto sub = progress.sub(0.5, 0.9);
        HS_TRY(specificity(model, x, params, sub, out));
    }
    {
        ScopedStepTimer timer(out.timings, "conditioning");
        HS_TRY(conditioningError(model, params, out));
    }
    progress.report("anatomy.evaluate", 1.0);
    return out;
}

} // namespace hs::anatomy
