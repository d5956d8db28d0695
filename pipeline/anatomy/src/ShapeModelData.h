#pragma once
/// The model's numbers (private: Eigen stays out of the public headers).

#include "hs/anatomy/ShapeModel.h"

#include <Eigen/Dense>

namespace hs::anatomy {

struct ShapeModel::Data {
    SurfaceMesh reference;
    std::optional<TemplateLayout> layout;
    Eigen::VectorXd mean;     ///< 3n, x y z per point
    Eigen::MatrixXd basis;    ///< 3n x k, orthonormal columns
    Eigen::VectorXd variance; ///< k, mm^2
    double noiseVariance = 0.0;
    double totalVariance = 0.0;
    int trainingSize = 0;
    bool conditioned = false;
    Eigen::MatrixXd regression;         ///< p x k: coefficients = regression^T * features
    Eigen::MatrixXd residualCovariance; ///< k x k, of residuals divided by the size ratio of their prediction
    Eigen::MatrixXd residualFactor;     ///< k x k, lower triangular: residualCovariance = L L^T
    PosePrior pose;
    std::string description;
    std::uint64_t cohortSeed = 0;
};

namespace detail {

/// The regression features of a patient (see conditioningFeatureNames()).
Eigen::VectorXd patientFeatures(const clinical::PatientParams& patient);
/// Centroid size (RMS distance to the centroid) of the instance with `coefficients`, relative to the mean's.
double sizeRatio(const ShapeModel::Data& d, const Eigen::VectorXd& coefficients);
/// Rounds to single precision, as stored in the file, so that a built and a loaded model sample identically.
void roundToFloat(Eigen::MatrixXd& m);
void roundToFloat(Eigen::VectorXd& v);
/// Lower Cholesky factor of a symmetric positive semi-definite matrix (tiny jitter added).
Eigen::MatrixXd choleskyFactor(const Eigen::MatrixXd& covariance);

} // namespace detail

} // namespace hs::anatomy
