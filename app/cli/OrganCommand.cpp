// `organ`: a healthy uterus for a patient from the statistical shape model, with its clinical dimensions.
#include "CliCommon.h"
#include "Commands.h"
#include "hs/generate/CaseStages.h"

#include "hs/core/Resources.h"
#include "hs/io/MeshIO.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

namespace hs::cli {
namespace {

struct OrganOptions {
    std::string casePath;
    std::optional<double> ageYears;
    std::optional<int> parity;
    std::optional<int> gravidity;
    std::optional<double> heightCm;
    std::optional<double> weightKg;
    std::string menopausal; ///< "yes" | "no" | "" (default no)
    std::optional<std::uint64_t> seed;
    bool mean = false;
    std::string modelPath;
    std::string output;
    CommonOptions common;
};

nlohmann::ordered_json dimensionsJson(const anatomy::UterusDimensions& d) {
    return {{"lengthMm", d.lengthMm},
            {"corpusLengthMm", d.corpusLengthMm},
            {"cervixLengthMm", d.cervixLengthMm},
            {"widthMm", d.widthMm},
            {"apDepthMm", d.apDepthMm},
            {"cavityLengthMm", d.cavityLengthMm},
            {"cavityWidthMm", d.cavityWidthMm},
            {"cavityAreaCm2", d.cavityAreaCm2},
            {"internalOsWidthMm", d.internalOsWidthMm},
            {"cervixDiameterMm", d.cervixDiameterMm},
            {"fundalWallMm", d.fundalWallMm},
            {"flexionDeg", d.flexionDeg},
            {"ellipsoidVolumeMl", d.ellipsoidVolumeMl},
            {"tissueVolumeMl", d.tissueVolumeMl},
            {"cavityVolumeMl", d.cavityVolumeMl}};
}

void printDimensions(const anatomy::UterusDimensions& d) {
    std::printf("length      %.1f mm (corpus %.1f, cervix %.1f)\n", d.lengthMm, d.corpusLengthMm, d.cervixLengthMm);
    std::printf("width       %.1f mm\n", d.widthMm);
    std::printf("AP depth    %.1f mm\n", d.apDepthMm);
    std::printf("cavity      length %.1f mm, width %.1f mm, area %.2f cm^2, internal os %.1f mm\n", d.cavityLengthMm,
                d.cavityWidthMm, d.cavityAreaCm2, d.internalOsWidthMm);
    std::printf("wall        fundal %.1f mm\n", d.fundalWallMm);
    std::printf("cervix      diameter %.1f mm\n", d.cervixDiameterMm);
    std::printf("flexion     %.1f deg\n", d.flexionDeg);
    std::printf("volume      %.1f mL tissue, %.1f mL cavity, %.1f mL ellipsoid estimate (L x W x AP x 0.523)\n",
                d.tissueVolumeMl, d.cavityVolumeMl, d.ellipsoidVolumeMl);
}

Result<generate::OrganRequest> requestFromOptions(const OrganOptions& o, std::string& modelPath) {
    const bool anyPatientOption =
        o.ageYears || o.parity || o.gravidity || o.heightCm || o.weightKg || !o.menopausal.empty();
    generate::OrganRequest request;
    if (!o.casePath.empty()) {
        if (anyPatientOption)
            return fail(ErrorCode::InvalidInput, "give either --case or the patient options (--age, --parity, "
                                                 "--gravidity, --height, --weight, --menopausal), not both");
        auto spec = scene::loadCase(o.casePath);
        if (!spec)
            return spec.failure();
        auto fromCase = generate::organRequestFor(*spec, o.casePath);
        if (!fromCase)
            return fromCase.failure();
        request = *fromCase;
        if (o.modelPath.empty())
            modelPath = generate::modelPathFor(*spec, o.casePath);
    } else {
        clinical::PatientParams p; // the default patient of a case
        p.ageYears = o.ageYears.value_or(p.ageYears);
        p.parity = o.parity.value_or(p.parity);
        p.gravidity = o.gravidity.value_or(p.parity);
        p.heightCm = o.heightCm.value_or(p.heightCm);
        p.weightKg = o.weightKg.value_or(p.weightKg);
        p.menopausal = o.menopausal == "yes";
        request.patient = p;
    }
    if (o.seed)
        request.seed = *o.seed;
    if (o.mean)
        request.mean = true;
    if (!o.modelPath.empty())
        modelPath = o.modelPath;
    else if (modelPath.empty())
        modelPath = resourcePath("models/uterus-default.h5");
    return request;
}

int runOrgan(const OrganOptions& options) {
    std::string modelPath;
    auto request = requestFromOptions(options, modelPath);
    if (!request)
        return reportError("organ", request.error());
    auto format = io::formatFromPath(options.output);
    if (!format)
        return reportError("organ", format.error());
    if (!io::isSurfaceFormat(*format) && *format != io::MeshFormat::Vtu)
        return reportError("organ", Error{ErrorCode::InvalidInput,
                                          options.output + ": the organ is a surface; use .vtp, .obj, .stl, .ply, "
                                                           ".off or .vtu"});
    auto model = anatomy::loadShapeModel(modelPath);
    if (!model)
        return reportError("organ", model.error());
    auto organ = generate::makeOrgan(*model, *request);
    if (!organ)
        return reportError("organ", organ.error());
    if (auto written = io::writeSurface(organ->mesh, options.output); !written.ok())
        return reportError("organ", written.error());

    const auto& p = request->patient;
    if (options.common.json) {
        nlohmann::ordered_json j;
        j["output"] = options.output;
        j["model"] = modelPath;
        j["patient"] = {{"ageYears", p.ageYears}, {"parity", p.parity},     {"gravidity", p.gravidity},
                        {"heightCm", p.heightCm}, {"weightKg", p.weightKg}, {"menopausal", p.menopausal}};
        j["shape"] = request->mean ? "mean" : "sample";
        j["seed"] = request->seed;
        j["vertices"] = organ->mesh.points.size();
        j["triangles"] = organ->mesh.triangles.size();
        j["dimensions"] = dimensionsJson(organ->dimensions);
        printJson(std::cout, j);
    } else {
        std::printf("wrote       %s (%zu vertices, %zu triangles, face label 'tissue')\n", options.output.c_str(),
                    organ->mesh.points.size(), organ->mesh.triangles.size());
        std::printf("patient     %.0f years, gravida %d para %d, %.0f cm, %.0f kg, %s\n", p.ageYears, p.gravidity,
                    p.parity, p.heightCm, p.weightKg, p.menopausal ? "postmenopausal" : "premenopausal");
        if (request->mean)
            std::printf("shape       expected organ for the patient (model %s)\n", modelPath.c_str());
        else
            std::printf("shape       sample, seed %llu (model %s)\n", static_cast<unsigned long long>(request->seed),
                        modelPath.c_str());
        printDimensions(organ->dimensions);
    }
    return kExitOk;
}

} // namespace

void addOrganCommand(CLI::App& app, int& exitCode) {
    auto o = std::make_shared<OrganOptions>();
    auto* sub = app.add_subcommand("organ", "Make a healthy uterus for a patient from the statistical shape model");
    sub->add_option("--case", o->casePath, "case file: patient, anatomy options and seed");
    sub->add_option("--age", o->ageYears, "age, years");
    sub->add_option("--parity", o->parity, "births");
    sub->add_option("--gravidity", o->gravidity, "pregnancies (>= parity; default: parity)");
    sub->add_option("--height", o->heightCm, "height, cm");
    sub->add_option("--weight", o->weightKg, "weight, kg");
    sub->add_option("--menopausal", o->menopausal, "yes or no (default no)")->check(CLI::IsMember({"yes", "no"}));
    sub->add_option("--seed", o->seed, "seed of the sample (default: the case's, else 1)");
    sub->add_flag("--mean", o->mean, "the expected organ for the patient instead of a seeded sample");
    sub->add_option("--model", o->modelPath, "shape model file (default: the bundled model)");
    sub->add_option("-o,--output", o->output, "output surface (.vtp keeps the tissue labels)")->required();
    sub->add_flag("--json", o->common.json, "print JSON for scripts");
    sub->callback([o, &exitCode] { exitCode = runOrgan(*o); });
}

} // namespace hs::cli
