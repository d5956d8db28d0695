#pragma once
/// How a world sets up its tissue, for the world and for whatever drives the same tissue without one (the cutting
/// benchmark): the solver's settings and the surface whose compliance is precomputed (docs/simulator.md, "Tissue").

#include "hs/mechanics/CorotationalFem.h"
#include "hs/mechanics/UterusModel.h"
#include "hs/sim/World.h"

#include <cstdint>
#include <vector>

namespace hs::sim {

/// The solver's settings of a world with `options`: its step and iterations, the contacts' force bound, the volume
/// bound, no line search and no end residual.
mechanics::FemSettings tissueSolverSettings(const WorldOptions& options);

/// The points of the surface the scope touches (the cavity's and the canal's faces), ascending.
std::vector<std::int32_t> touchablePoints(const mechanics::UterusModel& model);

} // namespace hs::sim
