#include "Procrustes.h"

#include <Eigen/Dense>

#include <cmath>

namespace hs::anatomy::detail {

void rigidAlign(std::vector<Vec3>& shape, const std::vector<Vec3>& target, bool rotation) {
    const Vec3 cs = centroid(shape), ct = centroid(target);
    if (!rotation) {
        for (auto& p : shape)
            p += ct - cs;
        return;
    }
    Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
    for (std::size_t i = 0; i < shape.size(); ++i) {
        const Vec3 a = shape[i] - cs, b = target[i] - ct;
        const Eigen::Vector3d av(a.x, a.y, a.z), bv(b.x, b.y, b.z);
        h += av * bv.transpose();
    }
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
    d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
    const Eigen::Matrix3d r = svd.matrixV() * d * svd.matrixU().transpose();
    for (auto& p : shape) {
        const Eigen::Vector3d q = r * Eigen::Vector3d(p.x - cs.x, p.y - cs.y, p.z - cs.z);
        p = Vec3{q.x(), q.y(), q.z()} + ct;
    }
}

ProcrustesResult generalizedProcrustes(const std::vector<std::vector<Vec3>>& shapes, bool rotation, int maxIterations,
                                       double toleranceMm) {
    ProcrustesResult result;
    result.aligned = shapes;
    result.mean = shapes.front();
    const std::size_t n = result.mean.size();
    for (int it = 0; it < maxIterations; ++it) {
        for (auto& s : result.aligned)
            rigidAlign(s, result.mean, rotation);
        std::vector<Vec3> next(n);
        for (const auto& s : result.aligned)
            for (std::size_t i = 0; i < n; ++i)
                next[i] += s[i];
        for (auto& p : next)
            p = p / static_cast<double>(result.aligned.size());
        // Keep the mean where it was: without this the frame drifts with every iteration.
        rigidAlign(next, result.mean, rotation);
        double sum = 0.0;
        for (std::size_t i = 0; i < n; ++i)
            sum += norm2(next[i] - result.mean[i]);
        result.mean = std::move(next);
        result.iterations = it + 1;
        result.changeMm = std::sqrt(sum / static_cast<double>(n));
        if (result.changeMm < toleranceMm)
            break;
    }
    for (auto& s : result.aligned)
        rigidAlign(s, result.mean, rotation);
    return result;
}

} // namespace hs::anatomy::detail
