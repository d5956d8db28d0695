#pragma once
/// Tissues: the volumetric tissues a scene region is made of, and the tissue labels of the organ surface.

#include <array>
#include <cstdint>
#include <string_view>

namespace hs::clinical {

/// What a region of the tetrahedral body is made of; decides its material (hs/scene/CaseSpec.h, defaultMaterial).
enum class Tissue { Myometrium, Endometrium, Cervix, Myoma, Polyp };
constexpr std::array<Tissue, 5> kTissues{Tissue::Myometrium, Tissue::Endometrium, Tissue::Cervix, Tissue::Myoma,
                                         Tissue::Polyp};

/// Values of the organ surface's face label kSurfaceTissueLabel (the uterus template, hs/anatomy/UterusGenerator.h).
/// The integers are stored in meshes, shape model files and scene packages: they never change.
enum class SurfaceTissue : std::int32_t {
    Serosa = 1,        ///< outer surface of corpus and cervix (perimetrium)
    Endometrium = 2,   ///< the uterine cavity, internal os to fundus
    CervicalCanal = 3, ///< endocervix, external to internal os
    TubalOstium = 4,   ///< the two cornual recesses of the cavity where the tubes open
    Ectocervix = 5,    ///< the rim around the external os that joins serosa and canal
};
constexpr std::array<SurfaceTissue, 5> kSurfaceTissues{SurfaceTissue::Serosa, SurfaceTissue::Endometrium,
                                                       SurfaceTissue::CervicalCanal, SurfaceTissue::TubalOstium,
                                                       SurfaceTissue::Ectocervix};
/// Name of the organ surface's face label holding SurfaceTissue values.
inline constexpr const char* kSurfaceTissueLabel = "tissue";

/// The value stored in the face label.
constexpr std::int32_t labelValue(SurfaceTissue tissue) {
    return static_cast<std::int32_t>(tissue);
}

std::string_view toString(Tissue value);        ///< "myometrium", "endometrium", "cervix", "myoma", "polyp"
std::string_view toString(SurfaceTissue value); ///< "serosa", "endometrium", "cervical-canal", "tubal-ostium", ...
/// Sets `out` and returns true when `key` is one of the keys above.
bool fromString(std::string_view key, Tissue& out);
bool fromString(std::string_view key, SurfaceTissue& out);

} // namespace hs::clinical
