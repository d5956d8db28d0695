// The batch manifest reader (manifest.tsv: one job per line, paths that must stay inside the batch folder).
// Properties: an error names the source; an accepted manifest formats and reads back to the same text.

#include "FuzzSupport.h"
#include "hs/batch/Manifest.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const auto manifest = hs::batch::parseManifest(text, "fuzz-manifest.tsv");
    if (!manifest.ok()) {
        hs::fuzz::check(manifest.error().detail.find("fuzz-manifest.tsv") != std::string::npos,
                        "an error names the source", manifest.error().detail);
        return 0;
    }
    const std::string formatted = hs::batch::formatManifest(*manifest);
    const auto again = hs::batch::parseManifest(formatted, "formatted.tsv");
    hs::fuzz::check(again.ok() && hs::batch::formatManifest(*again) == formatted, "a formatted manifest reads back");
    return 0;
}
