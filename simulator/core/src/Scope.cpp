#include "hs/sim/Scope.h"

#include <cmath>
#include <string>

namespace hs::sim {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

bool isOneOf(double v, std::initializer_list<double> allowed) {
    for (double a : allowed)
        if (std::abs(v - a) < 1e-9)
            return true;
    return false;
}

} // namespace

// Field of view: rigid Hopkins-type hysteroscopes of 2.9-5 mm have a 90-105 degree field in air; the sources in
// docs/simulator.md. The depth of field of a fixed-focus endoscope runs from a few mm to several cm.
double scopeFieldOfViewDeg(const ScopeConfig& config) {
    return config.fieldOfViewDeg > 0.0 ? config.fieldOfViewDeg : 90.0;
}
double scopeFocusNearMm(const ScopeConfig& config) {
    return config.focusNearMm > 0.0 ? config.focusNearMm : 2.0;
}
double scopeFocusFarMm(const ScopeConfig& config) {
    return config.focusFarMm > 0.0 ? config.focusFarMm : 50.0;
}

Status checkScopeConfig(const ScopeConfig& c) {
    if (!isOneOf(c.opticDeg, {0.0, 12.0, 30.0}))
        return fail(ErrorCode::InvalidInput,
                    "scope: opticDeg " + std::to_string(c.opticDeg) + " is not one of 0, 12, 30 degrees");
    if (!isOneOf(c.diameterMm, {2.9, 4.0, 5.0}))
        return fail(ErrorCode::InvalidInput,
                    "scope: diameterMm " + std::to_string(c.diameterMm) + " is not one of 2.9, 4, 5 mm");
    if (!std::isfinite(c.fieldOfViewDeg) ||
        (c.fieldOfViewDeg != 0.0 && !(c.fieldOfViewDeg >= 30.0 && c.fieldOfViewDeg <= 120.0)))
        return fail(ErrorCode::InvalidInput, "scope: fieldOfViewDeg must be 30-120 degrees (0: the optic's)");
    const double near = scopeFocusNearMm(c);
    const double far = scopeFocusFarMm(c);
    if (!std::isfinite(near) || !std::isfinite(far) || near < 0.5 || far > 200.0 || !(near < far))
        return fail(ErrorCode::InvalidInput, "scope: focus must satisfy 0.5 <= focusNearMm < focusFarMm <= 200 mm");
    return {};
}

Result<ScopeFrame> scopeFrame(const scene::ScopeLandmarks& landmarks) {
    const Vec3 canal = landmarks.internalOsMm - landmarks.externalOsMm;
    if (!(norm(canal) > 1e-6))
        return fail(ErrorCode::InvalidInput, "scope: the external and internal os coincide");
    ScopeFrame f;
    f.pivotMm = landmarks.externalOsMm;
    f.axis = normalized(canal);
    f.anterior = perpendicularTo(f.axis, {0.0, 1.0, 0.0});
    // The organ frame is right-handed with +y anterior and +z up the canal, so +x is the patient's right (RAS):
    // the patient's left is -x.
    f.left = cross(f.axis, f.anterior);
    if (f.left.x > 0.0)
        f.left = f.left * -1.0;
    return f;
}

ScopePose scopePose(const ScopeFrame& frame, const ScopeConfig& config, const DeviceSample& s) {
    ScopePose pose;
    pose.shaft =
        normalized(frame.axis + frame.anterior * std::tan(s.pitchDeg * kDeg) + frame.left * std::tan(s.yawDeg * kDeg));
    pose.tipMm = frame.pivotMm + pose.shaft * (s.insertionMm + frame.introitusMm);
    // Roll 0: the light post, hence an oblique optic's view, points towards anterior.
    const Vec3 anterior = perpendicularTo(pose.shaft, frame.anterior);
    const Vec3 post = rotatedAbout(anterior, pose.shaft, s.rollDeg * kDeg);
    const double tilt = config.opticDeg * kDeg;
    pose.direction = normalized(pose.shaft * std::cos(tilt) + post * std::sin(tilt));
    // The camera head: at 0 the image's up is the patient's anterior, turned by the camera's roll about the shaft.
    const Vec3 cameraUp = rotatedAbout(anterior, pose.shaft, s.cameraRollDeg * kDeg);
    pose.up = perpendicularTo(pose.direction, cameraUp);
    return pose;
}

DeviceSample sampleAiming(const ScopeFrame& frame, const Vec3& tipMm, double rollDeg, double cameraRollDeg) {
    DeviceSample s;
    const Vec3 d = tipMm - frame.pivotMm;
    const double along = dot(d, frame.axis);
    s.insertionMm = norm(d) - frame.introitusMm;
    if (along > 1e-9) {
        s.pitchDeg = std::atan(dot(d, frame.anterior) / along) / kDeg;
        s.yawDeg = std::atan(dot(d, frame.left) / along) / kDeg;
    } else {
        s.insertionMm = along - frame.introitusMm; // behind the pivot: straight back along the axis
    }
    s.rollDeg = rollDeg;
    s.cameraRollDeg = cameraRollDeg;
    return s;
}

double horizonErrorDeg(const ScopeFrame& frame, const ScopePose& pose) {
    const Vec3 seen = frame.anterior - pose.direction * dot(frame.anterior, pose.direction);
    if (norm(seen) < 1e-6)
        return 0.0;
    const double c = std::clamp(dot(normalized(seen), pose.up), -1.0, 1.0);
    return std::acos(c) / kDeg;
}

} // namespace hs::sim
