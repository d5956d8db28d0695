#include "hs/scene/CaseSpec.h"

#include <tuple>

namespace hs::scene {

namespace {

template <class E>
struct EnumKeys;

template <>
struct EnumKeys<ShapeMode> {
    static constexpr const auto& values = kShapeModes;
    static std::string_view key(ShapeMode v) {
        switch (v) {
        case ShapeMode::Sample:
            return "sample";
        case ShapeMode::Mean:
            return "mean";
        }
        return "";
    }
};

template <>
struct EnumKeys<MeshingMethod> {
    static constexpr const auto& values = kMeshingMethods;
    static std::string_view key(MeshingMethod v) {
        switch (v) {
        case MeshingMethod::Particle:
            return "particle";
        case MeshingMethod::TetGen:
            return "tetgen";
        case MeshingMethod::Cgal:
            return "cgal";
        }
        return "";
    }
};

template <>
struct EnumKeys<MeshingSeeding> {
    static constexpr const auto& values = kMeshingSeedings;
    static std::string_view key(MeshingSeeding v) {
        switch (v) {
        case MeshingSeeding::Lattice:
            return "lattice";
        case MeshingSeeding::Random:
            return "random";
        }
        return "";
    }
};

template <class E>
bool enumFromKey(std::string_view key, E& out) {
    for (const E value : EnumKeys<E>::values) {
        if (EnumKeys<E>::key(value) == key) {
            out = value;
            return true;
        }
    }
    return false;
}

} // namespace

std::string_view toString(ShapeMode value) {
    return EnumKeys<ShapeMode>::key(value);
}
std::string_view toString(MeshingMethod value) {
    return EnumKeys<MeshingMethod>::key(value);
}

bool fromString(std::string_view key, ShapeMode& out) {
    return enumFromKey(key, out);
}
bool fromString(std::string_view key, MeshingMethod& out) {
    return enumFromKey(key, out);
}
std::string_view toString(MeshingSeeding value) {
    return EnumKeys<MeshingSeeding>::key(value);
}
bool fromString(std::string_view key, MeshingSeeding& out) {
    return enumFromKey(key, out);
}

// ---- Equality ----

bool operator==(const UterusDimensions& a, const UterusDimensions& b) {
    return std::tie(a.lengthMm, a.widthMm, a.apMm, a.cavityLengthMm, a.cavityWidthMm, a.cornualAngleDeg,
                    a.fundalWallThicknessMm,
                    a.cervixLengthMm) == std::tie(b.lengthMm, b.widthMm, b.apMm, b.cavityLengthMm, b.cavityWidthMm,
                                                  b.cornualAngleDeg, b.fundalWallThicknessMm, b.cervixLengthMm);
}
bool operator==(const AnatomyParams& a, const AnatomyParams& b) {
    return std::tie(a.shape, a.modelPath, a.versionDeg, a.flexionDeg, a.dimensions, a.endometrialThicknessMm) ==
           std::tie(b.shape, b.modelPath, b.versionDeg, b.flexionDeg, b.dimensions, b.endometrialThicknessMm);
}
bool operator==(const PathologySpec& a, const PathologySpec& b) {
    return std::tie(a.id, a.kind, a.growthModel, a.sizeMm, a.figo, a.attachment, a.stalkLengthMm, a.placement) ==
           std::tie(b.id, b.kind, b.growthModel, b.sizeMm, b.figo, b.attachment, b.stalkLengthMm, b.placement);
}
bool operator==(const MeshingParams& a, const MeshingParams& b) {
    return std::tie(a.method, a.targetEdgeLengthMm, a.targetVertices, a.seeding, a.particlesPerInnerVoxel,
                    a.relaxationIterations, a.threads) == std::tie(b.method, b.targetEdgeLengthMm, b.targetVertices,
                                                                   b.seeding, b.particlesPerInnerVoxel,
                                                                   b.relaxationIterations, b.threads);
}
bool operator==(const TextureExemplars& a, const TextureExemplars& b) {
    return std::tie(a.endometrium, a.myoma, a.polyp, a.cervicalCanal) ==
           std::tie(b.endometrium, b.myoma, b.polyp, b.cervicalCanal);
}
bool operator==(const TextureParams& a, const TextureParams& b) {
    return std::tie(a.sizePx, a.exemplars, a.vesselDensity) == std::tie(b.sizePx, b.exemplars, b.vesselDensity);
}
bool operator==(const MaterialOverride& a, const MaterialOverride& b) {
    return std::tie(a.youngsModulusKpa, a.poissonRatio, a.densityKgPerM3, a.heterogeneity) ==
           std::tie(b.youngsModulusKpa, b.poissonRatio, b.densityKgPerM3, b.heterogeneity);
}
bool operator==(const SceneParams& a, const SceneParams& b) {
    return a.hydrometraPressureKpa == b.hydrometraPressureKpa && a.materials == b.materials;
}
bool operator==(const CaseSpec& a, const CaseSpec& b) {
    return std::tie(a.title, a.seed, a.patient, a.anatomy, a.pathologies, a.meshing, a.texture, a.scene) ==
           std::tie(b.title, b.seed, b.patient, b.anatomy, b.pathologies, b.meshing, b.texture, b.scene);
}
bool operator!=(const CaseSpec& a, const CaseSpec& b) {
    return !(a == b);
}

// ---- Materials (docs/references.md, "Tissue mechanics"; the keys below are its entries) ----

TissueMaterial defaultMaterial(clinical::Tissue tissue) {
    constexpr double kPoisson = 0.47;   // middle of 0.45-0.49 [SoftTissue]
    constexpr double kDensity = 1050.0; // generic soft tissue [SoftTissue]
    switch (tissue) {
    case clinical::Tissue::Myometrium:
        return {30.0, kPoisson, kDensity}; // [Kiss2006]
    case clinical::Tissue::Endometrium:
        return {26.2, kPoisson, kDensity}; // [Du2021], proliferative phase
    case clinical::Tissue::Cervix:
        return {30.0, kPoisson, kDensity}; // the myometrium's: cervical tissue spans the same 30-90 kPa [Kiss2006]
    case clinical::Tissue::Myoma:
        return {65.0, kPoisson, kDensity}; // [Omari2015]
    case clinical::Tissue::Polyp:
        return {15.0, kPoisson, kDensity}; // [Du2021]
    }
    return {30.0, kPoisson, kDensity};
}

Range youngsModulusRangeKpa(clinical::Tissue tissue) {
    switch (tissue) {
    case clinical::Tissue::Myometrium:
    case clinical::Tissue::Cervix:
        return {6.0, 90.0}; // [Stader2024], [Kiss2006]
    case clinical::Tissue::Endometrium:
        return {12.5, 26.2}; // [Du2021]
    case clinical::Tissue::Myoma:
        return {13.0, 206.0}; // 2.17 x 6 .. 2.29 x 90 [Omari2015]
    case clinical::Tissue::Polyp:
        return {1.0, 32.0}; // 15.7 + 2 x 8.2 [Du2021], floored at 1 kPa
    }
    return {6.0, 90.0};
}

TissueMaterial effectiveMaterial(const SceneParams& scene, clinical::Tissue tissue) {
    TissueMaterial m = defaultMaterial(tissue);
    const MaterialOverride& o = scene.materials[static_cast<std::size_t>(tissue)];
    m.youngsModulusKpa = o.youngsModulusKpa.value_or(m.youngsModulusKpa);
    m.poissonRatio = o.poissonRatio.value_or(m.poissonRatio);
    m.densityKgPerM3 = o.densityKgPerM3.value_or(m.densityKgPerM3);
    return m;
}

// ---- The bundled default (must equal resources/cases/default.json; a test checks it) ----

CaseSpec defaultCase() {
    CaseSpec spec;
    spec.title = "Default: 35-year-old primipara, FIGO 2 left lateral myoma, sessile right cornual polyp";
    spec.seed = 1;

    PathologySpec myoma;
    myoma.id = "myoma-1";
    myoma.kind = clinical::PathologyKind::Myoma;
    myoma.growthModel = clinical::GrowthModel::Skeleton;
    myoma.sizeMm = 20.0; // Lasmar size class <= 2 cm [Lasmar2005]; resectable type [Munro2011]
    myoma.figo = clinical::FigoType{2, -1};
    myoma.placement =
        clinical::ClinicalPlacement{clinical::UterineLocation::LeftLateral}; // lateral wall: +1 in the Lasmar score
    spec.pathologies.push_back(myoma);

    PathologySpec polyp;
    polyp.id = "polyp-1";
    polyp.kind = clinical::PathologyKind::Polyp;
    polyp.growthModel = clinical::GrowthModel::Skeleton; // a stalk is a skeleton with revolved contours [Sierra2004]
    polyp.sizeMm = 10.0;                                 // within the usual 5-30 mm [PolypSize]
    polyp.attachment = clinical::PolypAttachment::Sessile;
    polyp.placement =
        clinical::ClinicalPlacement{clinical::UterineLocation::CornualRight}; // cornual is common [PolypSize]
    spec.pathologies.push_back(polyp);
    return spec;
}

} // namespace hs::scene
