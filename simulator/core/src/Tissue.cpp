#include "Tissue.h"

#include "Bvh.h"
#include "hs/mechanics/TetMath.h"

#include <algorithm>
#include <cmath>

namespace hs::sim::detail {

namespace {

constexpr double kMm = 1e-3; // m per mm

using mechanics::column;
using mechanics::determinant;
using mechanics::invert;
using mechanics::Mat3;
using mechanics::multiply;
using mechanics::rotationOf;
using mechanics::shapeMatrix;

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
            mass[static_cast<std::size_t>(p)] += massScale * m.densityKgPerM3 * volume_[t] / 4.0;
    }
    w_.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        w_[i] = (fixed[i] || mass[i] <= 0.0) ? 0.0 : 1.0 / mass[i];
    lambdaH_.assign(tets_.size(), 0.0);
    lambdaD_.assign(tets_.size(), 0.0);
    rotation_.assign(tets_.size(), {1.0, 0.0, 0.0, 0.0});
    tethers_ = tethers;
    lambdaT_.assign(tethers_.size(), 0.0);
}

void TissueModel::step(double dt, int substeps, const std::vector<Vec3>& externalForcesN,
                       std::vector<ContactPair>& contacts, const std::vector<Triangle>& surface) {
    // Small steps (Macklin et al., "Small Steps in Physics Simulation", SCA 2019): `substeps` substeps of one
    // iteration each converge better than as many iterations of one step, at the same cost.
    const std::size_t n = x_.size();
    const double h = dt / static_cast<double>(substeps);
    const double h2 = h * h;
    const double keep = std::max(0.0, 1.0 - damping * h);
    std::vector<double> contactLambda(contacts.size(), 0.0);
    for (int sub = 0; sub < substeps; ++sub) {
        for (std::size_t i = 0; i < n; ++i) {
            prev_[i] = x_[i];
            if (w_[i] == 0.0)
                continue;
            v_[i] = v_[i] + externalForcesN[i] * (w_[i] * h);
            x_[i] = x_[i] + v_[i] * h;
        }
        std::fill(lambdaH_.begin(), lambdaH_.end(), 0.0);
        std::fill(lambdaD_.begin(), lambdaD_.end(), 0.0);
        std::fill(lambdaT_.begin(), lambdaT_.end(), 0.0);
        for (auto& c : contacts)
            c.lambda = 0.0;
        // The contacts first, the tets last: the tets then spread what the scope pushed over the wall behind it,
        // and the substep ends with every tet projected after its last push. Solved after the tets, a stiff point
        // contact on the coarse mesh folded the thin endometrial tets under the tip inside out (the inverted tets
        // of docs/simulator.md's first 10-minute trial); the price is a slight penetration of the tip, which the
        // next substep takes up.
        solveContacts(contacts, surface, h2);
        for (std::size_t k = 0; k < contacts.size(); ++k)
            contactLambda[k] += contacts[k].lambda;
        for (std::size_t t = 0; t < tets_.size(); ++t)
            solveTet(t, h2);
        solveTethers(h2);
        for (std::size_t i = 0; i < n; ++i)
            v_[i] = w_[i] == 0.0 ? Vec3{0.0, 0.0, 0.0} : (x_[i] - prev_[i]) * (keep / h);
    }
    // The contacts' mean force over the step is sum(lambda) / (substeps h^2): report it as lambda / dt^2.
    const double toStep = static_cast<double>(substeps);
    for (std::size_t k = 0; k < contacts.size(); ++k)
        contacts[k].lambda = contactLambda[k] * toStep;
}

void TissueModel::solveTet(std::size_t t, double dt2) {
    // The fixed corotated material (Stomakhin et al. 2012): psi = mu |F - R|^2 + lambda/2 (det F - 1)^2, as two XPBD
    // constraints solved together (a 2x2 system in the multipliers' increments, after Macklin & Muller 2021):
    // C_D = |F - R| with compliance 1 / (2 mu V) and C_H = det F - 1 with compliance 1 / (lambda V). Both vanish at
    // rest, so the rest state carries no pre-stress and stays put at large substeps.
    const Tet& tet = tets_[t];
    const auto p = [&tet](int k) { return static_cast<std::size_t>(tet[static_cast<std::size_t>(k)]); };
    const double vol = volume_[t];
    if (vol <= 0.0)
        return;
    const Mat3 f = multiply(shapeMatrix(x_[p(0)], x_[p(1)], x_[p(2)], x_[p(3)]), dmInv_[t]);
    const Mat3 r = rotationOf(f, rotation_[t], 1);
    Mat3 dDdF;
    double cD2 = 0.0;
    for (std::size_t k = 0; k < 9; ++k) {
        dDdF[k] = f[k] - r[k];
        cD2 += dDdF[k] * dDdF[k];
    }
    const double cD = std::sqrt(cD2);
    const bool deviatoric = cD > 1e-9;
    if (deviatoric)
        for (double& v : dDdF)
            v /= cD;
    const Vec3 f1 = column(f, 0), f2 = column(f, 1), f3 = column(f, 2);
    const Vec3 c1 = cross(f2, f3), c2 = cross(f3, f1), c3 = cross(f1, f2);
    const Mat3 dHdF{c1.x, c2.x, c3.x, c1.y, c2.y, c3.y, c1.z, c2.z, c3.z};
    const double cH = determinant(f) - 1.0;
    const std::array<Vec3, 4> gD = pointGradients(dDdF, dmInv_[t]);
    const std::array<Vec3, 4> gH = pointGradients(dHdF, dmInv_[t]);
    const double aD = 1.0 / (2.0 * mu_[t] * vol * dt2), aH = 1.0 / (lambda_[t] * vol * dt2);
    double dd = aD, hh = aH, dh = 0.0;
    for (int k = 0; k < 4; ++k) {
        const double wk = w_[p(k)];
        const auto ku = static_cast<std::size_t>(k);
        if (deviatoric) {
            dd += wk * dot(gD[ku], gD[ku]);
            dh += wk * dot(gD[ku], gH[ku]);
        }
        hh += wk * dot(gH[ku], gH[ku]);
    }
    const double rD = deviatoric ? -cD - aD * lambdaD_[t] : 0.0;
    const double rH = -cH - aH * lambdaH_[t];
    const double det = dd * hh - dh * dh;
    if (std::abs(det) < 1e-300)
        return;
    const double dLD = (rD * hh - dh * rH) / det;
    const double dLH = (dd * rH - dh * rD) / det;
    lambdaD_[t] += dLD;
    lambdaH_[t] += dLH;
    for (int k = 0; k < 4; ++k) {
        const auto ku = static_cast<std::size_t>(k);
        x_[p(k)] = x_[p(k)] + (gD[ku] * dLD + gH[ku] * dLH) * w_[p(k)];
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

void TissueModel::solveContacts(std::vector<ContactPair>& contacts, const std::vector<Triangle>& surface, double dt2) {
    for (ContactPair& pair : contacts) {
        const Triangle& tri = surface[static_cast<std::size_t>(pair.triangle)];
        const auto i0 = static_cast<std::size_t>(tri[0]), i1 = static_cast<std::size_t>(tri[1]),
                   i2 = static_cast<std::size_t>(tri[2]);
        const Vec3 n = cross(x_[i1] - x_[i0], x_[i2] - x_[i0]);
        const double area2 = norm(n);
        if (area2 < 1e-18)
            continue;
        const Vec3 normal = n / area2;
        const ClosestPoint closest = closestPointOnTriangle(pair.centre, x_[i0], x_[i1], x_[i2]);
        const double b0 = closest.wa, b1 = closest.wb, b2 = closest.wc;
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
            continue; // a held triangle: the scope cannot move it
        const double compliance = contactCompliance / dt2;
        const double dLambda = (-c - compliance * pair.lambda) / (denominator + compliance);
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
        std::array<double, 4> q = rotation_[t];
        const Mat3 r = rotationOf(f, q, 8);
        double d2 = 0.0;
        for (std::size_t k = 0; k < 9; ++k)
            d2 += (f[k] - r[k]) * (f[k] - r[k]);
        const double j = determinant(f) - 1.0;
        energy += (mu_[t] * d2 + 0.5 * lambda_[t] * j * j) * volume_[t];
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
