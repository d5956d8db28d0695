#pragma once
/// The appearance classes of the surface and their procedural default exemplars.
///
/// No licensed hysteroscopy photographs ship with the project, so the default exemplars are drawn by this code
/// (resources/exemplars/*.png are its output). A user replaces them with crops of real intra-operative images
/// (docs/texture.md).

#include "hs/core/Image.h"
#include "hs/core/Result.h"

#include <array>
#include <cstdint>
#include <string>

namespace hs::texture {

/// What a part of the surface looks like.
enum class Appearance : std::int32_t {
    Endometrium = 0, ///< healthy mucosa: pink-red, glandular openings, fine capillary network
    Myoma = 1,       ///< submucous myoma surface: paler, whitish, with larger tortuous vessels
    Polyp = 2,       ///< endometrial polyp: smooth, glossy, pink, a central vessel
    /// endocervix: whitish pink, papillae between clefts, fine branched vessels; its folds (plicae palmatae) are the
    /// bake's relief (BakeParams::canal)
    CervicalCanal = 3,
};
inline constexpr std::array<Appearance, 4> kAppearances{Appearance::Endometrium, Appearance::Myoma, Appearance::Polyp,
                                                        Appearance::CervicalCanal};
inline constexpr int kAppearanceCount = 4;

/// "endometrium", "myoma", "polyp", "cervical-canal".
std::string appearanceName(Appearance appearance);

/// The endometrium's look on the day of the hysteroscopy, after published hysteroscopic descriptions
/// (docs/texture.md, "The endometrium through the cycle"):
enum class EndometrialState : std::int32_t {
    Proliferative = 0, ///< pink-red, thin and smooth, small uniform gland openings, fine vessels
    Secretory = 1,     ///< paler, yellowish pink, thicker and wavy (oedema), larger open glands, vessels hidden
    Menstrual = 2,     ///< dark red, patches shedding and bleeding beside preserved ones
    Atrophic = 3,      ///< postmenopausal: thin, pale, smooth, vessels showing through, petechiae, few glands
};
inline constexpr std::array<EndometrialState, 4> kEndometrialStates{
    EndometrialState::Proliferative, EndometrialState::Secretory, EndometrialState::Menstrual,
    EndometrialState::Atrophic};
/// "proliferative", "secretory", "menstrual", "atrophic".
std::string endometrialStateName(EndometrialState state);
/// How the state changes what the bake draws over the base texture besides the exemplar: the density of the
/// surface vessels it grows and the height of the mucosa's relief, as factors on BakeParams' own.
struct EndometrialSurface {
    double vesselDensity = 1.0;
    double relief = 1.0;
};
EndometrialSurface endometrialSurface(EndometrialState state);

/// A procedural exemplar of `size` x `size` RGB pixels (32..4096), the same for the same seed. Without vessels on
/// endometrium, polyp and canal (vessels are grown on the surface); the myoma exemplar carries faint fibre streaks.
/// The endometrium's follows `state` (the others do not depend on it); Proliferative is the look of earlier versions.
Result<ImageU8> makeExemplar(Appearance appearance, int size = 256, std::uint64_t seed = 1,
                             EndometrialState state = EndometrialState::Proliferative);

} // namespace hs::texture
