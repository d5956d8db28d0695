#include "CaseStages.h"

#include "hs/core/Resources.h"

#include <filesystem>

namespace hs::cli {

anatomy::PatientParams patientOf(const scene::CaseSpec& spec) {
    anatomy::PatientParams p;
    p.ageYears = spec.patient.ageYears;
    p.parity = spec.patient.parity;
    p.gravidity = spec.patient.gravidity;
    p.heightCm = spec.patient.heightCm;
    p.weightKg = spec.patient.weightKg;
    p.menopausal = spec.patient.menopausal;
    return p;
}

std::string modelPathFor(const scene::CaseSpec& spec, const std::string& caseFile) {
    if (!spec.anatomy.modelPath)
        return resourcePath("models/uterus-default.h5");
    const std::filesystem::path model(*spec.anatomy.modelPath);
    if (model.is_absolute() || caseFile.empty())
        return model.string();
    return (std::filesystem::path(caseFile).parent_path() / model).string();
}

Result<OrganRequest> organRequestFor(const scene::CaseSpec& spec, const std::string& caseFile) {
    const auto& d = spec.anatomy.dimensions;
    const std::pair<const char*, bool> unsupported[] = {
        {"/anatomy/flexionDeg", spec.anatomy.flexionDeg.has_value()},
        {"/anatomy/dimensions/lengthMm", d.lengthMm.has_value()},
        {"/anatomy/dimensions/widthMm", d.widthMm.has_value()},
        {"/anatomy/dimensions/apMm", d.apMm.has_value()},
        {"/anatomy/dimensions/cavityLengthMm", d.cavityLengthMm.has_value()},
        {"/anatomy/dimensions/cavityWidthMm", d.cavityWidthMm.has_value()},
        {"/anatomy/dimensions/cornualAngleDeg", d.cornualAngleDeg.has_value()},
        {"/anatomy/dimensions/fundalWallThicknessMm", d.fundalWallThicknessMm.has_value()},
        {"/anatomy/dimensions/cervixLengthMm", d.cervixLengthMm.has_value()},
    };
    for (const auto& [path, set] : unsupported)
        if (set)
            return fail(ErrorCode::Unsupported,
                        caseFile + ": " + path +
                            ": the shape model conditions on the patient parameters only; conditioning on measured "
                            "dimensions and flexion is not available yet: remove the field");
    OrganRequest request;
    request.patient = patientOf(spec);
    request.seed = spec.seed;
    request.mean = spec.anatomy.shape == scene::ShapeMode::Mean;
    request.versionDeg = spec.anatomy.versionDeg;
    return request;
}

Result<OrganInstance> makeOrgan(const anatomy::ShapeModel& model, const OrganRequest& request) {
    if (!model.layout())
        return fail(ErrorCode::Unsupported, "the shape model has no uterus template layout: organ dimensions cannot "
                                            "be measured (build it from uterus-template instances)");
    auto mesh = request.mean ? model.mean(request.patient, request.versionDeg)
                             : model.sample(request.patient, request.seed, request.versionDeg);
    if (!mesh)
        return mesh.failure();
    auto dims = anatomy::measureUterus(*mesh, *model.layout());
    if (!dims)
        return dims.failure();
    return OrganInstance{std::move(mesh).value(), *dims};
}

} // namespace hs::cli
