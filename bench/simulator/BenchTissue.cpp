// The tissue solver (hs::mechanics::CorotationalFem): its verification against textbook solutions, the same problems
// on a scene's simulation-mesh resolution, and on the scene's simulation mesh its cost and its convergence per
// iteration. Tables, not tests (the bars are asserted by test_mechanics).
//
//   bench_tissue [PACKAGE [--package-only | --point-load]] | --coarse-punch | --deep-punch | --dimple
// --coarse-punch: the punch on uniform elements of 2-8 mm (the tip's load on one point, as on a simulation mesh), its
// force against Boussinesq's, and the effective radius that force means (docs/simulator.md, "Verification").
// --deep-punch [STRAIN]: the fine punch pressed 0.15-2.6 mm (to 1.8 radii, as the simulator's press checks press),
// linear and with the tissue's stiffening: how far a large indentation stands off Boussinesq's small-strain force;
// with STRAIN, the stiffening block stretched by that in-plane strain first, as the distension stretches the wall.
// --dimple: the give a scope's tip needs below a coarse mesh's resolution for the two in series to press as the fine
// punch does at each depth (dimpleTable), against punchDimpleStiffening's law at that dimple.
// --point-load: on the package's uterus model, a force along the inward normal of one cavity point, solved statically
// with the cavity at 0, 30 and 80 mmHg: the wall's point nearest the fundus and each pathology's cavity point nearest
// the internal os (the one a scope from the canal meets first), its stiffness and its ratio to the wall's.
// PACKAGE: a scene package with a simulation mesh (hysteroscene-cli generate resources/cases/default.json -o DIR).

#include "hs/core/Units.h"
#include "hs/mechanics/CorotationalFem.h"
#include "hs/mechanics/UterusModel.h"
#include "hs/mechanics/Verification.h"
#include "hs/scene/ScenePackage.h"
#include "hs/scene/ScopePassage.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using namespace hs;
using namespace hs::mechanics;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

void verificationTable() {
    std::printf("Verification (steady state of the solver's time steps; test_mechanics asserts the bars)\n");
    std::printf("%-34s %6s %5s %12s %12s %8s %7s %7s\n", "problem", "E kPa", "nu", "solver", "textbook", "error",
                "tets", "s");
    for (const double nu : {0.45, 0.47, 0.49})
        for (const double e : {15.0, 65.0}) {
            PunchParams p;
            p.youngsModulusKpa = e;
            p.poissonRatio = nu;
            const auto r = runPunch(p);
            if (r)
                std::printf("%-34s %6.0f %5.2f %10.5f N %10.5f N %+7.1f%% %7zu %7.1f\n",
                            "punch a 1.45 mm, delta 0.15 mm", e, nu, r->simulated, r->analytic, r->errorPercent,
                            r->tets, r->seconds);
        }
    for (const double nu : {0.45, 0.47, 0.49})
        for (const double e : {15.0, 65.0}) {
            LameParams p;
            p.youngsModulusKpa = e;
            p.poissonRatio = nu;
            p.pressureKpa = 0.015 * e;
            const auto r = runLameSphere(p);
            if (r)
                std::printf("%-34s %6.0f %5.2f %9.4f mm %9.4f mm %+7.1f%% %7zu %7.1f\n", "sphere 10/20 mm, p = 1.5 % E",
                            e, nu, r->simulated, r->analytic, r->errorPercent, r->tets, r->seconds);
        }
    // Beyond the small-strain solution: the distension pressures on the myometrium's modulus, linear and with the
    // myometrium's exponential stiffening (Pearsall & Roberts 1978; the line search keeps the iteration converging).
    for (const double stiffening : {0.0, 0.104})
        for (const double mmHg : {40.0, 60.0, 100.0}) {
            LameParams p;
            p.youngsModulusKpa = 30.0;
            p.pressureKpa = mmHg * 0.133322;
            p.stiffeningStrain = stiffening;
            p.solver.maxStiffening = 1e6;
            p.settleS = 1.5;
            const auto r = runLameSphere(p);
            const bool settled = r && std::isfinite(r->simulated) && std::abs(r->simulated) < 100.0;
            std::printf("sphere 10/20 mm, %3.0f mmHg, %-9s %6.0f %5.2f ", mmHg,
                        stiffening > 0.0 ? "stiffening" : "linear", p.youngsModulusKpa, p.poissonRatio);
            if (settled)
                std::printf("%9.4f mm %9.4f mm %+7.1f%% %7zu %7.1f\n", r->simulated, r->analytic, r->errorPercent,
                            r->tets, r->seconds);
            else
                std::printf("no equilibrium (the wall balloons past its limit point)\n");
        }
    // Without the nodal pressure: linear tets lock.
    for (const double nu : {0.45, 0.49}) {
        PunchParams p;
        p.poissonRatio = nu;
        p.solver.nodalPressure = false;
        const auto r = runPunch(p);
        if (r)
            std::printf("%-34s %6.0f %5.2f %10.5f N %10.5f N %+7.1f%% %7zu %7.1f\n", "punch, element pressure (locks)",
                        p.youngsModulusKpa, nu, r->simulated, r->analytic, r->errorPercent, r->tets, r->seconds);
    }
}

double meanEdgeMm(const TetMesh& mesh) {
    double sum = 0.0;
    std::size_t count = 0;
    for (const Tet& t : mesh.tets)
        for (std::size_t a = 0; a < 4; ++a)
            for (std::size_t b = a + 1; b < 4; ++b) {
                sum +=
                    distance(mesh.points[static_cast<std::size_t>(t[a])], mesh.points[static_cast<std::size_t>(t[b])]);
                ++count;
            }
    return count ? sum / static_cast<double>(count) : 0.0;
}

void packageTables(const std::string& package) {
    auto scene = scene::readScenePackage(package);
    if (!scene || !scene->simulation) {
        std::fprintf(stderr, "bench_tissue: %s: %s\n", package.c_str(),
                     scene ? "no simulation mesh" : scene.error().detail.c_str());
        return;
    }
    const TetMesh& mesh = scene->simulation->tets;
    const double edge = meanEdgeMm(mesh);
    std::printf("\nThe same problems at the simulation mesh's resolution (mean edge %.2f mm)\n", edge);
    {
        const auto r = runPunch(coarsePunchParams(edge));
        if (r)
            std::printf("punch a 1.45 mm on %.1f mm elements: %.5f N, Boussinesq %.5f N, error %+.1f %% (%zu tets)\n",
                        edge, r->simulated, r->analytic, r->errorPercent, r->tets);
    }
    {
        LameParams p;
        p.layers = std::max(1, static_cast<int>(std::lround((p.outerRadiusMm - p.innerRadiusMm) / edge)));
        p.subdivisions = std::max(1, static_cast<int>(std::lround(0.5 * 3.14159265 * p.innerRadiusMm / edge)));
        p.pressureKpa = 0.015 * p.youngsModulusKpa;
        const auto r = runLameSphere(p);
        if (r)
            std::printf("sphere 10/20 mm, %d layers: %.4f mm, Lame %.4f mm, error %+.1f %% (%zu tets)\n", p.layers,
                        r->simulated, r->analytic, r->errorPercent, r->tets);
    }

    // The solver on the simulation mesh: the portio held, a load like the distension's on the whole mesh.
    std::vector<Vec3> points;
    for (const Vec3& q : mesh.points)
        points.push_back(q * 1e-3);
    const auto& ids = mesh.tetLabels.at("material");
    std::vector<FemMaterial> materials;
    for (std::size_t t = 0; t < mesh.tetCount(); ++t) {
        const auto& m = scene->materials[static_cast<std::size_t>(ids[t])].material;
        materials.push_back({m.youngsModulusKpa * 1e3, m.poissonRatio, m.densityKgPerM3});
    }
    std::vector<std::array<bool, 3>> fixed(points.size(), {false, false, false});
    const auto& support = mesh.tetLabels.at("support");
    for (std::size_t t = 0; t < mesh.tetCount(); ++t)
        if (support[t] == 1)
            for (const std::int32_t q : mesh.tets[t])
                fixed[static_cast<std::size_t>(q)] = {true, true, true};
    const std::vector<Vec3> load(points.size(), Vec3{0.0, 2e-4, 0.0});
    std::printf("\nOn the simulation mesh (%zu points, %zu tets): cost and convergence under a load held 1 s\n",
                points.size(), mesh.tetCount());
    std::printf("%10s %9s %10s %12s %12s %16s %16s\n", "iterations", "matrix", "L nnz", "factor ms", "step ms",
                "residual 1st N", "residual end N");
    std::vector<Vec3> reference;
    struct Variant {
        int iterations;
        bool nodalMatrix;
    };
    for (const Variant variant : {Variant{8, true}, Variant{1, true}, Variant{2, true}, Variant{1, false},
                                  Variant{2, false}, Variant{3, false}}) {
        FemSettings settings;
        settings.iterations = variant.iterations;
        settings.nodalPressureMatrix = variant.nodalMatrix;
        CorotationalFem fem;
        const auto t0 = Clock::now();
        if (!fem.build(points, mesh.tets, materials, fixed, {}, settings))
            return;
        const double factorMs = msSince(t0);
        std::vector<FemConstraint> none;
        const auto t1 = Clock::now();
        double first = 0.0;
        for (int s = 0; s < 200; ++s) {
            fem.step(load, none);
            if (s == 0)
                first = fem.residualN();
        }
        const double stepMs = msSince(t1) / 200.0;
        const FemStepTimings timing = fem.lastTimings();
        std::printf("%10d %9s %10zu %12.1f %12.3f %16.3e %16.3e", variant.iterations,
                    variant.nodalMatrix ? "nodal" : "element", fem.factorNonZeros(), factorMs, stepMs, first,
                    fem.residualN());
        if (reference.empty()) {
            reference = fem.positionsM();
            std::printf("   (the reference)");
        } else {
            double worst = 0.0;
            for (std::size_t i = 0; i < points.size(); ++i)
                worst = std::max(worst, distance(fem.positionsM()[i], reference[i]));
            std::printf("   off the reference by %.2e mm", worst * 1e3);
        }
        std::printf("   (last step: forces %.2f ms, solves %.2f ms)\n", timing.forcesMs, timing.solveMs);
    }
}

} // namespace

/// The static stiffness of one cavity point under a force along its inward normal, N/mm, with the cavity at
/// `pressureKpa` (the static solver of generate's hydrometra curve, buildStaticSolver; settled to 1e-7 mm a step, far
/// tighter than the curve's volume criterion, since a 0.02 N load moves the point about 0.1 mm); {at 0.02 N, at 0.1 N}.
std::pair<double, double> pointStiffness(const UterusModel& model, std::size_t point, const Vec3& inward,
                                         double pressureKpa) {
    CorotationalFem still;
    if (!buildStaticSolver(model, still).ok())
        return {0.0, 0.0};
    std::vector<Vec3> pts = model.restMm, forces;
    std::vector<FemConstraint> none;
    const auto settle = [&](double forceN) {
        double last = 0.0;
        for (int step = 0; step < 400; ++step) {
            const double ramp = std::min(1.0, (step + 1) / 5.0);
            model.pressureForces(pts, pressureKpa * ramp, forces);
            forces[point] += inward * forceN;
            still.step(forces, none);
            for (std::size_t i = 0; i < pts.size(); ++i)
                pts[i] = still.positionsM()[i] * 1e3;
            const double along = dot(pts[point], inward);
            if (step > 5 && std::abs(along - last) < 1e-7)
                break;
            last = along;
        }
    };
    settle(0.0);
    const Vec3 before = pts[point];
    settle(0.02);
    const double small = 0.02 / dot(pts[point] - before, inward);
    settle(0.1);
    return {small, 0.1 / dot(pts[point] - before, inward)};
}

void pointLoadTable(const std::string& package) {
    auto scene = scene::readScenePackage(package);
    UterusModel model;
    if (!scene || !buildUterusModel(*scene, FemSettings{}, model).ok()) {
        std::fprintf(stderr, "bench_tissue: %s: no uterus model\n", package.c_str());
        return;
    }
    const auto landmarks = scene::findScopeLandmarks(*scene);
    if (!landmarks)
        return;
    // Each cavity point's inward normal (area-weighted, the cavity's faces face into it) and the regions it bounds.
    const std::size_t n = model.restMm.size();
    std::vector<Vec3> normal(n);
    std::vector<std::vector<std::int32_t>> regions(n);
    for (std::size_t f = 0; f < model.boundary.size(); ++f) {
        if (!model.faceCavity[f])
            continue;
        const Triangle& t = model.boundary[f];
        const Vec3 a = model.restMm[static_cast<std::size_t>(t[0])], b = model.restMm[static_cast<std::size_t>(t[1])],
                   c = model.restMm[static_cast<std::size_t>(t[2])];
        for (const std::int32_t v : t) {
            normal[static_cast<std::size_t>(v)] += cross(b - a, c - a);
            regions[static_cast<std::size_t>(v)].push_back(model.region[f]);
        }
    }
    struct Target {
        std::string name;
        std::int32_t region = -1;
        Vec3 towards;
        double youngsKpa = 0.0;
    };
    std::vector<Target> targets;
    std::int32_t wallRegion = -1;
    for (const auto& r : scene->regions)
        if (r.name == "endometrium")
            wallRegion = r.id;
    targets.push_back({"wall (endometrium, nearest the fundus)", wallRegion, landmarks->fundusMm, 0.0});
    for (const auto& r : scene->regions)
        if (!r.pathologyId.empty())
            targets.push_back({r.name + " (nearest the internal os)", r.id, landmarks->internalOsMm, 0.0});
    for (Target& t : targets)
        for (const auto& m : scene->materials)
            if (m.regionId == t.region)
                t.youngsKpa = m.material.youngsModulusKpa;
    std::printf("\nA point load on the uterus model (static; the point's own region only, not held)\n");
    std::printf(
        "| point | E kPa | cavity mmHg | stiffness at 0.02 N, N/mm | at 0.1 N, N/mm | / the wall's | E / the wall's |\n"
        "|---|---|---|---|---|---|---|\n");
    std::vector<double> wallStiffness;
    for (std::size_t k = 0; k < targets.size(); ++k) {
        const Target& t = targets[k];
        std::size_t best = n;
        for (std::size_t i = 0; i < n; ++i) {
            if (model.pointHeld[i] || regions[i].empty())
                continue;
            bool own = true;
            for (const std::int32_t r : regions[i])
                own = own && r == t.region;
            if (own && (best == n || distance(model.restMm[i], t.towards) < distance(model.restMm[best], t.towards)))
                best = i;
        }
        if (best == n) {
            std::printf("| %s | no cavity point of its own |\n", t.name.c_str());
            continue;
        }
        const Vec3 inward = normalized(normal[best]) * -1.0;
        std::size_t row = 0;
        for (const double mmHg : {0.0, 30.0, 80.0}) {
            const auto [small, large] = pointStiffness(model, best, inward, mmHg * units::kKpaPerMmHg);
            if (k == 0)
                wallStiffness.push_back(small);
            const double wall = row < wallStiffness.size() ? wallStiffness[row] : 0.0;
            std::printf("| %s | %.0f | %.0f | %.3f | %.3f | %.2f | %.2f |\n", t.name.c_str(), t.youngsKpa, mmHg, small,
                        large, wall > 0.0 ? small / wall : 0.0,
                        targets[0].youngsKpa > 0.0 ? t.youngsKpa / targets[0].youngsKpa : 0.0);
            ++row;
        }
    }
}

/// The punch on coarse uniform elements: the force is a point load's on a node, about Boussinesq's for an effective
/// radius proportional to the element's size.
void coarsePunchTable() {
    std::printf("| element mm | E kPa | nu | solver N | Boussinesq N | error | effective radius mm | / element |\n"
                "|---|---|---|---|---|---|---|---|\n");
    for (const double nu : {0.45, 0.47, 0.49})
        for (const double edge : {2.0, 3.0, 4.4, 6.0, 8.0}) {
            PunchParams p = coarsePunchParams(edge);
            p.poissonRatio = nu;
            const auto r = runPunch(p);
            if (!r)
                continue;
            // F = 2 a E delta / (1 - nu^2): the radius that gives the solver's force.
            const double effective = p.punchRadiusMm * r->simulated / r->analytic;
            std::printf("| %.1f | %.0f | %.2f | %.5f | %.5f | %+.1f %% | %.2f | %.3f |\n", edge, p.youngsModulusKpa, nu,
                        r->simulated, r->analytic, r->errorPercent, effective, effective / edge);
        }
}

/// `base` pressed `depthMm` deep into a material of stiffening strain `c`, ramped over a second a millimetre (at
/// least 0.1 s), as the deep tables press.
PunchParams pressedDeep(PunchParams base, double c, double depthMm) {
    base.stiffeningStrain = c;
    base.depthMm = depthMm;
    base.rampS = std::max(0.1, depthMm);
    return base;
}

/// The punch pressed deep, as the simulator's press checks press (an indentation of 1-1.6 tip radii): the fine mesh's
/// force against Boussinesq's small-strain one, with the material linear (the geometry's own nonlinearity) and with
/// the tissue's stiffening (kUterusStiffeningStrain, held below the solver's maxStiffening as the world holds it).
/// With `preStretch` > 0, the stiffening block stretched in its plane first (as the distension stretches the wall), and
/// Boussinesq's force taken with the modulus as stiffened round the punch when the press begins.
void deepPunchTable(double preStretch) {
    std::printf("| material | depth mm | depth / radius | solver N | Boussinesq N | solver / Boussinesq's | stiffening "
                "as pressed | tets | s |\n"
                "|---|---|---|---|---|---|---|---|---|\n");
    const std::vector<double> materials = preStretch > 0.0
                                              ? std::vector<double>{hs::mechanics::kUterusStiffeningStrain}
                                              : std::vector<double>{0.0, hs::mechanics::kUterusStiffeningStrain};
    for (const double c : materials)
        for (const double depth : {0.15, 0.5, 1.0, 1.5, 2.0, 2.3, 2.6}) {
            PunchParams p = pressedDeep(PunchParams{}, c, depth);
            p.preStretch = preStretch;
            const auto r = runPunch(p);
            if (!r) {
                std::printf("| %s | %.2f | - | %s |\n", c > 0.0 ? "stiffening" : "linear", depth,
                            r.error().detail.c_str());
                continue;
            }
            std::printf("| %s | %.2f | %.2f | %.5f | %.5f | %.3f | %.3f | %zu | %.1f |\n",
                        preStretch > 0.0 ? "stiffening, stretched"
                        : c > 0.0        ? "stiffening"
                                         : "linear",
                        depth, depth / p.punchRadiusMm, r->simulated, r->analytic, r->simulated / r->analytic,
                        r->preStiffening, r->tets, r->seconds);
        }
}

/// The tip's sub-element give as the fine punch asks for it at depth: a coarse mesh of `edge` mm pressed on one
/// point (as a scope's tip on a simulation mesh's face) carries the fine punch's force F(delta) with an indentation
/// delta_m of its own; the rest, delta - delta_m, is the give's dimple. The give's stiffening is then
/// C F / (delta - delta_m), C the small-strain sub-element give (punchSubElementCompliance at a point): what
/// punchDimpleStiffening should be at that dimple for the coarse mesh and the give in series to press as the fine mesh.
/// Then how much the tissue's stiffening raises the fine block's press and the coarse mesh's own over the linear
/// material's, indentation for indentation.
void dimpleTable() {
    std::printf("| material | element mm | depth mm | fine N | coarse mm | dimple mm | dimple / radius | stiffening "
                "asked | the law's | s |\n"
                "|---|---|---|---|---|---|---|---|---|---|\n");
    using Curve = std::vector<std::pair<double, double>>; // indentation mm, force N
    const auto forceAt = [](const Curve& curve, double depthMm) {
        for (std::size_t k = 1; k < curve.size(); ++k)
            if (curve[k].first >= depthMm)
                return curve[k - 1].second + (curve[k].second - curve[k - 1].second) * (depthMm - curve[k - 1].first) /
                                                 (curve[k].first - curve[k - 1].first);
        return 0.0;
    };
    Curve fineOf[2];
    std::vector<Curve> coarseOf[2];
    const std::array<double, 3> edges{3.0, 4.4, 6.0};
    for (const double c : {0.0, hs::mechanics::kUterusStiffeningStrain}) {
        Curve& fine = fineOf[c > 0.0 ? 1 : 0];
        for (const double depth : {0.15, 0.5, 1.0, 1.5, 2.0, 2.3}) {
            const auto r = runPunch(pressedDeep(PunchParams{}, c, depth));
            if (r)
                fine.emplace_back(depth, r->simulated);
        }
        for (const double edge : edges) {
            const auto start = Clock::now();
            // The coarse mesh's force against its own indentation, 0.02-3 mm.
            coarseOf[c > 0.0 ? 1 : 0].push_back({{0.0, 0.0}});
            Curve& coarse = coarseOf[c > 0.0 ? 1 : 0].back();
            for (double d = 0.02; d <= 3.0 + 1e-9; d *= 1.25) {
                const auto r = runPunch(pressedDeep(coarsePunchParams(edge), c, d));
                if (r)
                    coarse.emplace_back(d, r->simulated);
            }
            const PunchParams any;
            const FemMaterial material{any.youngsModulusKpa * 1e3, any.poissonRatio, 1050.0, c};
            const double radiusM = any.punchRadiusMm * 1e-3;
            const double give = punchSubElementCompliance(radiusM, edge * 1e-3, {1.0, 0.0, 0.0}, material);
            for (const auto& [depth, force] : fine) {
                double own = -1.0;
                for (std::size_t k = 1; k < coarse.size(); ++k)
                    if (coarse[k].second >= force) {
                        const auto [d0, f0] = coarse[k - 1];
                        const auto [d1, f1] = coarse[k];
                        own = d0 + (d1 - d0) * (force - f0) / (f1 - f0);
                        break;
                    }
                if (own < 0.0) {
                    std::printf("| %s | %.1f | %.2f | %.4f | beyond 3 mm |\n", c > 0.0 ? "stiffening" : "linear", edge,
                                depth, force);
                    continue;
                }
                const double dimpleMm = depth - own;
                const double asked = dimpleMm > 0.0 ? give * force / (dimpleMm * 1e-3) : 0.0;
                std::printf("| %s | %.1f | %.2f | %.4f | %.3f | %.3f | %.3f | %.3f | %.3f | %.1f |\n",
                            c > 0.0 ? "stiffening" : "linear", edge, depth, force, own, dimpleMm,
                            dimpleMm / any.punchRadiusMm, asked,
                            punchDimpleStiffening(dimpleMm * 1e-3, radiusM, material, FemSettings{}.maxStiffening),
                            msSince(start) * 1e-3);
            }
        }
    }
    // How much the stiffening raises each mesh's press over the linear material's at the same indentation: the fine
    // block's, and the coarse mesh's on one point alone (no give).
    std::printf("\n| indentation mm | fine: stiffening / linear |");
    for (const double edge : edges)
        std::printf(" coarse %.1f mm: stiffening / linear |", edge);
    std::printf("\n|---|---|---|---|---|\n");
    for (const double depth : {0.15, 0.5, 1.0, 1.5, 2.0, 2.3}) {
        const double lin = forceAt(fineOf[0], depth), stiff = forceAt(fineOf[1], depth);
        std::printf("| %.2f | %.3f |", depth, lin > 0.0 ? stiff / lin : 0.0);
        for (std::size_t e = 0; e < edges.size() && e < coarseOf[0].size() && e < coarseOf[1].size(); ++e) {
            const double cl = forceAt(coarseOf[0][e], depth), cs = forceAt(coarseOf[1][e], depth);
            std::printf(" %.3f |", cl > 0.0 ? cs / cl : 0.0);
        }
        std::printf("\n");
    }
}

int main(int argc, char** argv) {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    if (argc > 1 && std::string(argv[1]) == "--coarse-punch") {
        coarsePunchTable();
        return 0;
    }
    if (argc > 1 && std::string(argv[1]) == "--dimple") {
        dimpleTable();
        return 0;
    }
    if (argc > 1 && std::string(argv[1]) == "--deep-punch") {
        deepPunchTable(argc > 2 ? std::atof(argv[2]) : 0.0);
        return 0;
    }
    if (argc > 2 && std::string(argv[2]) == "--point-load") {
        pointLoadTable(argv[1]);
        return 0;
    }
    if (argc < 3 || std::string(argv[2]) != "--package-only")
        verificationTable();
    if (argc > 1)
        packageTables(argv[1]);
    return 0;
}
