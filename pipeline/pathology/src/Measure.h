#pragma once
/// Volume fractions, contacts and the FIGO rule shared by placement (on an idealised wall) and measurement.

#include "Geometry.h"
#include "Organ.h"

#include "hs/pathology/Pathology.h"

namespace hs::pathology::detail {

using Fractions = WallFractions;

/// Fraction of the pathology's volume inside the organ's wall, on voxels of edge h.
double tissueFraction(const SurfaceMesh& organ, const SurfaceMesh& pathology, double h);

/// The organ faces of one side as a surface (for distances).
SurfaceMesh organPart(const OrganInfo& info, Side side);

} // namespace hs::pathology::detail
