#pragma once
/// The command line of hysteroscene-sim (docs/simulator.md, "Running the simulator"):
///   hysteroscene-sim SCENE [--optic 0|12|30] [--diameter 2.9|4|5] [--exercise exploration|diagnosis]
///                    [--pump-mmhg P] [--map-mmhg M] [--seed N] [--device keyboard|hid[:VID:PID]|scripted:FILE]
///                    [--record TRIAL] [--replay TRIAL] [--headless] [--report OUT.json] [--html OUT.html]
///                    [--lang de|fr|it|en]
/// Exit codes are the project's (hs/core/ExitCode.h): 0 ok, 2 usage, 3 invalid input, 4 failed (docs/cli.md).

#include "hs/core/Result.h"
#include "hs/sim/World.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hs::simapp {

/// Where the device samples come from.
struct DeviceSpec {
    /// Demo: the world's own exploration (sim::explorationScript), played as a script.
    enum class Kind { Keyboard, Hid, Scripted, Demo };
    Kind kind = Kind::Keyboard;
    std::uint16_t vendorId = 0;  ///< hid: 0 = the first hysteroscope found
    std::uint16_t productId = 0; ///< hid
    std::string scriptPath;      ///< scripted
    /// "keyboard", "hid", "hid:046d:c62b", "scripted:FILE", "demo": as the trial's header records it.
    std::string text() const;
};
/// Parses "keyboard", "hid", "hid:VID:PID" (hexadecimal), "scripted:FILE" or "demo"; InvalidInput naming the value.
[[nodiscard]] Result<DeviceSpec> parseDeviceSpec(const std::string& text);

struct SimOptions {
    std::string scene;          ///< the package folder (may be empty in the GUI: File > Open)
    sim::WorldOptions world;    ///< scope, fluid, exercise, seed
    DeviceSpec device;          ///< --device
    std::string recordPath;     ///< --record: the trial file to write
    std::string replayPath;     ///< --replay: the trial to play back
    bool headless = false;      ///< --headless: no window (needs --replay, a scripted device or --demo)
    double stopAfterS = 0.0;    ///< --seconds: headless, stop the script or demo after this trial time, s (0: all)
    std::string reportPath;     ///< --report: the report's JSON
    std::string htmlPath;       ///< --html: the report's page
    std::string writeDemoPath;  ///< --write-demo: write the exercise's demonstration as a script here, then quit
    std::string language;       ///< --lang (also --language): the window's language; empty: HS_LANG, else the system's
    std::string screenshotPath; ///< --screenshot (hidden): save the window here after --screenshot-after, then quit
    double screenshotAfterS = 5.0; ///< --screenshot-after: s of wall clock after the window opened
};

/// What parsing decided: run with `options`, or exit with `exitCode` after printing `message` (help, version,
/// usage errors).
struct ParsedCommandLine {
    std::optional<SimOptions> options;
    int exitCode = 0;
    std::string message;
};
ParsedCommandLine parseCommandLine(int argc, const char* const* argv);

} // namespace hs::simapp
