#include "hs/sim/Vessels.h"

namespace hs::sim {

namespace {

double relativeVessels(clinical::Tissue tissue) {
    switch (tissue) {
    case clinical::Tissue::Myometrium:
        return kMyometriumVessels;
    case clinical::Tissue::Endometrium:
        return kEndometriumVessels;
    case clinical::Tissue::Cervix:
        return kCervixVessels;
    case clinical::Tissue::Myoma:
        return kMyomaVessels;
    case clinical::Tissue::Polyp:
        return kPolypVessels;
    }
    return kMyometriumVessels;
}

} // namespace

std::vector<VesselDensity> vesselDensities(const std::vector<clinical::Tissue>& tetTissue,
                                           const std::vector<std::int32_t>& tetPathology,
                                           const std::vector<std::array<std::int32_t, 4>>& neighbours) {
    const std::size_t n = tetTissue.size();
    if (tetPathology.size() != n || neighbours.size() != n)
        return {};
    std::vector<VesselDensity> out(n);
    for (std::size_t t = 0; t < n; ++t) {
        double relative = relativeVessels(tetTissue[t]);
        for (const std::int32_t u : neighbours[t]) {
            if (u < 0 || static_cast<std::size_t>(u) >= n)
                continue;
            const std::int32_t a = tetPathology[t], b = tetPathology[static_cast<std::size_t>(u)];
            if (a != b && (a >= 0 || b >= 0)) // a pathology's tet against another tissue, on either side
                relative = kCapsuleVessels;
        }
        out[t] = {relative * kArterialPerMm2, relative * kVenousPerMm2};
    }
    return out;
}

} // namespace hs::sim
