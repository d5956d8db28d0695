#pragma once
/// The workstation's main window: the case being authored (widgets::CaseDocument: New/Open/Save of case.json, undo,
/// autosave and recovery), a 3-D view of one mesh (surface or tetrahedral), File/Edit/View/Help menus, a status bar
/// with the mesh's counts, an orientation marker and the anatomical views (View > Look From, the Views tool bar).
/// Meshes load on a worker thread; the window keeps its mesh when a file fails to load.

#include "hs/core/Error.h"
#include "hs/io/MeshIO.h"
#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/jobs/GenerationSession.h"
#include "hs/widgets/view/AnatomicalViews.h"
#include "hs/widgets/view/ClipPlaneWidget.h"
#include "hs/widgets/view/ResultsDisplay.h"
#include "hs/widgets/view/VtkView.h"

#include <QFileSystemWatcher>
#include <QFutureWatcher>
#include <QMainWindow>
#include <QString>
#include <QStringList>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;

namespace hs::widgets {
class ExportPanel;
class HysteroscopicPreview;
class SurfaceHandles;
class VariantsView;
class MaterialsPanel;
class MeshDisplay;
class SceneParts;
class SceneTree;
class MeshPanel;
class PathologyPanel;
class PatientPanel;
class ReviewPanel;
class TexturePanel;
class TrialReportView;
} // namespace hs::widgets

namespace hs::workstation {

/// What a background load hands back to the GUI thread: a mesh or an error. The mesh is shared, not copied, when
/// the result is passed from the worker to the window.
struct LoadedMesh {
    QString path;
    std::shared_ptr<const io::AnyMesh> mesh;
    std::optional<Error> error;
};

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Starts loading `path` on a worker thread; fileLoaded or loadFailed follows on the GUI thread.
    void openFile(const QString& path);
    /// What `hysteroscene PATH` opens: a case file (.json) as the case being authored, a simulator's trial report
    /// (.json beginning with its format, "hysteroscene-trial-report") for review, a scene package (a folder with a
    /// manifest.json, or that manifest.json itself) for review, anything else as a mesh (openFile).
    void openArgument(const QString& path);
    /// Opens a dropped file or folder as openArgument does; while a package is reviewed, or for a file this program
    /// does not open, says why instead. Returns whether it was opened.
    bool openDropped(const QString& path);
    /// Whether `path` is a simulator's trial report: a .json file that begins with its format (reportJson writes it
    /// first). Only the file's beginning is read; the report's reader checks the rest.
    static bool isTrialReport(const QString& path);
    bool isLoading() const;
    /// The file shown now; empty before the first successful load.
    QString currentFile() const { return m_currentFile; }
    /// File > Open Recent's meshes, newest first (at most widgets::kMaxRecentFiles).
    QStringList recentFiles() const;

    /// Renders the whole window (menus, view, status bar) to an image file; false when it cannot be written.
    bool saveScreenshot(const QString& path);

    widgets::CaseDocument& document() { return m_document; }
    /// The pipeline's results for the document; its jobs run on worker threads.
    widgets::GenerationSession& session() { return m_session; }
    /// What the 3-D view shows of the session's results (None while it shows a mesh file or nothing).
    widgets::ResultLayer shownLayer() const { return m_shownLayer; }
    /// Opens the scene package `folder` read-only for a clinician's review (on a worker thread); reviewOpened or a
    /// message box naming the file and the problem follows.
    void reviewPackage(const QString& folder);
    bool isReviewing() const;
    /// Reads the scene packages in `folder`'s subfolders (the variants of a case, variant-NNN) on a worker thread and
    /// shows up to VariantsView::kMaxVariants side by side in their own window; variantsOpened follows.
    void compareVariants(const QString& folder);
    widgets::VariantsView* variantsView() const { return m_variantsView; }
    /// Reads the simulator's trial report `path` (hysteroscene-sim --report) on a worker thread and shows its metrics
    /// and plots in a window of its own; trialReportOpened or a message box naming the file and the field follows.
    void reviewTrialReport(const QString& path);
    widgets::TrialReportView* trialReportView() const { return m_trialReportView; }
    /// Plays the recorded trial `trialPath` in the simulator (`SIMULATOR PACKAGE --replay TRIAL`, a process of its
    /// own): on the package under review when the trial ran on it, otherwise on the package the user picks. Says why
    /// when the simulator is not there or does not start. Returns whether it started.
    bool replayTrial(const QString& trialPath);
    /// The simulator's executable replayTrial starts (default: hysteroscene-sim beside this program's).
    QString simulatorProgram() const;
    void setSimulatorProgram(const QString& program) { m_simulatorProgram = program; }
    /// Where autosave writes the case being edited (default: the application's data folder, "recovery").
    QString recoveryFolder() const { return m_recoveryFolder; }
    void setRecoveryFolder(const QString& folder) { m_recoveryFolder = folder; }
    /// Autosave interval (ms); the case is written only while it has unsaved changes.
    static constexpr int kAutosaveMs = 60 * 1000;
    /// Writes the recovery file now when the case has unsaved changes (what the autosave timer calls).
    void autosave();
    /// After a crash: when the recovery folder holds the unsaved case of the last session, asks whether to recover
    /// it and restores it (or discards it). main() calls it once the window is shown.
    void offerRecovery();

    widgets::VtkView* view() const { return m_view; }
    widgets::HysteroscopicPreview* preview() const { return m_preview; }
    const widgets::MeshDisplay& display() const { return *m_display; }
    widgets::SceneParts& sceneParts() const { return *m_parts; }
    widgets::SceneTree* sceneTree() const { return m_sceneTree; }
    /// The clip plane's handle in the 3-D view (shown while View > Clip is on).
    widgets::ClipPlaneWidget& clipPlane() { return *m_clipPlane; }
    /// The pathologies' growth while Grow runs.
    const widgets::GrowthDisplay& growthDisplay() const { return *m_growth; }
    /// The seat and size handles of the selected pathology, shown while it is being placed.
    widgets::SurfaceHandles* handles() const { return m_handles; }

signals:
    void reviewOpened(const QString& folder);
    void variantsOpened(int count);
    void trialReportOpened(const QString& path);
    void fileLoaded(const QString& path);
    void loadFailed(const QString& path);

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private slots:
    void onNewCase();
    void onOpenCase();
    void onOpenRecentCase();
    bool onSaveCase();
    bool onSaveCaseAs();
    void updateTitle();
    void onOpen();
    void onOpenRecent();
    void onClearRecent();
    void onClipToggled(bool enabled);
    void onResetCamera();
    void onAbout();
    void onLoadFinished();
    void onPicked(const hs::widgets::PickResult& result);
    void onResultsChanged();
    void onJobFailed(const QString& title, const hs::Error& error);
    void onReviewPackage();
    void onCloseReview();
    void onCompareVariants();
    void onReviewTrialReport();

private:
    void createActions();
    void createMenus();
    void createStatusBar();
    void createPanels();
    /// A dock for `panel` on `area`, listed in View > Panels.
    QDockWidget* addPanel(QWidget* panel, const QString& title, const QString& name, Qt::DockWidgetArea area);
    void showResults();
    /// Shows a mesh of its own in the view (a mesh file, a reviewed package): the results' parts leave it.
    void showOwnMesh();
    /// Marks the views an edit has outdated (their stage is no longer current) until the stage reruns.
    void updateOutOfDateMarks();
    /// Shows the handles of the selected pathology when the view shows the organ it is seated on.
    void updateHandles();
    void readSettings();
    void writeSettings() const;
    /// Before the case is replaced or the window closes: true when there are no unsaved changes, or the user saved
    /// or discarded them; false when they cancelled.
    bool maybeSave();
    /// The same for the ratings of a review in progress.
    bool maybeSaveReview();
    /// Enables what authoring needs while no package is reviewed (undo and redo as the stack allows), and only
    /// Close Review while one is.
    void updateAuthoringActions();
    void showCaseError(const QString& title, const Error& error);
    /// Opens `path` as the case (after maybeSave) and lists it among the recent cases.
    void openCase(const QString& path);
    /// Fills `menu` with one action per file ("&1 name", object names prefix0, prefix1, ...) that calls `slot`.
    void fillRecentMenu(QMenu* menu, const QStringList& files, const QString& prefix, void (MainWindow::*slot)());
    void rebuildRecentCasesMenu();
    void showMesh(const LoadedMesh& loaded);
    void showLoadError(const QString& path, const Error& error);
    void addRecentFile(const QString& path);
    void removeRecentFile(const QString& path);
    void rebuildRecentMenu();
    void updateStatus();
    /// Shows the clip plane's handle on the mesh shown (at the display's plane) while the clip is on, else hides it.
    void syncClipPlane();
    static QString layerName(widgets::ResultLayer layer);
    QString openFilter() const;
    /// Watches the case's file and the reviewed package's manifest for changes by another program.
    void watchFiles();
    /// A watched file changed: offers to reload what changed (a save of our own changes nothing and asks nothing).
    void onChangedOnDisk();

    widgets::VtkView* m_view = nullptr;
    std::unique_ptr<widgets::MeshDisplay> m_display; ///< the tetrahedral mesh (or the mesh file, the package's mesh)
    std::unique_ptr<widgets::SceneParts> m_parts;    ///< every part of the results, m_display their mesh
    std::unique_ptr<widgets::GrowthDisplay> m_growth;
    std::unique_ptr<widgets::OrientationMarker> m_orientationMarker;
    std::unique_ptr<widgets::ClipPlaneWidget> m_clipPlane; ///< the clip plane's handle, shown while the clip is on
    widgets::SurfaceHandles* m_handles = nullptr;
    QFutureWatcher<LoadedMesh> m_loadWatcher;
    QFileSystemWatcher m_diskWatcher;
    QTimer m_diskTimer; ///< lets a writer finish (editors write in steps) before the file is read
    QString m_currentFile;
    QString m_lastFolder;

    widgets::CaseDocument m_document;
    widgets::GenerationSession m_session{m_document};
    widgets::ResultLayer m_shownLayer = widgets::ResultLayer::None;
    widgets::PatientPanel* m_patientPanel = nullptr;
    widgets::PathologyPanel* m_pathologyPanel = nullptr;
    widgets::MeshPanel* m_meshPanel = nullptr;
    widgets::ExportPanel* m_exportPanel = nullptr;
    widgets::MaterialsPanel* m_materialsPanel = nullptr;
    widgets::TexturePanel* m_texturePanel = nullptr;
    widgets::HysteroscopicPreview* m_preview = nullptr;
    widgets::ReviewPanel* m_reviewPanel = nullptr;
    widgets::SceneTree* m_sceneTree = nullptr;
    QLabel* m_viewOutOfDate = nullptr;    ///< over the 3-D view while its stage is out of date
    QLabel* m_previewOutOfDate = nullptr; ///< over the hysteroscopic view while the scene is
    QDockWidget* m_reviewDock = nullptr;
    std::vector<QDockWidget*> m_authoringDocks; ///< disabled while a package is reviewed
    widgets::JobRunner m_reviewJobs;
    widgets::JobRunner m_trialJobs; ///< reads trial reports
    QAction* m_reviewAction = nullptr;
    QAction* m_closeReviewAction = nullptr;
    QAction* m_compareAction = nullptr;
    widgets::VariantsView* m_variantsView = nullptr; ///< a window of its own, made on first use
    QAction* m_trialReportAction = nullptr;
    widgets::TrialReportView* m_trialReportView = nullptr; ///< a window of its own, made on first use
    QString m_simulatorProgram;                            ///< empty: hysteroscene-sim beside this program
    QMenu* m_panelsMenu = nullptr;
    QMenu* m_stagesMenu = nullptr;
    QAction* m_cancelPlacingAction = nullptr;
    std::vector<QAction*> m_authoringActions; ///< the stages' actions: disabled while a package is reviewed
    QString m_recoveryFolder;
    QTimer m_autosaveTimer;

    QAction* m_newCaseAction = nullptr;
    QAction* m_openCaseAction = nullptr;
    QAction* m_saveCaseAction = nullptr;
    QAction* m_saveCaseAsAction = nullptr;
    QAction* m_undoAction = nullptr;
    QAction* m_redoAction = nullptr;
    QAction* m_openAction = nullptr;
    QAction* m_quitAction = nullptr;
    QAction* m_clipAction = nullptr;
    QAction* m_resetCameraAction = nullptr;
    QAction* m_orientationMarkerAction = nullptr;
    std::vector<QAction*> m_lookFromActions; ///< one per widgets::kAnatomicalViews, in its order
    QAction* m_aboutAction = nullptr;
    QAction* m_clearRecentAction = nullptr;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_recentCasesMenu = nullptr;
    QLabel* m_fileLabel = nullptr;
    QLabel* m_countsLabel = nullptr;
    QLabel* m_pickLabel = nullptr;
};

} // namespace hs::workstation
