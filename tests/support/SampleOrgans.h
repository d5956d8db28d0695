#pragma once
/// Seeded organs for the pathology and merge tests and the pathology benchmark: samples of the bundled statistical
/// shape model for a default patient (the generator's default uterus when the model file is missing).

#include "hs/anatomy/PatientParams.h"
#include "hs/anatomy/ShapeModel.h"
#include "hs/anatomy/UterusGenerator.h"
#include "hs/pathology/Pathology.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace hs::test {

inline const anatomy::ShapeModel* defaultShapeModel() {
    static const auto model = []() -> std::optional<anatomy::ShapeModel> {
        if (!std::filesystem::exists(HS_ANATOMY_DEFAULT_MODEL))
            return std::nullopt;
        auto m = anatomy::loadShapeModel(HS_ANATOMY_DEFAULT_MODEL);
        if (!m.ok())
            return std::nullopt;
        return std::move(*m);
    }();
    return model ? &*model : nullptr;
}

/// Organ `seed` (deterministic).
inline SurfaceMesh testOrgan(std::uint64_t seed) {
    if (const auto* model = defaultShapeModel()) {
        clinical::PatientParams patient; // stated in full: the pathology bars were measured on these organs
        patient.ageYears = 35.0;
        patient.parity = 1;
        patient.gravidity = 1;
        patient.heightCm = 164.0;
        patient.weightKg = 65.0;
        auto organ = model->sample(patient, seed);
        if (organ.ok())
            return std::move(*organ);
    }
    return generateUterus(anatomy::UterusShapeParams{}).value().mesh;
}

inline pathology::PathologyRequest myoma(const std::string& id, clinical::GrowthModel model, clinical::FigoType figo,
                                         double sizeMm,
                                         clinical::UterineLocation where = clinical::UterineLocation::Posterior) {
    pathology::PathologyRequest r;
    r.id = id;
    r.kind = clinical::PathologyKind::Myoma;
    r.model = model;
    r.figo = figo;
    r.sizeMm = sizeMm;
    r.placement = clinical::ClinicalPlacement{where};
    return r;
}

inline pathology::PathologyRequest polyp(const std::string& id, clinical::GrowthModel model, double sizeMm,
                                         bool pedunculated, double stalkMm,
                                         clinical::UterineLocation where = clinical::UterineLocation::Fundal) {
    pathology::PathologyRequest r;
    r.id = id;
    r.kind = clinical::PathologyKind::Polyp;
    r.model = model;
    r.sizeMm = sizeMm;
    r.attachment = pedunculated ? clinical::PolypAttachment::Pedunculated : clinical::PolypAttachment::Sessile;
    r.stalkLengthMm = stalkMm;
    r.placement = clinical::ClinicalPlacement{where};
    return r;
}

} // namespace hs::test
