#pragma once
/// What a trial measured, and its report (JSON and a self-contained HTML page with plots). The metrics follow the
/// published hysteroscopy simulators (Bajka et al. 2010: visualization, ergonomics, safety and fluid handling);
/// docs/simulator.md ("Exercises and metrics") defines each one.

#include "hs/core/Result.h"
#include "hs/core/Vec3.h"
#include "hs/sim/Scope.h"
#include "hs/sim/Trial.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hs::sim {

/// A target of the exploration exercise: a tubal ostium, the fundus or one wall of the cavity.
struct ExplorationTarget {
    std::string name; ///< "ostium-left", "ostium-right", "fundus", "anterior", "posterior", "left", "right"
    double visualizedPercent = 0.0; ///< % of the target's surface seen
    bool seen = false;              ///< an ostium: its centre seen; a zone: at least kZoneSeenPercent of it seen
    double firstSeenS = -1.0;       ///< s into the trial; -1 never
};
/// A wall zone counts as seen from this share of its surface on.
inline constexpr double kZoneSeenPercent = 50.0;

struct Perforation {
    double timeS = 0.0;
    Vec3 locationMm;           ///< where the tip went through the wall (scene frame)
    double depthMm = 0.0;      ///< mm, the deepest the tip went beyond the wall's surface
    std::string region;        ///< the region the tip went through ("myometrium", "myoma-1", ...)
    bool falsePassage = false; ///< through the cervical canal's wall (before the internal os), not the corpus'
};

struct PathologyFinding {
    std::string id;     ///< the case's pathology id
    std::string kind;   ///< "myoma", "polyp"
    bool seen = false;  ///< part of it was in view and in focus
    bool found = false; ///< the trainee marked it
    double foundS = -1.0;
};

/// One sample of the time series (10 Hz).
struct SeriesPoint {
    double timeS = 0.0;
    double forceN = 0.0;      ///< contact force between scope and tissue, N
    double pressureKpa = 0.0; ///< intrauterine pressure, kPa
    double deficitMl = 0.0;   ///< fluid deficit, mL
    double bloodLossMl = 0.0; ///< blood from the cut vessels so far, mL
    double pumpSetKpa = 0.0;  ///< the pump's set pressure then, kPa (its buttons move it during the trial)
};

/// One face of the cavity's surface, unrolled about the cavity's axis, for the visualized-surface plot.
struct SurfaceSample {
    double aroundDeg = 0.0; ///< degrees about the canal axis, 0 anterior, +90 the patient's left
    double alongMm = 0.0;   ///< mm from the internal os towards the fundus
    bool seen = false;
};

/// A pathology's resection (the operative exercises).
struct PathologyResection {
    std::string id;         ///< the case's pathology id
    std::string kind;       ///< "myoma", "polyp"
    double volumeMl = 0.0;  ///< its volume on the simulation mesh
    double removedMl = 0.0; ///< of it, cut away (chips included)
    double removedPercent = 0.0;
};

/// What the resectoscope's loop did (docs/simulator.md, "Cutting").
struct ResectionMetrics {
    std::vector<PathologyResection> pathologies;
    double healthyRemovedMl = 0.0;     ///< tissue cut away that was no pathology's
    double deepestMyometriumMm = 0.0;  ///< how far below the cavity's surface (at rest) a cut reached into the wall
    int perforatingCuts = 0;           ///< cut events that opened the serosa
    std::uint64_t cutEvents = 0;       ///< steps whose cut removed tissue
    std::uint64_t removedTets = 0;     ///< of the simulation mesh
    std::uint64_t chips = 0;           ///< pieces cut free
    std::uint64_t chipsMade = 0;       ///< chips in the fluid: a strip per pedal press, and each piece cut free
    std::uint64_t chipsCarriedOut = 0; ///< chips the drawn-in loop caught and took out through the canal
    std::uint64_t chipsLeft = 0;       ///< chips in the cavity now (at the end: left behind)
    double cuttingTimeS = 0.0;         ///< s with the cutting pedal down and the loop out
    double resectionTimeS = 0.0;       ///< s from the first cut that removed tissue to the last
    double firstCutS = -1.0;           ///< s into the trial; -1 none
    double loopPathMm = 0.0;           ///< the loop's path with the cutting pedal down
    double coagulationTimeS = 0.0;     ///< s with the coagulating pedal down and the loop out
};

struct TrialMetrics {
    double timeS = 0.0;
    double pathLengthMm = 0.0; ///< the tip's path inside the body (beyond the external os)
    double cavitySurfaceVisualizedPercent = 0.0;
    std::vector<ExplorationTarget> targets;
    double horizonErrorMeanDeg = 0.0; ///< mean over the time in the cavity
    double horizonErrorMaxDeg = 0.0;
    int wallContacts = 0; ///< contacts begun (tip or shaft against the cavity's wall)
    double peakForceN = 0.0;
    double contactTimeS = 0.0; ///< s, the tip or shaft touching the cavity's wall (not the sheath in the canal)
    std::vector<Perforation> perforations;
    double timeAboveMeanArterialPressureS = 0.0;
    double maxPressureKpa = 0.0;
    double inflowMl = 0.0;
    double outflowMl = 0.0;
    double deficitMl = 0.0;            ///< inflow - outflow (what the patient absorbed or retained), mL
    double intravasationMl = 0.0;      ///< of the fluid, what went into the patient's vessels, mL
    double bloodLossMl = 0.0;          ///< blood from the cut vessels, mL
    double finalPumpPressureKpa = 0.0; ///< the pump's set pressure at the end (its buttons move it)
    bool deficitWarning = false;
    bool deficitLimitReached = false;
    double redOutTimeS = 0.0; ///< s with the walls closed on the lens
    std::vector<PathologyFinding> pathologies;
    int falseMarks = 0;         ///< marks on no pathology
    ResectionMetrics resection; ///< the operative exercises' (empty pathologies otherwise)
};

struct TrialReport {
    TrialHeader header;
    std::uint64_t samples = 0;
    TrialMetrics metrics;
    bool explorationComplete = false; ///< every exploration target seen, no perforation
    bool diagnosisComplete = false;   ///< every pathology found, no false mark, no perforation
    std::vector<SeriesPoint> series;
    std::vector<SurfaceSample> surface;
};

/// One table of the report. The HTML page and the workstation's review show the same tables, made here once.
struct ReportTable {
    std::string section;                        ///< the heading it opens ("Fluid"); empty: it continues the one above
    std::vector<std::string> head;              ///< column names; empty: each row is a (name, value) pair
    std::vector<std::vector<std::string>> rows; ///< values as text, with their units
};
/// The report's tables in order: overview, exploration, safety, fluid, diagnosis and, in the operative exercises,
/// resection.
std::vector<ReportTable> reportTables(const TrialReport& report);

/// One line of a plot over the trial's time: (time s, value) points.
struct ReportLine {
    std::string label;
    std::vector<std::pair<double, double>> points;
};
struct ReportPlot {
    std::string title;
    std::string yTitle; ///< the value's unit ("kPa")
    std::vector<ReportLine> lines;
};
/// The plots over time: contact force; intrauterine pressure with the mean arterial pressure and the pump's set
/// pressure; the fluid deficit with its warning and limit; and, in the operative exercises, the blood loss.
std::vector<ReportPlot> reportPlots(const TrialReport& report);

/// The faces of the visualized-surface plot: all of the report's, or at most 20000 evenly strided (a plot of more
/// draws no better and slower; the JSON keeps them all).
std::vector<SurfaceSample> plottedSurface(const TrialReport& report);

/// JSON of the report (docs/file-formats.md, "Trial reports"). Doubles are written with 17 significant digits so
/// two replays compare bit for bit.
std::string reportJson(const TrialReport& report);

/// The report as one self-contained HTML page: the metrics' tables, force and pressure over time and the cavity's
/// visualized surface, plotted by Chart.js inlined from `chartLibrary` (Debian's libjs-chart.js). NotFound naming
/// the file when the library is missing.
[[nodiscard]] Result<std::string>
reportHtml(const TrialReport& report, const std::string& chartLibrary = "/usr/share/javascript/chart.js/chart.min.js");

/// Limits for reading untrusted reports.
struct ReportReadLimits {
    std::int64_t maxBytes = 256ll * 1024 * 1024;
    std::size_t maxSeries = 4u * 3600 * 10;    ///< four hours at 10 Hz
    std::size_t maxSurface = 4u * 1000 * 1000; ///< faces of the cavity
    std::size_t maxListed = 100000;            ///< targets, perforations, pathologies
};
/// Reads a report written by reportJson (version 1 or 2) and checks every field: its type, its range and that the
/// columns have equal lengths. Errors name `name`, the field's JSON pointer and the allowed range. Reports of
/// version 1 have no pump column: their series get the header's set pressure.
[[nodiscard]] Result<TrialReport> parseReport(std::string_view text, const std::string& name,
                                              const ReportReadLimits& limits = {});
/// The same from a file (IoError or LimitExceeded naming the file).
[[nodiscard]] Result<TrialReport> readReport(const std::string& path, const ReportReadLimits& limits = {});

/// Writes the JSON (and, when htmlPath is not empty, the page) atomically.
[[nodiscard]] Status writeReport(const TrialReport& report, const std::string& jsonPath,
                                 const std::string& htmlPath = {});

} // namespace hs::sim
