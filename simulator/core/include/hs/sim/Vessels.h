#pragma once
/// The vessels a cut opens (docs/simulator.md, "Bleeding"): per simulation tet, the conductance of the arterioles and
/// of the venules that cross one square millimetre of a surface cut through it, by its tissue. The fluid model
/// (simulator/core/src/Fluid.h) turns the open surface's conductances into bleeding below the mean arterial pressure
/// and intravasation above the venules' pressure. Conductances mL/(s kPa mm^2).

#include "hs/clinical/Tissue.h"

#include <array>
#include <cstdint>
#include <vector>

namespace hs::sim {

/// mL/(s kPa) per mm^2 of a cut through myometrium. The venules': an estimate by Poiseuille flow of saline
/// (0.7 mPa s at 37 C) through venules of 25 um radius and 5 mm to a wider vein (4.4e-5 each), five of them
/// assumed to cross a square millimetre; docs/simulator.md ("Bleeding") compares the rates it gives with the
/// intravasation measured in hysteroscopic myomectomy.
/// The arterioles': no published rate per cut area was found; chosen so that the demonstration polypectomy at the
/// default 80 mmHg reddens the view without hiding it (1 cm^2 of fresh myometrium bleeds about 0.7 mL/min at
/// 40 mmHg, nothing at the mean arterial pressure). Five times more hid the whole picture in red.
inline constexpr double kVenousPerMm2 = 2e-4;
inline constexpr double kArterialPerMm2 = 2e-5;

/// How vascular a tissue is relative to the myometrium's (both conductances scale together):
/// the myometrium 1 (arcuate and radial vessels), the cervix and the endometrium 0.5 (spiral arterioles), a myoma's
/// interior 0.2 and the layer on its pseudocapsule 2 (its vessels run in the pseudocapsule; Tinelli et al. 2009), a
/// polyp's body 0.3 and its base 2 (the pedicle artery; Timmerman et al. 2003).
inline constexpr double kMyometriumVessels = 1.0;
inline constexpr double kEndometriumVessels = 0.5;
inline constexpr double kCervixVessels = 0.5;
inline constexpr double kMyomaVessels = 0.2;
inline constexpr double kPolypVessels = 0.3;
inline constexpr double kCapsuleVessels = 2.0;

struct VesselDensity {
    double arterialPerMm2 = 0.0; ///< mL/(s kPa mm^2)
    double venousPerMm2 = 0.0;
};

/// Per tet, its vessels: by `tetTissue`, and where a pathology's tet meets a tet of other tissue across a face
/// (`neighbours`, -1 none; `tetPathology` -1 healthy), both are the capsule's (a myoma's pseudocapsule, a polyp's
/// base with its pedicle artery). Arrays of one length; a mismatch gives none.
std::vector<VesselDensity> vesselDensities(const std::vector<clinical::Tissue>& tetTissue,
                                           const std::vector<std::int32_t>& tetPathology,
                                           const std::vector<std::array<std::int32_t, 4>>& neighbours);

} // namespace hs::sim
