// The case reader: JSON text -> CaseSpec (strict JSON, schema upgrade, field rules, checkCase).
// Properties: an error names the source; an accepted case written back with toJson reads back equal.

#include "FuzzSupport.h"
#include "hs/scene/CaseSpec.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const auto spec = hs::scene::parseCase(text, "fuzz.json");
    if (!spec.ok()) {
        hs::fuzz::check(spec.error().detail.find("fuzz.json") != std::string::npos, "an error names the source",
                        spec.error().detail);
        return 0;
    }
    const auto again = hs::scene::parseCase(hs::scene::toJson(*spec), "written.json");
    hs::fuzz::check(again.ok(), "an accepted case, written, reads back");
    hs::fuzz::check(*again == *spec, "an accepted case, written, reads back equal");
    return 0;
}
