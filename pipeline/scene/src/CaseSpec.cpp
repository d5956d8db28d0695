#include "hs/scene/CaseSpec.h"

#include <tuple>

namespace hs::scene {

namespace {

template <class E>
struct EnumKeys;

template <>
struct EnumKeys<PathologyKind> {
    static constexpr const auto& values = kPathologyKinds;
    static std::string_view key(PathologyKind v) {
        switch (v) {
        case PathologyKind::Myoma:
            return "myoma";
        case PathologyKind::Polyp:
            return "polyp";
        }
        return "";
    }
};

template <>
struct EnumKeys<GrowthModel> {
    static constexpr const auto& values = kGrowthModels;
    static std::string_view key(GrowthModel v) {
        switch (v) {
        case GrowthModel::CellularAutomaton:
            return "ca";
        case GrowthModel::Skeleton:
            return "skeleton";
        case GrowthModel::Particles:
            return "particles";
        }
        return "";
    }
};

template <>
struct EnumKeys<UterineLocation> {
    static constexpr const auto& values = kUterineLocations;
    static std::string_view key(UterineLocation v) {
        switch (v) {
        case UterineLocation::Fundal:
            return "fundal";
        case UterineLocation::Anterior:
            return "anterior";
        case UterineLocation::Posterior:
            return "posterior";
        case UterineLocation::LeftLateral:
            return "left-lateral";
        case UterineLocation::RightLateral:
            return "right-lateral";
        case UterineLocation::CornualLeft:
            return "cornual-left";
        case UterineLocation::CornualRight:
            return "cornual-right";
        case UterineLocation::Isthmic:
            return "isthmic";
        case UterineLocation::Cervical:
            return "cervical";
        }
        return "";
    }
};

template <>
struct EnumKeys<PolypAttachment> {
    static constexpr const auto& values = kPolypAttachments;
    static std::string_view key(PolypAttachment v) {
        switch (v) {
        case PolypAttachment::Sessile:
            return "sessile";
        case PolypAttachment::Pedunculated:
            return "pedunculated";
        }
        return "";
    }
};

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
struct EnumKeys<Tissue> {
    static constexpr const auto& values = kTissues;
    static std::string_view key(Tissue v) {
        switch (v) {
        case Tissue::Myometrium:
            return "myometrium";
        case Tissue::Endometrium:
            return "endometrium";
        case Tissue::Cervix:
            return "cervix";
        case Tissue::Myoma:
            return "myoma";
        case Tissue::Polyp:
            return "polyp";
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

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

} // namespace

std::string_view toString(PathologyKind value) {
    return EnumKeys<PathologyKind>::key(value);
}
std::string_view toString(GrowthModel value) {
    return EnumKeys<GrowthModel>::key(value);
}
std::string_view toString(UterineLocation value) {
    return EnumKeys<UterineLocation>::key(value);
}
std::string_view toString(PolypAttachment value) {
    return EnumKeys<PolypAttachment>::key(value);
}
std::string_view toString(ShapeMode value) {
    return EnumKeys<ShapeMode>::key(value);
}
std::string_view toString(MeshingMethod value) {
    return EnumKeys<MeshingMethod>::key(value);
}
std::string_view toString(Tissue value) {
    return EnumKeys<Tissue>::key(value);
}

bool fromString(std::string_view key, PathologyKind& out) {
    return enumFromKey(key, out);
}
bool fromString(std::string_view key, GrowthModel& out) {
    return enumFromKey(key, out);
}
bool fromString(std::string_view key, UterineLocation& out) {
    return enumFromKey(key, out);
}
bool fromString(std::string_view key, PolypAttachment& out) {
    return enumFromKey(key, out);
}
bool fromString(std::string_view key, ShapeMode& out) {
    return enumFromKey(key, out);
}
bool fromString(std::string_view key, MeshingMethod& out) {
    return enumFromKey(key, out);
}
bool fromString(std::string_view key, Tissue& out) {
    return enumFromKey(key, out);
}

// ---- FIGO ----

std::string FigoType::toString() const {
    std::string text = std::to_string(type);
    if (isHybrid())
        text += "-" + std::to_string(serosal);
    return text;
}

std::optional<FigoType> FigoType::parse(std::string_view text) {
    // One digit, or digit-digit: every valid FIGO type is a single digit, so longer numbers are rejected here.
    if (text.size() == 1 && isDigit(text[0]))
        return FigoType{text[0] - '0', -1};
    if (text.size() == 3 && isDigit(text[0]) && text[1] == '-' && isDigit(text[2]))
        return FigoType{text[0] - '0', text[2] - '0'};
    return std::nullopt;
}

bool operator==(const FigoType& a, const FigoType& b) {
    return a.type == b.type && a.serosal == b.serosal;
}
bool operator!=(const FigoType& a, const FigoType& b) {
    return !(a == b);
}

std::string_view figoDefinition(int type) {
    switch (type) {
    case 0:
        return "pedunculated intracavitary";
    case 1:
        return "submucosal, < 50 % intramural";
    case 2:
        return "submucosal, >= 50 % intramural";
    case 3:
        return "contacts the endometrium, 100 % intramural";
    case 4:
        return "intramural";
    case 5:
        return "subserosal, >= 50 % intramural";
    case 6:
        return "subserosal, < 50 % intramural";
    case 7:
        return "subserosal pedunculated";
    case 8:
        return "other (cervical, parasitic)";
    default:
        return "";
    }
}

// ---- Equality ----

bool operator==(const PatientParams& a, const PatientParams& b) {
    return std::tie(a.ageYears, a.parity, a.gravidity, a.heightCm, a.weightKg, a.menopausal) ==
           std::tie(b.ageYears, b.parity, b.gravidity, b.heightCm, b.weightKg, b.menopausal);
}
bool operator==(const UterusDimensions& a, const UterusDimensions& b) {
    return std::tie(a.lengthMm, a.widthMm, a.apMm, a.cavityLengthMm, a.cavityWidthMm, a.cornualAngleDeg,
                    a.fundalWallThicknessMm,
                    a.cervixLengthMm) == std::tie(b.lengthMm, b.widthMm, b.apMm, b.cavityLengthMm, b.cavityWidthMm,
                                                  b.cornualAngleDeg, b.fundalWallThicknessMm, b.cervixLengthMm);
}
bool operator==(const AnatomyParams& a, const AnatomyParams& b) {
    return std::tie(a.shape, a.modelPath, a.versionDeg, a.flexionDeg, a.dimensions) ==
           std::tie(b.shape, b.modelPath, b.versionDeg, b.flexionDeg, b.dimensions);
}
bool operator==(const SurfacePlacement& a, const SurfacePlacement& b) {
    return a.pointMm == b.pointMm && a.normal == b.normal;
}
bool operator==(const ClinicalPlacement& a, const ClinicalPlacement& b) {
    return a.location == b.location;
}
bool operator==(const PathologySpec& a, const PathologySpec& b) {
    return std::tie(a.id, a.kind, a.growthModel, a.sizeMm, a.figo, a.attachment, a.stalkLengthMm, a.placement) ==
           std::tie(b.id, b.kind, b.growthModel, b.sizeMm, b.figo, b.attachment, b.stalkLengthMm, b.placement);
}
bool operator==(const MeshingParams& a, const MeshingParams& b) {
    return std::tie(a.method, a.targetEdgeLengthMm, a.targetVertices, a.particlesPerInnerVoxel,
                    a.particlesPerSurfaceVoxel, a.relaxationIterations,
                    a.threads) == std::tie(b.method, b.targetEdgeLengthMm, b.targetVertices, b.particlesPerInnerVoxel,
                                           b.particlesPerSurfaceVoxel, b.relaxationIterations, b.threads);
}
bool operator==(const TextureExemplars& a, const TextureExemplars& b) {
    return std::tie(a.endometrium, a.myoma, a.polyp) == std::tie(b.endometrium, b.myoma, b.polyp);
}
bool operator==(const TextureParams& a, const TextureParams& b) {
    return std::tie(a.sizePx, a.exemplars, a.vesselDensity) == std::tie(b.sizePx, b.exemplars, b.vesselDensity);
}
bool operator==(const MaterialOverride& a, const MaterialOverride& b) {
    return std::tie(a.youngsModulusKpa, a.poissonRatio, a.densityKgPerM3) ==
           std::tie(b.youngsModulusKpa, b.poissonRatio, b.densityKgPerM3);
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

// ---- Materials (UTERUS.md lines 52-59) ----

TissueMaterial defaultMaterial(Tissue tissue) {
    constexpr double kPoisson = 0.47;   // middle of 0.45-0.49 (line 59)
    constexpr double kDensity = 1050.0; // generic soft tissue (line 59)
    switch (tissue) {
    case Tissue::Myometrium:
        return {30.0, kPoisson, kDensity}; // line 55
    case Tissue::Endometrium:
        return {26.2, kPoisson, kDensity}; // line 58, proliferative phase
    case Tissue::Cervix:
        return {30.0, kPoisson, kDensity}; // no figure in the domain sheet: the myometrium's
    case Tissue::Myoma:
        return {65.0, kPoisson, kDensity}; // line 56
    case Tissue::Polyp:
        return {15.0, kPoisson, kDensity}; // line 57
    }
    return {30.0, kPoisson, kDensity};
}

Range youngsModulusRangeKpa(Tissue tissue) {
    switch (tissue) {
    case Tissue::Myometrium:
    case Tissue::Cervix:
        return {6.0, 90.0}; // line 55
    case Tissue::Endometrium:
        return {12.5, 26.2}; // line 58
    case Tissue::Myoma:
        return {13.0, 206.0}; // 2.17 x 6 .. 2.29 x 90 (lines 55-56)
    case Tissue::Polyp:
        return {1.0, 32.0}; // 15.7 + 2 x 8.2 (line 57), floored at 1 kPa
    }
    return {6.0, 90.0};
}

TissueMaterial effectiveMaterial(const SceneParams& scene, Tissue tissue) {
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
    myoma.kind = PathologyKind::Myoma;
    myoma.growthModel = GrowthModel::Skeleton;
    myoma.sizeMm = 20.0; // Lasmar size class <= 2 cm (line 67); resectable type (line 66)
    myoma.figo = FigoType{2, -1};
    myoma.placement = ClinicalPlacement{UterineLocation::LeftLateral}; // lateral wall: +1 in the Lasmar score
    spec.pathologies.push_back(myoma);

    PathologySpec polyp;
    polyp.id = "polyp-1";
    polyp.kind = PathologyKind::Polyp;
    polyp.growthModel = GrowthModel::Skeleton; // a stalk is a skeleton with revolved contours (line 12)
    polyp.sizeMm = 10.0;                       // within the usual 5-30 mm (line 71)
    polyp.attachment = PolypAttachment::Sessile;
    polyp.placement = ClinicalPlacement{UterineLocation::CornualRight}; // cornual is common (line 71)
    spec.pathologies.push_back(polyp);
    return spec;
}

} // namespace hs::scene
