#include "hs/haptics/HapticDevice.h"

#include <algorithm>
#include <cmath>

namespace hs::haptics {

namespace {

double limitOf(double limit) {
    return std::isfinite(limit) && limit > 0.0 ? limit : 0.0;
}

} // namespace

ForceCommand clampForce(const ForceCommand& command, const DeviceLimits& limits) {
    ForceCommand c;
    c.tipForceN = isFinite(command.tipForceN) ? command.tipForceN : Vec3{};
    const bool finite = std::isfinite(command.insertionForceN) && std::isfinite(command.pitchTorqueNmm) &&
                        std::isfinite(command.yawTorqueNmm) && std::isfinite(command.rollTorqueNmm);
    if (!command.enabled || !finite)
        return c;
    const double f = limitOf(limits.maxForceN);
    const double t = limitOf(limits.maxTorqueNmm);
    c.enabled = true;
    c.insertionForceN = std::clamp(command.insertionForceN, -f, f);
    c.pitchTorqueNmm = std::clamp(command.pitchTorqueNmm, -t, t);
    c.yawTorqueNmm = std::clamp(command.yawTorqueNmm, -t, t);
    c.rollTorqueNmm = std::clamp(command.rollTorqueNmm, -t, t);
    return c;
}

double loadFraction(const ForceCommand& command, const DeviceLimits& limits) {
    if (!command.enabled)
        return 0.0;
    const auto fraction = [](double v, double limit) { return limit > 0.0 ? std::abs(v) / limit : 0.0; };
    return std::max(
        {fraction(command.insertionForceN, limits.maxForceN), fraction(command.pitchTorqueNmm, limits.maxTorqueNmm),
         fraction(command.yawTorqueNmm, limits.maxTorqueNmm), fraction(command.rollTorqueNmm, limits.maxTorqueNmm)});
}

std::string_view toString(ReadStatus status) {
    switch (status) {
    case ReadStatus::Sample:
        return "sample";
    case ReadStatus::NoNewData:
        return "no new data";
    case ReadStatus::Disconnected:
        return "disconnected";
    case ReadStatus::Error:
        return "error";
    }
    return "error";
}

} // namespace hs::haptics
