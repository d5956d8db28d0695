// The batch job status record reader (status/<job>.json, written by jobs, read by `batch status`).
// Properties: an error names the source; an accepted record written with toJson reads back.

#include "FuzzSupport.h"
#include "hs/batch/JobStatus.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const auto record = hs::batch::parseStatus(text, "fuzz-status.json");
    if (!record.ok())
        hs::fuzz::check(record.error().detail.find("fuzz-status.json") != std::string::npos,
                        "an error names the source", record.error().detail);
    else
        hs::fuzz::check(hs::batch::parseStatus(hs::batch::toJson(*record), "written.json").ok(),
                        "an accepted record, written, reads back");
    return 0;
}
