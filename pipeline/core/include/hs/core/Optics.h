#pragma once
/// Optical constants shared by the texture stage (vessels beneath the mucosa) and the simulator's view (blood in the
/// distension fluid).

#include <array>

namespace hs {

/// Whole blood's absorption, 1/mm, at 630, 550 and 470 nm for red, green and blue (oxyhaemoglobin at 150 g/L, from
/// Prahl's tabulated molar extinction, docs/references.md [Prahl1999]).
inline constexpr std::array<double, 3> kWholeBloodAbsorptionPerMm{0.33, 23.0, 17.8};

} // namespace hs
