#pragma once
/// Where a pathology sits: by clinical description, or as a point on the organ surface (a click in the 3-D view).

#include "hs/clinical/Clinical.h"
#include "hs/core/Vec3.h"

#include <variant>

namespace hs::clinical {

/// A clinical description: where in the uterus (the depth comes from the FIGO type for myomas).
struct ClinicalPlacement {
    UterineLocation location = UterineLocation::Fundal;
};
/// A point on the organ surface and its outward normal, as a click in the 3-D view gives (organ frame, mm). It
/// refers to the organ generated from the case's patient, anatomy and seed.
struct SurfacePlacement {
    Vec3 pointMm;
    Vec3 normal{0.0, 0.0, 1.0}; ///< need not be unit length; must not be zero
};
/// Exactly one placement form per pathology.
using Placement = std::variant<ClinicalPlacement, SurfacePlacement>;

bool operator==(const ClinicalPlacement& a, const ClinicalPlacement& b);
bool operator==(const SurfacePlacement& a, const SurfacePlacement& b);

} // namespace hs::clinical
