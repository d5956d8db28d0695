#pragma once
/// Volume fractions, contacts and the FIGO rule shared by placement (on an idealised wall) and measurement.

#include "Geometry.h"
#include "Organ.h"

#include "hs/pathology/Pathology.h"

namespace hs::pathology::detail {

struct Fractions {
    double tissue = 0.0;  ///< inside the wall
    double cavity = 0.0;  ///< inside the cavity
    double outside = 0.0; ///< outside the serosa
    double endometriumDistanceMm = 1e9;
    double serosaDistanceMm = 1e9;
    bool pedunculated = false;
};

/// FIGO type from fractions and contacts (UTERUS.md: 0 pedunculated intracavitary, 1 < 50 % intramural, 2 >= 50 %,
/// 3 contacts the endometrium, 4 intramural, 5 subserosal >= 50 % intramural, 6 < 50 %, 7 pedunculated subserosal;
/// hybrids X-Y when it reaches both sides).
clinical::FigoType classifyFigo(const Fractions& f, double contactToleranceMm);

/// Fraction of the pathology's volume inside the organ's wall, on voxels of edge h.
double tissueFraction(const SurfaceMesh& organ, const SurfaceMesh& pathology, double h);

/// The organ faces of one side as a surface (for distances).
SurfaceMesh organPart(const OrganInfo& info, Side side);

} // namespace hs::pathology::detail
