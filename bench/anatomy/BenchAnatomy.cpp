// bench_anatomy: timings and bars of the anatomy module, and the command that builds the default model.
//   bench_anatomy build-default OUT.h5      cohort (400, seed 20040101) -> model -> OUT.h5, with timings
//   bench_anatomy bench MODEL.h5 [N]        sampling time and N (1000) organ checks over the supported range
//   bench_anatomy evaluate MODEL.h5 [FOLDS] compactness, generalisation, specificity (1000), conditioning error
#include "hs/anatomy/Cohort.h"
#include "hs/anatomy/ModelEvaluation.h"
#include "hs/anatomy/OrganChecks.h"
#include "hs/anatomy/ShapeModel.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace {

using namespace hs::anatomy;
using Clock = std::chrono::steady_clock;

constexpr int kCohortSize = 400;
constexpr std::uint64_t kCohortSeed = 20040101;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

int report(const hs::Error& e) {
    std::cerr << "bench_anatomy: " << e.message() << "\n";
    return 1;
}

hs::Result<CohortResult> defaultCohort() {
    CohortParams params;
    params.size = kCohortSize;
    params.seed = kCohortSeed;
    return generateCohort(params);
}

int buildDefault(const std::string& out) {
    const auto start = Clock::now();
    auto cohort = defaultCohort();
    if (!cohort)
        return report(cohort.error());
    const double cohortSeconds = secondsSince(start);
    ShapeModelParams params;
    params.description = "hysteroscene default uterus model: synthetic cohort of 400, seed 20040101";
    params.cohortSeed = kCohortSeed;
    auto built = buildShapeModel(cohort->training, params);
    if (!built)
        return report(built.error());
    const double total = secondsSince(start);
    if (auto saved = saveShapeModel(built->model, out); !saved)
        return report(saved.error());
    std::printf("cohort            %8.3f s  (%d members)\n", cohortSeconds, kCohortSize);
    for (const auto& s : built->timings.steps)
        std::printf("model.%-12s %8.3f s\n", s.name.c_str(), s.seconds);
    std::printf("build total       %8.3f s  (bar: <= 60 s)\n", total);
    std::printf("modes %d, procrustes iterations %d\n", built->model.modeCount(), built->procrustesIterations);
    for (const auto& w : cohort->warnings)
        std::printf("warning: %s\n", w.c_str());
    for (const auto& w : built->warnings)
        std::printf("warning: %s\n", w.c_str());
    std::printf("wrote %s\n", out.c_str());
    return 0;
}

int bench(const std::string& path, int count) {
    auto model = loadShapeModel(path);
    if (!model)
        return report(model.error());
    hs::Rng rng(99);
    double worstSample = 0.0, sumSample = 0.0, worstWall = 1e9;
    int valid = 0, watertight = 0, intersecting = 0, outside = 0;
    for (int i = 0; i < count; ++i) {
        const hs::clinical::PatientParams patient = sampleSupportedPatient(rng);
        const auto start = Clock::now();
        auto organ = model->sample(patient, static_cast<std::uint64_t>(i));
        const double dt = secondsSince(start);
        if (!organ)
            return report(organ.error());
        worstSample = std::max(worstSample, dt);
        sumSample += dt;
        auto check = checkOrgan(*organ, *model->layout());
        if (!check)
            return report(check.error());
        valid += check->valid() ? 1 : 0;
        watertight += check->topology.isWatertight() ? 1 : 0;
        intersecting += check->selfIntersecting ? 1 : 0;
        outside += check->cavityInside ? 0 : 1;
        worstWall = std::min(worstWall, check->minWallMm);
    }
    std::printf("sampling: mean %.3f ms, max %.3f ms per organ (bar: <= 50 ms)\n", 1e3 * sumSample / count,
                1e3 * worstSample);
    std::printf("%d samples over the supported range: %d valid, %d watertight, %d self-intersecting, %d with cavity "
                "outside, minimum wall %.2f mm (bar: >= 5 mm)\n",
                count, valid, watertight, intersecting, outside, worstWall);
    return valid == count ? 0 : 2;
}

int evaluate(const std::string& path, int folds) {
    auto model = loadShapeModel(path);
    if (!model)
        return report(model.error());
    auto cohort = defaultCohort();
    if (!cohort)
        return report(cohort.error());
    ModelEvaluationParams params;
    params.generalizationFolds = folds;
    auto ev = evaluateShapeModel(*model, cohort->training, params);
    if (!ev)
        return report(ev.error());
    std::printf("modes %d (training shapes %d)\n", model->modeCount(), model->trainingSize());
    std::printf("compactness: mode  variance[mm^2]  cumulative\n");
    for (std::size_t i = 0; i < ev->modeVariance.size(); ++i)
        if (i < 10 || i + 1 == ev->modeVariance.size())
            std::printf("             %4zu  %14.3f  %9.4f\n", i + 1, ev->modeVariance[i], ev->cumulativeExplained[i]);
    std::printf("generalisation (leave-one-out, %d folds): %.3f +- %.3f mm\n", ev->folds, ev->generalizationMm,
                ev->generalizationSdMm);
    std::printf("specificity (%d samples): %.3f +- %.3f mm\n", ev->specificitySamples, ev->specificityMm,
                ev->specificitySdMm);
    std::printf("conditioning error of mean(patient) vs the relations (%d patients):\n", params.conditioningPatients);
    for (const auto& c : ev->conditioning)
        std::printf("  %-16s mean |e| %6.3f mm  bias %+6.3f mm  max %6.3f mm\n", c.dimension.c_str(), c.meanAbsMm,
                    c.biasMm, c.maxAbsMm);
    for (const auto& s : ev->timings.steps)
        std::printf("time %-15s %8.3f s\n", s.name.c_str(), s.seconds);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "build-default" && argc == 3)
        return buildDefault(argv[2]);
    if (mode == "bench" && argc >= 3)
        return bench(argv[2], argc > 3 ? std::atoi(argv[3]) : 1000);
    if (mode == "evaluate" && argc >= 3)
        return evaluate(argv[2], argc > 3 ? std::atoi(argv[3]) : 0);
    std::cerr << "usage: bench_anatomy build-default OUT.h5 | bench MODEL.h5 [N] | evaluate MODEL.h5 [FOLDS]\n";
    return 1;
}
