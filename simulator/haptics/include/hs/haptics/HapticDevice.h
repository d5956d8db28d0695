#pragma once
/// A 4-DOF hysteroscope input device with force feedback, as the haptics loop sees it: it reads the newest device
/// sample once per tick and writes one force command per tick. Implementations: HidDevice (the HID protocol of
/// docs/haptics-protocol.md), ScriptedDevice (a script or a recorded trial, for tests and batch runs) and ManualDevice
/// (the app's keyboard and mouse).

#include "hs/core/Result.h"
#include "hs/core/Vec3.h"
#include "hs/sim/Device.h"

#include <string>

namespace hs::haptics {

/// What a device can render; every force written is clamped to these.
struct DeviceLimits {
    double maxForceN = 0.0;    ///< N, |insertion force|; 0: no actuator along the shaft
    double maxTorqueNmm = 0.0; ///< N*mm, |torque| about each pivot axis and about the shaft; 0: no actuators
    /// The device reports the resectoscope: the working element, the pedals, the pump's buttons and the instrument
    /// (HID protocol version 2). Without it its samples carry the diagnostic scope only (instrument 0).
    bool resectoscope = false;
};

/// The force the device renders for one tick, in the device's degrees of freedom. Signs follow DeviceSample: a
/// positive insertion force pushes the scope deeper, a positive pitch torque turns it towards +pitch (anterior), a
/// positive yaw torque towards +yaw (the patient's left), a positive roll torque towards +roll.
struct ForceCommand {
    bool enabled = false;         ///< false: the device's actuators are off (every value below is ignored)
    double insertionForceN = 0.0; ///< N, along the shaft
    double pitchTorqueNmm = 0.0;  ///< N*mm, about the pivot's pitch axis
    double yawTorqueNmm = 0.0;    ///< N*mm, about the pivot's yaw axis
    double rollTorqueNmm = 0.0;   ///< N*mm, about the shaft
    Vec3 tipForceN;               ///< N, the contact force at the tip in the scene frame (logging only; not sent)
};

/// `command` with every value clamped to `limits` (non-finite values, and any value of a disabled command, become 0;
/// a command with a non-finite value is disabled altogether).
ForceCommand clampForce(const ForceCommand& command, const DeviceLimits& limits);
/// The largest |value| of a command's rendered degrees of freedom, as a fraction of its limit (0 for a disabled one).
double loadFraction(const ForceCommand& command, const DeviceLimits& limits);

enum class ReadStatus {
    Sample,       ///< `out` holds the newest sample
    NoNewData,    ///< nothing arrived since the last read (`out` untouched)
    Disconnected, ///< the device is gone (unplugged); reopen to continue
    Error,        ///< the device is present but failed (not open, I/O error other than unplug)
};
std::string_view toString(ReadStatus status);

class HapticDevice {
public:
    virtual ~HapticDevice() = default;
    /// Opens the device and reads its limits. Idempotent.
    [[nodiscard]] virtual Status open() = 0;
    /// Turns the force off (best effort) and releases the device. Idempotent.
    virtual void close() = 0;
    /// Non-blocking: the newest sample since the last read (its tick is 0; the haptics loop numbers ticks).
    virtual ReadStatus read(sim::DeviceSample& out) = 0;
    /// Non-blocking: sends one command, clamped to limits(). IoError when the device is gone.
    [[nodiscard]] virtual Status writeForce(const ForceCommand& command) = 0;
    /// Valid after open().
    virtual DeviceLimits limits() const = 0;
    /// For the trial header and messages: "hid:1209:0001", "scripted:FILE", "keyboard".
    virtual std::string name() const = 0;
};

} // namespace hs::haptics
