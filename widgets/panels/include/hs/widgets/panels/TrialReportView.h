#pragma once
/// The workstation's review of a trial: a trial report (hs::sim::TrialReport, read by hs::sim::readReport) shown as
/// its metrics, its plots over time and the cavity's visualized surface. The tables and plots are the ones the
/// report's HTML page draws (hs::sim::reportTables, hs::sim::reportPlots), so the supervisor sees the same figures in
/// both.

#include "hs/sim/Metrics.h"

#include <QString>
#include <QWidget>

class QChartView;
class QLabel;
class QPushButton;
class QTabWidget;
class QTreeWidget;

namespace hs::widgets {

class TrialReportView : public QWidget {
    Q_OBJECT
public:
    explicit TrialReportView(QWidget* parent = nullptr);

    /// Shows `report`, read from `path` (named in the window's heading).
    void showReport(sim::TrialReport report, const QString& path);
    /// The scene open in the workstation (the SHA-256 of its package's manifest; empty: none): the heading says
    /// whether the trial ran on it.
    void setOpenScene(const QString& packageSha256);

    const sim::TrialReport& report() const { return m_report; }
    QString path() const { return m_path; }
    /// The metrics' tree: a top-level item per section of the report, its rows below.
    QTreeWidget* metrics() const { return m_metrics; }
    /// The plots over time (force, pressure, deficit and, after a resection, blood loss).
    const QList<QChartView*>& plots() const { return m_plots; }
    QChartView* surfacePlot() const { return m_surface; }
    /// Whether the trial ran on the open scene, in words.
    QString sceneNote() const;
    QTabWidget* tabs() const { return m_tabs; }
    /// The trial the report was written with: NAME.trial beside NAME.json, as the simulator's End Trial writes them
    /// (empty: there is none).
    QString trialPath() const;
    /// The report's scene (its SHA-256) is the open one.
    bool ranOnOpenScene() const;
    /// "Replay in the Simulator": enabled while the report's trial file is there.
    QPushButton* replayButton() const { return m_replay; }

signals:
    /// The user asked to watch the trial again in the simulator (`trialPath`: the recorded trial).
    void replayRequested(const QString& trialPath);

private:
    void fillMetrics();
    void fillPlots();
    void fillSurface();
    void updateSceneNote();

    sim::TrialReport m_report;
    QString m_path;
    QString m_openScene;
    QLabel* m_heading = nullptr;
    QLabel* m_details = nullptr;
    QLabel* m_sceneNote = nullptr;
    QPushButton* m_replay = nullptr;
    void updateReplay();
    QTabWidget* m_tabs = nullptr;
    QTreeWidget* m_metrics = nullptr;
    QWidget* m_plotPage = nullptr;
    QList<QChartView*> m_plots;
    QChartView* m_surface = nullptr;
};

} // namespace hs::widgets
