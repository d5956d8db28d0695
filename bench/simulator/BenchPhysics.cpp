// The simulator's physics on a scene package: the simulation mesh's size and quality, the step's cost (the bar:
// >= 100 Hz on 2 cores) and a long scripted trial's stability (no inverted tets, bounded energy). A table, not a test.
//
//   bench_physics PACKAGE [--seconds 60] [--iterations 6] [--trace]
// --trace: a line for every perforation and for every second in which a tet is inverted (the script's time and the
// tip's place), to find which move of the script is at fault.
// PACKAGE: a scene package with a simulation mesh (hysteroscene-cli generate resources/cases/default.json -o DIR).

#include "hs/meshing/QualityReport.h"
#include "hs/sim/World.h"

#include <algorithm>
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

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_physics PACKAGE [--seconds S] [--iterations N]\n");
        return 2;
    }
    const std::string package = argv[1];
    double seconds = 60.0;
    hs::sim::WorldOptions options;
    bool trace = false;
    for (int i = 2; i < argc; ++i) {
        if (std::strcmp(argv[i], "--trace") == 0)
            trace = true;
        else if (std::strcmp(argv[i], "--seconds") == 0 && i + 1 < argc)
            seconds = std::atof(argv[++i]);
        else if (std::strcmp(argv[i], "--iterations") == 0 && i + 1 < argc)
            options.solverIterations = std::atoi(argv[++i]);
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

    // The exploration script, repeated to fill `seconds` of simulated time.
    const hs::sim::Script script = hs::sim::explorationScript(w, 60.0);
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
    std::vector<double> stepMs;
    stepMs.reserve(steps);
    std::size_t maxInverted = 0, perforationsSeen = 0;
    double minRatio = 1e300, maxEnergy = 0.0, maxSpeed = 0.0;
    for (std::uint64_t s = 0; s < steps; ++s) {
        for (std::size_t i = 0; i < per; ++i) {
            const std::uint64_t tick = s * per + i;
            samples[i] = script.sampleAt(tick % scriptTicks);
            samples[i].tick = tick;
        }
        const auto t0 = std::chrono::steady_clock::now();
        if (!w.step(samples.data(), per).ok()) {
            std::fprintf(stderr, "bench_physics: step %llu failed\n", static_cast<unsigned long long>(s));
            return 4;
        }
        stepMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        if (trace && w.metrics().perforations.size() > perforationsSeen) {
            const hs::sim::Perforation& p = w.metrics().perforations.back();
            std::printf("trace: perforation at %.2f s (script %.2f s), %s, at %.1f %.1f %.1f mm\n", p.timeS,
                        std::fmod(p.timeS, 60.0), p.region.c_str(), p.locationMm.x, p.locationMm.y, p.locationMm.z);
            perforationsSeen = w.metrics().perforations.size();
        }
        if (s % 20 == 0 || s + 1 == steps) {
            const hs::sim::World::Health h = w.health();
            if (trace && h.invertedTets > 0) {
                const hs::sim::WorldState& st = w.state();
                std::printf("trace: %.2f s (script %.2f s): %zu inverted, min volume ratio %.3f, force %.2f N, tip "
                            "%.1f %.1f %.1f mm\n",
                            st.timeS, std::fmod(st.timeS, 60.0), h.invertedTets, h.minVolumeRatio, st.contact.forceN,
                            st.scope.tipMm.x, st.scope.tipMm.y, st.scope.tipMm.z);
            }
            maxInverted = std::max(maxInverted, h.invertedTets);
            minRatio = std::min(minRatio, h.minVolumeRatio);
            maxEnergy = std::max(maxEnergy, h.elasticEnergyJ);
            maxSpeed = std::max(maxSpeed, h.maxSpeedMmPerS);
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
    std::printf("| load (read, build, calibrate) | %.2f s |\n", loadS);
    std::printf("| physics step (%d iterations, dt %.0f ms) | mean %.2f ms, p50 %.2f ms, p99 %.2f ms, max %.2f ms |\n",
                options.solverIterations, options.stepS * 1e3, mean, percentile(stepMs, 0.5), percentile(stepMs, 0.99),
                percentile(stepMs, 1.0));
    std::printf("| physics rate | %.0f Hz mean, %.0f Hz at p99 (real time needs %.0f Hz) |\n", 1e3 / mean,
                1e3 / percentile(stepMs, 0.99), 1.0 / options.stepS);
    std::printf("| trial | %.0f s simulated in %.1f s |\n", seconds, total / 1e3);
    std::printf("| stability | inverted tets max %zu, min volume ratio %.3f, elastic energy max %.4f J, "
                "point speed max %.0f mm/s |\n",
                maxInverted, minRatio, maxEnergy, maxSpeed);
    std::printf("| trial metrics | surface %.1f %%, contacts %d, peak force %.2f N, perforations %zu |\n",
                m.cavitySurfaceVisualizedPercent, m.wallContacts, m.peakForceN, m.perforations.size());
    return 0;
}
