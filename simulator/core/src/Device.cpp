#include "hs/sim/Device.h"

#include <algorithm>
#include <cmath>

namespace hs::sim {

namespace {

bool within(double v, double lo, double hi) {
    return std::isfinite(v) && v >= lo && v <= hi;
}

double clampedValue(double v, double lo, double hi) {
    return std::isfinite(v) ? std::clamp(v, lo, hi) : 0.0;
}

} // namespace

std::string_view instrumentName(std::uint32_t instrument) {
    switch (instrument) {
    case kInstrumentLoop:
        return "loop";
    case kInstrumentScissors:
        return "scissors";
    case kInstrumentGrasper:
        return "grasper";
    default:
        return "none";
    }
}

std::uint32_t nextInstrument(std::uint32_t instrument) {
    return instrument >= kMaxInstrument ? kInstrumentNone : instrument + 1;
}

bool isValid(const DeviceSample& s) {
    return within(s.insertionMm, kMinInsertionMm, kMaxInsertionMm) && within(s.pitchDeg, -kMaxPivotDeg, kMaxPivotDeg) &&
           within(s.yawDeg, -kMaxPivotDeg, kMaxPivotDeg) && within(s.rollDeg, -kMaxRollDeg, kMaxRollDeg) &&
           within(s.cameraRollDeg, -kMaxRollDeg, kMaxRollDeg) && within(s.inflow, 0.0, 1.0) &&
           within(s.outflow, 0.0, 1.0) && within(s.workingElementMm, 0.0, kMaxWorkingElementMm) &&
           (s.buttons & ~kKnownButtons) == 0 && s.instrument <= kMaxInstrument;
}

DeviceSample clamped(const DeviceSample& s) {
    DeviceSample c = s;
    c.insertionMm = clampedValue(s.insertionMm, kMinInsertionMm, kMaxInsertionMm);
    c.pitchDeg = clampedValue(s.pitchDeg, -kMaxPivotDeg, kMaxPivotDeg);
    c.yawDeg = clampedValue(s.yawDeg, -kMaxPivotDeg, kMaxPivotDeg);
    c.rollDeg = clampedValue(s.rollDeg, -kMaxRollDeg, kMaxRollDeg);
    c.cameraRollDeg = clampedValue(s.cameraRollDeg, -kMaxRollDeg, kMaxRollDeg);
    c.inflow = clampedValue(s.inflow, 0.0, 1.0);
    c.outflow = clampedValue(s.outflow, 0.0, 1.0);
    c.workingElementMm = clampedValue(s.workingElementMm, 0.0, kMaxWorkingElementMm);
    c.buttons = s.buttons & kKnownButtons;
    c.instrument = s.instrument <= kMaxInstrument ? s.instrument : kInstrumentNone;
    return c;
}

} // namespace hs::sim
