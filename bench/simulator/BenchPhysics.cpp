// The simulator's physics on a scene package: the simulation mesh's size and quality, the step's cost (the bar:
// >= 200 Hz on 2 cores) and a long scripted trial's stability (no inverted tets, bounded energy). A table, not a test.
//
//   bench_physics PACKAGE [--seconds 60] [--iterations 6] [--trace] [--rough SEED] [--canal [--introitus MM]]
//                 [--press [--wall PKG2] [--linear] [--from-plan] [--faces N]]
//                 [--demo polypectomy|myomectomy [--steps FILE]]
// --press: instead of a trial, presses of the device 0.5, 1, 2 and 3 mm into the cavity's wall and into each
// pathology met head-on (pressScript), each on a fresh world, held 2 s. The depth is counted from the face where it
// stands as the tip leaves its stand-off (the plan made again there, pressFaceOffsetMm); --from-plan: from the face as
// the static solve at the planning pressure (60 mmHg) left it, as pressScript plans. Printed: the tip's force, the
// coupling's stretch (the force over its 1 N/mm), the tissue's indentation (the physics' scope's tip, its sub-element
// dimple included, beyond the face as it stood when the press began: pressIndentationMm), its secant stiffness, each
// pathology's force and stiffness against the wall's at the same depth; and, as the press began, the tissue's modulus
// round the face as its exponential stiffening has it in the distended state (World::tissueModulusNearKpa), the force
// ratio over that modulus' ratio, and how far the face stood off its planned place (along its normal, + towards the
// scope); and the fine verification block's force over Boussinesq's at the same indentation, at rest or stretched as
// the face's tissue is stiffened (fineBlockOverBoussinesq), with how far the press stands off it. --wall PACKAGE2: the
// wall's presses on that package instead (a scene whose pathologies leave a wall to press head-on). --linear: the
// tissue without its stiffening (WorldOptions::linearTissue). --faces N: instead, the 3 mm press into the wall at each
// of its N faces met most nearly head-on (pressScript's rank 0 to N-1, each a tip's diameter from the others), each on
// a fresh world: how the punch stands against Boussinesq's from one face of the simulation mesh to the next, and the
// spread of that ratio.
// --canal: instead of a trial, the entries through the cervical canal (entryScript: along its clearest line, and 15 and
// 30 degrees off it), each on a fresh world: the peak and held force, how far the physics' scope stayed off the
// device, how far the fundus and the internal os moved, perforations (false passages), the worst inverted-tet count.
// --introitus MM: the same entries with the scope pivoting at the introitus, MM behind the external os on each entry's
// line, and the portio free on the cervix's supports (WorldOptions::introitusMm), not at the held external os.
// --rough SEED: the rough trial (roughScript: random presses into the walls and the pathologies at a hand's speeds)
// instead of the exploration, repeated every 60 s.
// --trace: the script's keyframes, a line for every perforation, every 0.1 s with an inverted tet (the script's time,
// the tip's place, and each inverted tet with its region and its distance from the tip) or an elastic energy above
// 0.5 J, and every 50 ms with a contact above 2 N: to find which move of the script is at fault.
// --demo polypectomy|myomectomy: instead of the exploration, that exercise's demonstration (demonstrationScript), once:
// what it removed, the healthy tissue it took, and the physics step from the first cut on. --steps FILE: each of those
// steps as a line of FILE (CSV: its ms; the forces', solves', contact problem's and loop's ms; whether it cut, had
// the surface's compliance precomputed, took forward solves, had a volume row, touched).
// PACKAGE: a scene package with a simulation mesh (hysteroscene-cli generate resources/cases/default.json -o DIR).

#include "hs/core/TriangleGeometry.h"
#include "hs/meshing/QualityReport.h"
#include "hs/sim/World.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

double percentile(std::vector<double> v, double q) {
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5))];
}

} // namespace

namespace {

/// The fine verification punch's force over Boussinesq's at `depthRadii` (the indentation over the punch's radius),
/// as `bench_tissue --deep-punch` and `--deep-punch 0.10` print it: the linear block, the stiffening block at rest, and
/// the stiffening block stretched first until it stood at 1.856 times its modulus round the punch. A press into
/// tissue at `stiffening` times its modulus takes the two stiffening blocks' in proportion (the one at rest at 1, the
/// stretched one at 1.856 and beyond); held beyond the depths measured. The reference a press on the organ's coarse
/// mesh should meet where Boussinesq's small-strain solution no longer holds (docs/simulator.md, "Verification").
double fineBlockOverBoussinesq(double depthRadii, double stiffening, bool linear) {
    constexpr std::array<double, 7> kDepthRadii{0.10, 0.34, 0.69, 1.03, 1.38, 1.59, 1.79};
    constexpr std::array<double, 7> kLinear{1.077, 0.998, 0.888, 0.756, 0.676, 0.648, 0.644};
    constexpr std::array<double, 7> kAtRest{1.091, 1.113, 1.182, 1.112, 1.014, 1.006, 0.975};
    constexpr std::array<double, 7> kStretched{1.353, 1.208, 1.078, 0.937, 0.838, 0.822, 0.868};
    constexpr double kStretchedStiffening = 1.856;
    const auto at = [depthRadii, &kDepthRadii](const std::array<double, 7>& v) {
        if (!(depthRadii > kDepthRadii.front()))
            return v.front();
        for (std::size_t k = 1; k < v.size(); ++k)
            if (depthRadii <= kDepthRadii[k])
                return v[k - 1] +
                       (v[k] - v[k - 1]) * (depthRadii - kDepthRadii[k - 1]) / (kDepthRadii[k] - kDepthRadii[k - 1]);
        return v.back();
    };
    if (linear)
        return at(kLinear);
    const double w = std::clamp((stiffening - 1.0) / (kStretchedStiffening - 1.0), 0.0, 1.0);
    return (1.0 - w) * at(kAtRest) + w * at(kStretched);
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(
            stderr,
            "usage: bench_physics PACKAGE [--seconds S] [--iterations N] [--trace] [--rough SEED] "
            "[--canal [--introitus MM]] [--press [--wall PACKAGE2] [--linear] [--from-plan] [--faces N]] [--demo "
            "polypectomy|myomectomy [--steps FILE]]\n");
        return 2;
    }
    const std::string package = argv[1];
    double seconds = 60.0;
    hs::sim::WorldOptions options;
    bool trace = false;
    unsigned long long rough = 0; // the rough trial's seed; 0: the exploration
    bool canal = false;
    bool press = false;
    bool fromPlan = false; // --press: the depth counted from the face as planned, not as it stands
    std::string wallPackage;
    int faces = 0;         // --press --faces N: the wall's 3 mm press at its N most head-on faces
    std::string stepsFile; // --demo --steps FILE: each step from the first cut on, a CSV line
    for (int i = 2; i < argc; ++i) {
        if (std::strcmp(argv[i], "--trace") == 0)
            trace = true;
        else if (std::strcmp(argv[i], "--canal") == 0)
            canal = true;
        else if (std::strcmp(argv[i], "--press") == 0)
            press = true;
        else if (std::strcmp(argv[i], "--linear") == 0)
            options.linearTissue = true;
        else if (std::strcmp(argv[i], "--from-plan") == 0)
            fromPlan = true;
        else if (std::strcmp(argv[i], "--faces") == 0 && i + 1 < argc)
            faces = std::atoi(argv[++i]);
        else if (std::strcmp(argv[i], "--steps") == 0 && i + 1 < argc)
            stepsFile = argv[++i];
        else if (std::strcmp(argv[i], "--wall") == 0 && i + 1 < argc)
            wallPackage = argv[++i];
        else if (std::strcmp(argv[i], "--seconds") == 0 && i + 1 < argc)
            seconds = std::atof(argv[++i]);
        else if (std::strcmp(argv[i], "--rough") == 0 && i + 1 < argc)
            rough = std::strtoull(argv[++i], nullptr, 10);
        else if (std::strcmp(argv[i], "--iterations") == 0 && i + 1 < argc)
            options.solverIterations = std::atoi(argv[++i]);
        else if (std::strcmp(argv[i], "--introitus") == 0 && i + 1 < argc)
            options.introitusMm = std::atof(argv[++i]);
        else if (std::strcmp(argv[i], "--demo") == 0 && i + 1 < argc) {
            if (!hs::sim::fromString(argv[++i], options.exercise) || !hs::sim::isOperative(options.exercise)) {
                std::fprintf(stderr, "bench_physics: --demo takes polypectomy or myomectomy\n");
                return 2;
            }
        }
    }
    const auto loadStart = std::chrono::steady_clock::now();
    auto world = hs::sim::World::load(package, options);
    if (!world) {
        std::fprintf(stderr, "bench_physics: %s\n", world.error().detail.c_str());
        return 3;
    }
    const double loadS = std::chrono::duration<double>(std::chrono::steady_clock::now() - loadStart).count();
    hs::sim::World& w = **world;
    const hs::meshing::QualityReport q = hs::meshing::measureQuality(w.simulationMesh());
    // The canal: the clearance from its axis (external to internal os) to the contact surface and to the visual
    // surface, against the scope's radius.
    const auto canalClearance = [&w](const hs::SurfaceMesh& surface, hs::Vec3 direction = {}) {
        std::pair<double, double> narrowest{1e300, 0.0}; // mm, and where (mm above the external os)
        const hs::Vec3 from = w.landmarks().externalOsMm, to = w.landmarks().internalOsMm;
        const double length = hs::distance(from, to);
        if (hs::norm2(direction) == 0.0)
            direction = hs::normalized(to - from);
        for (double d = 0.0; d <= length; d += 0.5) {
            const hs::Vec3 p = from + direction * d;
            double nearest = 1e300;
            for (const hs::Triangle& t : surface.triangles)
                nearest =
                    std::min(nearest, hs::closestPointOnTriangle(p, surface.points[static_cast<std::size_t>(t[0])],
                                                                 surface.points[static_cast<std::size_t>(t[1])],
                                                                 surface.points[static_cast<std::size_t>(t[2])])
                                          .distance2);
            if (std::sqrt(nearest) < narrowest.first)
                narrowest = {std::sqrt(nearest), d};
        }
        return narrowest;
    };
    const auto canalSim = canalClearance(w.contactSurface());
    const auto canalVisual = canalClearance(w.scene().surface.mesh);
    // The clearest straight line through the canal from the external os (pitch and yaw about the pivot, 1 degree
    // steps within 20 degrees): the way a rigid scope can pass.
    double clearest = 0.0, clearestPitch = 0.0, clearestYaw = 0.0;
    {
        const hs::Vec3 axis = w.frame().axis, anterior = w.frame().anterior, left = w.frame().left;
        constexpr double kDeg = 3.14159265358979323846 / 180.0;
        for (double pitch = -20.0; pitch <= 20.0; pitch += 1.0)
            for (double yaw = -20.0; yaw <= 20.0; yaw += 1.0) {
                const hs::Vec3 d =
                    hs::normalized(axis + anterior * std::tan(pitch * kDeg) + left * std::tan(yaw * kDeg));
                const double c = canalClearance(w.contactSurface(), d).first;
                if (c > clearest) {
                    clearest = c;
                    clearestPitch = pitch;
                    clearestYaw = yaw;
                }
            }
    }

    if (press) {
        // Presses into the wall and each pathology, at four depths, each on a fresh world.
        struct Pressed {
            double forceN = 0.0, couplingMm = 0.0, indentationMm = 0.0;
            double stiffenedKpa = 0.0; ///< the tissue's modulus around the face as the press began, stiffened
            double faceOffMm = 0.0;    ///< the face then, off its planned place along its normal (+: towards the scope)
            double boussinesqNPerMm = 0.0;  ///< a punch of the tip's radius on a half-space of the stiffened modulus
            double shortOfCouplingMm = 0.0; ///< the depth less the coupling's stretch (the scope's whole load)
            double alignment = 0.0;         ///< the face's, head-on 1
            hs::Vec3 surfaceMm;             ///< the face's centre as planned
        };
        const auto run = [&](int pathology, double depthMm, std::string& label, double& modulus,
                             std::size_t rank = 0) -> Pressed {
            auto fresh = hs::sim::World::load(pathology < 0 && !wallPackage.empty() ? wallPackage : package, options);
            if (!fresh)
                return {};
            hs::sim::World& e = **fresh;
            auto plan = hs::sim::pressScript(e, pathology, depthMm, 2.0, rank);
            if (!plan) {
                label = plan.error().detail;
                return {};
            }
            label = plan->region;
            modulus = plan->youngsModulusKpa;
            const std::size_t tpb = e.ticksPerStep();
            std::vector<hs::sim::DeviceSample> batch(tpb);
            const auto pressFrom = static_cast<std::uint64_t>(plan->pressFromS * hs::sim::kDeviceRateHz);
            Pressed p;
            for (std::uint64_t s = 0; s * tpb < plan->script.tickCount(); ++s) {
                if (s * tpb <= pressFrom && pressFrom < (s + 1) * tpb) {
                    p.stiffenedKpa = e.tissueModulusNearKpa(plan->surfaceMm, hs::sim::kPressReachTipRadii * 0.5 *
                                                                                 options.scope.diameterMm);
                    p.faceOffMm = hs::sim::pressFaceOffsetMm(e, *plan);
                    if (!fromPlan) {
                        // The depth counted from the face where it stands now: the same script up to here.
                        auto again = hs::sim::pressScript(e, pathology, depthMm - p.faceOffMm, 2.0, rank);
                        if (!again || again->pressFromS != plan->pressFromS) {
                            label = again ? "the press planned again differs before the press" : again.error().detail;
                            return {};
                        }
                        plan = std::move(again);
                    }
                }
                for (std::size_t i = 0; i < tpb; ++i) {
                    batch[i] = plan->script.sampleAt(s * tpb + i);
                    batch[i].tick = s * tpb + i;
                }
                if (!e.step(batch.data(), tpb).ok())
                    return {};
                if (trace && (s + 1) * tpb > pressFrom && (s + 1) % 20 == 0) {
                    const hs::sim::WorldState& st = e.state();
                    std::printf(
                        "  %.2f s: tip %.3f N of %.3f N on the scope, %.2f kPa, distension %.2f mL, tip %.2f mm "
                        "beyond the face\n",
                        static_cast<double>((s + 1) * tpb) / hs::sim::kDeviceRateHz, st.contact.tipForceN,
                        st.contact.forceN, st.fluid.pressureKpa, st.fluid.distensionMl,
                        hs::dot(plan->surfaceMm - st.scope.tipMm, plan->normal) - 0.5 * options.scope.diameterMm);
                }
            }
            p.forceN = e.state().contact.tipForceN;
            if (trace)
                if (const auto held = e.hapticFrame())
                    for (const hs::sim::HapticContact& c : held->contacts)
                        if (c.forceN > 0.0)
                            std::printf("  %s contact %.3f N, its normal %.2f off the face's, gap %.3f mm\n",
                                        c.tip ? "tip" : "shaft", c.forceN, hs::dot(c.normal, plan->normal),
                                        c.gapM * 1e3);
            // Boussinesq's 2 a E / (1 - nu^2) with the modulus round the face as the press began.
            p.boussinesqNPerMm = 2.0 * 0.5 * options.scope.diameterMm * p.stiffenedKpa * 1e-3 /
                                 (1.0 - plan->poissonRatio * plan->poissonRatio);
            // The coupling's stretch along the shaft (its 1 N/mm at the tip, head-on): the rest of the depth is the
            // tissue's, the tip's sub-element dimple included (the scope is drawn out of its dimple, so its drawn tip
            // does not tell).
            const auto frame = e.hapticFrame();
            const double couplingNPerMm = frame ? frame->couplingStiffness[0] * 1e-3 : 1.0;
            p.couplingMm = p.forceN / couplingNPerMm;
            // The tissue's indentation: the physics' scope against the face as it stood when the press began
            // (pressIndentationMm), not the depth less the coupling's stretch, which answers the shaft's load too.
            p.indentationMm = hs::sim::pressIndentationMm(e, *plan, p.faceOffMm);
            p.shortOfCouplingMm = depthMm + (fromPlan ? p.faceOffMm : 0.0) - p.couplingMm;
            p.alignment = plan->alignment;
            p.surfaceMm = plan->surfaceMm;
            return p;
        };
        if (faces > 0) {
            std::printf("| wall face (rank) | region | head-on | face centre mm | stiffened E kPa | tip force N | "
                        "tip's indentation mm | secant stiffness N/mm | Boussinesq's N/mm | secant / Boussinesq's | "
                        "depth less the coupling's stretch mm | its stiffness / Boussinesq's |\n"
                        "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
            std::vector<double> ratios;
            for (int r = 0; r < faces; ++r) {
                std::string label;
                double e = 0.0;
                const Pressed p = run(-1, 3.0, label, e, static_cast<std::size_t>(r));
                if (e == 0.0) {
                    std::printf("| %d | %s |\n", r, label.c_str());
                    break;
                }
                const double k = p.indentationMm > 0.0 ? p.forceN / p.indentationMm : 0.0;
                const double ratio = p.boussinesqNPerMm > 0.0 ? k / p.boussinesqNPerMm : 0.0;
                ratios.push_back(ratio);
                const double viaCoupling = p.shortOfCouplingMm > 0.0 && p.boussinesqNPerMm > 0.0
                                               ? p.forceN / p.shortOfCouplingMm / p.boussinesqNPerMm
                                               : 0.0;
                std::printf(
                    "| %d | %s | %.3f | %.1f %.1f %.1f | %.1f | %.3f | %.2f | %.3f | %.3f | %.2f | %.2f | %.2f |\n", r,
                    label.c_str(), p.alignment, p.surfaceMm.x, p.surfaceMm.y, p.surfaceMm.z, p.stiffenedKpa, p.forceN,
                    p.indentationMm, k, p.boussinesqNPerMm, ratio, p.shortOfCouplingMm, viaCoupling);
            }
            if (!ratios.empty()) {
                double mean = 0.0;
                for (const double r : ratios)
                    mean += r / static_cast<double>(ratios.size());
                double sd = 0.0;
                for (const double r : ratios)
                    sd += (r - mean) * (r - mean) / static_cast<double>(ratios.size());
                std::printf(
                    "secant / Boussinesq's over %zu faces: mean %.3f, sd %.3f, median %.3f, min %.3f, max %.3f\n",
                    ratios.size(), mean, std::sqrt(sd), percentile(ratios, 0.5),
                    *std::min_element(ratios.begin(), ratios.end()), *std::max_element(ratios.begin(), ratios.end()));
            }
            return 0;
        }
        std::printf(
            "| target | E kPa | stiffened E kPa | device depth mm | tip force N | coupling's share mm | tissue "
            "indentation mm | secant stiffness N/mm | Boussinesq's N/mm (stiffened E) | secant / Boussinesq's | "
            "fine block / Boussinesq's | secant against the fine block | force / wall's | stiffness / wall's | E / "
            "wall's | stiffened E / wall's | force / stiffened E ratio | face off plan mm |\n"
            "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        const double radiusMm = 0.5 * options.scope.diameterMm;
        const auto row = [&](const char* label, double e, const Pressed& p, double depth) {
            const double k = p.indentationMm > 0.0 ? p.forceN / p.indentationMm : 0.0;
            const double ratio = p.boussinesqNPerMm > 0.0 ? k / p.boussinesqNPerMm : 0.0;
            const double fine = fineBlockOverBoussinesq(p.indentationMm / radiusMm, e > 0.0 ? p.stiffenedKpa / e : 1.0,
                                                        options.linearTissue);
            std::printf("| %s | %.0f | %.1f | %.1f | %.3f | %.2f | %.2f | %.3f | %.3f | %.2f | %.2f | %+.0f %% |",
                        label, e, p.stiffenedKpa, depth, p.forceN, p.couplingMm, p.indentationMm, k, p.boussinesqNPerMm,
                        ratio, fine, 100.0 * (ratio / fine - 1.0));
            return k;
        };
        const int pathologies = static_cast<int>(w.metrics().pathologies.size());
        for (const double depth : {0.5, 1.0, 2.0, 3.0}) {
            std::string wallLabel;
            double wallE = 0.0;
            const Pressed wall = run(-1, depth, wallLabel, wallE);
            const double wallK = row(("wall (" + wallLabel + ")").c_str(), wallE, wall, depth);
            std::printf(" - | - | - | - | - | %.2f |\n", wall.faceOffMm);
            for (int p = 0; p < pathologies; ++p) {
                std::string label;
                double e = 0.0;
                const Pressed hit = run(p, depth, label, e);
                if (e == 0.0) {
                    std::printf("| %s | - | - | %.1f | %s |\n",
                                w.metrics().pathologies[static_cast<std::size_t>(p)].id.c_str(), depth, label.c_str());
                    continue;
                }
                const double k = row(label.c_str(), e, hit, depth);
                const double forceRatio = wall.forceN > 0.0 ? hit.forceN / wall.forceN : 0.0;
                const double stiffenedRatio = wall.stiffenedKpa > 0.0 ? hit.stiffenedKpa / wall.stiffenedKpa : 0.0;
                std::printf(" %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", forceRatio, wallK > 0.0 ? k / wallK : 0.0,
                            wallE > 0.0 ? e / wallE : 0.0, stiffenedRatio,
                            stiffenedRatio > 0.0 ? forceRatio / stiffenedRatio : 0.0, hit.faceOffMm);
            }
        }
        return 0;
    }

    if (canal) {
        const std::size_t tpb = w.ticksPerStep();
        // The entries' lines through the external os, found with the scope pivoting there; with --introitus each
        // entry's world pivots at the introitus on its line, the portio free.
        hs::sim::WorldOptions atOs = options;
        atOs.introitusMm = 0.0;
        auto pivotAtOs = hs::sim::World::load(package, atOs);
        if (!pivotAtOs)
            return 3;
        hs::sim::World& w0 = **pivotAtOs;
        if (options.introitusMm > 0.0)
            std::printf("the scope pivots at the introitus, %.0f mm behind the external os on each entry's line; the "
                        "portio hangs on the cervix's supports\n",
                        options.introitusMm);
        {
            // The clearance along the axial entry's line, every mm from the external os: the contact surface, the held
            // faces, the visual surface.
            const hs::sim::Script entry = hs::sim::entryScript(w0, 0.0, 0.0);
            const hs::sim::ScopePose pose = hs::sim::scopePose(w0.frame(), atOs.scope, entry.keyframes.back().sample);
            const auto nearestOn = [](const hs::SurfaceMesh& m, const hs::Vec3& p) {
                double d2 = 1e300;
                for (const hs::Triangle& t : m.triangles)
                    d2 = std::min(d2, hs::closestPointOnTriangle(p, m.points[static_cast<std::size_t>(t[0])],
                                                                 m.points[static_cast<std::size_t>(t[1])],
                                                                 m.points[static_cast<std::size_t>(t[2])])
                                          .distance2);
                return std::sqrt(d2);
            };
            std::printf("| along the entry line mm | wall mm (contact surface) | wall mm (visual surface) |\n");
            for (double d = 0.0; d <= hs::distance(w0.frame().pivotMm, pose.tipMm); d += 2.0) {
                const hs::Vec3 p = w0.frame().pivotMm + pose.shaft * d;
                std::printf("| %.0f | %.2f | %.2f |\n", d, nearestOn(w0.contactSurface(), p),
                            nearestOn(w0.scene().surface.mesh, p));
            }
        }
        // The canal as an obstacle: entries along the canal's clearest line and off it, each on a fresh world.
        std::printf(
            "| entry | peak force N | held force N | scope tip off the device's mm | fundus moved mm | "
            "internal os moved mm | fundus off the axial entry's mm | internal os off the axial entry's mm | "
            "perforations | inverted tets max | energy max J |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
        // The axial entry's fundus and internal os, step by step: an entry off the axis deflects the uterus from them.
        std::vector<hs::Vec3> axialFundus, axialOs;
        for (const auto& [off, toward] : std::vector<std::pair<double, double>>{
                 {0.0, 0.0}, {15.0, 0.0}, {30.0, 0.0}, {30.0, 90.0}, {30.0, 180.0}, {30.0, 270.0}}) {
            auto fresh = hs::sim::World::load(package, options);
            if (!fresh)
                return 3;
            hs::sim::World& e = **fresh;
            const hs::Vec3 line = hs::sim::entryShaft(w0, off, toward);
            if (options.introitusMm > 0.0 && !e.setApproach(line).ok())
                return 3;
            const hs::sim::Script entry = hs::sim::entryScriptAlong(e, line);
            const hs::Vec3 fundus = e.landmarks().fundusMm;
            std::size_t nearest = 0;
            for (std::size_t i = 0; i < e.simulationPointsMm().size(); ++i)
                if (hs::distance(e.simulationPointsMm()[i], fundus) <
                    hs::distance(e.simulationPointsMm()[nearest], fundus))
                    nearest = i;
            const hs::Vec3 fundusBefore = e.simulationPointsMm()[nearest];
            std::size_t os = 0;
            for (std::size_t i = 0; i < e.simulationPointsMm().size(); ++i)
                if (hs::distance(e.simulationPointsMm()[i], e.landmarks().internalOsMm) <
                    hs::distance(e.simulationPointsMm()[os], e.landmarks().internalOsMm))
                    os = i;
            const hs::Vec3 osBefore = e.simulationPointsMm()[os];
            double osMoved = 0.0, fundusOff = 0.0, osOff = 0.0;
            const bool axial = off == 0.0;
            double peak = 0.0, held = 0.0, offTip = 0.0, moved = 0.0, energy = 0.0;
            std::size_t inverted = 0;
            const std::uint64_t ticks = entry.tickCount();
            std::vector<hs::sim::DeviceSample> batch(tpb);
            for (std::uint64_t s = 0; s * tpb < ticks; ++s) {
                for (std::size_t i = 0; i < tpb; ++i) {
                    batch[i] = entry.sampleAt(s * tpb + i);
                    batch[i].tick = s * tpb + i;
                }
                if (!e.step(batch.data(), tpb).ok())
                    return 4;
                const hs::sim::WorldState& st = e.state();
                peak = std::max(peak, st.contact.forceN);
                held = st.contact.forceN;
                offTip =
                    hs::distance(st.scope.tipMm, hs::sim::scopePose(e.frame(), options.scope, batch[tpb - 1]).tipMm);
                moved = std::max(moved, hs::distance(e.simulationPointsMm()[nearest], fundusBefore));
                osMoved = std::max(osMoved, hs::distance(e.simulationPointsMm()[os], osBefore));
                if (axial) {
                    axialFundus.push_back(e.simulationPointsMm()[nearest]);
                    axialOs.push_back(e.simulationPointsMm()[os]);
                } else if (s < axialFundus.size()) {
                    fundusOff = std::max(fundusOff, hs::distance(e.simulationPointsMm()[nearest], axialFundus[s]));
                    osOff = std::max(osOff, hs::distance(e.simulationPointsMm()[os], axialOs[s]));
                }
                const hs::sim::World::Health h = e.health();
                inverted = std::max(inverted, h.invertedTets);
                energy = std::max(energy, h.elasticEnergyJ);
                if (trace && s % 10 == 0)
                    std::printf("trace: %.2f s: device insertion %.1f mm, scope tip %.1f mm from the pivot, %.1f mm "
                                "off the device's; force %.2f N (tip %.2f N), %zu inverted, energy %.4f J\n",
                                st.timeS, batch[tpb - 1].insertionMm, hs::distance(st.scope.tipMm, e.frame().pivotMm),
                                offTip, st.contact.forceN, st.contact.tipForceN, h.invertedTets, h.elasticEnergyJ);
            }
            std::printf(
                "| %.0f deg off, towards %.0f deg | %.3f | %.3f | %.1f | %.2f | %.2f | %.2f | %.2f | %zu%s | %zu | "
                "%.4f |\n",
                off, toward, peak, held, offTip, moved, osMoved, fundusOff, osOff, e.metrics().perforations.size(),
                !e.metrics().perforations.empty() && e.metrics().perforations[0].falsePassage ? " (false passage)" : "",
                inverted, energy);
        }
        return 0;
    }

    // The exploration script, repeated to fill `seconds` of simulated time; or the exercise's demonstration, once.
    hs::sim::Script script;
    const bool operative = hs::sim::isOperative(options.exercise);
    if (operative) {
        auto planned = hs::sim::demonstrationScript(w);
        if (!planned) {
            std::fprintf(stderr, "bench_physics: %s\n", planned.error().detail.c_str());
            return 3;
        }
        script = std::move(*planned);
        seconds = static_cast<double>(script.tickCount()) / hs::sim::kDeviceRateHz;
    } else {
        script = rough > 0 ? hs::sim::roughScript(w, 60.0, rough) : hs::sim::explorationScript(w, 60.0);
    }
    const std::size_t per = w.ticksPerStep();
    if (trace)
        for (const hs::sim::KeyFrame& k : script.keyframes) {
            const hs::sim::ScopePose pose = hs::sim::scopePose(w.frame(), options.scope, k.sample);
            std::printf("trace: key %.2f s: tip %.1f %.1f %.1f mm, roll %.0f deg%s\n", k.timeS, pose.tipMm.x,
                        pose.tipMm.y, pose.tipMm.z, k.sample.rollDeg, k.sample.buttons ? ", mark" : "");
        }
    const auto steps = static_cast<std::uint64_t>(seconds / options.stepS);
    const std::uint64_t scriptTicks = script.tickCount();
    std::vector<hs::sim::DeviceSample> samples(per);
    std::vector<double> stepMs, cuttingStepMs;
    struct StepCost {
        double ms, forcesMs, solvesMs, contactMs, cutMs;
        bool cut, precomputed, forwarded, volume, touching;
    };
    std::vector<StepCost> cuttingSteps; ///< from the first cut on, with what each step did
    stepMs.reserve(steps);
    std::size_t maxInverted = 0, perforationsSeen = 0;
    double minRatio = 1e300, maxEnergy = 0.0, maxSpeed = 0.0;
    for (std::uint64_t s = 0; s < steps; ++s) {
        for (std::size_t i = 0; i < per; ++i) {
            const std::uint64_t tick = s * per + i;
            samples[i] = script.sampleAt(tick % scriptTicks);
            samples[i].tick = tick;
        }
        const hs::sim::World::StepTimings before = w.stepTimings();
        const std::uint64_t eventsBefore = w.metrics().resection.cutEvents;
        const bool precomputedBefore = w.surfacePrecomputed();
        const auto t0 = std::chrono::steady_clock::now();
        if (!w.step(samples.data(), per).ok()) {
            std::fprintf(stderr, "bench_physics: step %llu failed\n", static_cast<unsigned long long>(s));
            return 4;
        }
        stepMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        if (operative && w.metrics().resection.firstCutS >= 0.0) {
            cuttingStepMs.push_back(stepMs.back()); // from the first cut on
            const hs::sim::World::StepTimings& after = w.stepTimings();
            cuttingSteps.push_back({stepMs.back(), after.tissueForcesMs - before.tissueForcesMs,
                                    after.tissueSolvesMs - before.tissueSolvesMs,
                                    after.contactSolveMs - before.contactSolveMs, after.cutMs - before.cutMs,
                                    w.metrics().resection.cutEvents > eventsBefore, precomputedBefore,
                                    after.forwardContactSteps > before.forwardContactSteps,
                                    after.volumeRowSteps > before.volumeRowSteps, w.state().contact.touching});
        }
        if (std::getenv("HS_SLOW_TRACE") && !cuttingSteps.empty() && cuttingSteps.back().cutMs > 15.0)
            std::printf("slow: step %llu %.1f ms, loop %.1f ms, cut %d, precomputed before %d after %d\n",
                        static_cast<unsigned long long>(s), cuttingSteps.back().ms, cuttingSteps.back().cutMs,
                        cuttingSteps.back().cut ? 1 : 0, precomputedBefore ? 1 : 0, w.surfacePrecomputed() ? 1 : 0);
        if (trace && w.state().contact.forceN > 2.0 && w.state().step % 10 == 0) {
            const hs::sim::WorldState& st = w.state();
            const double along = hs::dot(st.scope.tipMm - w.landmarks().internalOsMm, w.frame().axis);
            std::printf("trace: %.2f s: contact %.2f N at %.1f %.1f %.1f mm, tip %.1f mm beyond the internal os, "
                        "device insertion %.1f mm, scope %.1f mm\n",
                        st.timeS, st.contact.forceN, st.contact.pointMm.x, st.contact.pointMm.y, st.contact.pointMm.z,
                        along, st.sample.insertionMm, hs::dot(st.scope.tipMm - w.frame().pivotMm, w.frame().axis));
        }
        if (trace && w.metrics().perforations.size() > perforationsSeen) {
            const hs::sim::Perforation& p = w.metrics().perforations.back();
            std::printf("trace: perforation at %.2f s (script %.2f s), %s, at %.1f %.1f %.1f mm\n", p.timeS,
                        std::fmod(p.timeS, 60.0), p.region.c_str(), p.locationMm.x, p.locationMm.y, p.locationMm.z);
            perforationsSeen = w.metrics().perforations.size();
        }
        if (s % 20 == 0 || s + 1 == steps) {
            const hs::sim::World::Health h = w.health();
            if (trace && (h.invertedTets > 0 || h.elasticEnergyJ > 0.5)) {
                const hs::sim::WorldState& st = w.state();
                std::printf(
                    "trace: %.2f s (script %.2f s): %zu inverted, min volume ratio %.3f, elastic energy %.3f J, "
                    "force %.2f N, tip %.1f %.1f %.1f mm\n",
                    st.timeS, std::fmod(st.timeS, 60.0), h.invertedTets, h.minVolumeRatio, h.elasticEnergyJ,
                    st.contact.forceN, st.scope.tipMm.x, st.scope.tipMm.y, st.scope.tipMm.z);
            }
            if (trace && h.invertedTets > 0) {
                // Where: the inverted tets' centres, their region and their distance from the tip.
                const hs::TetMesh& mesh = w.simulationMesh();
                const std::vector<hs::Vec3>& x = w.simulationPointsMm();
                for (std::size_t t = 0; t < mesh.tetCount(); ++t) {
                    const auto& tet = mesh.tets[t];
                    const hs::Vec3 a = x[static_cast<std::size_t>(tet[0])], b = x[static_cast<std::size_t>(tet[1])],
                                   c = x[static_cast<std::size_t>(tet[2])], d = x[static_cast<std::size_t>(tet[3])];
                    const hs::Vec3 ra = mesh.points[static_cast<std::size_t>(tet[0])];
                    const double now = hs::dot(b - a, hs::cross(c - a, d - a));
                    const double rest = hs::dot(mesh.points[static_cast<std::size_t>(tet[1])] - ra,
                                                hs::cross(mesh.points[static_cast<std::size_t>(tet[2])] - ra,
                                                          mesh.points[static_cast<std::size_t>(tet[3])] - ra));
                    if (now / rest <= 0.0)
                        std::printf("trace:   tet %zu region %d ratio %.2f at %.1f %.1f %.1f, %.1f mm from the tip\n",
                                    t, mesh.regionOf(t), now / rest, (a.x + b.x + c.x + d.x) / 4,
                                    (a.y + b.y + c.y + d.y) / 4, (a.z + b.z + c.z + d.z) / 4,
                                    hs::distance((a + b + c + d) / 4.0, w.state().scope.tipMm));
                }
            }
            maxInverted = std::max(maxInverted, h.invertedTets);
            minRatio = std::min(minRatio, h.minVolumeRatio);
            maxEnergy = std::max(maxEnergy, h.elasticEnergyJ);
            maxSpeed = std::max(maxSpeed, h.maxSpeedMmPerS);
        }
    }
    if (!stepsFile.empty()) {
        // Written whole to a temporary name, then renamed: never half a file.
        const std::string temporary = stepsFile + ".part";
        FILE* f = std::fopen(temporary.c_str(), "w");
        bool written = f != nullptr &&
                       std::fprintf(f, "ms,forces_ms,solves_ms,contact_ms,loop_ms,cut,precomputed,forward,volume_row,"
                                       "touching\n") > 0;
        for (const StepCost& c : cuttingSteps)
            written = written && std::fprintf(f, "%.3f,%.3f,%.3f,%.3f,%.3f,%d,%d,%d,%d,%d\n", c.ms, c.forcesMs,
                                              c.solvesMs, c.contactMs, c.cutMs, c.cut ? 1 : 0, c.precomputed ? 1 : 0,
                                              c.forwarded ? 1 : 0, c.volume ? 1 : 0, c.touching ? 1 : 0) > 0;
        written = f != nullptr && std::fclose(f) == 0 && written;
        if (!written || std::rename(temporary.c_str(), stepsFile.c_str()) != 0) {
            std::remove(temporary.c_str());
            std::fprintf(stderr, "bench_physics: cannot write %s\n", stepsFile.c_str());
            return 5;
        }
    }
    double total = 0.0;
    for (double v : stepMs)
        total += v;
    const double mean = stepMs.empty() ? 0.0 : total / static_cast<double>(stepMs.size());
    const hs::sim::TrialMetrics& m = w.metrics();
    std::printf("| measure | value |\n|---|---|\n");
    std::printf("| simulation mesh | %zu vertices, %zu tets, %zu contact faces |\n", q.vertexCount, q.tetCount,
                w.contactSurface().faceCount());
    std::printf("| quality | mean radius ratio %.3f, min %.3f; dihedral %.1f-%.1f deg; %zu slivers |\n",
                q.meanRadiusRatio, q.minRadiusRatio, q.minDihedralDeg, q.maxDihedralDeg, q.sliverCount);
    std::printf(
        "| canal | its axis %.2f mm from the simulation mesh's wall at the narrowest (%.1f mm above the external os), "
        "%.2f mm from the visual surface (%.1f mm); the scope's radius %.2f mm |\n",
        canalSim.first, canalSim.second, canalVisual.first, canalVisual.second, 0.5 * options.scope.diameterMm);
    std::printf(
        "| canal's clearest straight line | %.0f deg anterior, %.0f deg left of its axis: the wall %.2f mm from it at "
        "the narrowest |\n",
        clearestPitch, clearestYaw, clearest);
    {
        // The canal's angle to the cavity's axis (internal os to fundus), + anterior: the flexion the scope must turn.
        const hs::Vec3 cavity = hs::normalized(w.landmarks().fundusMm - w.landmarks().internalOsMm);
        const double angle = std::atan2(hs::norm(hs::cross(w.frame().axis, cavity)), hs::dot(w.frame().axis, cavity)) *
                             180.0 / 3.14159265358979323846;
        std::printf("| canal to cavity | %.1f deg %s |\n", angle,
                    hs::dot(cavity, w.frame().anterior) >= 0.0 ? "anterior (anteflexed)" : "posterior (retroflexed)");
    }
    std::printf("| load (read, build, calibrate) | %.2f s |\n", loadS);
    std::printf("| physics step (%d iterations, dt %.0f ms) | mean %.2f ms, p50 %.2f ms, p99 %.2f ms, max %.2f ms |\n",
                options.solverIterations, options.stepS * 1e3, mean, percentile(stepMs, 0.5), percentile(stepMs, 0.99),
                percentile(stepMs, 1.0));
    std::printf("| physics rate | %.0f Hz mean, %.0f Hz at p99 (real time needs %.0f Hz) |\n", 1e3 / mean,
                1e3 / percentile(stepMs, 0.99), 1.0 / options.stepS);
    std::printf("| trial | %.0f s simulated in %.1f s |\n", seconds, total / 1e3);
    const hs::sim::World::StepTimings& t = w.stepTimings();
    const double perStep = t.steps > 0 ? 1.0 / static_cast<double>(t.steps) : 0.0;
    std::printf(
        "| step breakdown (mean) | tissue forces %.2f ms, tissue solves %.2f ms, contact problem %.2f ms, "
        "contact search %.2f ms, visibility %.2f ms, the rest %.2f ms |\n",
        t.tissueForcesMs * perStep, t.tissueSolvesMs * perStep, t.contactSolveMs * perStep, t.contactSearchMs * perStep,
        t.visibilityMs * perStep,
        (t.totalMs - t.tissueForcesMs - t.tissueSolvesMs - t.contactSolveMs - t.contactSearchMs - t.visibilityMs) *
            perStep);
    std::printf("| stability | inverted tets max %zu, min volume ratio %.3f, elastic energy max %.4f J, point speed "
                "max %.0f mm/s; %.1f %% of steps checked by the line search (a tet held at the volume bound) |\n",
                maxInverted, minRatio, maxEnergy, maxSpeed,
                t.steps > 0 ? 100.0 * static_cast<double>(t.searchedSteps) / static_cast<double>(t.steps) : 0.0);
    std::printf("| trial metrics | surface %.1f %%, contacts %d, peak force %.2f N, perforations %zu |\n",
                m.cavitySurfaceVisualizedPercent, m.wallContacts, m.peakForceN, m.perforations.size());
    if (operative) {
        const hs::sim::ResectionMetrics& r = m.resection;
        double cutTotal = 0.0;
        for (double v : cuttingStepMs)
            cutTotal += v;
        const double cutMean = cuttingStepMs.empty() ? 0.0 : cutTotal / static_cast<double>(cuttingStepMs.size());
        std::printf("| demonstration | %s, %.1f s simulated |\n",
                    std::string(hs::sim::toString(options.exercise)).c_str(), m.timeS);
        for (const hs::sim::PathologyResection& p : r.pathologies)
            std::printf("| %s (%s) | %.3f of %.3f mL removed (%.1f %%) |\n", p.id.c_str(), p.kind.c_str(), p.removedMl,
                        p.volumeMl, p.removedPercent);
        std::printf("| healthy tissue | %.3f mL removed, deepest %.1f mm into the myometrium, %d perforating cuts |\n",
                    r.healthyRemovedMl, r.deepestMyometriumMm, r.perforatingCuts);
        std::printf("| cutting | %llu events, %llu tets, %llu pieces cut free; pedal down %.1f s, first to last cut "
                    "%.1f s, loop path %.0f mm |\n",
                    static_cast<unsigned long long>(r.cutEvents), static_cast<unsigned long long>(r.removedTets),
                    static_cast<unsigned long long>(r.chips), r.cuttingTimeS, r.resectionTimeS, r.loopPathMm);
        std::printf("| chips | %llu made, %llu carried out by the loop, %llu left in the cavity |\n",
                    static_cast<unsigned long long>(r.chipsMade), static_cast<unsigned long long>(r.chipsCarriedOut),
                    static_cast<unsigned long long>(r.chipsLeft));
        std::printf(
            "| physics step from the first cut on | mean %.2f ms (%.0f Hz), p99 %.2f ms (%.0f Hz), %zu steps |\n",
            cutMean, cutMean > 0.0 ? 1e3 / cutMean : 0.0, percentile(cuttingStepMs, 0.99),
            percentile(cuttingStepMs, 0.99) > 0.0 ? 1e3 / percentile(cuttingStepMs, 0.99) : 0.0, cuttingStepMs.size());
        // The slowest percent of the steps from the first cut on: what they did.
        if (!cuttingSteps.empty()) {
            const double p99 = percentile(cuttingStepMs, 0.99);
            double n = 0, ms = 0, forces = 0, solves = 0, contact = 0, cutMs = 0, cuts = 0, stale = 0, touching = 0;
            double staleAll = 0, touchingAll = 0, forwarded = 0, forwardedAll = 0, volume = 0, volumeAll = 0;
            for (const StepCost& c : cuttingSteps) {
                staleAll += c.precomputed ? 0 : 1;
                forwardedAll += c.forwarded ? 1 : 0;
                volumeAll += c.volume ? 1 : 0;
                touchingAll += c.touching ? 1 : 0;
                if (c.ms < p99)
                    continue;
                n += 1;
                ms += c.ms;
                forces += c.forcesMs;
                solves += c.solvesMs;
                contact += c.contactMs;
                cutMs += c.cutMs;
                cuts += c.cut ? 1 : 0;
                stale += c.precomputed ? 0 : 1;
                forwarded += c.forwarded ? 1 : 0;
                volume += c.volume ? 1 : 0;
                touching += c.touching ? 1 : 0;
            }
            const double all = static_cast<double>(cuttingSteps.size());
            std::printf("| the slowest 1 %% of those steps | %.0f steps of %.2f ms mean: tissue forces %.2f ms, solves "
                        "%.2f ms, contact problem %.2f ms, the loop (cuts, rebuilds) %.2f ms; %.0f %% cut, %.0f %% "
                        "with the surface's compliance not precomputed for the factor in use (%.0f %% of all), %.0f %% "
                        "with the contacts by forward solves (%.0f %% of all), %.0f %% with a tet at the volume bound "
                        "(%.0f %% of all), %.0f %% touching (%.0f %% of all) |\n",
                        n, ms / n, forces / n, solves / n, contact / n, cutMs / n, 100.0 * cuts / n, 100.0 * stale / n,
                        100.0 * staleAll / all, 100.0 * forwarded / n, 100.0 * forwardedAll / all, 100.0 * volume / n,
                        100.0 * volumeAll / all, 100.0 * touching / n, 100.0 * touchingAll / all);
        }
        if (!cuttingSteps.empty()) {
            // The steps over the bar's budget (150 Hz: 6.67 ms) and what they did.
            constexpr double kBudgetMs = 1e3 / 150.0;
            double over = 0, volume = 0, refreshing = 0, forwarded = 0, cuts = 0;
            for (const StepCost& c : cuttingSteps) {
                if (c.ms <= kBudgetMs)
                    continue;
                over += 1;
                volume += c.volume ? 1 : 0;
                refreshing += c.precomputed ? 0 : 1;
                forwarded += c.forwarded ? 1 : 0;
                cuts += c.cut ? 1 : 0;
            }
            const double d = std::max(1.0, over);
            std::printf("| steps over 6.67 ms (150 Hz) from the first cut on | %.0f (%.2f %%): %.0f %% with a tet in "
                        "the volume bound's band, %.0f %% with the surface's compliance being refreshed, %.0f %% with "
                        "forward solves, %.0f %% with a cut |\n",
                        over, 100.0 * over / static_cast<double>(cuttingSteps.size()), 100.0 * volume / d,
                        100.0 * refreshing / d, 100.0 * forwarded / d, 100.0 * cuts / d);
        }
        std::printf("| fluid | %s, deficit %.0f mL in %.1f min (%.0f mL/min), intravasation %.0f mL, highest pressure "
                    "%.1f kPa |\n",
                    std::string(hs::sim::toString(options.fluid.medium)).c_str(), m.deficitMl, m.timeS / 60.0,
                    m.timeS > 0.0 ? 60.0 * m.deficitMl / m.timeS : 0.0, m.intravasationMl, m.maxPressureKpa);
        const hs::sim::FluidState& f = w.state().fluid;
        std::printf("| bleeding | blood loss %.2f mL, at the end %.2f mL/min with %.3f mL/(s kPa) of arterioles open; "
                    "cut intravasation %.1f mL/min; coagulating %.1f s |\n",
                    m.bloodLossMl, 60.0 * f.bleedingMlPerS,
                    f.pressureKpa < options.fluid.meanArterialPressureKpa
                        ? f.bleedingMlPerS / (options.fluid.meanArterialPressureKpa - f.pressureKpa)
                        : 0.0,
                    60.0 * f.cutIntravasationMlPerS, r.coagulationTimeS);
    }
    return 0;
}
