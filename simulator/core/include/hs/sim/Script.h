#pragma once
/// A scripted trial: key frames of the device's degrees of freedom in time, played at 1 kHz by the scripted device
/// (tests, demonstrations, batch assessment: `hysteroscene-sim SCENE --device scripted:FILE --headless`).
///
/// JSON: {"format": "hysteroscene-script", "version": 1, "keyframes": [{"t": 0.0, "insertionMm": -5, "pitchDeg": 0,
/// "yawDeg": 0, "rollDeg": 0, "cameraRollDeg": 0, "inflow": 1, "outflow": 0.3, "workingElementMm": 0, "buttons": 0,
/// "instrument": 0}, ...]}. Times in s, strictly increasing, from 0; between key frames every value is interpolated
/// linearly, the buttons and the instrument held from a key frame to the next. Missing members keep the previous key
/// frame's value (0 for the first).

#include "hs/core/Result.h"
#include "hs/sim/Device.h"

#include <cstdint>
#include <string>
#include <vector>

namespace hs::sim {

struct KeyFrame {
    double timeS = 0.0;
    DeviceSample sample; ///< its tick is ignored
};

struct Script {
    std::vector<KeyFrame> keyframes; ///< strictly increasing times from 0
    /// Ticks in the script: up to and including the last key frame.
    std::uint64_t tickCount() const;
    /// The sample at `tick` (clamped to the last key frame).
    DeviceSample sampleAt(std::uint64_t tick) const;
};

/// Limits for untrusted scripts.
inline constexpr std::size_t kMaxKeyFrames = 100000;
inline constexpr double kMaxScriptSeconds = 4.0 * 3600.0;

[[nodiscard]] Result<Script> parseScript(const std::string& text, const std::string& name);
[[nodiscard]] Result<Script> readScript(const std::string& path);
/// JSON text of a script (parseScript reads it back to the same key frames).
std::string scriptJson(const Script& script);
/// Writes atomically.
[[nodiscard]] Status writeScript(const Script& script, const std::string& path);

} // namespace hs::sim
