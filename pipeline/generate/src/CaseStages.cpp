#include "hs/generate/CaseStages.h"

#include "hs/core/Resources.h"
#include "hs/generate/Seeds.h"

#include <filesystem>

namespace hs::generate {
namespace {

pathology::Location locationOf(scene::UterineLocation l) {
    switch (l) {
    case scene::UterineLocation::Fundal:
        return pathology::Location::Fundal;
    case scene::UterineLocation::Anterior:
        return pathology::Location::Anterior;
    case scene::UterineLocation::Posterior:
        return pathology::Location::Posterior;
    case scene::UterineLocation::LeftLateral:
        return pathology::Location::LeftLateral;
    case scene::UterineLocation::RightLateral:
        return pathology::Location::RightLateral;
    case scene::UterineLocation::CornualLeft:
        return pathology::Location::CornualLeft;
    case scene::UterineLocation::CornualRight:
        return pathology::Location::CornualRight;
    case scene::UterineLocation::Isthmic:
        return pathology::Location::Isthmic;
    case scene::UterineLocation::Cervical:
        return pathology::Location::Cervical;
    }
    return pathology::Location::Fundal;
}

pathology::GrowthModel modelOf(scene::GrowthModel m) {
    switch (m) {
    case scene::GrowthModel::CellularAutomaton:
        return pathology::GrowthModel::CellularAutomaton;
    case scene::GrowthModel::Skeleton:
        return pathology::GrowthModel::Skeleton;
    case scene::GrowthModel::Particles:
        return pathology::GrowthModel::Particles;
    }
    return pathology::GrowthModel::Skeleton;
}

} // namespace

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
    if (d.cornualAngleDeg)
        return fail(ErrorCode::Unsupported, caseFile +
                                                ": /anatomy/dimensions/cornualAngleDeg: the shape model does not "
                                                "measure the cornual angle yet: remove the field");
    OrganRequest request;
    request.patient = patientOf(spec);
    request.seed = organSeed(spec.seed);
    request.mean = spec.anatomy.shape == scene::ShapeMode::Mean;
    request.versionDeg = spec.anatomy.versionDeg;
    request.dimensions.lengthMm = d.lengthMm;
    request.dimensions.widthMm = d.widthMm;
    request.dimensions.apDepthMm = d.apMm;
    request.dimensions.cavityLengthMm = d.cavityLengthMm;
    request.dimensions.cavityWidthMm = d.cavityWidthMm;
    request.dimensions.fundalWallMm = d.fundalWallThicknessMm;
    request.dimensions.cervixLengthMm = d.cervixLengthMm;
    request.dimensions.flexionDeg = spec.anatomy.flexionDeg;
    return request;
}

Result<OrganInstance> makeOrgan(const anatomy::ShapeModel& model, const OrganRequest& request) {
    if (!model.layout())
        return fail(ErrorCode::Unsupported, "the shape model has no uterus template layout: organ dimensions cannot "
                                            "be measured (build it from uterus-template instances)");
    auto mesh = request.dimensions.any()
                    ? model.withDimensions(request.patient, request.dimensions,
                                           request.mean ? std::nullopt : std::optional<std::uint64_t>(request.seed),
                                           request.versionDeg)
                : request.mean ? model.mean(request.patient, request.versionDeg)
                               : model.sample(request.patient, request.seed, request.versionDeg);
    if (!mesh)
        return mesh.failure();
    auto dims = anatomy::measureUterus(*mesh, *model.layout());
    if (!dims)
        return dims.failure();
    return OrganInstance{std::move(mesh).value(), *dims};
}

pathology::PathologyParams pathologyParamsFor(const scene::CaseSpec& spec,
                                              const std::optional<scene::GrowthModel>& override) {
    pathology::PathologyParams params;
    params.seed = streamSeed(spec.seed, Stream::Pathology);
    for (const auto& p : spec.pathologies) {
        pathology::PathologyRequest r;
        r.id = p.id;
        r.kind = p.kind == scene::PathologyKind::Myoma ? pathology::Kind::Myoma : pathology::Kind::Polyp;
        r.model = modelOf(override ? *override : p.growthModel);
        r.sizeMm = p.sizeMm;
        if (p.figo)
            r.figo = pathology::Figo{p.figo->type, p.figo->serosal};
        if (p.attachment)
            r.attachment = *p.attachment == scene::PolypAttachment::Sessile ? pathology::Attachment::Sessile
                                                                            : pathology::Attachment::Pedunculated;
        r.stalkLengthMm = p.stalkLengthMm.value_or(0.0);
        if (const auto* c = std::get_if<scene::ClinicalPlacement>(&p.placement))
            r.placement = pathology::ClinicalPlacement{locationOf(c->location)};
        else {
            const auto& s = std::get<scene::SurfacePlacement>(p.placement);
            r.placement = pathology::SurfacePlacement{s.pointMm, s.normal};
        }
        params.pathologies.push_back(r);
    }
    return params;
}

meshing::MeshMethod meshMethodFor(const scene::CaseSpec& spec) {
    switch (spec.meshing.method) {
    case scene::MeshingMethod::Particle:
        return meshing::MeshMethod::Particle;
    case scene::MeshingMethod::TetGen:
        return meshing::MeshMethod::TetGen;
    case scene::MeshingMethod::Cgal:
        return meshing::MeshMethod::Cgal;
    }
    return meshing::MeshMethod::Particle;
}

meshing::MeshParams meshParamsFor(const scene::CaseSpec& spec, std::optional<int> threads) {
    meshing::MeshParams p;
    p.targetEdgeLength = spec.meshing.targetEdgeLengthMm.value_or(0.0);
    p.targetVertices = spec.meshing.targetVertices.value_or(0);
    p.seed = streamSeed(spec.seed, Stream::Meshing);
    p.threads = threads.value_or(spec.meshing.threads);
    p.particlesPerVoxel = spec.meshing.particlesPerInnerVoxel;
    p.relaxationIterations = spec.meshing.relaxationIterations;
    return p;
}

texture::BakeParams bakeParamsFor(const scene::CaseSpec& spec, std::optional<int> threads) {
    texture::BakeParams p;
    p.size = spec.texture.sizePx;
    p.seed = streamSeed(spec.seed, Stream::Texture);
    p.threads = threads.value_or(spec.meshing.threads);
    p.labels.appearanceLabel = kAppearanceLabel;
    p.labels.myomaValues = {1};
    p.labels.polypValues = {2};
    p.exemplarFiles[static_cast<std::size_t>(texture::Appearance::Endometrium)] =
        spec.texture.exemplars.endometrium.value_or("");
    p.exemplarFiles[static_cast<std::size_t>(texture::Appearance::Myoma)] = spec.texture.exemplars.myoma.value_or("");
    p.exemplarFiles[static_cast<std::size_t>(texture::Appearance::Polyp)] = spec.texture.exemplars.polyp.value_or("");
    p.vessels = spec.texture.vesselDensity > 0.0;
    for (auto& c : p.vesselParams.perClass)
        c.attractorsPerMm2 *= spec.texture.vesselDensity;
    return p;
}

} // namespace hs::generate
