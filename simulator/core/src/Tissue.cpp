#include "Tissue.h"

#include "Bvh.h"

#include <algorithm>
#include <cmath>

namespace hs::sim::detail {

namespace {

constexpr double kMm = 1e-3; // m per mm

using Mat3 = std::array<double, 9>; // row-major

Vec3 column(const Mat3& m, int c) {
    return {m[static_cast<std::size_t>(c)], m[static_cast<std::size_t>(3 + c)], m[static_cast<std::size_t>(6 + c)]};
}

/// The shape matrix of points (columns p1 - p0, p2 - p0, p3 - p0).
Mat3 shapeMatrix(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
    const Vec3 a = p1 - p0, b = p2 - p0, c = p3 - p0;
    return {a.x, b.x, c.x, a.y, b.y, c.y, a.z, b.z, c.z};
}

Mat3 multiply(const Mat3& a, const Mat3& b) {
    Mat3 r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double s = 0.0;
            for (int k = 0; k < 3; ++k)
                s += a[static_cast<std::size_t>(3 * i + k)] * b[static_cast<std::size_t>(3 * k + j)];
            r[static_cast<std::size_t>(3 * i + j)] = s;
        }
    return r;
}

bool invert(const Mat3& m, Mat3& out, double& det) {
    det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
    if (std::abs(det) < 1e-300)
        return false;
    const double i = 1.0 / det;
    out = {(m[4] * m[8] - m[5] * m[7]) * i, (m[2] * m[7] - m[1] * m[8]) * i, (m[1] * m[5] - m[2] * m[4]) * i,
           (m[5] * m[6] - m[3] * m[8]) * i, (m[0] * m[8] - m[2] * m[6]) * i, (m[2] * m[3] - m[0] * m[5]) * i,
           (m[3] * m[7] - m[4] * m[6]) * i, (m[1] * m[6] - m[0] * m[7]) * i, (m[0] * m[4] - m[1] * m[3]) * i};
    return true;
}

/// Gradients of a constraint with respect to the tet's four points from dC/dF (row-major) and Dm^-1:
/// [g1 g2 g3] = dC/dF * Dm^-T, g0 = -(g1 + g2 + g3).
std::array<Vec3, 4> pointGradients(const Mat3& dCdF, const Mat3& dmInv) {
    std::array<Vec3, 4> g;
    for (int c = 0; c < 3; ++c) {
        // column c of dCdF * Dm^-T = dCdF * (row c of Dm^-1)^T
        Vec3 v{0.0, 0.0, 0.0};
        for (int k = 0; k < 3; ++k) {
            const double d = dmInv[static_cast<std::size_t>(3 * c + k)];
            v.x += dCdF[static_cast<std::size_t>(k)] * d;
            v.y += dCdF[static_cast<std::size_t>(3 + k)] * d;
            v.z += dCdF[static_cast<std::size_t>(6 + k)] * d;
        }
        g[static_cast<std::size_t>(c + 1)] = v;
    }
    g[0] = (g[1] + g[2] + g[3]) * -1.0;
    return g;
}

double determinant(const Mat3& m) {
    return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
}

} // namespace

void TissueModel::build(const TetMesh& mesh, const std::vector<TetMaterial>& materials, const std::vector<bool>& fixed,
                        const std::vector<std::pair<std::int32_t, double>>& tethers) {
    const std::size_t n = mesh.points.size();
    rest_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        rest_[i] = mesh.points[i] * kMm;
    x_ = rest_;
    prev_ = rest_;
    v_.assign(n, Vec3{0.0, 0.0, 0.0});
    std::vector<double> mass(n, 0.0);
    tets_ = mesh.tets;
    dmInv_.resize(tets_.size());
    volume_.resize(tets_.size());
    mu_.resize(tets_.size());
    lambda_.resize(tets_.size());
    for (std::size_t t = 0; t < tets_.size(); ++t) {
        const Tet& tet = tets_[t];
        const Mat3 dm = shapeMatrix(rest_[static_cast<std::size_t>(tet[0])], rest_[static_cast<std::size_t>(tet[1])],
                                    rest_[static_cast<std::size_t>(tet[2])], rest_[static_cast<std::size_t>(tet[3])]);
        double det = 0.0;
        if (!invert(dm, dmInv_[t], det))
            dmInv_[t] = Mat3{};
        volume_[t] = std::abs(det) / 6.0;
        const TetMaterial& m = materials[t];
        const double e = m.youngsModulusPa, nu = m.poissonRatio;
        mu_[t] = e / (2.0 * (1.0 + nu));
        lambda_[t] = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
        for (const std::int32_t p : tet)
            mass[static_cast<std::size_t>(p)] += m.densityKgPerM3 * volume_[t] / 4.0;
    }
    w_.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        w_[i] = (fixed[i] || mass[i] <= 0.0) ? 0.0 : 1.0 / mass[i];
    lambdaH_.assign(tets_.size(), 0.0);
    lambdaD_.assign(tets_.size(), 0.0);
    tethers_ = tethers;
    lambdaT_.assign(tethers_.size(), 0.0);
}

void TissueModel::step(double dt, int iterations, const std::vector<Vec3>& externalForcesN,
                       std::vector<ContactPair>& contacts, const std::vector<Triangle>& surface) {
    const std::size_t n = x_.size();
    for (std::size_t i = 0; i < n; ++i) {
        prev_[i] = x_[i];
        if (w_[i] == 0.0)
            continue;
        v_[i] = v_[i] + externalForcesN[i] * (w_[i] * dt);
        x_[i] = x_[i] + v_[i] * dt;
    }
    std::fill(lambdaH_.begin(), lambdaH_.end(), 0.0);
    std::fill(lambdaD_.begin(), lambdaD_.end(), 0.0);
    std::fill(lambdaT_.begin(), lambdaT_.end(), 0.0);
    for (auto& c : contacts)
        c.lambda = 0.0;
    const double dt2 = dt * dt;
    for (int it = 0; it < iterations; ++it) {
        for (std::size_t t = 0; t < tets_.size(); ++t)
            solveTet(t, dt2);
        solveTethers(dt2);
        solveContacts(contacts, surface);
    }
    const double keep = std::max(0.0, 1.0 - damping * dt);
    for (std::size_t i = 0; i < n; ++i)
        v_[i] = w_[i] == 0.0 ? Vec3{0.0, 0.0, 0.0} : (x_[i] - prev_[i]) * (keep / dt);
}

void TissueModel::solveTet(std::size_t t, double dt2) {
    const Tet& tet = tets_[t];
    const auto p = [&tet](int k) { return static_cast<std::size_t>(tet[static_cast<std::size_t>(k)]); };
    const double vol = volume_[t];
    if (vol <= 0.0)
        return;
    const auto apply = [&](const std::array<Vec3, 4>& g, double c, double compliance, double& lambda) {
        double denominator = compliance / dt2;
        for (int k = 0; k < 4; ++k)
            denominator += w_[p(k)] * dot(g[static_cast<std::size_t>(k)], g[static_cast<std::size_t>(k)]);
        if (denominator < 1e-300)
            return;
        const double dLambda = (-c - compliance / dt2 * lambda) / denominator;
        lambda += dLambda;
        for (int k = 0; k < 4; ++k)
            x_[p(k)] = x_[p(k)] + g[static_cast<std::size_t>(k)] * (w_[p(k)] * dLambda);
    };
    // Deviatoric: C = sqrt(tr(F^T F)), compliance 1 / (mu V).
    {
        const Mat3 f = multiply(shapeMatrix(x_[p(0)], x_[p(1)], x_[p(2)], x_[p(3)]), dmInv_[t]);
        double ic = 0.0;
        for (double v : f)
            ic += v * v;
        const double c = std::sqrt(ic);
        if (c > 1e-12) {
            Mat3 dCdF;
            for (std::size_t k = 0; k < 9; ++k)
                dCdF[k] = f[k] / c;
            apply(pointGradients(dCdF, dmInv_[t]), c, 1.0 / (mu_[t] * vol), lambdaD_[t]);
        }
    }
    // Hydrostatic: C = det F - (1 + mu / lambda), compliance 1 / (lambda V).
    {
        const Mat3 f = multiply(shapeMatrix(x_[p(0)], x_[p(1)], x_[p(2)], x_[p(3)]), dmInv_[t]);
        const Vec3 f1 = column(f, 0), f2 = column(f, 1), f3 = column(f, 2);
        const Vec3 c1 = cross(f2, f3), c2 = cross(f3, f1), c3 = cross(f1, f2);
        const Mat3 dCdF{c1.x, c2.x, c3.x, c1.y, c2.y, c3.y, c1.z, c2.z, c3.z};
        const double c = determinant(f) - (1.0 + mu_[t] / lambda_[t]);
        apply(pointGradients(dCdF, dmInv_[t]), c, 1.0 / (lambda_[t] * vol), lambdaH_[t]);
    }
}

void TissueModel::solveTethers(double dt2) {
    for (std::size_t k = 0; k < tethers_.size(); ++k) {
        const auto i = static_cast<std::size_t>(tethers_[k].first);
        if (w_[i] == 0.0)
            continue;
        const Vec3 d = x_[i] - rest_[i];
        const double c = norm(d);
        if (c < 1e-12)
            continue;
        const double compliance = 1.0 / tethers_[k].second;
        const double dLambda = (-c - compliance / dt2 * lambdaT_[k]) / (w_[i] + compliance / dt2);
        lambdaT_[k] += dLambda;
        x_[i] = x_[i] + (d / c) * (w_[i] * dLambda);
    }
}

void TissueModel::solveContacts(std::vector<ContactPair>& contacts, const std::vector<Triangle>& surface) {
    for (ContactPair& pair : contacts) {
        const Triangle& tri = surface[static_cast<std::size_t>(pair.triangle)];
        const auto i0 = static_cast<std::size_t>(tri[0]), i1 = static_cast<std::size_t>(tri[1]),
                   i2 = static_cast<std::size_t>(tri[2]);
        const Vec3 n = cross(x_[i1] - x_[i0], x_[i2] - x_[i0]);
        const double area2 = norm(n);
        if (area2 < 1e-18)
            continue;
        const Vec3 normal = n / area2;
        double b0 = 0.0, b1 = 0.0, b2 = 0.0;
        closestOnTriangle(pair.centre, x_[i0], x_[i1], x_[i2], b0, b1, b2);
        const Vec3 q = x_[i0] * b0 + x_[i1] * b1 + x_[i2] * b2;
        const double s = dot(pair.centre - q, normal);
        // Only a sphere in front of the face (or just through it) pushes it; the tissue lies behind the face.
        if (s < -pair.radius)
            continue;
        const double c = s - pair.radius;
        if (c >= 0.0)
            continue;
        const double denominator = w_[i0] * b0 * b0 + w_[i1] * b1 * b1 + w_[i2] * b2 * b2;
        if (denominator < 1e-300)
            continue;
        const double dLambda = -c / denominator;
        pair.lambda += dLambda;
        pair.normal = normal;
        x_[i0] = x_[i0] - normal * (w_[i0] * b0 * dLambda);
        x_[i1] = x_[i1] - normal * (w_[i1] * b1 * dLambda);
        x_[i2] = x_[i2] - normal * (w_[i2] * b2 * dLambda);
    }
}

void TissueModel::pointsMm(std::vector<Vec3>& out) const {
    out.resize(x_.size());
    for (std::size_t i = 0; i < x_.size(); ++i)
        out[i] = x_[i] / kMm;
}

double TissueModel::elasticEnergyJ() const {
    double energy = 0.0;
    for (std::size_t t = 0; t < tets_.size(); ++t) {
        const Tet& tet = tets_[t];
        const auto p = [&tet](int k) { return static_cast<std::size_t>(tet[static_cast<std::size_t>(k)]); };
        const Mat3 f = multiply(shapeMatrix(x_[p(0)], x_[p(1)], x_[p(2)], x_[p(3)]), dmInv_[t]);
        double ic = 0.0;
        for (double v : f)
            ic += v * v;
        const double j = determinant(f);
        const double alpha = 1.0 + mu_[t] / lambda_[t];
        // Stable Neo-Hookean (Smith et al. 2018), shifted so the rest state has zero energy.
        const double psi = 0.5 * mu_[t] * (ic - 3.0) + 0.5 * lambda_[t] * (j - alpha) * (j - alpha) -
                           0.5 * lambda_[t] * (1.0 - alpha) * (1.0 - alpha);
        energy += psi * volume_[t];
    }
    return energy;
}

double TissueModel::minVolumeRatio(std::size_t& inverted) const {
    inverted = 0;
    double smallest = 1e300;
    for (std::size_t t = 0; t < tets_.size(); ++t) {
        const Tet& tet = tets_[t];
        const auto p = [&tet](int k) { return static_cast<std::size_t>(tet[static_cast<std::size_t>(k)]); };
        const double j = determinant(multiply(shapeMatrix(x_[p(0)], x_[p(1)], x_[p(2)], x_[p(3)]), dmInv_[t]));
        if (j <= 0.0)
            ++inverted;
        smallest = std::min(smallest, j);
    }
    return tets_.empty() ? 1.0 : smallest;
}

double TissueModel::maxSpeedMPerS() const {
    double fastest = 0.0;
    for (const Vec3& v : v_)
        fastest = std::max(fastest, norm(v));
    return fastest;
}

} // namespace hs::sim::detail
