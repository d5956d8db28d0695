// Conditioning the shape model on measured clinical dimensions (statismo's "posterior model" idea for landmarks,
// here for the non-linear clinical measures: a regularised least-squares fit of the coefficients).
#include "ShapeModelData.h"

#include "hs/anatomy/OrganChecks.h"
#include "hs/core/Rng.h"

#include <cmath>
#include <cstdio>
#include <functional>

namespace hs::anatomy {
namespace {

constexpr double kToleranceMm = 1.0;    ///< a target counts as met within this, mm
constexpr double kToleranceDeg = 2.0;   ///< flexion, degrees
constexpr double kSigmaMm = 0.25;       ///< weight of a dimension residual in the fit, mm
constexpr double kSigmaDeg = 0.5;       ///< degrees
constexpr double kMaxCoefficient = 3.5; ///< |coefficient| beyond this leaves the training range (SD)
constexpr double kStep = 0.05;          ///< finite-difference step, SD
constexpr int kIterations = 10;
constexpr double kWallMm = 5.25; ///< as the sampler

struct Target {
    const char* name;
    double value;
    bool degrees;
    std::function<double(const UterusDimensions&)> measure;
};

std::vector<Target> targetsOf(const DimensionTargets& t) {
    std::vector<Target> out;
    auto add = [&out](const char* name, const std::optional<double>& v, bool degrees,
                      std::function<double(const UterusDimensions&)> f) {
        if (v)
            out.push_back({name, *v, degrees, std::move(f)});
    };
    add("lengthMm", t.lengthMm, false, [](const UterusDimensions& d) { return d.lengthMm; });
    add("widthMm", t.widthMm, false, [](const UterusDimensions& d) { return d.widthMm; });
    add("apDepthMm", t.apDepthMm, false, [](const UterusDimensions& d) { return d.apDepthMm; });
    add("cavityLengthMm", t.cavityLengthMm, false, [](const UterusDimensions& d) { return d.cavityLengthMm; });
    add("cavityWidthMm", t.cavityWidthMm, false, [](const UterusDimensions& d) { return d.cavityWidthMm; });
    add("fundalWallMm", t.fundalWallMm, false, [](const UterusDimensions& d) { return d.fundalWallMm; });
    add("cervixLengthMm", t.cervixLengthMm, false, [](const UterusDimensions& d) { return d.cervixLengthMm; });
    add("flexionDeg", t.flexionDeg, true, [](const UterusDimensions& d) { return d.flexionDeg; });
    return out;
}

std::string fmt(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.1f", v);
    return b;
}

} // namespace

Result<SurfaceMesh> ShapeModel::withDimensions(const clinical::PatientParams& patient, const DimensionTargets& targets,
                                               std::optional<std::uint64_t> seed,
                                               std::optional<double> versionDeg) const {
    const auto& d = *m_data;
    if (!d.layout)
        return fail(ErrorCode::Unsupported, "conditioning on dimensions needs a model of the uterus template");
    auto mu = conditionalCoefficients(patient);
    if (!mu)
        return mu.failure();
    const auto k = static_cast<Eigen::Index>(mu->size());
    Eigen::VectorXd prior = Eigen::Map<const Eigen::VectorXd>(mu->data(), k);
    if (seed) { // the first draw of sample(): the patient's natural variation, then moved to the targets
        Rng rng(*seed);
        Eigen::VectorXd z(k);
        for (Eigen::Index i = 0; i < k; ++i) {
            double v = rng.normal();
            while (std::abs(v) > 2.5)
                v = rng.normal();
            z(i) = v;
        }
        prior += detail::sizeRatio(d, prior) * (d.residualFactor * z);
    }
    const auto wanted = targetsOf(targets);
    for (const auto& t : wanted)
        if (!std::isfinite(t.value))
            return fail(ErrorCode::InvalidInput, std::string("dimension ") + t.name + " must be a finite number");
    if (wanted.empty())
        return sample(patient, seed.value_or(1), versionDeg);

    const auto m = static_cast<Eigen::Index>(wanted.size());
    auto measure = [&](const Eigen::VectorXd& c, Eigen::VectorXd& out) -> Status {
        const SurfaceMesh mesh = [&] {
            SurfaceMesh s = d.reference;
            const Eigen::VectorXd v = d.mean + d.basis * d.variance.cwiseSqrt().cwiseProduct(c);
            for (std::size_t i = 0; i < s.points.size(); ++i) {
                const auto j = static_cast<Eigen::Index>(3 * i);
                s.points[i] = {v(j), v(j + 1), v(j + 2)};
            }
            return s;
        }();
        auto dims = measureUterus(mesh, *d.layout);
        if (!dims)
            return dims.failure();
        out.resize(m);
        for (Eigen::Index i = 0; i < m; ++i)
            out(i) = wanted[static_cast<std::size_t>(i)].measure(*dims);
        return {};
    };
    Eigen::VectorXd sigma(m), target(m);
    for (Eigen::Index i = 0; i < m; ++i) {
        sigma(i) = wanted[static_cast<std::size_t>(i)].degrees ? kSigmaDeg : kSigmaMm;
        target(i) = wanted[static_cast<std::size_t>(i)].value;
    }

    // Gauss-Newton on  sum ((m(c) - t) / sigma)^2 + |c - prior|^2  (the prior term: one SD costs like sigma).
    Eigen::VectorXd c = prior, value, probe;
    for (int it = 0; it < kIterations; ++it) {
        HS_TRY(measure(c, value));
        Eigen::MatrixXd J(m, k);
        for (Eigen::Index j = 0; j < k; ++j) {
            Eigen::VectorXd cj = c;
            cj(j) += kStep;
            HS_TRY(measure(cj, probe));
            J.col(j) = (probe - value) / kStep;
        }
        const Eigen::MatrixXd Jw = sigma.cwiseInverse().asDiagonal() * J;
        const Eigen::VectorXd rw = (value - target).cwiseQuotient(sigma);
        const Eigen::MatrixXd A = Jw.transpose() * Jw + Eigen::MatrixXd::Identity(k, k);
        const Eigen::VectorXd g = Jw.transpose() * rw + (c - prior);
        const Eigen::VectorXd delta = A.ldlt().solve(-g);
        c += delta;
        if (delta.norm() < 1e-4)
            break;
    }
    HS_TRY(measure(c, value));
    for (Eigen::Index i = 0; i < m; ++i) {
        const auto& t = wanted[static_cast<std::size_t>(i)];
        const double tolerance = t.degrees ? kToleranceDeg : kToleranceMm;
        if (std::abs(value(i) - t.value) > tolerance)
            return fail(ErrorCode::InvalidInput, std::string("dimension ") + t.name + " = " + fmt(t.value) +
                                                     " cannot be reached by the shape model for this patient " +
                                                     "(closest " + fmt(value(i)) + "); the model does not extrapolate");
    }
    std::string requested;
    for (const auto& t : wanted)
        requested += (requested.empty() ? "" : ", ") + std::string(t.name) + " = " + fmt(t.value);
    for (Eigen::Index j = 0; j < k; ++j)
        if (std::abs(c(j)) > kMaxCoefficient)
            return fail(ErrorCode::InvalidInput, "the requested dimensions (" + requested +
                                                     ") lie outside the range of the model's training shapes (mode " +
                                                     std::to_string(j + 1) + " at " + fmt(c(j)) +
                                                     " SD); the model does not extrapolate");
    auto mesh = instance(std::vector<double>(c.data(), c.data() + k));
    if (!mesh)
        return mesh.failure();
    openPassage(*mesh, *d.layout);
    auto thick = wallAtLeast(*mesh, *d.layout, kWallMm);
    if (!thick)
        return thick.failure();
    if (!*thick || hasSelfIntersections(*mesh))
        return fail(ErrorCode::InvalidInput, "the requested dimensions (" + requested +
                                                 ") give an organ whose wall is thinner than 5 mm or that intersects "
                                                 "itself: ask for less extreme values");
    return pose(std::move(mesh).value(), versionDeg.value_or(d.pose.antevertedMeanDeg));
}

} // namespace hs::anatomy
