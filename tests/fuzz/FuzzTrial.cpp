// The simulator's trial recordings (docs/file-formats.md, "Trial files"): binary files others pass around to replay.
// Properties: an error names the source; an accepted trial, written with writeTrial, reads back with the same header
// and samples.

#include "FuzzSupport.h"
#include "hs/sim/Trial.h"

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    hs::sim::TrialReadLimits limits;
    limits.maxSamples = 4096; // a campaign's inputs are small; the count check runs before any allocation anyway
    const auto trial = hs::sim::parseTrial(bytes, "fuzz.trial", limits);
    if (!trial.ok()) {
        hs::fuzz::check(trial.error().detail.find("fuzz.trial") != std::string::npos, "an error names the source",
                        trial.error().detail);
        return 0;
    }
    const std::string path = (hs::fuzz::scratchFolder() / "written.trial").string();
    const auto written = hs::sim::writeTrial(*trial, path);
    hs::fuzz::check(written.ok(), "an accepted trial can be written", written.ok() ? "" : written.error().detail);
    const auto again = hs::sim::readTrial(path, limits);
    hs::fuzz::check(again.ok() && again->samples.size() == trial->samples.size() &&
                        again->header.seed == trial->header.seed,
                    "an accepted trial, written, reads back", again.ok() ? "" : again.error().detail);
    return 0;
}
