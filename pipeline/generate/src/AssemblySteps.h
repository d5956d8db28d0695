#pragma once
/// What the sources of the scene assembly share (Assembly.cpp, AssemblyBoundary.cpp, AssemblyDescriptors.cpp): the
/// surface tissue label values they look for.

#include "hs/clinical/Tissue.h"

namespace hs::generate::detail {

/// The "tissue" face label value of the cervical canal.
constexpr auto kTissueCervicalCanal = clinical::labelValue(clinical::SurfaceTissue::CervicalCanal);
/// The "tissue" face label value of a tubal ostium.
constexpr auto kTissueOstium = clinical::labelValue(clinical::SurfaceTissue::TubalOstium);

} // namespace hs::generate::detail
