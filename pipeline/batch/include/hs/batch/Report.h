#pragma once
/// The summary of a batch: BATCH/report/report.csv (one row per job), BATCH/report/report.html, the index (the summary,
/// the distributions of the drawn values against what the curriculum asked, plotted by Chart.js inlined from
/// Debian's libjs-chart.js, one line per page of cases, and the jobs that failed) and BATCH/report/pages/, the table
/// ReportParams::rowsPerPage cases a page with a thumbnail of each organ, so that a report of 10 000 cases opens at
/// once. Every page is self-contained (no network access; thumbnails inlined); pages link to each other.
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
    std::size_t rowsPerPage = 100;                  ///< cases per page of the table (pages/cases-NNNN.html)
};

struct ReportResult {
    std::string csvPath;
    std::string htmlPath;
    std::size_t rows = 0;
    std::size_t pages = 0; ///< case pages
    std::size_t charts = 0;
    std::vector<std::string> warnings; ///< e.g. the chart library is missing, a thumbnail could not be drawn
};

/// Reads every job's case file and status record and writes the CSV and the page atomically. Jobs without a record
/// are listed as pending. Fails on an unreadable curriculum copy or a write error; a record that does not parse is
/// listed with its error.
[[nodiscard]] Result<ReportResult> writeBatchReport(const std::string& batchFolder, const Manifest& manifest,
                                                    const ReportParams& params = {});

} // namespace hs::batch
