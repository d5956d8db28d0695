// The haptics' local contact model (HapticFrame.h).
#include "hs/sim/HapticFrame.h"

#include <algorithm>
#include <cmath>

namespace hs::sim {

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
    // gap(lambda) = gap_end + G (device - end) + G K^-1 G^T lambda + W (lambda - lambda_end) >= 0, lambda >= 0.
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
        if (!std::isfinite(g))
            return false;
        free[i] = g;
    }
    for (const double v : w)
        if (!std::isfinite(v))
            return false;
    for (int sweep = 0; sweep < 40; ++sweep) {
        double change = 0.0, largest = 0.0;
        for (std::size_t i = 0; i < k; ++i) {
            if (!(w[i * k + i] > 0.0))
                continue;
            double g = free[i];
            for (std::size_t j = 0; j < k; ++j)
                g += w[i * k + j] * forcesN[j];
            const double next = std::max(0.0, forcesN[i] - g / w[i * k + i]);
            change = std::max(change, std::abs(next - forcesN[i]));
            largest = std::max(largest, next);
            forcesN[i] = next;
        }
        if (change <= 1e-9 * largest)
            break;
    }
    for (std::size_t i = 0; i < k; ++i)
        for (std::size_t d = 0; d < 3; ++d)
            generalizedForce[d] += frame.contacts[i].scopeGradient[d] * forcesN[i];
    return true;
}

} // namespace hs::sim
