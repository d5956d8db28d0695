#pragma once
/// What a hysteroscope input device reports, once per device tick (1 kHz), in the units the simulator uses. Every
/// source of samples gives these: the HID device (simulator/haptics, docs/haptics-protocol.md), the scripted device,
/// the keyboard and mouse, and a recorded trial (Trial.h). The physics consumes them in tick order, so a trial that
/// replays the same samples gives the same world, bit for bit.

#include "hs/core/Units.h"

#include <cstdint>
#include <string_view>

namespace hs::sim {

/// Device ticks per second: the haptics loop's rate and the trial file's sample rate.
inline constexpr int kDeviceRateHz = 1000;

/// Button bits of DeviceSample::buttons.
enum DeviceButton : std::uint32_t {
    kButtonMark = 1u << 0,      ///< diagnosis: mark the pathology at the centre of the view
    kButtonCapture = 1u << 1,   ///< take a still (recorded as an event; no effect on the world)
    kButtonCut = 1u << 2,       ///< the resectoscope's cutting pedal: the loop carries cutting current (scissors and
                                ///< grasper: their jaws close)
    kButtonCoagulate = 1u << 3, ///< the coagulating pedal: the loop seals the vessels it touches
    kButtonPumpUp = 1u << 4,    ///< each press raises the pump's set pressure by kPumpStepKpa
    kButtonPumpDown = 1u << 5,  ///< each press lowers it by kPumpStepKpa
};
/// Every button bit a sample may carry.
inline constexpr std::uint32_t kKnownButtons =
    kButtonMark | kButtonCapture | kButtonCut | kButtonCoagulate | kButtonPumpUp | kButtonPumpDown;
/// kPa, one press of the pump's buttons: 5 mmHg, the set-pressure step of hysteroscopy pumps.
inline constexpr double kPumpStepKpa = 5.0 * units::kKpaPerMmHg;

/// The instrument in use (DeviceSample::instrument).
enum Instrument : std::uint32_t {
    kInstrumentNone = 0, ///< the diagnostic scope alone (a protocol-v1 device, the exploration)
    kInstrumentLoop = 1, ///< the bipolar resectoscope's loop electrode on its working element
    /// The office hysteroscope's 5 Fr instruments through its working channel (docs/simulator.md, "The office scope's
    /// scissors and grasper"), pushed out by the working element; kButtonCut closes their jaws (the handle squeezed).
    kInstrumentScissors = 2, ///< semi-rigid scissors: the blades closing cut what lies between them
    kInstrumentGrasper = 3,  ///< grasping forceps: the jaws closing on a chip hold it until they open
};
inline constexpr std::uint32_t kMaxInstrument = kInstrumentGrasper;
/// "none", "loop", "scissors", "grasper" (an id out of range: "none").
std::string_view instrumentName(std::uint32_t instrument);
/// The instrument an exchange brings: loop, scissors, grasper, none, loop again.
std::uint32_t nextInstrument(std::uint32_t instrument);

/// The allowed range of every field (the HID codec clamps to these; a sample outside them is refused).
inline constexpr double kMinInsertionMm = -50.0; ///< mm, the tip this far outside the pivot (external os)
inline constexpr double kMaxInsertionMm = 150.0; ///< mm, longer than any uterus (docs/references.md [Verguts2013])
inline constexpr double kMaxPivotDeg = 60.0;     ///< degrees, |pitch| and |yaw| about the cervical pivot
inline constexpr double kMaxRollDeg = 180.0;     ///< degrees, |roll| and |camera roll|
/// mm, the loop's travel beyond the sheath's tip on the working element (docs/simulator.md, "The resectoscope in the
/// simulator").
inline constexpr double kMaxWorkingElementMm = 20.0;

struct DeviceSample {
    std::uint64_t tick = 0;     ///< device ticks since the trial started (1 kHz)
    double insertionMm = 0.0;   ///< mm, the scope's tip beyond the cervical pivot along the shaft
    double pitchDeg = 0.0;      ///< degrees, the shaft turned about the pivot towards anterior (+) / posterior
    double yawDeg = 0.0;        ///< degrees, the shaft turned about the pivot towards the patient's left (+)
    double rollDeg = 0.0;       ///< degrees, the scope (its light post, hence an oblique optic) turned about the shaft
    double cameraRollDeg = 0.0; ///< degrees, the camera head turned about the shaft (0: image up is anterior)
    double inflow = 0.0;        ///< inflow valve opening, 0 (closed) to 1 (open)
    double outflow = 0.0;       ///< outflow valve opening, 0 to 1
    std::uint32_t buttons = 0;  ///< DeviceButton bits held down
    double workingElementMm = 0.0; ///< mm, the loop beyond the sheath's tip, 0 (drawn in) to kMaxWorkingElementMm
    std::uint32_t instrument = kInstrumentNone; ///< Instrument
};

/// Whether every field is finite and inside its range.
bool isValid(const DeviceSample& sample);

/// `sample` with every field clamped into its range (non-finite values become 0).
DeviceSample clamped(const DeviceSample& sample);

} // namespace hs::sim
