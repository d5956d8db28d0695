// The scripted device's key frames (docs/file-formats.md, after "Trial files"): JSON written by hand or by tools.
// Properties: an error names the source; an accepted script, written with scriptJson, reads back to the same key
// frames; every sample it gives is inside the device's ranges.

#include "FuzzSupport.h"
#include "hs/sim/Device.h"
#include "hs/sim/Script.h"

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const auto script = hs::sim::parseScript(text, "fuzz-script.json");
    if (!script.ok()) {
        hs::fuzz::check(script.error().detail.find("fuzz-script.json") != std::string::npos,
                        "an error names the source", script.error().detail);
        return 0;
    }
    const auto again = hs::sim::parseScript(hs::sim::scriptJson(*script), "written.json");
    hs::fuzz::check(again.ok() && again->keyframes.size() == script->keyframes.size(),
                    "an accepted script, written, reads back", again.ok() ? "" : again.error().detail);
    const std::uint64_t ticks = script->tickCount();
    for (const std::uint64_t tick : {std::uint64_t{0}, ticks / 2, ticks})
        hs::fuzz::check(hs::sim::isValid(script->sampleAt(tick)), "every sample is inside the device's ranges");
    return 0;
}
