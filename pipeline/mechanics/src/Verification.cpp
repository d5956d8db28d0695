#include "hs/mechanics/Verification.h"

#include "hs/mechanics/CorotationalFem.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace hs::mechanics {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMm = 1e-3;

/// A layered mesh: a triangulated sheet (points per layer, triangles) repeated through layers, each prism between two
/// layers split into three tets so that neighbouring prisms agree on every quad face's diagonal (the diagonal through
/// the face's lowest-numbered point; Dompierre et al., "How to subdivide pyramids, prisms and hexahedra into
/// tetrahedra", IMR 1999).
std::vector<Tet> extrudePrisms(const std::vector<Triangle>& sheet, std::size_t pointsPerLayer, std::size_t layers) {
    std::vector<Tet> tets;
    for (std::size_t l = 0; l + 1 < layers; ++l)
        for (const Triangle& t : sheet) {
            std::array<std::int32_t, 6> v{};
            for (std::size_t k = 0; k < 3; ++k) {
                v[k] = static_cast<std::int32_t>(l * pointsPerLayer) + t[k];
                v[k + 3] = static_cast<std::int32_t>((l + 1) * pointsPerLayer) + t[k];
            }
            // Turn the prism so its lowest point is v[0] (a turn of the triangle, and top for bottom).
            const auto lowest = static_cast<std::size_t>(std::min_element(v.begin(), v.end()) - v.begin());
            if (lowest >= 3)
                std::swap_ranges(v.begin(), v.begin() + 3, v.begin() + 3);
            const std::size_t r = lowest % 3;
            std::array<std::int32_t, 6> w{v[r],     v[(r + 1) % 3],     v[(r + 2) % 3],
                                          v[3 + r], v[3 + (r + 1) % 3], v[3 + (r + 2) % 3]};
            if (std::min(w[1], w[5]) < std::min(w[2], w[4])) {
                tets.push_back({w[0], w[1], w[2], w[5]});
                tets.push_back({w[0], w[1], w[5], w[4]});
            } else {
                tets.push_back({w[0], w[1], w[2], w[4]});
                tets.push_back({w[0], w[4], w[2], w[5]});
            }
            tets.push_back({w[0], w[4], w[5], w[3]});
        }
    return tets;
}

/// Radii from 0: `inner` equal steps to `first`, then steps growing by `growth` up to `last` (the last one exact).
std::vector<double> gradedRadii(double first, int inner, double step, double growth, double last) {
    std::vector<double> r{0.0};
    for (int k = 1; k <= inner; ++k)
        r.push_back(first * k / inner);
    double h = step;
    while (r.back() + h < last - 0.3 * h) {
        r.push_back(r.back() + h);
        h *= growth;
    }
    r.push_back(last);
    return r;
}

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

std::vector<FemMaterial> uniform(std::size_t tets, double eKpa, double nu, double stiffeningStrain = 0.0) {
    return std::vector<FemMaterial>(tets, FemMaterial{eKpa * 1e3, nu, 1050.0, stiffeningStrain});
}

VerificationResult result(double simulated, double analytic, std::size_t points, std::size_t tets,
                          const CorotationalFem& fem, std::chrono::steady_clock::time_point start) {
    VerificationResult r;
    r.simulated = simulated;
    r.analytic = analytic;
    r.errorPercent = 100.0 * (simulated - analytic) / analytic;
    r.points = points;
    r.tets = tets;
    r.residualN = fem.residualN();
    r.seconds = seconds(start);
    return r;
}

Status checkMaterial(double eKpa, double nu) {
    if (!(eKpa > 0.0 && eKpa < 1e6) || !(nu >= 0.0 && nu < 0.5))
        return fail(ErrorCode::InvalidInput, "verification: Young's modulus 0-1e6 kPa, Poisson ratio 0-0.5");
    return {};
}

} // namespace

double boussinesqPunchForceN(double radiusMm, double depthMm, double youngsModulusKpa, double poissonRatio) {
    return 2.0 * radiusMm * kMm * youngsModulusKpa * 1e3 * depthMm * kMm / (1.0 - poissonRatio * poissonRatio);
}

double lameInnerDisplacementMm(double innerMm, double outerMm, double pressureKpa, double youngsModulusKpa,
                               double poissonRatio) {
    const double a = innerMm, b = outerMm, a3 = a * a * a, b3 = b * b * b;
    return pressureKpa * a3 / (youngsModulusKpa * (b3 - a3)) *
           ((1.0 - 2.0 * poissonRatio) * a + (1.0 + poissonRatio) * b3 / (2.0 * a * a));
}

PunchParams coarsePunchParams(double edgeMm) {
    PunchParams p;
    p.finestMm = edgeMm;
    p.growth = 1.0;
    p.domainRadii = std::max(20.0, 8.0 * edgeMm / p.punchRadiusMm);
    p.sectors = 4;
    return p;
}

Result<VerificationResult> runPunch(const PunchParams& p) {
    HS_TRY(checkMaterial(p.youngsModulusKpa, p.poissonRatio));
    if (!(p.punchRadiusMm > 0.0) || !(p.depthMm > 0.0) || !(p.domainRadii >= 2.0) || !(p.finestMm > 0.0) ||
        !(p.growth >= 1.0) || p.sectors < 2 || p.sectors > 64 || !(p.settleS >= 0.0) || !(p.rampS > 0.0) ||
        !(p.stiffeningStrain >= 0.0) || !(p.preStretch >= 0.0 && p.preStretch <= 0.3))
        return fail(ErrorCode::InvalidInput, "punch: radius, depth, finest, ramp > 0; domain >= 2 radii; growth >= 1; "
                                             "stiffening >= 0; pre-stretch 0-0.3");
    const auto start = std::chrono::steady_clock::now();
    const double a = p.punchRadiusMm, extent = p.domainRadii * a;
    // Rings: equal steps of about `finestMm` under the punch (its edge on a ring), growing beyond it.
    const int inner = std::max(1, static_cast<int>(std::lround(a / p.finestMm)));
    std::vector<double> rings = p.finestMm >= a ? gradedRadii(p.finestMm, 1, p.finestMm * p.growth, p.growth, extent)
                                                : gradedRadii(a, inner, a / inner * p.growth, p.growth, extent);
    const std::vector<double> depths = rings; // the same grading downwards
    const auto sectors = static_cast<std::size_t>(p.sectors);
    // The sheet: the axis point, then each ring's sectors + 1 points from angle 0 (the y = 0 plane) to 90 degrees.
    std::vector<Vec3> sheet{{0.0, 0.0, 0.0}};
    for (std::size_t k = 1; k < rings.size(); ++k)
        for (std::size_t j = 0; j <= sectors; ++j) {
            const double angle = 0.5 * kPi * static_cast<double>(j) / static_cast<double>(sectors);
            sheet.push_back({rings[k] * std::cos(angle), rings[k] * std::sin(angle), 0.0});
        }
    const auto ringPoint = [sectors](std::size_t k, std::size_t j) {
        return static_cast<std::int32_t>(1 + (k - 1) * (sectors + 1) + j);
    };
    std::vector<Triangle> triangles;
    for (std::size_t j = 0; j < sectors; ++j)
        triangles.push_back({0, ringPoint(1, j), ringPoint(1, j + 1)});
    for (std::size_t k = 1; k + 1 < rings.size(); ++k)
        for (std::size_t j = 0; j < sectors; ++j) {
            triangles.push_back({ringPoint(k, j), ringPoint(k + 1, j), ringPoint(k + 1, j + 1)});
            triangles.push_back({ringPoint(k, j), ringPoint(k + 1, j + 1), ringPoint(k, j + 1)});
        }
    std::vector<Vec3> points;
    for (const double z : depths)
        for (const Vec3& s : sheet)
            points.push_back(Vec3{s.x, s.y, -z} * kMm);
    const std::vector<Tet> tets = extrudePrisms(triangles, sheet.size(), depths.size());
    // Held: x on the x = 0 plane, y on the y = 0 plane (symmetry), z on the base; the punch holds z of the top's
    // points within its radius (frictionless: x and y free).
    // With a pre-stretch the rim (the block's outer cylinder) is drawn out radially, x and y held.
    std::vector<std::array<bool, 3>> fixed(points.size(), {false, false, false});
    std::vector<std::size_t> punched, rim, beside;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3 q = points[i] / kMm;
        const double r = std::hypot(q.x, q.y);
        const bool onRim = p.preStretch > 0.0 && r > rings.back() - 1e-9;
        fixed[i][0] = std::abs(q.x) < 1e-9 || onRim;
        fixed[i][1] = std::abs(q.y) < 1e-9 || onRim;
        fixed[i][2] = q.z < -extent + 1e-9;
        if (onRim)
            rim.push_back(i);
        if (std::abs(q.z) < 1e-9 && r <= a + 1e-9) {
            fixed[i][2] = true;
            punched.push_back(i);
        }
        // The top's ring just beyond the punch: where the free surface stands while the block is stretched.
        if (std::abs(q.z) < 1e-9 && r > a + 1e-9 && r <= rings[static_cast<std::size_t>(inner) + 1] + 1e-9)
            beside.push_back(i);
    }
    CorotationalFem fem;
    HS_TRY(fem.build(points, tets, uniform(tets.size(), p.youngsModulusKpa, p.poissonRatio, p.stiffeningStrain), fixed,
                     {}, p.solver));
    const std::vector<Vec3> none;
    std::vector<FemConstraint> contacts;
    // The pre-stretch: the rim drawn out over 0.5 s and held 1.5 s, the punch's points following the free top.
    std::vector<double> topZ(points.size(), 0.0);
    double reactionBefore = 0.0;
    if (p.preStretch > 0.0) {
        const int stretchSteps = static_cast<int>(std::lround(2.0 / p.solver.stepS));
        for (int s = 1; s <= stretchSteps; ++s) {
            const double e = p.preStretch * std::min(1.0, 4.0 * static_cast<double>(s) / stretchSteps);
            for (const std::size_t i : rim)
                fem.setTarget(i, {points[i].x * (1.0 + e), points[i].y * (1.0 + e), fem.positionsM()[i].z});
            double z = 0.0;
            for (const std::size_t i : beside)
                z += fem.positionsM()[i].z;
            z /= static_cast<double>(std::max<std::size_t>(1, beside.size()));
            for (const std::size_t i : punched)
                fem.setTarget(i, {fem.positionsM()[i].x, fem.positionsM()[i].y, z});
            fem.step(none, contacts);
        }
        for (const std::size_t i : punched)
            reactionBefore -= fem.reactionN(i).z;
    }
    for (const std::size_t i : punched)
        topZ[i] = fem.positionsM()[i].z;
    // The tissue's stiffening round the punch as the press begins.
    double weighted = 0.0, volume = 0.0;
    const double reach2 = (3.0 * a * kMm) * (3.0 * a * kMm);
    for (std::size_t t = 0; t < tets.size(); ++t) {
        bool near = false;
        for (const std::int32_t k : tets[t]) {
            const Vec3 x = fem.positionsM()[static_cast<std::size_t>(k)];
            near =
                near || x.x * x.x + x.y * x.y + (x.z - topZ[punched.front()]) * (x.z - topZ[punched.front()]) <= reach2;
        }
        if (near) {
            weighted += fem.restVolumeM3(t) * fem.stiffeningAt(t);
            volume += fem.restVolumeM3(t);
        }
    }
    const double preStiffening = volume > 0.0 ? weighted / volume : 1.0;
    const auto ramp = std::max(1, static_cast<int>(std::lround(p.rampS / p.solver.stepS)));
    const auto hold = static_cast<int>(std::lround(p.settleS / p.solver.stepS));
    for (int s = 1; s <= ramp + hold; ++s) {
        const double depth = p.depthMm * std::min(1.0, static_cast<double>(s) / ramp);
        for (const std::size_t i : punched)
            fem.setTarget(i, {fem.positionsM()[i].x, fem.positionsM()[i].y, topZ[i] - depth * kMm});
        fem.step(none, contacts);
    }
    // The punch's force on the block: the supports' reaction on the punched points (pushing down: -z), less what
    // holding them on the stretched top took, times 4.
    double force = -reactionBefore;
    for (const std::size_t i : punched)
        force -= fem.reactionN(i).z;
    auto r =
        result(4.0 * force, boussinesqPunchForceN(a, p.depthMm, p.youngsModulusKpa * preStiffening, p.poissonRatio),
               points.size(), tets.size(), fem, start);
    r.preStiffening = preStiffening;
    return r;
}

Result<VerificationResult> runLameSphere(const LameParams& p) {
    HS_TRY(checkMaterial(p.youngsModulusKpa, p.poissonRatio));
    if (!(p.innerRadiusMm > 0.0) || !(p.outerRadiusMm > p.innerRadiusMm) || !(p.pressureKpa > 0.0) || p.layers < 1 ||
        p.layers > 64 || p.subdivisions < 1 || p.subdivisions > 64 || !(p.settleS >= 0.0))
        return fail(ErrorCode::InvalidInput, "sphere: 0 < inner < outer radius, pressure > 0, layers and "
                                             "subdivisions 1-64");
    const auto start = std::chrono::steady_clock::now();
    // The octant's sheet: the triangle (1,0,0), (0,1,0), (0,0,1) cut into subdivisions^2 triangles, on the sphere.
    const auto n = static_cast<std::size_t>(p.subdivisions);
    std::vector<Vec3> unit;
    std::vector<std::vector<std::int32_t>> index(n + 1);
    for (std::size_t i = 0; i <= n; ++i)
        for (std::size_t j = 0; j + i <= n; ++j) {
            const double x = static_cast<double>(n - i - j), y = static_cast<double>(j), z = static_cast<double>(i);
            index[i].push_back(static_cast<std::int32_t>(unit.size()));
            unit.push_back(normalized(Vec3{x, y, z}));
        }
    std::vector<Triangle> triangles;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j + i < n; ++j) {
            triangles.push_back({index[i][j], index[i][j + 1], index[i + 1][j]});
            if (j + i + 1 < n)
                triangles.push_back({index[i][j + 1], index[i + 1][j + 1], index[i + 1][j]});
        }
    const auto layers = static_cast<std::size_t>(p.layers) + 1;
    std::vector<Vec3> points;
    for (std::size_t l = 0; l < layers; ++l) {
        const double r = p.innerRadiusMm +
                         (p.outerRadiusMm - p.innerRadiusMm) * static_cast<double>(l) / static_cast<double>(layers - 1);
        for (const Vec3& u : unit)
            points.push_back(u * (r * kMm));
    }
    const std::vector<Tet> tets = extrudePrisms(triangles, unit.size(), layers);
    std::vector<std::array<bool, 3>> fixed(points.size(), {false, false, false});
    for (std::size_t i = 0; i < points.size(); ++i)
        for (int d = 0; d < 3; ++d)
            fixed[i][static_cast<std::size_t>(d)] = std::abs(points[i][d]) < 1e-12;
    CorotationalFem fem;
    HS_TRY(fem.build(points, tets, uniform(tets.size(), p.youngsModulusKpa, p.poissonRatio, p.stiffeningStrain), fixed,
                     {}, p.solver));
    std::vector<Vec3> forces(points.size());
    std::vector<FemConstraint> contacts;
    const auto ramp = static_cast<int>(std::lround(0.1 / p.solver.stepS));
    const auto hold = static_cast<int>(std::lround(p.settleS / p.solver.stepS));
    for (int s = 1; s <= ramp + hold; ++s) {
        // The pressure on the inner faces as they lie now (a follower load), pushing the wall outwards.
        const double pa = p.pressureKpa * 1e3 * std::min(1.0, static_cast<double>(s) / ramp);
        std::fill(forces.begin(), forces.end(), Vec3{});
        const auto& x = fem.positionsM();
        for (const Triangle& t : triangles) {
            const Vec3 a = x[static_cast<std::size_t>(t[0])], b = x[static_cast<std::size_t>(t[1])],
                       c = x[static_cast<std::size_t>(t[2])];
            Vec3 area = cross(b - a, c - a) * 0.5;
            if (dot(area, a + b + c) < 0.0)
                area = area * -1.0;
            for (const std::int32_t v : t)
                forces[static_cast<std::size_t>(v)] += area * (pa / 3.0);
        }
        fem.step(forces, contacts);
    }
    double sum = 0.0;
    for (std::size_t i = 0; i < unit.size(); ++i)
        sum += dot(fem.positionsM()[i] - points[i], unit[i]) / kMm;
    return result(
        sum / static_cast<double>(unit.size()),
        lameInnerDisplacementMm(p.innerRadiusMm, p.outerRadiusMm, p.pressureKpa, p.youngsModulusKpa, p.poissonRatio),
        points.size(), tets.size(), fem, start);
}

} // namespace hs::mechanics
