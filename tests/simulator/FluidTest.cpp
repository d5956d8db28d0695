// The distension fluid's exchange with a cut's open vessels (docs/simulator.md, "Bleeding"): bleeding with its
// tamponade, intravasation through the cut venules, the blood's washout, and the fluid's balance.
#include "Fluid.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace hs::sim;
using namespace hs::sim::detail;

constexpr double kDt = 0.005;     // s, the world's step
constexpr double kCompliance = 2; // mL/kPa over one step

/// Runs the model for `seconds` with the cavity holding exactly the fluid it is given (the tissue's opening follows
/// the pressure by `kCompliance`), the valves at `inflow` and `outflow`.
void settle(FluidModel& fluid, double seconds, double outflow, const OpenVessels& vessels, double inflow = 1.0) {
    for (int k = 0; k < static_cast<int>(std::lround(seconds / kDt)); ++k)
        fluid.step(kDt, inflow, outflow, fluid.state().distensionMl, kCompliance, 0.0, vessels);
}

TEST(Fluid, ACutBleedsInProportionToHowFarThePressureIsBelowTheMeanArterialPressureAndNotAboveIt) {
    FluidSettings settings;
    const double map = settings.meanArterialPressureKpa;
    const OpenVessels vessels{0.05, 0.0, {}};
    for (const double pump : {4.0, 6.0, 8.0, 10.0}) {
        settings.pumpPressureKpa = pump;
        FluidModel fluid;
        fluid.reset(settings);
        settle(fluid, 20.0, 0.5, vessels);
        const FluidState& s = fluid.state();
        ASSERT_LT(s.pressureKpa, map);
        EXPECT_NEAR(s.bleedingMlPerS, vessels.arterialMlPerSKpa * (map - s.pressureKpa), 1e-12);
    }
    // The pump above the mean arterial pressure with the outflow shut: the pressure rises past it, the tamponade
    // stops the bleeding exactly.
    settings.pumpPressureKpa = 15.0;
    FluidModel fluid;
    fluid.reset(settings);
    settle(fluid, 20.0, 0.0, vessels);
    EXPECT_GT(fluid.state().pressureKpa, map);
    EXPECT_EQ(fluid.state().bleedingMlPerS, 0.0);
}

TEST(Fluid, TheCutsVenulesTakeFluidInProportionToTheirConductanceAndThePressureAboveTheirs) {
    FluidSettings settings;
    double lastRate = 0.0;
    for (const double gv : {0.01, 0.02, 0.04}) {
        FluidModel fluid;
        fluid.reset(settings);
        settle(fluid, 20.0, 0.5, {0.0, gv, {}});
        const FluidState& s = fluid.state();
        ASSERT_GT(s.pressureKpa, kVenulePressureKpa);
        EXPECT_NEAR(s.cutIntravasationMlPerS, gv * (s.pressureKpa - kVenulePressureKpa), 1e-12);
        EXPECT_GT(s.cutIntravasationMlPerS, lastRate); // more open venules, more intravasation
        lastRate = s.cutIntravasationMlPerS;
        EXPECT_GE(s.intravasationMlPerS, s.cutIntravasationMlPerS);
    }
    // Below the venules' pressure nothing flows into them.
    settings.pumpPressureKpa = 2.7;
    FluidModel low;
    low.reset(settings);
    settle(low, 20.0, 1.0, {0.0, 0.04, {}}, 0.5);
    ASSERT_LT(low.state().pressureKpa, kVenulePressureKpa);
    EXPECT_EQ(low.state().cutIntravasationMlPerS, 0.0);
}

TEST(Fluid, TheFluidBalancesAndTheBloodWashesOutOnceTheBleedingStops) {
    FluidSettings settings;
    settings.pumpPressureKpa = 6.0;
    FluidModel fluid;
    fluid.reset(settings);
    settle(fluid, 10.0, 0.5, {0.05, 0.02, {}});
    const FluidState bleeding = fluid.state();
    EXPECT_GT(bleeding.bloodLossMl, 0.0);
    EXPECT_GT(bleeding.bloodFraction, 0.0);
    // In = out + intravasated + held, blood included: the balance closes to rounding.
    EXPECT_NEAR(bleeding.inflowTotalMl + bleeding.bloodLossMl,
                bleeding.outflowTotalMl + bleeding.intravasationTotalMl + bleeding.distensionMl, 1e-9);
    // Sealed: the blood leaves with the outflow, a well-mixed cavity halving it every V ln 2 / Q.
    const double volume = bleeding.distensionMl;
    const double leaving = bleeding.outflowMlPerS + bleeding.intravasationMlPerS;
    const double halfLife = volume * std::log(2.0) / leaving;
    settle(fluid, halfLife, 0.5, {0.0, 0.0, {}});
    const double ratio = fluid.state().bloodInCavityMl / bleeding.bloodInCavityMl;
    std::printf("blood in the cavity %.4f mL of %.2f mL fluid; after the half-life %.2f s: ratio %.3f\n",
                bleeding.bloodInCavityMl, volume, halfLife, ratio);
    EXPECT_NEAR(ratio, 0.5, 0.05); // the flows change a little once the bleeding stops
    EXPECT_EQ(fluid.state().bleedingMlPerS, 0.0);
}

TEST(Fluid, ThePumpsSetPressureMovesAndStaysInItsRange) {
    FluidSettings settings;
    FluidModel fluid;
    fluid.reset(settings);
    EXPECT_EQ(fluid.state().pumpSetKpa, settings.pumpPressureKpa);
    fluid.setPumpPressure(settings.pumpPressureKpa + kPumpStepKpa);
    EXPECT_DOUBLE_EQ(fluid.state().pumpSetKpa, settings.pumpPressureKpa + kPumpStepKpa);
    fluid.setPumpPressure(100.0);
    EXPECT_EQ(fluid.state().pumpSetKpa, 20.0);
    fluid.setPumpPressure(-1.0);
    EXPECT_EQ(fluid.state().pumpSetKpa, 2.7);
    fluid.setPumpPressure(std::nan(""));
    EXPECT_EQ(fluid.state().pumpSetKpa, 2.7);
    // Not finite conductances are no vessels.
    fluid.step(kDt, 1.0, 0.5, 0.0, kCompliance, 0.0, {std::nan(""), INFINITY, {}});
    EXPECT_TRUE(std::isfinite(fluid.state().pressureKpa));
}

/// The flux of the fluid's flow out through a sphere of `radiusMm` about `centreMm`, mL/s, by the midpoint rule on a
/// latitude-longitude grid of n x 2n cells.
double fluxThroughSphere(const hs::Vec3& centreMm, double radiusMm, const hs::Vec3& tipMm, const hs::Vec3& shaft,
                         double inflow, double outflow, double coreMm, int n) {
    constexpr double kPi = 3.14159265358979323846;
    double flux = 0.0;
    for (int i = 0; i < n; ++i) {
        const double theta = (i + 0.5) * kPi / n;
        for (int j = 0; j < 2 * n; ++j) {
            const double phi = (j + 0.5) * kPi / n;
            const hs::Vec3 normal{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
            const double area = radiusMm * radiusMm * std::sin(theta) * (kPi / n) * (kPi / n);
            const hs::Vec3 u = flowVelocityMmPerS(centreMm + normal * radiusMm, tipMm, shaft, inflow, outflow, coreMm);
            flux += hs::dot(u, normal) * area;
        }
    }
    return flux / 1000.0; // mm^3/s -> mL/s
}

TEST(Fluid, TheFlowThatCarriesChipsIsASourceAtTheTipAndASinkAtTheOutflowHoles) {
    // Verified against the analytic flow of a point source and a point sink (Batchelor): its speed Q / (4 pi r^2)
    // along the line from each, its flux through any sphere what the sphere holds, its divergence zero between them.
    const hs::Vec3 tip{1.0, -2.0, 30.0};
    const hs::Vec3 shaft = hs::normalized(hs::Vec3{0.1, 0.2, 1.0});
    const double inflow = 5.0, outflow = 3.5, core = 1.45; // mL/s; mm, the 2.9 mm sheath's radius
    // The source alone, 10 mm ahead of the tip: 5000 mm^3/s over 4 pi 100 mm^2, away from the tip.
    const hs::Vec3 ahead = flowVelocityMmPerS(tip + shaft * 10.0, tip, shaft, inflow, 0.0, core);
    EXPECT_NEAR(hs::dot(ahead, shaft), 5000.0 / (4.0 * M_PI * 100.0), 1e-12);
    EXPECT_NEAR(hs::norm(ahead - shaft * hs::dot(ahead, shaft)), 0.0, 1e-12);
    // Inside the sheath's radius the speed is that at its radius.
    const hs::Vec3 near = flowVelocityMmPerS(tip + shaft * 0.1, tip, shaft, inflow, 0.0, core);
    EXPECT_NEAR(hs::norm(near), 5000.0 / (4.0 * M_PI * core * core), 1e-9);
    // Gauss: a sphere round the tip alone passes the inflow; one round both, inflow less outflow; one round neither,
    // nothing. (The sink lies kOutflowBehindTipMm behind the tip.)
    const hs::Vec3 holes = tip - shaft * kOutflowBehindTipMm;
    const double aroundTip = fluxThroughSphere(tip, 3.0, tip, shaft, inflow, outflow, core, 400);
    const double aroundBoth = fluxThroughSphere(tip, 30.0, tip, shaft, inflow, outflow, core, 400);
    const double aroundHoles = fluxThroughSphere(holes, 3.0, tip, shaft, inflow, outflow, core, 400);
    const double aroundNeither = fluxThroughSphere(tip + shaft * 20.0, 5.0, tip, shaft, inflow, outflow, core, 400);
    std::printf("flux out through spheres: round the tip %.5f mL/s, round both %.5f, round the holes %.5f, round "
                "neither %.2e\n",
                aroundTip, aroundBoth, aroundHoles, aroundNeither);
    EXPECT_NEAR(aroundTip, inflow, 1e-3 * inflow);
    EXPECT_NEAR(aroundBoth, inflow - outflow, 1e-3 * inflow);
    EXPECT_NEAR(aroundHoles, -outflow, 1e-3 * inflow);
    EXPECT_NEAR(aroundNeither, 0.0, 1e-3 * inflow);
    // Divergence by central differences at points between and round them: zero against the field's own gradients.
    for (const hs::Vec3 at : {tip + shaft * 5.0, tip + hs::Vec3{6.0, 0.0, 0.0}, holes + hs::Vec3{0.0, -4.0, -3.0}}) {
        const double h = 1e-3;
        double divergence = 0.0, scale = 0.0;
        for (int axis = 0; axis < 3; ++axis) {
            hs::Vec3 e{};
            (axis == 0 ? e.x : axis == 1 ? e.y : e.z) = h;
            const hs::Vec3 plus = flowVelocityMmPerS(at + e, tip, shaft, inflow, outflow, core);
            const hs::Vec3 minus = flowVelocityMmPerS(at - e, tip, shaft, inflow, outflow, core);
            const double dPlus = axis == 0 ? plus.x : axis == 1 ? plus.y : plus.z;
            const double dMinus = axis == 0 ? minus.x : axis == 1 ? minus.y : minus.z;
            divergence += (dPlus - dMinus) / (2.0 * h);
            scale += std::abs(dPlus - dMinus) / (2.0 * h);
        }
        EXPECT_LT(std::abs(divergence), 1e-5 * scale);
    }
    // Closed valves, no flow; not finite flows are none.
    EXPECT_EQ(hs::norm(flowVelocityMmPerS(tip + shaft * 5.0, tip, shaft, 0.0, 0.0, core)), 0.0);
    EXPECT_EQ(hs::norm(flowVelocityMmPerS(tip + shaft * 5.0, tip, shaft, std::nan(""), INFINITY, core)), 0.0);
}

} // namespace

namespace {

TEST(Fluid, BloodLeavesACutVesselAsCloudsThatDriftWithTheFlowSpreadAndMixIn) {
    // A vessel 6 mm ahead of the tip bleeding 0.02 mL/s for 3 s, then sealed; the cavity's blood washes out at
    // 0.1 / s (the fluid model's well-mixed washout), in 10 mL of fluid.
    const hs::Vec3 tip{0.0, 0.0, 30.0}, shaft{0.0, 0.0, 1.0};
    const hs::Vec3 vessel = tip + hs::Vec3{0.0, 6.0, 0.0};
    const FlowField flow{tip, shaft, 2.0, 1.5, 1.45};
    const double volumeMl = 10.0, washoutPerS = 0.1, bleedMlPerS = 0.02;
    BloodClouds blood;
    double total = 0.0;
    const auto step = [&](double bleeding) {
        const double bled = kDt * bleeding;
        const double keep = 1.0 / (1.0 + kDt * washoutPerS);
        total = (total + bled) * keep;
        advanceBloodClouds(blood, kDt, bled, vessel, flow, keep, total, total / volumeMl);
    };
    const auto inClouds = [&] {
        double sum = 0.0;
        for (std::size_t i = 0; i < blood.count; ++i)
            sum += blood.clouds[i].bloodMl;
        return sum;
    };
    for (int k = 0; k < 600; ++k) { // 3 s
        step(bleedMlPerS);
        // Clouds and mixed blood together are the cavity's blood.
        ASSERT_NEAR(inClouds() + blood.mixedFraction * volumeMl, total, 1e-12);
    }
    // A cloud every 0.5 s: six, the newest at the vessel, the oldest spread as sigma^2 = 0.25 + 2 D t and carried
    // by the flow away from the vessel.
    ASSERT_EQ(blood.count, 6u);
    const BloodCloud& oldest = blood.clouds[0];
    const BloodCloud& newest = blood.clouds[blood.count - 1];
    // The newest at most kBloodCloudIntervalS of drift from the vessel (the flow there 3.8 mm/s, slower farther from
    // the tip).
    const double speedAtVessel =
        hs::norm(flowVelocityMmPerS(vessel, tip, shaft, flow.inflowMlPerS, flow.outflowMlPerS, 1.45));
    EXPECT_LT(hs::distance(newest.centreMm, vessel), kBloodCloudIntervalS * speedAtVessel);
    EXPECT_NEAR(oldest.sigmaMm,
                std::sqrt(kBloodCloudStartMm * kBloodCloudStartMm + 2.0 * kBloodEddyDiffusivityMm2PerS * oldest.ageS),
                1e-9);
    const hs::Vec3 drift = flowVelocityMmPerS(vessel, tip, shaft, flow.inflowMlPerS, flow.outflowMlPerS, 1.45);
    std::printf("after 3 s of bleeding: %zu clouds, the oldest %.2f s old, %.2f mm wide, %.2f mm from the vessel "
                "(the flow there %.2f mm/s); %.4f mL in clouds, %.4f mL mixed\n",
                blood.count, oldest.ageS, oldest.sigmaMm, hs::distance(oldest.centreMm, vessel), hs::norm(drift),
                inClouds(), blood.mixedFraction * volumeMl);
    // Where a tracer leaving the vessel is after the oldest cloud's age (the flow's path by fourth-order Runge-Kutta
    // in steps a tenth of the world's).
    hs::Vec3 tracer = vessel;
    const auto velocity = [&](const hs::Vec3& at) {
        return flowVelocityMmPerS(at, tip, shaft, flow.inflowMlPerS, flow.outflowMlPerS, 1.45);
    };
    const double h = 0.1 * kDt;
    for (int k = 0; k < static_cast<int>(std::lround(oldest.ageS / h)); ++k) {
        const hs::Vec3 a = velocity(tracer), b = velocity(tracer + a * (0.5 * h));
        const hs::Vec3 c = velocity(tracer + b * (0.5 * h)), d = velocity(tracer + c * h);
        tracer = tracer + (a + b * 2.0 + c * 2.0 + d) * (h / 6.0);
    }
    EXPECT_GT(hs::distance(tracer, vessel), 3.0);
    EXPECT_LT(hs::distance(oldest.centreMm, tracer), 0.05);
    // Nothing has mixed yet: a cloud takes (6^2 - 0.5^2) / (2 D) = 4.5 s to reach the cavity's half-width.
    EXPECT_NEAR(blood.mixedFraction, 0.0, 1e-12);
    // Sealed: no new cloud; 4.5 s later every cloud has mixed in.
    for (int k = 0; k < 900; ++k)
        step(0.0);
    EXPECT_EQ(blood.count, 0u);
    EXPECT_NEAR(blood.mixedFraction, total / volumeMl, 1e-12);
    EXPECT_GT(total, 0.0);
    // Not finite blood is none. However long the bleeding, it keeps one cloud per kBloodCloudIntervalS over the
    // time a cloud takes to mix (4.5 s: 9), within kMaxBloodClouds.
    advanceBloodClouds(blood, kDt, std::nan(""), vessel, flow, 1.0, total, total / volumeMl);
    EXPECT_EQ(blood.count, 0u);
    for (int k = 0; k < 4000; ++k)
        advanceBloodClouds(blood, 0.05, 0.001, vessel, flow, 1.0, 1.0, 0.1);
    EXPECT_GE(blood.count, 8u);
    EXPECT_LE(blood.count, 10u);
    static_assert(kMaxBloodClouds >= 10);
}

} // namespace
