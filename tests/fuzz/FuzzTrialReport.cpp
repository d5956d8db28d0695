// The simulator's trial reports (docs/file-formats.md, "Trial reports"): JSON files the workstation opens to review
// a trial. Properties: an error names the source; an accepted report, written again, reads back to the same bytes.

#include "FuzzSupport.h"
#include "hs/sim/Metrics.h"

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    hs::sim::ReportReadLimits limits;
    limits.maxSeries = 4096; // a campaign's inputs are small
    limits.maxSurface = 4096;
    const auto report = hs::sim::parseReport(text, "fuzz.json", limits);
    if (!report.ok()) {
        hs::fuzz::check(report.error().detail.find("fuzz.json") != std::string::npos, "an error names the source",
                        report.error().detail);
        return 0;
    }
    const std::string written = hs::sim::reportJson(*report);
    const auto again = hs::sim::parseReport(written, "written.json", limits);
    hs::fuzz::check(again.ok() && hs::sim::reportJson(*again) == written,
                    "an accepted report, written, reads back to the same bytes",
                    again.ok() ? "" : again.error().detail);
    // The tables and plots the page and the workstation draw are made from any accepted report.
    (void)hs::sim::reportTables(*report);
    (void)hs::sim::reportPlots(*report);
    return 0;
}
