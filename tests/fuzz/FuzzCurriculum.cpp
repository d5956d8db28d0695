// The batch curriculum reader (JSON with case templates and samplers). Property: an error names the source.

#include "FuzzSupport.h"
#include "hs/batch/Curriculum.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const auto curriculum = hs::batch::parseCurriculum(text, "fuzz-curriculum.json");
    if (!curriculum.ok())
        hs::fuzz::check(curriculum.error().detail.find("fuzz-curriculum.json") != std::string::npos,
                        "an error names the source", curriculum.error().detail);
    return 0;
}
