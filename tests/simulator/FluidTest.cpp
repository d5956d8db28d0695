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
    const OpenVessels vessels{0.05, 0.0};
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
        settle(fluid, 20.0, 0.5, {0.0, gv});
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
    settle(low, 20.0, 1.0, {0.0, 0.04}, 0.5);
    ASSERT_LT(low.state().pressureKpa, kVenulePressureKpa);
    EXPECT_EQ(low.state().cutIntravasationMlPerS, 0.0);
}

TEST(Fluid, TheFluidBalancesAndTheBloodWashesOutOnceTheBleedingStops) {
    FluidSettings settings;
    settings.pumpPressureKpa = 6.0;
    FluidModel fluid;
    fluid.reset(settings);
    settle(fluid, 10.0, 0.5, {0.05, 0.02});
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
    settle(fluid, halfLife, 0.5, {0.0, 0.0});
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
    fluid.step(kDt, 1.0, 0.5, 0.0, kCompliance, 0.0, {std::nan(""), INFINITY});
    EXPECT_TRUE(std::isfinite(fluid.state().pressureKpa));
}

} // namespace
