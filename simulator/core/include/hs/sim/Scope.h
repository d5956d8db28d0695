#pragma once
/// The rigid hysteroscope: its configuration (optic, diameter, field and depth of view) and its pose for a device
/// sample. Four degrees of freedom about the cervical pivot (insertion, roll about the shaft, two pivot angles) plus
/// the camera head's roll. docs/simulator.md ("Scope") gives the sources of the optical figures.
///
/// Frame: the scene's mm frame (+y anterior). The pivot is the external os; at pitch = yaw = 0 the shaft runs along
/// the cervical canal's axis (external -> internal os), the convention of scene::scopeView.

#include "hs/core/Result.h"
#include "hs/core/Vec3.h"
#include "hs/scene/ScopePassage.h"
#include "hs/sim/Device.h"

namespace hs::sim {

/// Rigid office and operative hysteroscopes: optics 0/12/15/30/70 degrees, 2.9-5 mm (docs/references.md [Bradley]).
struct ScopeConfig {
    double opticDeg = 30.0;    ///< degrees: 0, 12 or 30
    double diameterMm = 2.9;   ///< mm, outer sheath: 2.9, 4 or 5
    double fieldOfViewDeg = 0; ///< degrees, full angle; 0: the optic's (scopeFieldOfViewDeg)
    double focusNearMm = 0;    ///< mm, nearest sharp distance; 0: the optic's
    double focusFarMm = 0;     ///< mm, farthest sharp distance; 0: the optic's
};

/// The optic's full field of view, degrees (docs/simulator.md: 2.9 mm Hopkins-type optics ~ 90 degrees in water).
double scopeFieldOfViewDeg(const ScopeConfig& config);
/// The depth of field, mm: {near, far} (docs/simulator.md).
double scopeFocusNearMm(const ScopeConfig& config);
double scopeFocusFarMm(const ScopeConfig& config);

/// InvalidInput naming the field and the allowed values (optic 0/12/30, diameter 2.9/4/5, field of view 30-120,
/// focus 0.5 <= near < far <= 200).
[[nodiscard]] Status checkScopeConfig(const ScopeConfig& config);

/// The pivot and its axes.
struct ScopeFrame {
    /// Where the shaft pivots: the external os (introitusMm 0), or the introitus that far behind it on the approach.
    Vec3 pivotMm;
    /// mm from the pivot to the external os along the shaft (0: the pivot is the os). The insertion counts from the
    /// os either way: the tip stands at pivot + shaft (insertion + introitusMm).
    double introitusMm = 0.0;
    Vec3 axis;     ///< unit, along the canal (external -> internal os)
    Vec3 anterior; ///< unit, perpendicular to axis, as close to +y as possible
    Vec3 left;     ///< unit, perpendicular to both, towards the patient's left (-x: the frame is RAS-like)
};
[[nodiscard]] Result<ScopeFrame> scopeFrame(const scene::ScopeLandmarks& landmarks);

struct ScopePose {
    Vec3 tipMm;     ///< the distal end of the shaft, where lens and light are
    Vec3 shaft;     ///< unit, from the handle to the tip
    Vec3 direction; ///< unit, where the optic looks (the shaft tilted by the optic angle towards the light post)
    Vec3 up;        ///< unit, perpendicular to direction: the image's up (the camera head's roll)
};

/// The scope's pose for a device sample.
ScopePose scopePose(const ScopeFrame& frame, const ScopeConfig& config, const DeviceSample& sample);

/// The device sample that puts the shaft's tip at `tipMm` (beyond the pivot) with the given rolls and valves; the
/// inverse of scopePose for the tip (scripts aim the scope with it).
DeviceSample sampleAiming(const ScopeFrame& frame, const Vec3& tipMm, double rollDeg = 0.0, double cameraRollDeg = 0.0);

/// Angle between the image's up and the patient's anterior as seen in the image (the horizon error), degrees 0-180;
/// 0 when the view looks along the anterior axis (no horizon to keep).
double horizonErrorDeg(const ScopeFrame& frame, const ScopePose& pose);

} // namespace hs::sim
