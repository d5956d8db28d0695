// The workstation's review of a trial: the report's own tables and plots (hs::sim::reportTables, reportPlots), drawn
// with Qt Charts.
#include "hs/widgets/panels/TrialReportView.h"

#include <QChart>
#include <QChartView>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineSeries>
#include <QList>
#include <QPointF>
#include <QPushButton>
#include <QScatterSeries>
#include <QTabWidget>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <utility>

namespace hs::widgets {

namespace {

/// The metrics' tree has as many columns as the widest table of the report.
constexpr int kMetricColumns = 5;

QString text(const std::string& s) {
    return QString::fromStdString(s);
}

QString duration(double s) {
    const int whole = static_cast<int>(std::lround(s));
    return whole >= 60 ? TrialReportView::tr("%1 min %2 s").arg(whole / 60).arg(whole % 60, 2, 10, QLatin1Char('0'))
                       : TrialReportView::tr("%1 s").arg(whole);
}

QString exerciseName(sim::Exercise exercise) {
    switch (exercise) {
    case sim::Exercise::Exploration:
        return TrialReportView::tr("Exploration");
    case sim::Exercise::Diagnosis:
        return TrialReportView::tr("Diagnosis");
    case sim::Exercise::Polypectomy:
        return TrialReportView::tr("Polypectomy");
    case sim::Exercise::Myomectomy:
        return TrialReportView::tr("Myomectomy");
    }
    return {};
}

QChartView* makeChartView(QWidget* parent, const QString& name) {
    auto* chart = new QChart;
    chart->setMargins(QMargins(2, 2, 2, 2));
    auto* view = new QChartView(chart, parent);
    view->setObjectName(name);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumSize(320, 220);
    return view;
}

/// The smallest box holding `points` (x then y), or none for no points.
struct Bounds {
    double xMin = 0.0, xMax = 0.0, yMin = 0.0, yMax = 0.0;
    bool empty = true;
    void add(double x, double y) {
        if (!std::isfinite(x) || !std::isfinite(y))
            return;
        xMin = empty ? x : std::min(xMin, x);
        xMax = empty ? x : std::max(xMax, x);
        yMin = empty ? y : std::min(yMin, y);
        yMax = empty ? y : std::max(yMax, y);
        empty = false;
    }
};

/// Attaches a linear x and y axis with their titles to every series of `chart`, spanning all of them (an axis
/// attached to several series takes the first one's range otherwise, and a limit line above the values is lost).
void addAxes(QChart* chart, const QString& xTitle, const QString& yTitle, const Bounds& bounds) {
    auto* x = new QValueAxis;
    x->setTitleText(xTitle);
    auto* y = new QValueAxis;
    y->setTitleText(yTitle);
    if (!bounds.empty) {
        x->setRange(bounds.xMin, bounds.xMax > bounds.xMin ? bounds.xMax : bounds.xMin + 1.0);
        const double pad = std::max(0.05 * (bounds.yMax - bounds.yMin), 1e-3);
        y->setRange(bounds.yMin >= 0.0 ? 0.0 : bounds.yMin - pad, bounds.yMax + pad); // from 0 when all are above
        y->applyNiceNumbers();
    }
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    for (QAbstractSeries* series : chart->series()) {
        series->attachAxis(x);
        series->attachAxis(y);
    }
}

} // namespace

TrialReportView::TrialReportView(QWidget* parent) : QWidget(parent) {
    setObjectName("trialReportView");
    m_heading = new QLabel(this);
    m_heading->setObjectName("trialHeading");
    QFont bold = m_heading->font();
    bold.setBold(true);
    bold.setPointSizeF(bold.pointSizeF() * 1.2);
    m_heading->setFont(bold);
    m_details = new QLabel(this);
    m_details->setObjectName("trialDetails");
    m_details->setWordWrap(true);
    m_details->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_sceneNote = new QLabel(this);
    m_sceneNote->setObjectName("trialSceneNote");
    m_sceneNote->setWordWrap(true);

    m_metrics = new QTreeWidget(this);
    m_metrics->setObjectName("trialMetrics");
    m_metrics->setColumnCount(kMetricColumns);
    m_metrics->setHeaderHidden(true);
    m_metrics->setRootIsDecorated(false);
    m_metrics->setAlternatingRowColors(true);
    m_metrics->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_plotPage = new QWidget(this);
    new QGridLayout(m_plotPage);
    m_surface = makeChartView(this, QStringLiteral("trialSurfacePlot"));

    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName("trialTabs");
    m_tabs->addTab(m_metrics, tr("&Metrics"));
    m_tabs->addTab(m_plotPage, tr("&Over Time"));
    m_tabs->addTab(m_surface, tr("&Visualized Surface"));

    m_replay = new QPushButton(tr("&Replay in the Simulator..."), this);
    m_replay->setObjectName("trialReplay");
    m_replay->setEnabled(false);
    connect(m_replay, &QPushButton::clicked, this, [this] {
        const QString trial = trialPath();
        if (!trial.isEmpty())
            emit replayRequested(trial);
        else
            updateReplay(); // gone since: say so on the button
    });

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_heading);
    layout->addWidget(m_details);
    auto* sceneRow = new QHBoxLayout;
    sceneRow->addWidget(m_sceneNote, 1);
    sceneRow->addWidget(m_replay);
    layout->addLayout(sceneRow);
    layout->addWidget(m_tabs, 1);
}

QString TrialReportView::trialPath() const {
    if (m_path.isEmpty())
        return {};
    QString base = m_path;
    if (base.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive))
        base.chop(5);
    const QString trial = base + QStringLiteral(".trial");
    return QFileInfo(trial).isFile() ? trial : QString();
}

bool TrialReportView::ranOnOpenScene() const {
    return !m_openScene.isEmpty() && m_openScene == text(m_report.header.sceneSha256);
}

void TrialReportView::updateReplay() {
    const bool trial = !trialPath().isEmpty();
    m_replay->setEnabled(trial);
    QString base = QFileInfo(m_path).completeBaseName();
    m_replay->setToolTip(trial ? tr("Play the recorded trial again in the simulator, on its scene package.")
                               : tr("No recorded trial (%1.trial) beside the report: the simulator writes one "
                                    "with the report when a trial ends.")
                                     .arg(base));
}

void TrialReportView::showReport(sim::TrialReport report, const QString& path) {
    m_report = std::move(report);
    m_path = path;
    const sim::TrialHeader& h = m_report.header;
    m_heading->setText(tr("%1 trial, %2").arg(exerciseName(h.exercise), duration(m_report.metrics.timeS)));
    QString details = tr("Scene %1, seed %2, %3° optic, %4 mm scope; device %5; physics %6.")
                          .arg(text(h.sceneSha256.substr(0, 12)))
                          .arg(h.seed)
                          .arg(h.scope.opticDeg, 0, 'f', 0)
                          .arg(h.scope.diameterMm, 0, 'f', 1)
                          .arg(text(h.device), text(h.physics.engine));
    if (!h.startedUtc.empty())
        details += QLatin1Char(' ') + tr("Started %1 (UTC).").arg(text(h.startedUtc));
    details += QLatin1Char(' ') + tr("Report: %1").arg(QFileInfo(path).fileName());
    m_details->setText(details);
    fillMetrics();
    fillPlots();
    fillSurface();
    updateSceneNote();
    updateReplay();
}

void TrialReportView::setOpenScene(const QString& packageSha256) {
    m_openScene = packageSha256;
    updateSceneNote();
}

QString TrialReportView::sceneNote() const {
    return m_sceneNote->text();
}

void TrialReportView::updateSceneNote() {
    if (m_path.isEmpty() || m_openScene.isEmpty())
        m_sceneNote->setText(tr("Open the trial's scene package for review (File > Review Scene Package) to see "
                                "its organ beside the report."));
    else if (m_openScene == text(m_report.header.sceneSha256))
        m_sceneNote->setText(tr("This trial ran on the scene under review."));
    else
        m_sceneNote->setText(tr("This trial ran on another scene than the one under review (%1, not %2).")
                                 .arg(text(m_report.header.sceneSha256.substr(0, 12)), m_openScene.left(12)));
}

void TrialReportView::fillMetrics() {
    m_metrics->clear();
    QTreeWidgetItem* section = nullptr;
    QFont bold = m_metrics->font();
    bold.setBold(true);
    for (const sim::ReportTable& table : sim::reportTables(m_report)) {
        if (!table.section.empty() || !section) {
            section = new QTreeWidgetItem(m_metrics, {text(table.section)});
            section->setFont(0, bold);
            section->setFirstColumnSpanned(true);
        }
        if (!table.head.empty()) {
            auto* head = new QTreeWidgetItem(section);
            for (std::size_t c = 0; c < table.head.size() && c < kMetricColumns; ++c) {
                head->setText(static_cast<int>(c), text(table.head[c]));
                head->setFont(static_cast<int>(c), bold);
            }
        }
        for (const std::vector<std::string>& row : table.rows) {
            auto* item = new QTreeWidgetItem(section);
            for (std::size_t c = 0; c < row.size() && c < kMetricColumns; ++c)
                item->setText(static_cast<int>(c), text(row[c]));
        }
    }
    m_metrics->expandAll();
    for (int c = 0; c < kMetricColumns; ++c)
        m_metrics->resizeColumnToContents(c);
}

void TrialReportView::fillPlots() {
    qDeleteAll(m_plots);
    m_plots.clear();
    auto* grid = static_cast<QGridLayout*>(m_plotPage->layout());
    const std::vector<sim::ReportPlot> plots = sim::reportPlots(m_report);
    for (std::size_t i = 0; i < plots.size(); ++i) {
        const sim::ReportPlot& plot = plots[i];
        QChartView* view = makeChartView(m_plotPage, QStringLiteral("trialPlot%1").arg(i));
        QChart* chart = view->chart();
        chart->setTitle(text(plot.title));
        Bounds bounds;
        for (const sim::ReportLine& line : plot.lines) {
            QList<QPointF> points;
            points.reserve(static_cast<qsizetype>(line.points.size()));
            for (const auto& [x, y] : line.points) {
                points.append(QPointF(x, y));
                bounds.add(x, y);
            }
            auto* series = new QLineSeries;
            series->setName(text(line.label));
            series->replace(points);
            chart->addSeries(series);
        }
        addAxes(chart, tr("time (s)"), text(plot.yTitle), bounds);
        grid->addWidget(view, static_cast<int>(i / 2), static_cast<int>(i % 2));
        m_plots.append(view);
    }
}

void TrialReportView::fillSurface() {
    QChart* chart = m_surface->chart();
    chart->removeAllSeries();
    for (QAbstractAxis* axis : chart->axes())
        chart->removeAxis(axis);
    chart->setTitle(tr("Cavity surface, unrolled about the canal's axis"));
    auto* seen = new QScatterSeries;
    seen->setName(tr("seen"));
    auto* unseen = new QScatterSeries;
    unseen->setName(tr("not seen"));
    for (QScatterSeries* series : {seen, unseen}) {
        series->setMarkerSize(3.0);
        series->setBorderColor(Qt::transparent);
    }
    seen->setColor(QColor(46, 139, 87));
    unseen->setColor(QColor(200, 60, 60));
    QList<QPointF> seenPoints, unseenPoints;
    Bounds bounds;
    for (const sim::SurfaceSample& face : sim::plottedSurface(m_report)) { // as the report's page plots it
        (face.seen ? seenPoints : unseenPoints).append(QPointF(face.aroundDeg, face.alongMm));
        bounds.add(face.aroundDeg, face.alongMm);
    }
    seen->replace(seenPoints);
    unseen->replace(unseenPoints);
    chart->addSeries(seen);
    chart->addSeries(unseen);
    addAxes(chart, tr("around the axis (degrees; 0 anterior, +90 the patient's left)"), tr("from the internal os (mm)"),
            bounds);
    if (auto* x = qobject_cast<QValueAxis*>(chart->axes(Qt::Horizontal).value(0)))
        x->setRange(-180.0, 180.0);
}

} // namespace hs::widgets
