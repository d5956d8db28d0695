// The simulator's world on a generated package: loading, distension against the hydrometra curve, a scripted
// exploration, a perforation, replay bit for bit, and the refusals.

#include "hs/sim/World.h"
#include "SimPackage.h"
#include "hs/scene/Sha256.h"

#include <gtest/gtest.h>

#include <cmath>
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
void run(World& world, const Script& script, double seconds, std::vector<DeviceSample>* samples = nullptr) {
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

TEST(World, TheCavityOpensWithPressureAlongTheHydrometraCurve) {
    auto world = loadWorld();
    ASSERT_TRUE(world);
    const auto& h = world->scene().hydrometra;
    const double compliance = h.cavityVolumeMl / h.pressureKpa;
    // The pump's set pressure, inflow open, outflow closed: the cavity fills to about the pump's pressure.
    for (const double mmHg : {40.0, 60.0, 100.0}) {
        WorldOptions options;
        options.fluid.pumpPressureKpa = mmHg * 0.133322;
        options.fluid.meanArterialPressureKpa = 20.0;
        auto w = loadWorld(options);
        ASSERT_TRUE(w);
        DeviceSample s;
        s.insertionMm = -5.0;
        s.inflow = 1.0;
        run(*w, holding(s, 3.0), 3.0);
        const double p = w->state().fluid.pressureKpa;
        const double opened = w->state().cavityOpeningMl;
        const double expected = compliance * p;
        EXPECT_NEAR(opened, expected, 0.2 * expected) << mmHg << " mmHg: pressure " << p << " kPa";
        EXPECT_LT(w->state().fluid.redOut, 1.0);
        EXPECT_EQ(w->health().invertedTets, 0u);
    }
}

TEST(World, AScriptedExplorationSeesBothOstiaWithoutPerforation) {
    auto world = loadWorld();
    ASSERT_TRUE(world);
    const Script script = explorationScript(*world, 30.0);
    run(*world, script, 0.0);
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
    const World::Health health = world->health();
    EXPECT_EQ(health.invertedTets, 0u);
    EXPECT_LT(health.elasticEnergyJ, 1.0);
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
    key(9.0, lm.fundusMm + towards * 40.0);
    run(*world, script, 0.0);
    const auto& perforations = world->metrics().perforations;
    ASSERT_EQ(perforations.size(), 1u);
    EXPECT_GT(perforations[0].depthMm, 5.0);
    EXPECT_LT(distance(perforations[0].locationMm, lm.fundusMm), 25.0);
    EXPECT_FALSE(perforations[0].region.empty());
    EXPECT_TRUE(world->state().contact.perforated);
    EXPECT_FALSE(world->report().explorationComplete);
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
