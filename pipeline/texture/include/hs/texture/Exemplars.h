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
};
inline constexpr std::array<Appearance, 3> kAppearances{Appearance::Endometrium, Appearance::Myoma, Appearance::Polyp};
inline constexpr int kAppearanceCount = 3;

/// "endometrium", "myoma", "polyp".
std::string appearanceName(Appearance appearance);

/// A procedural exemplar of `size` x `size` RGB pixels (32..4096), the same for the same seed. Without vessels on
/// endometrium and polyp (vessels are grown on the surface); the myoma exemplar carries faint fibre streaks.
Result<ImageU8> makeExemplar(Appearance appearance, int size = 256, std::uint64_t seed = 1);

} // namespace hs::texture
