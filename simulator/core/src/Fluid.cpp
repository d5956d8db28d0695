#include "Fluid.h"

#include <algorithm>
#include <cmath>

namespace hs::sim::detail {

void FluidModel::reset(const FluidSettings& settings) {
    m_settings = settings;
    m_state = FluidState{};
    m_state.redOut = 1.0;
    m_state.pumpSetKpa = settings.pumpPressureKpa;
    m_fluidMl = 0.0;
}

void FluidModel::setPumpPressure(double kpa) {
    if (std::isfinite(kpa))
        m_state.pumpSetKpa = std::clamp(kpa, 2.7, 20.0);
}

double FluidModel::step(double dt, double inflowValve, double outflowValve, double cavityMl, double complianceMlPerKpa,
                        double contactForceN, const OpenVessels& vessels) {
    const double p0 = m_state.pressureKpa;
    const double pump = m_state.pumpSetKpa;
    const double map = m_settings.meanArterialPressureKpa;
    const double gin = kInflowConductance * std::clamp(std::isfinite(inflowValve) ? inflowValve : 0.0, 0.0, 1.0);
    const double gout = kOutflowConductance * std::clamp(std::isfinite(outflowValve) ? outflowValve : 0.0, 0.0, 1.0);
    const double c = std::isfinite(complianceMlPerKpa) ? std::max(complianceMlPerKpa, 1e-6) : 1e-6;
    const double cavity = std::isfinite(cavityMl) ? cavityMl : m_fluidMl;
    const auto conductance = [](double g) { return std::isfinite(g) ? std::clamp(g, 0.0, 1e3) : 0.0; };
    const double ga = conductance(vessels.arterialMlPerSKpa);
    const double gv = conductance(vessels.venousMlPerSKpa);
    // The cavity after the step holds cavity + c (p - p0); the fluid after it, V + dt (gin (pump - p) - gout p - q(p)
    // - gv (p - pv)+ + ga (map - p)+). Equal, for p (backward Euler in the flows): G(p) = 0 with G rising and linear
    // between the breakpoints pv and map, so p is exact on the piece where G changes sign.
    const double base = m_fluidMl - cavity + c * p0 + dt * gin * pump;
    const auto piece = [&](double at, double& slope, double& intercept) {
        slope = c + dt * (gin + gout + kIntravasationBelowMap);
        intercept = -base;
        if (at > map) {
            slope += dt * kIntravasationAboveMap;
            intercept -= dt * kIntravasationAboveMap * map;
        } else {
            slope += dt * ga;
            intercept -= dt * ga * map;
        }
        if (at > kVenulePressureKpa) {
            slope += dt * gv;
            intercept -= dt * gv * kVenulePressureKpa;
        }
    };
    const double lower = std::min(kVenulePressureKpa, map), upper = std::max(kVenulePressureKpa, map);
    double slope = 0.0, intercept = 0.0;
    const auto at = [&](double x) {
        piece(x, slope, intercept);
        return slope * x + intercept;
    };
    // The piece: below `lower`, between, or above `upper` (G is continuous, so its sign at a breakpoint decides).
    const double probe = at(lower) >= 0.0 ? lower - 1.0 : (at(upper) >= 0.0 ? 0.5 * (lower + upper) : upper + 1.0);
    piece(probe, slope, intercept);
    double p = -intercept / slope;
    p = std::max(p, 0.0); // the fluid cannot pull the walls in: an emptied cavity is a slit at rest
    FluidState& s = m_state;
    s.pressureKpa = p;
    s.inflowMlPerS = gin * std::max(pump - p, 0.0);
    s.outflowMlPerS = gout * p;
    s.cutIntravasationMlPerS = gv * std::max(p - kVenulePressureKpa, 0.0);
    s.intravasationMlPerS =
        kIntravasationBelowMap * p + kIntravasationAboveMap * std::max(p - map, 0.0) + s.cutIntravasationMlPerS;
    s.bleedingMlPerS = ga * std::max(map - p, 0.0);
    m_fluidMl += dt * (s.inflowMlPerS - s.outflowMlPerS - s.intravasationMlPerS + s.bleedingMlPerS);
    if (p == 0.0)
        m_fluidMl = std::min(m_fluidMl, cavity); // no pressure: the fluid is what the open cavity holds, at most
    m_fluidMl = std::max(m_fluidMl, 0.0);
    s.inflowTotalMl += s.inflowMlPerS * dt;
    s.outflowTotalMl += s.outflowMlPerS * dt;
    s.intravasationTotalMl += s.intravasationMlPerS * dt;
    s.bloodLossMl += s.bleedingMlPerS * dt;
    s.deficitMl = s.inflowTotalMl - s.outflowTotalMl;
    s.distensionMl = m_fluidMl;
    s.deficitWarning = s.deficitMl >= m_settings.deficitWarningMl;
    s.deficitLimit = s.deficitMl >= m_settings.deficitLimitMl;
    // Turbidity: contact stirs debris and blood into the fluid; the flow through the cavity washes it out.
    const double volume = std::max(s.distensionMl, 0.5);
    const double washout = (s.outflowMlPerS + s.intravasationMlPerS) / volume;
    const double stir = std::isfinite(contactForceN) ? std::clamp(contactForceN, 0.0, 100.0) : 0.0;
    s.turbidity = std::clamp(s.turbidity + dt * (0.05 * stir - washout * s.turbidity), 0.0, 1.0);
    // The blood mixes into the cavity's fluid and leaves with it (well mixed; backward Euler).
    s.bloodInCavityMl = std::min((s.bloodInCavityMl + dt * s.bleedingMlPerS) / (1.0 + dt * washout), volume);
    s.bloodFraction = std::clamp(s.bloodInCavityMl / volume, 0.0, 1.0);
    s.redOut = std::clamp((kWallsClosePressureKpa - p) / kWallsClosePressureKpa, 0.0, 1.0);
    return p;
}

namespace {
constexpr double kPi = 3.14159265358979323846;
} // namespace

Vec3 flowVelocityMmPerS(const Vec3& pointMm, const Vec3& tipMm, const Vec3& shaft, double inflowMlPerS,
                        double outflowMlPerS, double coreMm) {
    const double core = std::max(coreMm, 1e-3);
    // One point source of `mlPerS` at `atMm` (a sink for a negative one): Q / (4 pi r^2) along r, r at least `core`.
    const auto source = [&](const Vec3& atMm, double mlPerS) {
        if (!std::isfinite(mlPerS) || mlPerS == 0.0)
            return Vec3{};
        const Vec3 r = pointMm - atMm;
        const double distance = norm(r);
        if (!(distance > 0.0))
            return Vec3{};
        const double reach = std::max(distance, core);
        return r * (1000.0 * mlPerS / (4.0 * kPi * reach * reach * distance));
    };
    return source(tipMm, inflowMlPerS) + source(tipMm - shaft * kOutflowBehindTipMm, -outflowMlPerS);
}

void advanceBloodClouds(BloodClouds& blood, double dt, double bledMl, const Vec3& bleedingMm, const FlowField& flow,
                        double keep, double bloodInCavityMl, double bloodFraction) {
    const double k = std::isfinite(keep) ? std::clamp(keep, 0.0, 1.0) : 1.0;
    const double spread = 2.0 * kBloodEddyDiffusivityMm2PerS * dt;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < blood.count; ++i) {
        BloodCloud c = blood.clouds[i];
        c.centreMm = c.centreMm + flowVelocityMmPerS(c.centreMm, flow.tipMm, flow.shaft, flow.inflowMlPerS,
                                                     flow.outflowMlPerS, flow.coreMm) *
                                      dt;
        c.sigmaMm = std::sqrt(c.sigmaMm * c.sigmaMm + spread);
        c.bloodMl *= k;
        c.ageS += dt;
        if (c.sigmaMm < kBloodCloudMixedMm) // wider: mixed through the cavity
            blood.clouds[kept++] = c;
    }
    blood.count = kept;
    if (bledMl > 0.0 && std::isfinite(bledMl)) {
        if (blood.count == 0 || blood.clouds[blood.count - 1].ageS >= kBloodCloudIntervalS) {
            if (blood.count == kMaxBloodClouds) { // the oldest mixes to make room
                std::copy(blood.clouds.begin() + 1, blood.clouds.end(), blood.clouds.begin());
                blood.count -= 1;
            }
            BloodCloud fresh;
            fresh.centreMm = bleedingMm;
            fresh.sigmaMm = kBloodCloudStartMm;
            blood.clouds[blood.count++] = fresh;
        }
        blood.clouds[blood.count - 1].bloodMl += bledMl * k;
    }
    // The clouds hold at most the cavity's blood; the rest of it is mixed.
    double inClouds = 0.0;
    for (std::size_t i = 0; i < blood.count; ++i)
        inClouds += blood.clouds[i].bloodMl;
    const double total = std::max(bloodInCavityMl, 0.0);
    if (inClouds > total && inClouds > 0.0) {
        for (std::size_t i = 0; i < blood.count; ++i)
            blood.clouds[i].bloodMl *= total / inClouds;
        inClouds = total;
    }
    blood.mixedFraction = total > 0.0 ? std::clamp(bloodFraction * (total - inClouds) / total, 0.0, 1.0) : 0.0;
}

} // namespace hs::sim::detail
