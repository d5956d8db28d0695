// Cutting with the resectoscope's loop on a scene's tissue (hs::sim::Resection on the world's solver): the cost of a
// cut event's topology update, the physics step while cutting, the factor rebuilt when the pedal is released, and the
// tissue's validity after every event. A table, not a test (test_sim_core asserts the validity on small meshes).
//
//   bench_cutting PACKAGE [--events N] [--speed MM_PER_S] [--paced 0|1] [--rebuild-steps K] [--demo 0|1]
// The loop strokes through each pathology in turn (the sheath's axis from the internal os to the pathology, strip by
// strip from its free side towards its base, retracted along the axis with the pedal on), then into the cavity's
// walls at random faces, until N cut events (steps that removed a tet; default 1000) have run. The cavity is held
// at 60 mmHg throughout. The steps are paced as the simulator's physics thread paces them (one every 5 ms of wall
// clock; --paced 0: back to back). The steps go on with the factor the tissue had before the cuts (the default), or
// with --rebuild-steps K the factor is rebuilt on a thread of its own after each stroke and taken in K steps later.
// --demo 1: the pathologies' strokes only, the pedal held only where the wire would take nothing but that pathology (a
// demonstration's precision on the simulation mesh). PACKAGE: a scene package with a simulation mesh (hysteroscene-cli
// generate resources/cases/default.json -o DIR).

#include "hs/core/Rng.h"
#include "hs/mechanics/UterusModel.h"
#include "hs/scene/ScenePackage.h"
#include "hs/sim/Resection.h"
#include "hs/sim/TissueSetup.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace hs;
using Clock = std::chrono::steady_clock;

constexpr double kPressureKpa = 8.0; // 60 mmHg

double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

double quantile(std::vector<double> v, double q) {
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    const auto k = static_cast<std::size_t>(
        std::min<double>(static_cast<double>(v.size() - 1), std::floor(q * static_cast<double>(v.size()))));
    return v[k];
}

double mean(const std::vector<double>& v) {
    double s = 0.0;
    for (const double x : v)
        s += x;
    return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

struct Stroke {
    Vec3 fromMm, toMm; ///< the loop's centre
    Vec3 axis, down;
};

struct Run {
    mechanics::UterusModel model;
    sim::Resection resection;
    sim::LoopElectrode loop;
    double speedMmPerS = 15.0;
    std::size_t targetEvents = 1000;
    std::vector<double> eventMs, idleCutMs, stepMs, stepRebuildingMs;
    std::size_t manifoldTets = 0, sweptTets = 0, steps = 0;
    std::vector<Vec3> forces, pointsMm;

    void points() {
        const auto& x = model.fem.positionsM();
        pointsMm.resize(x.size());
        for (std::size_t i = 0; i < x.size(); ++i)
            pointsMm[i] = x[i] * 1e3;
    }
    /// With K > 0 the factor is rebuilt on its own thread from a stroke's end and taken in K steps later (a fixed
    /// step, so a replay takes it at the same step); 0: never.
    std::size_t rebuildSteps = 0;
    std::size_t finishAt = 0;
    std::vector<double> startMs, finishMs;
    bool paced = true;
    Clock::time_point paceStart = Clock::now();
    std::size_t paceSteps = 0, lateSteps = 0;
    void physicsStep() {
        if (model.fem.refactorRunning() && steps >= finishAt) {
            const auto t = Clock::now();
            model.fem.finishRefactor();
            finishMs.push_back(msSince(t));
        }
        points();
        model.pressureForces(pointsMm, kPressureKpa, forces);
        std::vector<mechanics::FemConstraint> none;
        // Paced as the simulator's physics thread is: a step every stepS of wall clock (none skipped when late).
        if (paced) {
            const auto due = paceStart + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
                                             static_cast<double>(paceSteps) * model.fem.settings().stepS));
            if (Clock::now() < due)
                std::this_thread::sleep_until(due);
            else
                ++lateSteps;
            ++paceSteps;
        }
        const bool rebuilding = model.fem.refactorRunning();
        const auto t = Clock::now();
        model.fem.step(forces, none);
        (rebuilding ? stepRebuildingMs : stepMs).push_back(msSince(t));
        ++steps;
    }
    /// --demo: the pedal is held only where the wire would take nothing but pathology `only` (a demonstration that
    /// keeps off healthy tissue); -1: always.
    std::int32_t only = -1;
    /// --refactor-at F: the factor rebuilt on the physics thread after an event that leaves it staler than F (1:
    /// never).
    double refactorAt = 1.0;
    std::vector<double> syncRebuildMs;
    std::size_t pedalSteps = 0;
    /// One stroke with the pedal on; false once the events asked for have run.
    bool stroke(const Stroke& s) {
        const double length = norm(s.toMm - s.fromMm);
        const double perStep = speedMmPerS * model.fem.settings().stepS;
        const auto count = static_cast<std::size_t>(std::ceil(length / perStep));
        std::vector<Vec3> before = sim::loopWire(loop, s.fromMm, s.axis, s.down);
        bool cut = false;
        for (std::size_t k = 1; k <= count; ++k) {
            const Vec3 centre = s.fromMm + (s.toMm - s.fromMm) * (static_cast<double>(k) / static_cast<double>(count));
            std::vector<Vec3> after = sim::loopWire(loop, centre, s.axis, s.down);
            bool pedal = true;
            if (only >= 0)
                for (const std::size_t t : resection.sweptTets(model.fem, loop.sampleMm, before, after))
                    pedal = pedal && resection.tetPathology()[t] == only;
            if (!pedal) {
                before = std::move(after);
                physicsStep();
                continue;
            }
            ++pedalSteps;
            const sim::CutEvent event = resection.cut(model, loop.sampleMm, before, after);
            if (refactorAt < 1.0 && model.fem.factorStaleness() > refactorAt) {
                const auto t = Clock::now();
                model.fem.refactor();
                syncRebuildMs.push_back(msSince(t));
            }
            if (event.removed.empty()) {
                idleCutMs.push_back(event.topologyMs);
            } else {
                eventMs.push_back(event.topologyMs);
                sweptTets += event.sweptTets;
                cut = true;
            }
            before = std::move(after);
            physicsStep();
            if (eventMs.size() >= targetEvents)
                break;
        }
        // The pedal released: the factor is rebuilt from the live tets.
        if (cut && rebuildSteps > 0 && model.fem.factorStale() && !model.fem.refactorRunning()) {
            const auto t = Clock::now();
            model.fem.startRefactor();
            startMs.push_back(msSince(t));
            finishAt = steps + rebuildSteps;
        }
        return eventMs.size() < targetEvents;
    }
};

Vec3 anyPerpendicular(const Vec3& a) {
    const Vec3 trial = std::abs(a.x) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
    return normalized(cross(a, trial));
}

/// Strokes through pathology `k`: strips from its free side towards its base.
std::vector<Stroke> pathologyStrokes(Run& run, std::size_t k) {
    const auto& tetPathology = run.resection.tetPathology();
    const auto& tets = run.model.fem.tets();
    run.points();
    std::vector<char> inside(run.pointsMm.size(), 0), outside(run.pointsMm.size(), 0);
    for (std::size_t t = 0; t < tets.size(); ++t)
        for (const std::int32_t p : tets[t])
            (tetPathology[t] == static_cast<std::int32_t>(k) ? inside : outside)[static_cast<std::size_t>(p)] = 1;
    Vec3 centre, base;
    double count = 0.0, baseCount = 0.0;
    for (std::size_t i = 0; i < inside.size(); ++i)
        if (inside[i]) {
            centre += run.pointsMm[i];
            count += 1.0;
            if (outside[i]) {
                base += run.pointsMm[i];
                baseCount += 1.0;
            }
        }
    if (count == 0.0)
        return {};
    centre = centre / count;
    double radius = 0.0;
    for (std::size_t i = 0; i < inside.size(); ++i)
        if (inside[i])
            radius = std::max(radius, norm(run.pointsMm[i] - centre));
    const Vec3 axis = normalized(centre - run.model.internalOsMm);
    Vec3 down = baseCount > 0.0 ? base / baseCount - centre : Vec3{};
    down = down - axis * dot(down, axis);
    down = norm(down) > 1e-6 ? normalized(down) : anyPerpendicular(axis);
    const Vec3 side = normalized(cross(axis, down));
    const double r = 0.5 * run.loop.widthMm;
    std::vector<Stroke> strokes;
    for (double d = -radius - r; d <= radius; d += 0.5 * r)
        for (double s = -radius; s <= radius + 1e-9; s += 0.8 * run.loop.widthMm) {
            const Vec3 c = centre + down * d + side * s;
            strokes.push_back({c + axis * (radius + 2.0), c - axis * (radius + 2.0), axis, down});
        }
    return strokes;
}

/// A stroke into the cavity's wall at a random cavity face: the loop drawn back along the line from the internal os,
/// reaching `depthMm` beyond the face.
Stroke wallStroke(Run& run, Rng& rng, double depthMm) {
    const auto& model = run.model;
    run.points();
    for (;;) {
        const auto f = static_cast<std::size_t>(rng.below(model.boundary.size()));
        if (!model.faceCavity[f] || model.fem.tetRemoved(static_cast<std::size_t>(model.faceTet[f])))
            continue;
        const Triangle& t = model.boundary[f];
        const Vec3 c = (run.pointsMm[static_cast<std::size_t>(t[0])] + run.pointsMm[static_cast<std::size_t>(t[1])] +
                        run.pointsMm[static_cast<std::size_t>(t[2])]) /
                       3.0;
        if (norm(c - model.internalOsMm) < 10.0)
            continue; // the canal: not a place a loop cuts
        const Vec3 axis = normalized(c - model.internalOsMm);
        const Vec3 down = anyPerpendicular(axis);
        return {c + axis * depthMm, c - axis * 3.0, axis, down};
    }
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_cutting PACKAGE [--events N] [--speed MM_PER_S] [--paced 0|1] "
                             "[--rebuild-steps K] [--demo 0|1]\n");
        return 2;
    }
    Run run;
    bool demo = false;
    for (int i = 2; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--events")
            run.targetEvents = static_cast<std::size_t>(std::max(1L, std::strtol(argv[i + 1], nullptr, 10)));
        else if (a == "--rebuild-steps")
            run.rebuildSteps = static_cast<std::size_t>(std::max(0L, std::strtol(argv[i + 1], nullptr, 10)));
        else if (a == "--refactor-at")
            run.refactorAt = std::strtod(argv[i + 1], nullptr);
        else if (a == "--demo")
            demo = std::string(argv[i + 1]) != "0";
        else if (a == "--paced")
            run.paced = std::string(argv[i + 1]) != "0";
        else if (a == "--speed")
            run.speedMmPerS = std::max(1.0, std::strtod(argv[i + 1], nullptr));
        else {
            std::fprintf(stderr, "bench_cutting: unknown option %s\n", a.c_str());
            return 2;
        }
    }
    auto scene = scene::readScenePackage(argv[1]);
    if (!scene) {
        std::fprintf(stderr, "bench_cutting: %s\n", scene.error().detail.c_str());
        return 1;
    }
    const auto built = Clock::now();
    if (auto s = mechanics::buildUterusModel(*scene, sim::tissueSolverSettings(sim::WorldOptions{}), run.model); !s) {
        std::fprintf(stderr, "bench_cutting: %s\n", s.error().detail.c_str());
        return 1;
    }
    run.model.fem.precomputeCompliance(sim::touchablePoints(run.model));
    const double buildMs = msSince(built);
    auto resection = sim::Resection::make(*scene, scene->simulation->tets, run.model.boundary, run.model.faceCavity);
    if (!resection) {
        std::fprintf(stderr, "bench_cutting: %s\n", resection.error().detail.c_str());
        return 1;
    }
    run.resection = std::move(*resection);
    const std::size_t singularBefore = run.model.fem.singularPoints().size();
    // The cavity opened at 60 mmHg first (1 s), paced as the cutting: the physics step's baseline in this run.
    run.paceStart = Clock::now();
    for (int k = 0; k < 200; ++k)
        run.physicsStep();
    const std::vector<double> baselineMs = run.stepMs;
    run.stepMs.clear();
    run.paceStart = Clock::now();
    run.paceSteps = 0;
    run.lateSteps = 0;
    std::printf("bench_cutting %s: %zu points, %zu tets (model and factor %.0f ms), loop %.1f mm at %.0f mm/s, "
                "cavity at %.0f mmHg\n",
                argv[1], run.model.fem.pointCount(), run.model.fem.tetCount(), buildMs, run.loop.widthMm,
                run.speedMmPerS, kPressureKpa * 7.50062);
    bool more = true;
    const auto& pathologies = scene->clinical.pathologies;
    // Polyps first (the smaller job), then myomas; each pathology's own strokes' events and healthy tissue.
    std::vector<std::size_t> order;
    for (const auto kind : {clinical::PathologyKind::Polyp, clinical::PathologyKind::Myoma})
        for (std::size_t k = 0; k < pathologies.size(); ++k)
            if (pathologies[k].kind == kind)
                order.push_back(k);
    std::vector<std::string> strokeRows;
    for (const std::size_t k : order) {
        if (!more)
            break;
        const double healthyBefore = run.resection.totals().healthyMl;
        const std::size_t eventsBefore = run.eventMs.size();
        const std::vector<Stroke> strokes = pathologyStrokes(run, k);
        const std::size_t stepsBefore = run.steps, pedalBefore = run.pedalSteps;
        run.only = demo ? static_cast<std::int32_t>(k) : -1;
        for (const Stroke& s : strokes)
            if (!(more = run.stroke(s)))
                break;
        const double stepS = run.model.fem.settings().stepS;
        char row[256];
        std::snprintf(row, sizeof row,
                      "%-44s %zu strokes in %.0f s (the pedal on %.0f s), %zu events, %.1f %% of it removed, %.3f mL "
                      "healthy tissue\n",
                      (pathologies[k].id + "'s strokes").c_str(), strokes.size(),
                      static_cast<double>(run.steps - stepsBefore) * stepS,
                      static_cast<double>(run.pedalSteps - pedalBefore) * stepS, run.eventMs.size() - eventsBefore,
                      100.0 * run.resection.totals().pathologyRemovedMl[k] /
                          std::max(1e-12, run.resection.totals().pathologyMl[k]),
                      run.resection.totals().healthyMl - healthyBefore);
        strokeRows.emplace_back(row);
    }
    Rng rng(7);
    for (int guard = 0; more && !demo && guard < 100000; ++guard)
        more = run.stroke(wallStroke(run, rng, rng.uniform(1.0, 4.0)));

    const sim::ResectionTotals& totals = run.resection.totals();
    std::size_t inverted = 0;
    const double minRatio = run.model.fem.minVolumeRatio(inverted);
    const std::size_t singularAfter = run.model.fem.singularPoints().size();
    std::printf("\n%-44s %s\n", "quantity", "value");
    std::printf("%-44s %zu (%zu tets swept, %zu removed, %zu in %zu chips)\n", "cut events (steps that removed tets)",
                totals.events, run.sweptTets, totals.removedTets, std::size_t{0}, totals.chips);
    std::printf("%-44s %.3f / %.3f / %.3f ms\n", "topology update median / p99 / max", quantile(run.eventMs, 0.5),
                quantile(run.eventMs, 0.99), quantile(run.eventMs, 1.0));
    std::printf("%-44s %.3f / %.3f ms over %zu steps\n", "loop sweep with nothing cut, median / p99",
                quantile(run.idleCutMs, 0.5), quantile(run.idleCutMs, 0.99), run.idleCutMs.size());
    std::printf("%-44s %.2f ms mean (%.0f Hz), p99 %.2f ms (%.0f Hz), %zu steps\n", "physics step before any cut",
                mean(baselineMs), 1e3 / mean(baselineMs), quantile(baselineMs, 0.99), 1e3 / quantile(baselineMs, 0.99),
                baselineMs.size());
    std::printf("%-44s %.2f ms mean (%.0f Hz), p99 %.2f ms (%.0f Hz), %zu steps\n",
                "physics step while cutting (no rebuild running)", mean(run.stepMs), 1e3 / mean(run.stepMs),
                quantile(run.stepMs, 0.99), 1e3 / quantile(run.stepMs, 0.99), run.stepMs.size());
    if (!run.stepRebuildingMs.empty())
        std::printf("%-44s %.2f ms mean (%.0f Hz), p99 %.2f ms (%.0f Hz), %zu steps\n",
                    "physics step while a rebuild runs", mean(run.stepRebuildingMs), 1e3 / mean(run.stepRebuildingMs),
                    quantile(run.stepRebuildingMs, 0.99), 1e3 / quantile(run.stepRebuildingMs, 0.99),
                    run.stepRebuildingMs.size());
    std::printf("%-44s %zu of %zu (%s)\n", "steps begun late (the last overran its 5 ms)", run.lateSteps, run.paceSteps,
                run.paced ? "paced" : "back to back, not paced");
    std::printf("%-44s %zu (%.0f ms median, %.0f max), staleness now %.2f\n", "factor rebuilt on the physics thread",
                run.syncRebuildMs.size(), quantile(run.syncRebuildMs, 0.5), quantile(run.syncRebuildMs, 1.0),
                run.model.fem.factorStaleness());
    std::printf("%-44s %zu, started at a stroke's end, taken %zu steps later\n", "factor rebuilt on its thread",
                run.startMs.size(), run.rebuildSteps);
    std::printf("%-44s %.2f / %.2f ms\n", "  its start (the copy) median / max", quantile(run.startMs, 0.5),
                quantile(run.startMs, 1.0));
    std::printf("%-44s %.2f / %.2f ms\n", "  its taking in (waiting included) median / max",
                quantile(run.finishMs, 0.5), quantile(run.finishMs, 1.0));
    {
        // How far the stale factor's steps are from the tissue's equilibrium: 2 s held with the factor the cuts left,
        // then 2 s with the factor rebuilt; the second's further motion is what the first had not reached.
        run.paced = false;
        if (run.model.fem.refactorRunning())
            run.model.fem.finishRefactor();
        const bool stale = run.model.fem.factorStale();
        for (int k = 0; k < 400; ++k)
            run.physicsStep();
        run.points();
        const std::vector<Vec3> settled = run.pointsMm;
        const auto t = Clock::now();
        run.model.fem.refactor();
        const double rebuildMs = msSince(t);
        for (int k = 0; k < 400; ++k)
            run.physicsStep();
        run.points();
        double further = 0.0;
        for (std::size_t i = 0; i < settled.size(); ++i)
            further = std::max(further, norm(run.pointsMm[i] - settled[i]));
        std::printf("%-44s %.0f ms\n", "the same rebuild on the physics thread, once", rebuildMs);
        std::printf("%-44s %.4f mm (the factor %s)\n", "settled 2 s, further motion 2 s after rebuild", further,
                    stale ? "stale" : "fresh");
    }
    std::printf("%-44s %zu -> %zu (%zu live tets)\n", "singular points before -> after", singularBefore, singularAfter,
                run.model.fem.liveTetCount());
    std::printf("%-44s %zu\n", "live pieces held by nothing", run.model.fem.looseLivePieces());
    std::printf("%-44s %zu inverted, smallest volume ratio %.3f\n", "tets", inverted, minRatio);
    std::printf("%-44s %zu recoveries, largest speed %.1f mm/s, energy %.3g J\n", "solver", run.model.fem.recoveries(),
                run.model.fem.maxSpeedMPerS() * 1e3, run.model.fem.elasticEnergyJ());
    for (std::size_t k = 0; k < pathologies.size(); ++k)
        std::printf("%-44s %.3f of %.3f mL (%.1f %%)\n", (pathologies[k].id + " removed").c_str(),
                    totals.pathologyRemovedMl[k], totals.pathologyMl[k],
                    totals.pathologyMl[k] > 0.0 ? 100.0 * totals.pathologyRemovedMl[k] / totals.pathologyMl[k] : 0.0);
    for (const std::string& row : strokeRows)
        std::printf("%s", row.c_str());
    std::printf("%-44s %.3f mL, deepest %.1f mm into the myometrium, %d perforating events\n", "healthy tissue removed",
                totals.healthyMl, totals.deepestMyometriumMm, totals.perforations);
    return 0;
}
