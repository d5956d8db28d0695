// `model build|info|sample|evaluate`: statistical shape models, the bundled one or one built from the user's data.
#include "CliCommon.h"
#include "Commands.h"

#include "hs/anatomy/Cohort.h"
#include "hs/anatomy/ModelEvaluation.h"
#include "hs/anatomy/ShapeModel.h"
#include "hs/anatomy/TrainingData.h"
#include "hs/core/Resources.h"
#include "hs/io/MeshIO.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

namespace hs::cli {
namespace {

/// The synthetic cohort the bundled model is built from (docs/anatomy.md).
constexpr int kDefaultCohortSize = 400;
constexpr std::uint64_t kDefaultCohortSeed = 20040101;

struct TrainingOptions {
    std::string meshDir;
    std::string paramsCsv;
    int cohortSize = kDefaultCohortSize;
    std::uint64_t cohortSeed = kDefaultCohortSeed;
};

struct ModelOptions {
    TrainingOptions training;
    std::string modelPath;
    std::string output;
    double explainedVariance = 0.995;
    int maxModes = 40;
    std::uint64_t seed = 1;
    int mode = 0;    ///< 1-based mode for `sample --mode`
    double sd = 0.0; ///< standard deviations along that mode
    int folds = 0;   ///< leave-one-out folds, 0: all
    int specificitySamples = 1000;
    CommonOptions common;
};

bool fromFiles(const TrainingOptions& t) {
    return !t.meshDir.empty() || !t.paramsCsv.empty();
}

Result<anatomy::TrainingSet> loadTraining(const TrainingOptions& t) {
    if (fromFiles(t)) {
        if (t.meshDir.empty() || t.paramsCsv.empty())
            return fail(ErrorCode::InvalidInput, "--meshes and --params go together");
        return anatomy::loadTrainingSet(t.meshDir, t.paramsCsv);
    }
    anatomy::CohortParams params;
    params.size = t.cohortSize;
    params.seed = t.cohortSeed;
    auto cohort = anatomy::generateCohort(params);
    if (!cohort)
        return cohort.failure();
    return std::move(cohort->training);
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int runBuild(const ModelOptions& o) {
    const auto start = std::chrono::steady_clock::now();
    auto training = loadTraining(o.training);
    if (!training)
        return reportError("model build", training.error());
    const double loadSeconds = secondsSince(start);
    anatomy::ShapeModelParams params;
    params.explainedVariance = o.explainedVariance;
    params.maxModes = o.maxModes;
    if (fromFiles(o.training)) {
        params.description = "uterus shape model built from " + o.training.paramsCsv;
    } else {
        params.description = "hysteroscene default uterus model: synthetic cohort of " +
                             std::to_string(o.training.cohortSize) + ", seed " + std::to_string(o.training.cohortSeed);
        params.cohortSeed = o.training.cohortSeed;
    }
    auto built = anatomy::buildShapeModel(*training, params);
    if (!built)
        return reportError("model build", built.error());
    if (auto saved = anatomy::saveShapeModel(built->model, o.output); !saved.ok())
        return reportError("model build", saved.error());
    const double total = secondsSince(start);
    if (o.common.json) {
        nlohmann::ordered_json j;
        j["output"] = o.output;
        j["trainingShapes"] = training->shapes.size();
        j["modes"] = built->model.modeCount();
        j["seconds"] = total;
        auto steps = nlohmann::ordered_json::array();
        steps.push_back({{"name", "training"}, {"seconds", loadSeconds}});
        for (const auto& s : built->timings.steps)
            steps.push_back({{"name", s.name}, {"seconds", s.seconds}});
        j["steps"] = steps;
        j["warnings"] = built->warnings;
        printJson(std::cout, j);
    } else {
        std::printf("training    %zu shapes of %zu vertices (%s), %.3f s\n", training->shapes.size(),
                    training->reference.points.size(), fromFiles(o.training) ? "files" : "synthetic cohort",
                    loadSeconds);
        for (const auto& s : built->timings.steps)
            std::printf("%-11s %.3f s\n", s.name.c_str(), s.seconds);
        std::printf("model       %d modes, Procrustes %d iterations\n", built->model.modeCount(),
                    built->procrustesIterations);
        for (const auto& w : built->warnings)
            std::printf("warning     %s\n", w.c_str());
        std::printf("wrote       %s in %.3f s\n", o.output.c_str(), total);
    }
    return kExitOk;
}

int runInfo(const ModelOptions& o) {
    auto model = anatomy::loadShapeModel(o.modelPath);
    if (!model)
        return reportError("model info", model.error());
    const auto variances = model->variances();
    const double total = model->totalVariance();
    if (o.common.json) {
        nlohmann::ordered_json j;
        j["file"] = o.modelPath;
        j["points"] = model->pointCount();
        j["triangles"] = model->reference().triangles.size();
        j["modes"] = model->modeCount();
        j["trainingShapes"] = model->trainingSize();
        j["totalVarianceMm2"] = total;
        j["noiseVarianceMm2"] = model->noiseVariance();
        j["modeVariancesMm2"] = variances;
        j["uterusTemplate"] = model->layout().has_value();
        j["conditioningFeatures"] = anatomy::conditioningFeatureNames();
        printJson(std::cout, j);
        return kExitOk;
    }
    std::printf("file        %s\n", o.modelPath.c_str());
    std::printf("points      %zu, triangles %zu%s\n", model->pointCount(), model->reference().triangles.size(),
                model->layout() ? " (uterus template)" : "");
    std::printf("training    %d shapes, total variance %.2f mm^2, noise %.4f mm^2 per coordinate\n",
                model->trainingSize(), total, model->noiseVariance());
    std::printf("modes       %d\n", model->modeCount());
    double cumulative = 0.0;
    for (std::size_t i = 0; i < variances.size(); ++i) {
        cumulative += variances[i];
        std::printf("  mode %2zu   variance %9.3f mm^2   sd %6.3f mm   cumulative %6.2f %%\n", i + 1, variances[i],
                    std::sqrt(variances[i]), total > 0 ? 100.0 * cumulative / total : 0.0);
    }
    std::printf("conditioned on:");
    for (const auto& name : anatomy::conditioningFeatureNames())
        std::printf(" %s", name.c_str());
    std::printf("\n");
    return kExitOk;
}

int runSample(const ModelOptions& o) {
    auto model = anatomy::loadShapeModel(o.modelPath);
    if (!model)
        return reportError("model sample", model.error());
    SurfaceMesh mesh;
    std::string what;
    if (o.mode > 0) {
        if (o.mode > model->modeCount())
            return reportError("model sample",
                               Error{ErrorCode::InvalidInput, "--mode " + std::to_string(o.mode) + " outside 1.." +
                                                                  std::to_string(model->modeCount())});
        std::vector<double> coefficients(static_cast<std::size_t>(model->modeCount()), 0.0);
        coefficients[static_cast<std::size_t>(o.mode - 1)] = o.sd;
        auto instance = model->instance(coefficients);
        if (!instance)
            return reportError("model sample", instance.error());
        mesh = model->pose(std::move(instance).value(), 0.0);
        char buffer[96];
        std::snprintf(buffer, sizeof buffer, "population mean %+.1f SD along mode %d", o.sd, o.mode);
        what = buffer;
    } else {
        mesh = model->pose(model->sampleUnconditional(o.seed), 0.0);
        what = "unconditional sample, seed " + std::to_string(o.seed);
    }
    if (auto written = io::writeSurface(mesh, o.output); !written.ok())
        return reportError("model sample", written.error());
    if (o.common.json) {
        printJson(std::cout, {{"output", o.output}, {"shape", what}, {"vertices", mesh.points.size()}});
    } else {
        std::printf("wrote       %s (%s)\n", o.output.c_str(), what.c_str());
    }
    return kExitOk;
}

int runEvaluate(const ModelOptions& o) {
    auto model = anatomy::loadShapeModel(o.modelPath);
    if (!model)
        return reportError("model evaluate", model.error());
    auto training = loadTraining(o.training);
    if (!training)
        return reportError("model evaluate", training.error());
    anatomy::ModelEvaluationParams params;
    params.generalizationFolds = o.folds;
    params.specificitySamples = o.specificitySamples;
    params.seed = o.seed;
    auto ev = anatomy::evaluateShapeModel(*model, *training, params);
    if (!ev)
        return reportError("model evaluate", ev.error());
    if (o.common.json) {
        nlohmann::ordered_json j;
        j["file"] = o.modelPath;
        j["compactness"] = {{"modeVarianceMm2", ev->modeVariance}, {"cumulativeExplained", ev->cumulativeExplained}};
        j["generalization"] = {
            {"meanMm", ev->generalizationMm}, {"sdMm", ev->generalizationSdMm}, {"folds", ev->folds}};
        j["specificity"] = {
            {"meanMm", ev->specificityMm}, {"sdMm", ev->specificitySdMm}, {"samples", ev->specificitySamples}};
        auto cond = nlohmann::ordered_json::array();
        for (const auto& c : ev->conditioning)
            cond.push_back({{"dimension", c.dimension},
                            {"meanAbsMm", c.meanAbsMm},
                            {"biasMm", c.biasMm},
                            {"maxAbsMm", c.maxAbsMm}});
        j["conditioning"] = cond;
        printJson(std::cout, j);
        return kExitOk;
    }
    std::printf("model           %s (%d modes, %d training shapes)\n", o.modelPath.c_str(), model->modeCount(),
                model->trainingSize());
    std::printf("compactness     mode  variance [mm^2]  cumulative\n");
    for (std::size_t i = 0; i < ev->modeVariance.size(); ++i)
        std::printf("                %4zu  %15.3f  %9.2f %%\n", i + 1, ev->modeVariance[i],
                    100.0 * ev->cumulativeExplained[i]);
    std::printf("generalisation  %.3f +- %.3f mm (leave-one-out, %d folds)\n", ev->generalizationMm,
                ev->generalizationSdMm, ev->folds);
    std::printf("specificity     %.3f +- %.3f mm (%d samples to the nearest training shape)\n", ev->specificityMm,
                ev->specificitySdMm, ev->specificitySamples);
    if (!ev->conditioning.empty()) {
        std::printf("conditioning    dimension            mean |err| [mm]  bias [mm]  max |err| [mm]\n");
        for (const auto& c : ev->conditioning)
            std::printf("                %-20s %15.2f %10.2f %15.2f\n", c.dimension.c_str(), c.meanAbsMm, c.biasMm,
                        c.maxAbsMm);
    }
    return kExitOk;
}

void addTrainingOptions(CLI::App* sub, TrainingOptions& t) {
    sub->add_option("--meshes", t.meshDir, "folder of training meshes in correspondence");
    sub->add_option("--params", t.paramsCsv,
                    "CSV: file,ageYears,parity,gravidity,heightCm,weightKg,menopausal (one row per mesh)");
    sub->add_option("--cohort-size", t.cohortSize, "without --meshes: size of the synthetic cohort")
        ->check(CLI::Range(10, 100000));
    sub->add_option("--cohort-seed", t.cohortSeed, "without --meshes: seed of the synthetic cohort");
}

} // namespace

void addModelCommand(CLI::App& app, int& exitCode) {
    auto o = std::make_shared<ModelOptions>();
    auto* model = app.add_subcommand("model", "Statistical shape models: build, info, sample, evaluate");
    model->require_subcommand(1);

    auto* build = model->add_subcommand(
        "build", "Build a model from meshes in correspondence (--meshes, --params) or from the synthetic cohort");
    addTrainingOptions(build, o->training);
    build->add_option("-o,--output", o->output, "model file (HDF5, statismo layout)")->required();
    build->add_option("--explained", o->explainedVariance, "fraction of the variance the kept modes explain")
        ->check(CLI::Range(0.5, 1.0));
    build->add_option("--max-modes", o->maxModes, "upper bound on kept modes")->check(CLI::Range(1, 1000));
    build->add_flag("--json", o->common.json, "print JSON for scripts");
    build->callback([o, &exitCode] { exitCode = runBuild(*o); });

    auto* info = model->add_subcommand("info", "Modes, variances and conditioning of a model file");
    info->add_option("MODEL", o->modelPath, "model file")->required();
    info->add_flag("--json", o->common.json, "print JSON for scripts");
    info->callback([o, &exitCode] { exitCode = runInfo(*o); });

    auto* sample = model->add_subcommand("sample", "Write an unconditional sample, or the mean moved along one mode");
    sample->add_option("MODEL", o->modelPath, "model file")->required();
    sample->add_option("-o,--output", o->output, "output surface")->required();
    sample->add_option("--seed", o->seed, "seed of the sample");
    sample->add_option("--mode", o->mode, "1-based mode to move along (with --sd)")->check(CLI::Range(1, 1000));
    sample->add_option("--sd", o->sd, "standard deviations along --mode")->check(CLI::Range(-5.0, 5.0));
    sample->add_flag("--json", o->common.json, "print JSON for scripts");
    sample->callback([o, &exitCode] { exitCode = runSample(*o); });

    auto* evaluate = model->add_subcommand(
        "evaluate", "Compactness, generalisation, specificity and conditioning error against the training set");
    evaluate->add_option("MODEL", o->modelPath, "model file")->required();
    addTrainingOptions(evaluate, o->training);
    evaluate->add_option("--folds", o->folds, "leave-one-out folds (0: every shape)")->check(CLI::Range(0, 100000));
    evaluate->add_option("--samples", o->specificitySamples, "samples for specificity")->check(CLI::Range(1, 100000));
    evaluate->add_option("--seed", o->seed, "seed of the specificity samples");
    evaluate->add_flag("--json", o->common.json, "print JSON for scripts");
    evaluate->callback([o, &exitCode] { exitCode = runEvaluate(*o); });
}

} // namespace hs::cli
