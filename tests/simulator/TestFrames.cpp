#include "TestFrames.h"

namespace hs::test {

sim::ScopeFrame testPivot() {
    sim::ScopeFrame f;
    f.pivotMm = {0.0, 0.0, 0.0};
    f.axis = {0.0, 0.0, 1.0};
    f.anterior = {0.0, 1.0, 0.0};
    f.left = {-1.0, 0.0, 0.0};
    return f;
}

std::shared_ptr<const sim::HapticFrame> wallFrame(double wallZ, double stiffnessNPerMm) {
    auto frame = std::make_shared<sim::HapticFrame>();
    frame->pivot = testPivot();
    const double radiusMm = 0.5 * frame->scope.diameterMm;
    frame->scopeDofs = {(wallZ - radiusMm) * 1e-3, 0.0, 0.0};
    sim::HapticContact c;
    c.gapM = 0.0;
    c.scopeGradient = {-1.0, 0.0, 0.0}; // deeper: less gap
    c.forceN = 0.0;
    c.normal = {0.0, 0.0, -1.0};
    c.tip = true;
    frame->contacts.push_back(c);
    frame->compliance = {1e-3 / stiffnessNPerMm}; // m/N
    return frame;
}

} // namespace hs::test
