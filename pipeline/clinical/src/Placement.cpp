#include "hs/clinical/Placement.h"

namespace hs::clinical {

bool operator==(const ClinicalPlacement& a, const ClinicalPlacement& b) {
    return a.location == b.location;
}
bool operator==(const SurfacePlacement& a, const SurfacePlacement& b) {
    return a.pointMm == b.pointMm && a.normal == b.normal;
}

} // namespace hs::clinical
