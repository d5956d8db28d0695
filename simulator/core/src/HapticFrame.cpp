// The haptics' local contact model (HapticFrame.h).
#include "hs/sim/HapticFrame.h"

#include "hs/mechanics/CorotationalFem.h"

#include <algorithm>
#include <cmath>

namespace hs::sim {

namespace {
/// Sweeps of the 1 kHz re-solve: it starts from the last step's forces, a few contacts, within a millisecond.
constexpr int kHapticSweeps = 40;
} // namespace

bool solveHapticContacts(const HapticFrame& frame, const std::array<double, 3>& device, std::vector<double>& forcesN,
                         std::array<double, 3>& generalizedForce) {
    const std::size_t k = frame.contacts.size();
    forcesN.assign(k, 0.0);
    generalizedForce = {0.0, 0.0, 0.0};
    if (frame.compliance.size() != k * k)
        return false;
    for (const double s : frame.couplingStiffness)
        if (!(s > 0.0) || !std::isfinite(s))
            return false;
    for (const double q : device)
        if (!std::isfinite(q))
            return false;
    // gap(lambda) = gap_end + G (device - end) + G K^-1 G^T lambda + W (lambda - lambda_end) + C lambda >= 0,
    // lambda >= 0 (C: the tip's own give between its contacts).
    std::vector<double> free(k), w(k * k);
    for (std::size_t i = 0; i < k; ++i) {
        const HapticContact& c = frame.contacts[i];
        double g = c.gapM;
        for (std::size_t d = 0; d < 3; ++d)
            g += c.scopeGradient[d] * (device[d] - frame.scopeDofs[d]);
        for (std::size_t j = 0; j < k; ++j) {
            double coupling = 0.0;
            for (std::size_t d = 0; d < 3; ++d)
                coupling += c.scopeGradient[d] * frame.contacts[j].scopeGradient[d] / frame.couplingStiffness[d];
            w[i * k + j] = frame.compliance[i * k + j] + coupling;
            g -= frame.compliance[i * k + j] * frame.contacts[j].forceN;
        }
        // The tip's own give between its contacts: the physics' scope is held in its dimple, so a tip row's gap at
        // the step's end is -C lambda_end, and the re-solve at the step's own pose gives the step's forces back.
        const double give = frame.tipComplianceMPerN;
        if (c.tip && std::isfinite(give) && give > 0.0)
            for (std::size_t j = 0; j < k; ++j)
                if (frame.contacts[j].tip)
                    w[i * k + j] += give * dot(c.normal, frame.contacts[j].normal);
        if (!std::isfinite(g))
            return false;
        free[i] = g;
    }
    for (const double v : w)
        if (!std::isfinite(v))
            return false;
    mechanics::solveComplementarity(w, free, 1e300, kHapticSweeps, forcesN);
    for (std::size_t i = 0; i < k; ++i)
        for (std::size_t d = 0; d < 3; ++d)
            generalizedForce[d] += frame.contacts[i].scopeGradient[d] * forcesN[i];
    return true;
}

} // namespace hs::sim
