// The command line of hysteroscene-sim: CLI11 checks the syntax and the choices; the world's own checks
// (checkScopeConfig, checkFluidSettings) name the field of a value out of range.
#include "hs/simapp/SimOptions.h"

#include "hs/core/ExitCode.h"
#include "hs/core/Units.h"
#include "hs/sim/Script.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace hs::simapp {

namespace {

bool parseHex16(const std::string& text, std::uint16_t& out) {
    if (text.empty() || text.size() > 4)
        return false;
    unsigned value = 0;
    for (char ch : text) {
        const int digit = ch >= '0' && ch <= '9'   ? ch - '0'
                          : ch >= 'a' && ch <= 'f' ? ch - 'a' + 10
                          : ch >= 'A' && ch <= 'F' ? ch - 'A' + 10
                                                   : -1;
        if (digit < 0)
            return false;
        value = value * 16u + static_cast<unsigned>(digit);
    }
    out = static_cast<std::uint16_t>(value);
    return true;
}

std::string hex4(std::uint16_t v) {
    char text[8];
    std::snprintf(text, sizeof text, "%04x", static_cast<unsigned>(v));
    return text;
}

/// Combinations CLI11 cannot express; empty when fine.
std::string combinationProblem(const SimOptions& o) {
    if (o.headless && o.replayPath.empty() && o.device.kind != DeviceSpec::Kind::Scripted &&
        o.device.kind != DeviceSpec::Kind::Demo)
        return "--headless needs --replay TRIAL, --device scripted:FILE or --demo";
    if (!o.replayPath.empty() && o.device.kind != DeviceSpec::Kind::Keyboard)
        return "--replay plays the trial's own samples: it takes no --device";
    if (o.headless && o.scene.empty())
        return "--headless needs a SCENE";
    if (!o.writeDemoPath.empty() && o.scene.empty())
        return "--write-demo needs a SCENE";
    if (o.stopAfterS > 0.0 && (!o.headless || !o.replayPath.empty()))
        return "--seconds cuts a headless scripted run or the demo short: a replay plays its whole trial, a window "
               "runs until it is closed";
    if (!o.htmlPath.empty() && o.reportPath.empty() && o.headless)
        return "--html needs --report OUT.json";
    return {};
}

} // namespace

std::string DeviceSpec::text() const {
    switch (kind) {
    case Kind::Keyboard:
        return "keyboard";
    case Kind::Hid:
        return vendorId == 0 && productId == 0 ? "hid" : "hid:" + hex4(vendorId) + ":" + hex4(productId);
    case Kind::Scripted:
        return "scripted:" + scriptPath;
    case Kind::Demo:
        return "demo";
    }
    return "keyboard";
}

Result<DeviceSpec> parseDeviceSpec(const std::string& text) {
    DeviceSpec spec;
    if (text == "keyboard")
        return spec;
    if (text == "hid") {
        spec.kind = DeviceSpec::Kind::Hid;
        return spec;
    }
    if (text.rfind("hid:", 0) == 0) {
        spec.kind = DeviceSpec::Kind::Hid;
        const std::string ids = text.substr(4);
        const auto colon = ids.find(':');
        if (colon == std::string::npos || !parseHex16(ids.substr(0, colon), spec.vendorId) ||
            !parseHex16(ids.substr(colon + 1), spec.productId))
            return fail(ErrorCode::InvalidInput,
                        "--device: \"" + text + "\" is not hid:VID:PID with hexadecimal ids (e.g. hid:046d:c62b)");
        return spec;
    }
    if (text == "demo") {
        spec.kind = DeviceSpec::Kind::Demo;
        return spec;
    }
    if (text.rfind("scripted:", 0) == 0 && text.size() > 9) {
        spec.kind = DeviceSpec::Kind::Scripted;
        spec.scriptPath = text.substr(9);
        return spec;
    }
    return fail(ErrorCode::InvalidInput,
                "--device: \"" + text + "\" is not one of keyboard, hid, hid:VID:PID, scripted:FILE, demo");
}

ParsedCommandLine parseCommandLine(int argc, const char* const* argv) {
    CLI::App app{"hysteroscene-sim: the preview simulator. Runs a scene package with a hysteroscope driven by the "
                 "keyboard and mouse, a haptic device or a script, and reports the trial's metrics."};
    app.name("hysteroscene-sim");
    app.set_version_flag("--version", std::string("hysteroscene-sim ") + HS_VERSION);
    app.footer("Exit codes: 0 ok, 2 usage, 3 invalid input, 4 failed. See docs/simulator.md.");
    SimOptions o;
    double optic = o.world.scope.opticDeg, diameter = o.world.scope.diameterMm;
    double pumpMmHg = o.world.fluid.pumpPressureKpa / units::kKpaPerMmHg;
    double mapMmHg = o.world.fluid.meanArterialPressureKpa / units::kKpaPerMmHg;
    std::string exercise = "exploration", device = "keyboard";
    app.add_option("SCENE", o.scene, "the scene package (a folder written by the workstation or hysteroscene-cli)");
    app.add_option("--optic", optic, "the optic's angle, degrees")
        ->check(CLI::IsMember({0.0, 12.0, 30.0}))
        ->capture_default_str();
    app.add_option("--diameter", diameter, "the sheath's diameter, mm")
        ->check(CLI::IsMember({2.9, 4.0, 5.0}))
        ->capture_default_str();
    app.add_option("--exercise", exercise, "the exercise")
        ->check(CLI::IsMember({"exploration", "diagnosis", "polypectomy", "myomectomy"}))
        ->capture_default_str();
    // Without the options the settings stay the world's defaults in kPa (no round trip through mmHg).
    CLI::Option* pumpOption = app.add_option("--pump-mmhg", pumpMmHg, "the pump's set pressure, mmHg (20-150)")
                                  ->default_str(std::to_string(std::lround(pumpMmHg)));
    CLI::Option* mapOption =
        app.add_option("--map-mmhg", mapMmHg, "the patient's mean arterial pressure, mmHg (50-150)")
            ->default_str(std::to_string(std::lround(mapMmHg)));
    std::string medium = "saline";
    app.add_option("--medium", medium,
                   "the distension medium: saline (isotonic, bipolar) or glycine (hypotonic, monopolar); sets the "
                   "deficit's warning and limit of the guidelines")
        ->check(CLI::IsMember({"saline", "glycine"}))
        ->capture_default_str();
    bool elderly = false;
    app.add_flag("--elderly-or-comorbid", elderly,
                 "the patient is elderly or has comorbidities: the guidelines' lower deficit limits");
    app.add_option("--seed", o.world.seed, "the world's seed")->capture_default_str();
    app.add_option("--device", device, "keyboard, hid, hid:VID:PID, scripted:FILE or demo")->capture_default_str();
    bool demo = false;
    app.add_flag(
        "--demo", demo,
        "play the built-in demonstration of the exercise (the same as --device demo): a supervisor watches it, a "
        "check runs it headless");
    app.add_option("--record", o.recordPath, "write the trial (every device sample) to this file");
    app.add_option("--replay", o.replayPath, "play a recorded trial back");
    app.add_option("--write-demo", o.writeDemoPath,
                   "write the exercise's demonstration as a script (JSON) to this file and quit: edit it, play it with "
                   "--device scripted:FILE");
    // For the docs' pictures: the window saved after a while, then closed (not in --help).
    app.add_option("--screenshot", o.screenshotPath, "save the window to this image, then quit")->group("");
    app.add_option("--screenshot-after", o.screenshotAfterS, "seconds after the window opened")
        ->check(CLI::Range(0.0, 3600.0))
        ->group("");
    app.add_flag("--headless", o.headless, "no window: step as fast as possible (with --replay or a scripted device)");
    app.add_option("--seconds", o.stopAfterS,
                   "headless: stop the script or the demo after this many seconds of trial time (a check of its "
                   "first part; the recorded trial holds the samples played)")
        ->check(CLI::Range(1.0 / sim::kDeviceRateHz, sim::kMaxScriptSeconds));
    app.add_option("--report", o.reportPath, "write the trial's report (JSON) here");
    app.add_option("--html", o.htmlPath, "write the trial's report page (HTML) here");
    // The workstation's convention (--lang, else HS_LANG, else the system locale); headless runs stay English.
    app.add_option("--lang,--language", o.language,
                   "the window's language: de, fr, it or en (default: HS_LANG, else the system locale)");

    ParsedCommandLine parsed;
    std::ostringstream out, err;
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) { // --help, --version
        parsed.exitCode = app.exit(e, out, err);
        parsed.message = out.str() + err.str();
        return parsed;
    } catch (const CLI::ParseError& e) {
        app.exit(e, out, err);
        parsed.exitCode = kExitUsage;
        parsed.message = err.str() + out.str();
        return parsed;
    }
    if (demo && device != "keyboard" && device != "demo") {
        parsed.exitCode = kExitUsage;
        parsed.message = "--demo plays the built-in demonstration: it takes no --device " + device + "\n";
        return parsed;
    }
    auto spec = parseDeviceSpec(demo ? std::string("demo") : device);
    if (!spec) {
        parsed.exitCode = kExitUsage;
        parsed.message = spec.error().detail + "\n";
        return parsed;
    }
    o.device = *spec;
    o.world.scope.opticDeg = optic;
    o.world.scope.diameterMm = diameter;
    fromString(exercise, o.world.exercise);
    if (pumpOption->count() > 0)
        o.world.fluid.pumpPressureKpa = units::kpaFromMmHg(pumpMmHg);
    if (mapOption->count() > 0)
        o.world.fluid.meanArterialPressureKpa = units::kpaFromMmHg(mapMmHg);
    sim::fromString(medium, o.world.fluid.medium);
    o.world.fluid.elderlyOrComorbid = elderly;
    o.world.fluid = sim::withGuidelineDeficits(o.world.fluid);
    if (const std::string problem = combinationProblem(o); !problem.empty()) {
        parsed.exitCode = kExitUsage;
        parsed.message = problem + "\nRun with --help for more information.\n";
        return parsed;
    }
    parsed.options = std::move(o);
    return parsed;
}

} // namespace hs::simapp
