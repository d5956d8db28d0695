#pragma once
/// The summary of a batch: BATCH/report/report.csv (one row per job) and BATCH/report/report.html, a self-contained
/// page (no file or network access) with the same table, a thumbnail of each organ, and the distributions of the
/// drawn values against what the curriculum asked, plotted by Chart.js (inlined from Debian's libjs-chart.js).
/// docs/batch.md, "Report".

#include "hs/batch/Manifest.h"
#include "hs/core/Result.h"
#include "hs/io/HtmlPage.h"

#include <cstddef>
#include <string>
#include <vector>

namespace hs::batch {

constexpr std::string_view kReportFolder = "report";
/// Where Debian's libjs-chart.js puts the library.
constexpr std::string_view kDefaultChartLibrary = io::kDefaultChartLibrary;

struct ReportParams {
    std::string chartLibrary{kDefaultChartLibrary}; ///< Chart.js (UMD build) to inline; missing: no plots, a note
    int thumbnailWidthPx = 96;                      ///< px; the height follows the organ's proportions
};

struct ReportResult {
    std::string csvPath;
    std::string htmlPath;
    std::size_t rows = 0;
    std::size_t charts = 0;
    std::vector<std::string> warnings; ///< e.g. the chart library is missing, a thumbnail could not be drawn
};

/// Reads every job's case file and status record and writes the CSV and the page atomically. Jobs without a record
/// are listed as pending. Fails on an unreadable curriculum copy or a write error; a record that does not parse is
/// listed with its error.
[[nodiscard]] Result<ReportResult> writeBatchReport(const std::string& batchFolder, const Manifest& manifest,
                                                    const ReportParams& params = {});

} // namespace hs::batch
