// The simulator's world on a generated package: loading, distension against the hydrometra curve, a scripted
// exploration, a perforation, replay bit for bit, and the refusals.

#include "hs/sim/World.h"
#include "SimPackage.h"
#include "hs/scene/Hydrometra.h"
#include "hs/scene/Sha256.h"
#include "hs/sim/Resection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace hs::sim {
namespace {

std::unique_ptr<World> loadWorld(const WorldOptions& options = {}) {
    auto world = World::load(test::SimPackage::folder(), options);
    EXPECT_TRUE(world) << (world ? "" : world.error().detail);
    return world ? std::move(*world) : nullptr;
}

/// Runs `script` through `world` for `seconds` (all of it when 0); the samples it fed are appended to `samples`.
/// The worst of the tissue's health seen while a script runs (checked every 50 ms).
struct Worst {
    std::size_t invertedTets = 0;
    double minVolumeRatio = 1e300;
    double peakForceN = 0.0; ///< on the scope, every step
    double elasticEnergyJ = 0.0;
};

void run(World& world, const Script& script, double seconds, std::vector<DeviceSample>* samples = nullptr,
         Worst* worst = nullptr) {
    const std::size_t per = world.ticksPerStep();
    const std::uint64_t ticks =
        seconds > 0.0 ? static_cast<std::uint64_t>(seconds * kDeviceRateHz) : script.tickCount();
    std::vector<DeviceSample> step(per);
    std::uint64_t tick = world.state().step * per;
    const std::uint64_t end = tick + ticks;
    while (tick + per <= end) {
        for (std::size_t i = 0; i < per; ++i) {
            step[i] = script.sampleAt(tick + i);
            step[i].tick = tick + i;
        }
        ASSERT_TRUE(world.step(step.data(), per).ok());
        if (samples)
            samples->insert(samples->end(), step.begin(), step.end());
        tick += per;
        if (std::getenv("HS_WORLD_TRACE") && world.state().step % 20 == 0)
            std::printf("trace %.2f s: force %.2f N at %.1f %.1f %.1f, tip depth %.1f mm, device insertion %.1f, "
                        "pressure %.2f kPa, tip %.1f %.1f %.1f dir %.2f %.2f %.2f\n",
                        world.state().timeS, world.state().contact.forceN, world.state().contact.pointMm.x,
                        world.state().contact.pointMm.y, world.state().contact.pointMm.z,
                        dot(world.state().scope.tipMm - world.frame().pivotMm, world.frame().axis),
                        world.state().sample.insertionMm, world.state().fluid.pressureKpa, world.state().scope.tipMm.x,
                        world.state().scope.tipMm.y, world.state().scope.tipMm.z, world.state().scope.shaft.x,
                        world.state().scope.shaft.y, world.state().scope.shaft.z);
        if (worst)
            worst->peakForceN = std::max(worst->peakForceN, world.state().contact.forceN);
        if (worst && world.state().step % 10 == 0) {
            const World::Health h = world.health();
            worst->invertedTets = std::max(worst->invertedTets, h.invertedTets);
            worst->minVolumeRatio = std::min(worst->minVolumeRatio, h.minVolumeRatio);
            worst->elasticEnergyJ = std::max(worst->elasticEnergyJ, h.elasticEnergyJ);
            ASSERT_TRUE(std::isfinite(h.elasticEnergyJ) && std::isfinite(h.maxSpeedMmPerS) &&
                        std::isfinite(world.state().contact.forceN))
                << "at " << world.state().timeS << " s: energy " << h.elasticEnergyJ << " J, speed " << h.maxSpeedMmPerS
                << " mm/s, " << h.invertedTets << " inverted, ratio " << h.minVolumeRatio << ", tip "
                << world.state().scope.tipMm.x << " " << world.state().scope.tipMm.y << " "
                << world.state().scope.tipMm.z << ", force " << world.state().contact.forceN;
        }
    }
}

/// Steps `world` with `sample` held for `seconds` (ticks renumbered), appending what it fed to `samples`.
void stepHeld(World& world, DeviceSample sample, double seconds, std::vector<DeviceSample>& samples) {
    const std::size_t per = world.ticksPerStep();
    std::vector<DeviceSample> step(per, sample);
    for (int k = 0; k < static_cast<int>(std::lround(seconds / world.options().stepS)); ++k) {
        for (std::size_t i = 0; i < per; ++i)
            step[i].tick = world.state().step * per + i;
        ASSERT_TRUE(world.step(step.data(), per).ok());
        samples.insert(samples.end(), step.begin(), step.end());
    }
}

Script holding(const DeviceSample& sample, double seconds) {
    Script s;
    KeyFrame a;
    a.sample = sample;
    KeyFrame b = a;
    b.timeS = seconds;
    s.keyframes = {a, b};
    return s;
}

TEST(World, LoadsThePackagesSimulationMeshHeldAtTheCervix) {
    auto world = loadWorld();
    ASSERT_TRUE(world);
    const TetMesh& sim = world->simulationMesh();
    EXPECT_GT(sim.tetCount(), 4000u);
    EXPECT_LT(sim.tetCount(), 20000u);
    EXPECT_GT(world->contactSurface().faceCount(), 1000u);
    EXPECT_EQ(world->ticksPerStep(), 5u);
    // Both ostia and the wall zones are exploration targets; the default case's two pathologies are to be found.
    std::vector<std::string> names;
    for (const auto& t : world->metrics().targets)
        names.push_back(t.name);
    EXPECT_EQ(names, (std::vector<std::string>{"ostium-left", "ostium-right", "fundus", "anterior", "posterior", "left",
                                               "right"}));
    EXPECT_EQ(world->metrics().pathologies.size(), 2u);
    // At rest, nothing moves without a load.
    DeviceSample outside;
    outside.insertionMm = -5.0;
    run(*world, holding(outside, 0.5), 0.5);
    EXPECT_LT(world->health().maxSpeedMmPerS, 1.0);
    EXPECT_EQ(world->health().invertedTets, 0u);
    EXPECT_EQ(world->state().fluid.pressureKpa, 0.0);
    EXPECT_EQ(world->state().fluid.redOut, 1.0); // no distension: the walls close on the lens
}

TEST(World, TheCavityOpensWithPressureAlongThePackagesCurve) {
    // The pump at 100 mmHg; the valves hold about 40, then 60, then 100 mmHg (inflow gin (pump - p) = outflow gout p).
    // The pressure comes from the cavity's volume in the deformed tissue each step, and loads its faces with no gain:
    // once the fluid has settled the cavity is opened as the package's curve says (generate's static solve of the same
    // tissue model, within 10 % with the curve's linear interpolation) and as a static solve at that pressure (1 %).
    WorldOptions options;
    options.fluid.pumpPressureKpa = 100.0 * 0.133322;
    options.fluid.meanArterialPressureKpa = 20.0;
    auto world = loadWorld(options);
    ASSERT_TRUE(world);
    const auto& h = world->scene().hydrometra;
    const std::pair<double, double> valves[] = {{0.52, 1.0}, {1.0, 0.85}, {1.0, 0.0}};
    for (const auto& [inflow, outflow] : valves) {
        DeviceSample s;
        s.insertionMm = -5.0;
        s.inflow = inflow;
        s.outflow = outflow;
        run(*world, holding(s, 4.0), 4.0);
        const double p = world->state().fluid.pressureKpa;
        const double opened = world->state().cavityOpeningMl;
        const auto still = world->staticCavityOpeningMl(p);
        ASSERT_TRUE(still) << still.error().detail;
        const double curve = scene::modelOpeningMl(h, p);
        std::printf("%.0f mmHg: opened %.2f mL, the package's curve %.2f mL, a static solve %.2f mL, Bajka's fit "
                    "(linear in pressure) %.2f mL\n",
                    p / 0.133322, opened, curve, *still, h.cavityVolumeMl / h.pressureKpa * p);
        ASSERT_FALSE(h.modelCurve.empty());
        EXPECT_NEAR(opened, curve, 0.1 * curve) << "pressure " << p << " kPa";
        EXPECT_NEAR(opened, *still, 0.01 * *still) << "pressure " << p << " kPa";
        EXPECT_LT(world->state().fluid.redOut, 1.0);
        EXPECT_EQ(world->health().invertedTets, 0u);
    }
    // With the outflow closed the cavity fills towards the pump's pressure (still filling after 4 s: the tissue opens
    // 8 mL at 100 mmHg through the inflow's resistance), never beyond it.
    EXPECT_GT(world->state().fluid.pressureKpa, 0.9 * options.fluid.pumpPressureKpa);
    EXPECT_LT(world->state().fluid.pressureKpa, options.fluid.pumpPressureKpa);
    // Nothing left the cavity but through the outflow and a little intravasation: the deficit is what it holds.
    EXPECT_GT(world->metrics().deficitMl, 0.0);
}

TEST(World, NamesALoneOstiumByThePatientsSide) {
    // A polyp put on the right cornu's ostium (by a point, on purpose) covers it, so the scene has one, in the left
    // cornu (the patient's left: -x). The fundus landmark is then that cornu and the cavity's axis points at it: the
    // side comes from the canal's frame. (Named by the cavity's axis, it was "ostium-right".)
    auto loaded = World::load(test::SimPackage::polypOnTheRightOstiumFolder(), WorldOptions{});
    ASSERT_TRUE(loaded) << loaded.error().detail;
    const World& world = **loaded;
    EXPECT_EQ(world.landmarks().ostiaFound, 1);
    std::vector<std::string> ostia;
    for (const auto& t : world.metrics().targets)
        if (t.name.rfind("ostium", 0) == 0)
            ostia.push_back(t.name);
    EXPECT_EQ(ostia, std::vector<std::string>{"ostium-left"});
    EXPECT_LT(world.frame().left.x, 0.0); // the scene's frame is RAS-like
}

TEST(World, AScriptedExplorationSeesBothOstiaWithoutPerforation) {
    auto world = loadWorld();
    ASSERT_TRUE(world);
    const Script script = explorationScript(*world, 16.0);
    Worst worst;
    run(*world, script, 0.0, nullptr, &worst);
    const TrialReport report = world->report();
    const TrialMetrics& m = report.metrics;
    for (const auto& t : m.targets)
        std::printf("target %-12s seen %d  %.1f %%  at %.2f s\n", t.name.c_str(), t.seen ? 1 : 0, t.visualizedPercent,
                    t.firstSeenS);
    for (const auto& p : m.pathologies)
        std::printf("pathology %-8s seen %d found %d\n", p.id.c_str(), p.seen ? 1 : 0, p.found ? 1 : 0);
    std::printf("surface %.1f %%, path %.1f mm, contacts %d, peak %.2f N, pressure max %.2f kPa, deficit %.1f mL, "
                "horizon %.1f deg, false marks %d\n",
                m.cavitySurfaceVisualizedPercent, m.pathLengthMm, m.wallContacts, m.peakForceN, m.maxPressureKpa,
                m.deficitMl, m.horizonErrorMeanDeg, m.falseMarks);
    EXPECT_TRUE(m.targets[0].seen);
    EXPECT_TRUE(m.targets[1].seen);
    EXPECT_TRUE(m.perforations.empty());
    EXPECT_GT(m.cavitySurfaceVisualizedPercent, 30.0);
    EXPECT_GT(m.pathLengthMm, 50.0);
    for (const auto& p : m.pathologies)
        EXPECT_TRUE(p.seen) << p.id;
    // Never an inverted tet on the way (the script keeps to the middle of the opened cavity, off the myoma that
    // bulges into it), and no tet squeezed to near nothing.
    std::printf("smallest volume ratio on the way %.3f\n", worst.minVolumeRatio);
    EXPECT_EQ(worst.invertedTets, 0u);
    EXPECT_GT(worst.minVolumeRatio, 0.2);
    const World::Health health = world->health();
    EXPECT_EQ(health.invertedTets, 0u);
    EXPECT_LT(health.elasticEnergyJ, 1.0);
}

/// After a press: the tissue's force on the tip (N); checks that the device gets the solver's reaction: the haptics
/// loop's re-solve at the device's pose against the step's contact forces, as generalized forces on the scope (N along
/// the shaft, N m about the pivot), within 10 %.
double pressed(World& world) {
    const auto frame = world.hapticFrame();
    std::vector<double> forces;
    std::array<double, 3> device{}, solver{};
    EXPECT_TRUE(solveHapticContacts(*frame, scopeDofsOf(world.state().sample), forces, device));
    for (const HapticContact& c : frame->contacts)
        for (std::size_t d = 0; d < 3; ++d)
            solver[d] += c.scopeGradient[d] * c.forceN;
    const double lever = std::max(1e-3, world.state().sample.insertionMm * 1e-3); // m: torques as forces at the tip
    double solverNorm = 0.0, differenceNorm = 0.0;
    for (std::size_t d = 0; d < 3; ++d) {
        const double scale = d == 0 ? 1.0 : 1.0 / lever;
        solverNorm += solver[d] * solver[d] * scale * scale;
        differenceNorm += (device[d] - solver[d]) * (device[d] - solver[d]) * scale * scale;
    }
    std::printf("  the solver's %.3f N at the tip, the device's off it by %.4f N\n", std::sqrt(solverNorm),
                std::sqrt(differenceNorm));
    EXPECT_GT(solverNorm, 0.0);
    EXPECT_LE(std::sqrt(differenceNorm), 0.1 * std::sqrt(solverNorm));
    return world.state().contact.tipForceN;
}

/// Runs a press; returns pressed().
double press(World& world, const PressPlan& plan) {
    run(world, plan.script, 0.0);
    return pressed(world);
}

/// The press of `plan`, its depth counted from the face where it stands as the tip leaves its stand-off (the plan
/// made again there for `pathology`: pressFaceOffsetMm); `stiffenedKpa` gets the tissue's modulus round the face
/// then, stiffened as the distended state has it (World::tissueModulusNearKpa), and `indentationMm` the tip's own
/// indentation at the end (pressIndentationMm: the physics' scope beyond that face). Returns the tip's force (N).
double pressFromTheLiveFace(World& world, const PressPlan& plan, int pathology, double depthMm, double& stiffenedKpa,
                            double& indentationMm) {
    run(world, plan.script, plan.pressFromS);
    stiffenedKpa =
        world.tissueModulusNearKpa(plan.surfaceMm, kPressReachTipRadii * 0.5 * world.options().scope.diameterMm);
    const double offsetMm = pressFaceOffsetMm(world, plan);
    const auto again = pressScript(world, pathology, depthMm - offsetMm, 2.0);
    EXPECT_TRUE(again);
    if (!again)
        return 0.0;
    EXPECT_EQ(again->pressFromS, plan.pressFromS); // the same script up to here
    std::printf("  the face %.2f mm off its planned place as the press began\n", offsetMm);
    const double doneS = static_cast<double>(world.state().step * world.ticksPerStep()) / kDeviceRateHz;
    run(world, again->script, static_cast<double>(again->script.tickCount()) / kDeviceRateHz - doneS);
    indentationMm = pressIndentationMm(world, *again, offsetMm);
    return pressed(world);
}

TEST(World, APressIntoTheWallGivesTheDeviceTheSolversReaction) {
    // A 3 mm press of the device into the cavity's wall, head-on: the device gets the solver's reaction (within 10 %,
    // in press()), and the wall holds. (On the default case the fundus press tilts the corpus onto the shaft, and the
    // shaft carries most of it: docs/simulator.md, "What is not modelled yet".)
    auto world = loadWorld();
    ASSERT_TRUE(world);
    const auto plan = pressScript(*world, -1, 3.0, 2.0);
    ASSERT_TRUE(plan) << plan.error().detail;
    const double tip = press(*world, *plan);
    std::printf("wall (%s, %.0f kPa, head-on %.2f): %.3f N on the scope, %.3f N of it on the tip\n",
                plan->region.c_str(), plan->youngsModulusKpa, plan->alignment, world->state().contact.forceN, tip);
    EXPECT_GT(plan->alignment, 0.9);
    EXPECT_GT(world->state().contact.forceN, 0.05);
    EXPECT_TRUE(world->metrics().perforations.empty());
    // The tip's flat end presses as a punch finer than the wall's faces: it sinks into them by the sub-element give
    // times its force (docs/simulator.md, "Collision and contact"), each tip row's gap at the step's end
    // -give sum_j (n_i . n_j) lambda_j; and the scope is drawn out of that dimple, in front of the face it presses.
    const auto frame = world->hapticFrame();
    ASSERT_TRUE(frame);
    const double give = frame->tipComplianceMPerN;
    EXPECT_GT(give, 0.0);
    DeviceSample physics = world->state().sample;
    physics.insertionMm = frame->scopeDofs[0] * 1e3;
    physics.pitchDeg = frame->scopeDofs[1] * 180.0 / 3.14159265358979323846;
    physics.yawDeg = frame->scopeDofs[2] * 180.0 / 3.14159265358979323846;
    const Vec3 physicsTipMm = scopePose(world->frame(), world->options().scope, physics).tipMm;
    const HapticContact* strongest = nullptr;
    for (const HapticContact& c : frame->contacts) {
        if (!c.tip || c.forceN <= 0.0)
            continue;
        double dimpleM = 0.0;
        for (const HapticContact& o : frame->contacts)
            if (o.tip)
                dimpleM += give * dot(c.normal, o.normal) * o.forceN;
        EXPECT_NEAR(c.gapM, -dimpleM, 0.05 * dimpleM + 1e-6);
        if (!strongest || c.forceN > strongest->forceN)
            strongest = &c;
    }
    ASSERT_TRUE(strongest);
    const double drawnGapMm = strongest->gapM * 1e3 + dot(world->state().scope.tipMm - physicsTipMm, strongest->normal);
    std::printf("the tip %.3f mm into its dimple (give %.2f mm/N); drawn, its end %.3f mm from touching the face\n",
                -strongest->gapM * 1e3, give * 1e3, drawnGapMm);
    EXPECT_LT(strongest->gapM * 1e3, -0.5);
    EXPECT_GT(drawnGapMm, -0.25); // within the contacts' depenetration step of the face, not in the dimple
    // The next faces met most nearly head-on (to press one tissue at several places): each less head-on than the one
    // before and a tip's diameter from every face before it; beyond the last such face, none.
    std::vector<Vec3> taken{plan->surfaceMm};
    double alignment = plan->alignment;
    std::size_t rank = 1;
    for (;; ++rank) {
        const auto next = pressScript(*world, -1, 3.0, 2.0, rank);
        if (!next)
            break;
        EXPECT_LE(next->alignment, alignment);
        for (const Vec3& p : taken)
            EXPECT_GE(distance(p, next->surfaceMm), world->options().scope.diameterMm);
        alignment = next->alignment;
        taken.push_back(next->surfaceMm);
    }
    std::printf("%zu wall faces can be pressed head-on a tip's diameter apart\n", rank);
    EXPECT_GE(rank, 2u);
    // A press asks for a pathology the scene has, a depth and a hold in range.
    EXPECT_FALSE(pressScript(*world, 99));
    EXPECT_FALSE(pressScript(*world, -1, std::nan("")));
    EXPECT_FALSE(pressScript(*world, -1, 3.0, -1.0));
}

TEST(World, APressIntoAFundalMyomaAndIntoTheWallStandsAsTheirStiffness) {
    // The same 3 mm press, counted from the face where it stands, into a fundal FIGO 2 myoma (65 kPa, met head-on) and
    // into the wall (the endometrium, 26 kPa): the tip meets the myoma's own tissue (the simulation mesh does not line
    // it), and the device gets the solver's reaction (pressed()). The distension stretches the wall round the cavity,
    // and the tissue's exponential stiffening with it, far more than the myoma: each press stands as Boussinesq's
    // punch of the tip's radius on a half-space of the modulus round its face as the press begins, within the
    // textbook punch's 15 %, and the forces stand as those moduli within 25 % (docs/simulator.md, "What is not
    // modelled yet": the press's force as the tissues' moduli).
    auto wallWorld = loadWorld();
    auto fundal = World::load(test::SimPackage::fundalMyomaFolder(), WorldOptions{});
    ASSERT_TRUE(wallWorld);
    ASSERT_TRUE(fundal) << fundal.error().detail;
    World& myomaWorld = **fundal;
    int myoma = -1;
    for (std::size_t p = 0; p < myomaWorld.metrics().pathologies.size(); ++p)
        if (myomaWorld.metrics().pathologies[p].id.rfind("myoma", 0) == 0)
            myoma = static_cast<int>(p);
    ASSERT_GE(myoma, 0);
    const auto wallPlan = pressScript(*wallWorld, -1, 3.0, 2.0);
    const auto myomaPlan = pressScript(myomaWorld, myoma, 3.0, 2.0);
    ASSERT_TRUE(wallPlan) << wallPlan.error().detail;
    ASSERT_TRUE(myomaPlan) << myomaPlan.error().detail;
    double wallKpa = 0.0, myomaKpa = 0.0, wallMm = 0.0, myomaMm = 0.0;
    const double wall = pressFromTheLiveFace(*wallWorld, *wallPlan, -1, 3.0, wallKpa, wallMm);
    const double myomaForce = pressFromTheLiveFace(myomaWorld, *myomaPlan, myoma, 3.0, myomaKpa, myomaMm);
    // The punch's secant stiffness: the tip's force over the tip's own indentation (the physics' scope, held by its
    // contacts, beyond the face as it stood; not the 3 mm less the coupling's stretch, for the coupling answers the
    // scope's whole load and the shaft bears on the canal), and Boussinesq's 2 a E / (1 - nu^2) for the tip's radius a.
    ASSERT_GT(wallMm, 0.5);
    ASSERT_GT(myomaMm, 0.5);
    const double wallK = wall / wallMm, myomaK = myomaForce / myomaMm;
    const auto boussinesq = [](const World& world, const PressPlan& plan, double modulusKpa) {
        return world.options().scope.diameterMm * modulusKpa * 1e-3 / (1.0 - plan.poissonRatio * plan.poissonRatio);
    };
    const double wallPunch = boussinesq(*wallWorld, *wallPlan, wallKpa);
    const double myomaPunch = boussinesq(myomaWorld, *myomaPlan, myomaKpa);
    std::printf("wall  (%s, %.0f kPa, head-on %.2f): %.3f N on the tip, %.2f mm in; %.1f kPa round the face as "
                "pressed, %.3f N/mm against Boussinesq's %.3f\n",
                wallPlan->region.c_str(), wallPlan->youngsModulusKpa, wallPlan->alignment, wall, wallMm, wallKpa, wallK,
                wallPunch);
    std::printf("myoma (%s, %.0f kPa, head-on %.2f): %.3f N on the tip, %.2f mm in; %.1f kPa round the face as "
                "pressed, %.3f N/mm against Boussinesq's %.3f\n",
                myomaPlan->region.c_str(), myomaPlan->youngsModulusKpa, myomaPlan->alignment, myomaForce, myomaMm,
                myomaKpa, myomaK, myomaPunch);
    const double stiffened = myomaKpa / wallKpa;
    std::printf("force ratio %.2f; the moduli round the faces as pressed %.2f (at rest, the faces' own: %.2f)\n",
                myomaForce / wall, stiffened, myomaPlan->youngsModulusKpa / wallPlan->youngsModulusKpa);
    EXPECT_GT(myomaPlan->alignment, 0.9);
    EXPECT_EQ(myomaPlan->region, "myoma-1");
    EXPECT_NEAR(wallK, wallPunch, 0.15 * wallPunch);
    EXPECT_NEAR(myomaK, myomaPunch, 0.15 * myomaPunch);
    EXPECT_NEAR(myomaForce / wall, stiffened, 0.25 * stiffened);
}

TEST(World, ARoughTrialLeavesNoInvertedTetAndBoundedEnergy) {
    // Random presses into the walls and the myoma at a hand's speeds, 20 s (bench_physics --rough runs 10 minutes):
    // nothing becomes NaN, the elastic energy stays bounded, and no tet is inverted at any step.
    auto world = loadWorld();
    ASSERT_TRUE(world);
    const Script script = roughScript(*world, 20.0, 7);
    EXPECT_GT(script.keyframes.size(), 20u);
    Worst worst;
    run(*world, script, 0.0, nullptr, &worst);
    const double energy = worst.elasticEnergyJ;
    const TrialMetrics& m = world->metrics();
    std::printf("rough: %d wall contacts, peak %.2f N, %zu perforations; at worst %zu tets inverted (ratio %.3f), "
                "energy %.4f J\n",
                m.wallContacts, m.peakForceN, m.perforations.size(), worst.invertedTets, worst.minVolumeRatio, energy);
    EXPECT_GT(m.wallContacts, 5);
    EXPECT_LT(energy, 1.0);
    EXPECT_EQ(world->health().invertedTets, 0u);
    // Not even for a moment (sampled every 50 ms): no tet keeps less than the volume bound (a fifth) by more than a
    // step's linearization.
    EXPECT_EQ(worst.invertedTets, 0u);
    EXPECT_GT(worst.minVolumeRatio, 0.1);
    // The same seed, the same script; another seed, another.
    EXPECT_EQ(scriptJson(roughScript(*world, 20.0, 7)), scriptJson(script));
    EXPECT_NE(scriptJson(roughScript(*world, 20.0, 8)), scriptJson(script));
}

TEST(World, TheCanalLetsAnEntryAlongItsLinePassAndStopsOneThirtyDegreesOff) {
    // The shaft collides along the whole canal, whose lining and stroma are free inside the held portio's outer
    // surface (docs/simulator.md, "The canal"). The scripted entry along the canal's clearest straight line reaches
    // 5 mm beyond the internal os with a light touch (the simulation mesh's canal is a little narrower than the scope
    // there, and the sheath dilates it), no perforation and no inverted tet; the same entry turned 30 degrees meets
    // the cervix with at least three times that force and, pushed on, goes through its wall: a false passage.
    auto world = loadWorld();
    ASSERT_TRUE(world);
    const Script script = entryScript(*world, 0.0, 0.0);
    ASSERT_GE(script.keyframes.size(), 3u);
    Worst worst;
    run(*world, script, 0.0, nullptr, &worst);
    const double peak = worst.peakForceN;
    const WorldState& st = world->state();
    const double beyond = dot(st.scope.tipMm - world->landmarks().internalOsMm, world->frame().axis);
    EXPECT_GT(beyond, 3.0);
    EXPECT_LT(peak, 1.0);
    EXPECT_TRUE(world->metrics().perforations.empty());
    EXPECT_EQ(worst.invertedTets, 0u);
    // The same entry turned 30 degrees (towards the anterior wall): the device aims elsewhere, and meets the cervix.
    const Script off = entryScript(*world, 30.0, 0.0);
    const ScopePose a = scopePose(world->frame(), world->options().scope, script.keyframes.back().sample);
    const ScopePose b = scopePose(world->frame(), world->options().scope, off.keyframes.back().sample);
    EXPECT_NEAR(std::acos(std::clamp(dot(a.shaft, b.shaft), -1.0, 1.0)) * 180.0 / 3.14159265358979323846, 30.0, 0.5);
    auto offWorld = loadWorld();
    ASSERT_TRUE(offWorld);
    Worst offWorst;
    run(*offWorld, off, 0.0, nullptr, &offWorst);
    const auto& perforations = offWorld->metrics().perforations;
    std::printf("entry along the line: tip %.1f mm beyond the internal os, peak %.3f N; 30 degrees off: peak %.3f N, "
                "%zu perforations%s\n",
                beyond, peak, offWorst.peakForceN, perforations.size(),
                !perforations.empty() && perforations[0].falsePassage ? " (a false passage)" : "");
    EXPECT_GE(offWorst.peakForceN, 3.0 * peak);
    ASSERT_FALSE(perforations.empty());
    EXPECT_TRUE(perforations[0].falsePassage);
    EXPECT_EQ(offWorst.invertedTets, 0u);
}

TEST(World, PushingThroughTheFundusIsAPerforation) {
    auto world = loadWorld();
    ASSERT_TRUE(world);
    const auto& lm = world->landmarks();
    Script script;
    const auto key = [&](double t, const Vec3& tip) {
        KeyFrame k;
        k.timeS = t;
        k.sample = sampleAiming(world->frame(), tip);
        k.sample.inflow = 1.0;
        k.sample.outflow = 0.3;
        script.keyframes.push_back(k);
    };
    DeviceSample outside;
    key(0.0, lm.externalOsMm - world->frame().axis * 5.0);
    key(1.0, lm.externalOsMm - world->frame().axis * 5.0);
    key(3.0, lm.internalOsMm + world->frame().axis * 2.0);
    const Vec3 towards = normalized(lm.fundusMm - lm.internalOsMm);
    key(5.0, lm.fundusMm);
    key(9.0, lm.fundusMm + towards * 60.0);
    std::vector<DeviceSample> samples;
    run(*world, script, 0.0, &samples);
    const auto& perforations = world->metrics().perforations;
    ASSERT_EQ(perforations.size(), 1u);
    EXPECT_GT(perforations[0].depthMm, 5.0);
    EXPECT_LT(distance(perforations[0].locationMm, lm.fundusMm), 40.0); // the corpus yields before the wall gives way
    EXPECT_FALSE(perforations[0].region.empty());
    EXPECT_TRUE(world->state().contact.perforated);
    EXPECT_FALSE(world->report().explorationComplete);

    // Replayed, the trial gives the same metrics, bit for bit.
    Trial trial;
    trial.header = world->trialHeader();
    trial.samples = samples;
    auto replayed = replayTrial(test::SimPackage::folder(), trial);
    ASSERT_TRUE(replayed) << replayed.error().detail;
    EXPECT_EQ(reportJson(*replayed), reportJson(world->report()));
    const TrialMetrics& a = replayed->metrics;
    const TrialMetrics& b = world->metrics();
    EXPECT_EQ(std::memcmp(&a.pathLengthMm, &b.pathLengthMm, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&a.peakForceN, &b.peakForceN, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&a.perforations[0].depthMm, &b.perforations[0].depthMm, sizeof(double)), 0);
    EXPECT_EQ(a.wallContacts, b.wallContacts);

    // A trial of another physics engine, or replayed with other settings, is refused by the field.
    Trial other = trial;
    other.header.physics.engine = "xpbd-fixed-corotated/0";
    auto engine = replayTrial(test::SimPackage::folder(), other);
    ASSERT_FALSE(engine);
    EXPECT_NE(engine.error().detail.find("header.physics.engine"), std::string::npos) << engine.error().detail;
    WorldOptions options = world->options();
    options.solverIterations += 1;
    const Status settings = checkReplay(trial.header, options);
    ASSERT_FALSE(settings);
    EXPECT_NE(settings.error().detail.find("header.physics.solverIterations"), std::string::npos);
    EXPECT_TRUE(checkReplay(trial.header, world->options()));

    // A trial of another scene is refused.
    trial.header.sceneSha256 = std::string(64, '0');
    auto refused = replayTrial(test::SimPackage::folder(), trial);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().detail.find("not on"), std::string::npos) << refused.error().detail;
}

TEST(World, TheDemonstrationsStrokesEachMeetThePolypAndMostOfThemCut) {
    // The polypectomy's plan makes only strokes whose wire, as planned, meets the polyp, and puts the pedal down where
    // the wire passes through nothing but the polyp, its base and the fluid: a wire point in the fluid beyond the polyp
    // lies in no tissue (not in the boundary tet nearest it). Most strokes then cut, and the plan ends within the
    // demonstration's 3 minutes. (Before, the fluid counted as the nearest wall, and on the 20-case sweep's sessile
    // polyps the pedal went down in 0-31 % of the strokes: docs/simulator.md, "The demonstration".)
    WorldOptions options;
    options.exercise = Exercise::Polypectomy;
    auto world = loadWorld(options);
    ASSERT_TRUE(world);
    const auto script = demonstrationScript(*world);
    ASSERT_TRUE(script) << script.error().detail;
    std::size_t strokes = 0, cutting = 0;
    bool pedal = false, coagulating = false;
    const auto& keys = script->keyframes;
    for (std::size_t k = 1; k <= keys.size(); ++k) {
        const bool pushedOut =
            k == keys.size() || keys[k].sample.workingElementMm > keys[k - 1].sample.workingElementMm;
        if (pushedOut) { // the stroke before ends
            if (!coagulating && pedal)
                ++cutting;
            if (k == keys.size())
                break;
            coagulating = (keys[k].sample.buttons & kButtonCoagulate) != 0;
            strokes += coagulating ? 0 : 1;
            pedal = false;
        }
        pedal = pedal || (keys[k].sample.buttons & kButtonCut) != 0;
    }
    std::printf("demonstration: %zu strokes, %zu of them with the pedal down; %.1f s\n", strokes, cutting,
                keys.back().timeS);
    EXPECT_GT(strokes, 0u);
    EXPECT_GE(2 * cutting, strokes);
    EXPECT_LE(keys.back().timeS, 180.0);
}

TEST(World, TheLoopCutsThePolypAndTheContactSurfaceFollowsTheCut) {
    // The polypectomy's demonstration until 2 s after its first cut (the entry and the first strips): the loop takes
    // polyp and little else, the contact surface gains the faces the cuts bared, the tissue stays sound, and the trial
    // replays bit for bit.
    WorldOptions options;
    options.exercise = Exercise::Polypectomy;
    auto world = loadWorld(options);
    ASSERT_TRUE(world);
    int polyp = -1;
    const auto& pathologies = world->scene().clinical.pathologies;
    for (std::size_t k = 0; k < pathologies.size() && polyp < 0; ++k)
        if (pathologies[k].kind == clinical::PathologyKind::Polyp)
            polyp = static_cast<int>(k);
    ASSERT_GE(polyp, 0);
    auto script = resectionScript(*world, polyp);
    ASSERT_TRUE(script) << script.error().detail;
    auto demo = demonstrationScript(*world);
    ASSERT_TRUE(demo);
    EXPECT_EQ(demo->keyframes.size(), script->keyframes.size());
    const std::size_t facesBefore = world->contactSurface().triangles.size();
    std::vector<DeviceSample> samples;
    Worst worst;
    // Second by second until 2 s after the first cut (at most 25 s).
    for (int second = 0; second < 25; ++second) {
        run(*world, *script, 1.0, &samples, &worst);
        const double first = world->metrics().resection.firstCutS;
        if (first >= 0.0 && world->state().timeS > first + 2.0)
            break;
    }
    const ResectionMetrics& cut = world->metrics().resection;
    ASSERT_EQ(cut.pathologies.size(), pathologies.size());
    const PathologyResection& p = cut.pathologies[static_cast<std::size_t>(polyp)];
    std::printf("after %.1f s: %.3f of %.3f mL of %s removed (%.1f %%), %.3f mL healthy, %llu cut events, %zu faces "
                "-> %zu\n",
                world->state().timeS, p.removedMl, p.volumeMl, p.id.c_str(), p.removedPercent, cut.healthyRemovedMl,
                static_cast<unsigned long long>(cut.cutEvents), facesBefore, world->contactSurface().triangles.size());
    EXPECT_GT(cut.cutEvents, 0u);
    EXPECT_GT(p.removedMl, 0.0);
    EXPECT_LT(cut.healthyRemovedMl, p.removedMl); // the plan keeps the pedal off where the wire meets other tissue
    EXPECT_GT(cut.cuttingTimeS, 0.0);
    EXPECT_GT(cut.loopPathMm, 0.0);
    EXPECT_GT(world->contactSurface().triangles.size(), facesBefore);
    EXPECT_EQ(worst.invertedTets, 0u);
    EXPECT_EQ(world->health().invertedTets, 0u);

    // The cut bleeds below the mean arterial pressure, in proportion to how far below (the open arterioles'
    // conductance, bleeding / (MAP - p), stays while the pressure changes), and its venules take fluid.
    const double map = world->options().fluid.meanArterialPressureKpa;
    const auto arterial = [&] {
        const FluidState& f = world->state().fluid;
        EXPECT_LT(f.pressureKpa, map);
        return f.bleedingMlPerS / (map - f.pressureKpa);
    };
    DeviceSample held = samples.back();
    held.buttons = 0;
    stepHeld(*world, held, 0.1, samples);
    // The pedal up: what the presses cut came off the loop as chips, every millilitre cut away in one of them.
    const WorldSnapshot afterCut = world->snapshot();
    double cutAway = world->metrics().resection.healthyRemovedMl, inChips = 0.0;
    for (const PathologyResection& r : world->metrics().resection.pathologies)
        cutAway += r.removedMl;
    for (const Chip& chip : afterCut.chips)
        inChips += chip.volumeMl;
    EXPECT_GT(world->metrics().resection.chipsMade, 0u);
    EXPECT_EQ(world->metrics().resection.chipsLeft, afterCut.chips.size());
    EXPECT_NEAR(inChips, cutAway, 1e-9);
    const double openBefore = arterial();
    const FluidState cutFluid = world->state().fluid;
    EXPECT_GT(openBefore, 0.0);
    EXPECT_GT(cutFluid.bloodLossMl, 0.0);
    EXPECT_GT(cutFluid.cutIntravasationMlPerS, 0.0);
    // Two presses of the pump's down button: 10 mmHg less, the pressure falls and the cut bleeds faster.
    DeviceSample down = held;
    down.buttons = kButtonPumpDown;
    for (int press = 0; press < 2; ++press) {
        stepHeld(*world, down, 0.05, samples);
        stepHeld(*world, held, 0.05, samples);
    }
    stepHeld(*world, held, 0.5, samples);
    const WorldSnapshot later = world->snapshot();
    ASSERT_GE(later.chips.size(), afterCut.chips.size());
    EXPECT_NEAR(world->state().fluid.pumpSetKpa, world->options().fluid.pumpPressureKpa - 2.0 * kPumpStepKpa, 1e-12);
    EXPECT_LT(world->state().fluid.pressureKpa, cutFluid.pressureKpa);
    EXPECT_GT(world->state().fluid.bleedingMlPerS, cutFluid.bleedingMlPerS);
    EXPECT_NEAR(arterial(), openBefore, 1e-12 * openBefore); // no cut, no seal: the same vessels are open
    // The cut's blood leaves it as clouds (docs/simulator.md, "Blood clouds"): the newest one by the faces the cut
    // bared, all of them together no more blood than the cavity holds.
    const BloodClouds& clouds = later.state.blood;
    ASSERT_GT(clouds.count, 0u);
    double inClouds = 0.0;
    for (std::size_t i = 0; i < clouds.count; ++i)
        inClouds += clouds.clouds[i].bloodMl;
    EXPECT_GT(inClouds, 0.0);
    EXPECT_LE(inClouds, later.state.fluid.bloodInCavityMl * (1.0 + 1e-12));
    ASSERT_TRUE(later.cut);
    double cloudToCut = 1e300; // mm, from the newest cloud to the nearest point of a bared face
    for (const Triangle& face : later.cut->faces)
        for (const std::int32_t q : face)
            cloudToCut = std::min(cloudToCut, distance(clouds.clouds[clouds.count - 1].centreMm,
                                                       later.simulationPointsMm[static_cast<std::size_t>(q)]));
    std::printf("blood clouds: %zu holding %.4f of the cavity's %.4f mL, the newest %.2f mm from the cut\n",
                clouds.count, inClouds, later.state.fluid.bloodInCavityMl, cloudToCut);
    EXPECT_LT(cloudToCut, 5.0);
    // The last half second of cutting once more with the coagulating pedal instead: the loop passes over the faces
    // it bared and seals their vessels, less is open.
    std::size_t lastCut = 0;
    for (std::size_t i = 0; i < samples.size(); ++i)
        if (samples[i].buttons & kButtonCut)
            lastCut = i;
    ASSERT_GT(lastCut, 500u);
    std::vector<DeviceSample> again(samples.begin() + static_cast<std::ptrdiff_t>(lastCut - 500),
                                    samples.begin() + static_cast<std::ptrdiff_t>(lastCut + 1));
    for (DeviceSample& a : again)
        a.buttons = (a.buttons & kButtonCut) ? kButtonCoagulate : 0u;
    for (std::size_t i = world->ticksPerStep() - 1; i < again.size(); i += world->ticksPerStep())
        stepHeld(*world, again[i], world->options().stepS, samples); // the step's last sample moves the scope
    const double openAfter = arterial();
    std::printf("open arterioles %.3g -> %.3g mL/(s kPa) after 0.5 s of coagulation; blood loss %.3f mL, cut "
                "intravasation %.3f mL/min at %.2f kPa\n",
                openBefore, openAfter, world->state().fluid.bloodLossMl,
                world->state().fluid.cutIntravasationMlPerS * 60.0, world->state().fluid.pressureKpa);
    EXPECT_LT(openAfter, openBefore);
    EXPECT_GT(world->metrics().resection.coagulationTimeS, 0.0);
    EXPECT_DOUBLE_EQ(world->metrics().bloodLossMl, world->state().fluid.bloodLossMl);

    // Instrument exchange: the office scope's 5 Fr scissors and grasper. `reach` brings an instrument's jaws, open,
    // their middle on `target` (the shaft on the line from the pivot), over 0.7 s.
    const JawInstrument jaws;
    const auto reach = [&](const Vec3& target, std::uint32_t instrument) {
        // The jaws' middle is the tip + (travel + half a jaw) along the shaft + the channel's offset towards the
        // image's bottom: the tip aimed for twice, the second time with the first pose's bottom.
        const double travel = 3.0;
        Vec3 jawsAt = target;
        DeviceSample to;
        for (int pass = 0; pass < 2; ++pass) {
            const Vec3 along = normalized(jawsAt - world->frame().pivotMm);
            to = sampleAiming(world->frame(), jawsAt - along * (travel + 0.5 * jaws.jawLengthMm));
            const ScopePose pose = scopePose(world->frame(), world->options().scope, to);
            const Vec3 up = pose.up - pose.shaft * dot(pose.up, pose.shaft);
            jawsAt = target + normalized(up) * jaws.channelOffsetMm;
        }
        const DeviceSample from = samples.back();
        to.inflow = from.inflow;
        to.outflow = from.outflow;
        to.workingElementMm = travel;
        to.instrument = instrument;
        to.buttons = 0;
        for (int k = 1; k <= 12; ++k) {
            DeviceSample s = to;
            const double u = k / 12.0;
            s.insertionMm = from.insertionMm + (to.insertionMm - from.insertionMm) * u;
            s.pitchDeg = from.pitchDeg + (to.pitchDeg - from.pitchDeg) * u;
            s.yawDeg = from.yawDeg + (to.yawDeg - from.yawDeg) * u;
            s.rollDeg = from.rollDeg + (to.rollDeg - from.rollDeg) * u;
            stepHeld(*world, s, 0.05, samples);
        }
        stepHeld(*world, to, 0.1, samples);
        const LoopState& now = world->state().loop;
        EXPECT_EQ(now.instrument, instrument);
        EXPECT_NEAR(now.jawOpenDeg, jaws.openDeg, 1e-9);
        std::printf("%s: the jaws' middle %.2f mm from its target\n", std::string(instrumentName(instrument)).c_str(),
                    distance(now.middleMm + now.axis * (0.5 * now.jawLengthMm), target));
        return to;
    };
    // The scissors on the live polyp tet nearest the scope's tip: their blades closing take it.
    const TetMesh& rest = world->simulationMesh();
    const std::int32_t polypRegion = pathologies[static_cast<std::size_t>(polyp)].regionId;
    const std::shared_ptr<const CutView> cutSoFar = world->snapshot().cut;
    ASSERT_TRUE(cutSoFar);
    std::size_t target = rest.tetCount();
    Vec3 targetMm;
    for (std::size_t t = 0; t < rest.tetCount(); ++t) {
        if (rest.regionOf(t) != polypRegion || cutSoFar->removedTets[t])
            continue;
        Vec3 c;
        for (const std::int32_t v : rest.tets[t])
            c += world->simulationPointsMm()[static_cast<std::size_t>(v)] * 0.25;
        if (target == rest.tetCount() ||
            distance(c, world->state().scope.tipMm) < distance(targetMm, world->state().scope.tipMm)) {
            target = t;
            targetMm = c;
        }
    }
    ASSERT_LT(target, rest.tetCount());
    const std::uint64_t eventsBefore = world->metrics().resection.cutEvents;
    const double polypBefore = world->metrics().resection.pathologies[static_cast<std::size_t>(polyp)].removedMl;
    const double cuttingBefore = world->metrics().resection.cuttingTimeS;
    const WorldSnapshot beforeExchange = world->snapshot();
    DeviceSample snip = reach(targetMm, kInstrumentScissors);
    // The loop exchanged let go of the chips it had caught; meanwhile the fluid's flow from the tip to the sheath's
    // outflow holes carried every free chip while it sank (docs/simulator.md, "Chips"): one at least moved other than
    // straight down, as sinking alone would move it.
    {
        const WorldSnapshot afterExchange = world->snapshot();
        ASSERT_EQ(afterExchange.chips.size(), beforeExchange.chips.size());
        ASSERT_FALSE(afterExchange.chips.empty());
        double drifted = 0.0; // mm, the largest move of a free chip across the sinking direction
        for (std::size_t k = 0; k < afterExchange.chips.size(); ++k) {
            EXPECT_FALSE(afterExchange.chips[k].hooked);
            const Vec3 moved = afterExchange.chips[k].positionMm - beforeExchange.chips[k].positionMm;
            drifted = std::max(drifted, std::hypot(moved.x, moved.z));
        }
        std::printf("chips: %zu let go by the loop, the farthest carried %.2f mm across the sinking in 0.7 s\n",
                    afterExchange.chips.size(), drifted);
        EXPECT_GT(drifted, 0.1);
    }
    EXPECT_FALSE(world->state().loop.cutting);
    snip.buttons = kButtonCut;
    stepHeld(*world, snip, 0.3, samples); // shut after jaws.closeS
    EXPECT_DOUBLE_EQ(world->state().loop.jawOpenDeg, 0.0);
    EXPECT_GT(world->metrics().resection.cutEvents, eventsBefore);
    EXPECT_TRUE(world->snapshot().cut->removedTets[target]) << "the tet between the blades was left";
    std::printf("scissors: %llu cut events, %.4f mL more of the polyp removed\n",
                static_cast<unsigned long long>(world->metrics().resection.cutEvents - eventsBefore),
                world->metrics().resection.pathologies[static_cast<std::size_t>(polyp)].removedMl - polypBefore);
    EXPECT_GT(world->metrics().resection.pathologies[static_cast<std::size_t>(polyp)].removedMl, polypBefore);
    EXPECT_GT(world->metrics().resection.cuttingTimeS, cuttingBefore);
    snip.buttons = 0;
    stepHeld(*world, snip, 0.3, samples);
    EXPECT_NEAR(world->state().loop.jawOpenDeg, jaws.openDeg, 1e-9); // let go, they open again
    EXPECT_EQ(world->health().invertedTets, 0u);

    // The grasper on the chip nearest the scope's tip (the loop, put down, let go of those it held): its jaws
    // shutting take hold of it; drawn out through the canal, the chip goes with them out of the cavity.
    const WorldSnapshot beforeGrasp = world->snapshot();
    ASSERT_FALSE(beforeGrasp.chips.empty());
    const Chip* nearest = &beforeGrasp.chips.front();
    for (const Chip& chip : beforeGrasp.chips) {
        EXPECT_FALSE(chip.hooked);
        if (distance(chip.positionMm, world->state().scope.tipMm) <
            distance(nearest->positionMm, world->state().scope.tipMm))
            nearest = &chip;
    }
    DeviceSample grasp = reach(nearest->positionMm, kInstrumentGrasper);
    const std::uint64_t outBefore = world->metrics().resection.chipsCarriedOut;
    const std::size_t leftBefore = world->snapshot().chips.size();
    EXPECT_FALSE(world->state().loop.holding);
    grasp.buttons = kButtonCut;
    stepHeld(*world, grasp, 0.3, samples);
    EXPECT_TRUE(world->state().loop.holding);
    for (int k = 1; k <= 20; ++k) { // out to 5 mm beyond the pivot over a second
        DeviceSample s = grasp;
        s.insertionMm = grasp.insertionMm + (5.0 - grasp.insertionMm) * (k / 20.0);
        stepHeld(*world, s, 0.05, samples);
    }
    EXPECT_EQ(world->metrics().resection.chipsCarriedOut, outBefore + 1);
    EXPECT_EQ(world->snapshot().chips.size(), leftBefore - 1);
    EXPECT_FALSE(world->state().loop.holding);

    Trial trial;
    trial.header = world->trialHeader();
    trial.samples = samples;
    auto replayed = replayTrial(test::SimPackage::folder(), trial);
    ASSERT_TRUE(replayed) << replayed.error().detail;
    EXPECT_EQ(reportJson(*replayed), reportJson(world->report()));
    EXPECT_NE(reportJson(*replayed).find("\"resection\""), std::string::npos);

    // The diagnostic exercises do not cut: no resection is planned for them.
    auto exploring = loadWorld();
    ASSERT_TRUE(exploring);
    auto refused = resectionScript(*exploring, polyp);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().detail.find("exploration"), std::string::npos) << refused.error().detail;
    EXPECT_TRUE(exploring->metrics().resection.pathologies.empty());
}

TEST(World, RefusesSamplesOutOfSequenceOrRange) {
    auto world = loadWorld();
    ASSERT_TRUE(world);
    std::vector<DeviceSample> samples(world->ticksPerStep());
    for (std::size_t i = 0; i < samples.size(); ++i)
        samples[i].tick = i + 1;
    EXPECT_FALSE(world->step(samples.data(), samples.size()).ok());
    for (std::size_t i = 0; i < samples.size(); ++i)
        samples[i].tick = i;
    samples[2].pitchDeg = std::nan("");
    EXPECT_FALSE(world->step(samples.data(), samples.size()).ok());
    EXPECT_FALSE(world->step(samples.data(), 3).ok());
    EXPECT_EQ(world->state().step, 0u);
}

TEST(World, RefusesAPackageWithoutASimulationMesh) {
    auto scene = scene::readScenePackage(test::SimPackage::folder());
    ASSERT_TRUE(scene);
    scene->simulation.reset();
    test::TempDir dir;
    ASSERT_TRUE(scene::writeScenePackage(*scene, dir.file("old")));
    auto world = World::load(dir.file("old"), {});
    ASSERT_FALSE(world);
    EXPECT_NE(world.error().detail.find("no simulation mesh"), std::string::npos) << world.error().detail;
    EXPECT_NE(world.error().detail.find(dir.file("old")), std::string::npos) << world.error().detail;
}

} // namespace
} // namespace hs::sim
