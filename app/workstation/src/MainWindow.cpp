#include "hs/workstation/MainWindow.h"

#include "MainWindowSettings.h"

#include "hs/scene/Review.h"
#include "hs/scene/ScenePackage.h"
#include "hs/widgets/common/FileDialog.h"
#include "hs/widgets/common/MessageBox.h"
#include "hs/widgets/jobs/JobStatusWidget.h"
#include "hs/widgets/panels/ExportPanel.h"
#include "hs/widgets/panels/MaterialsPanel.h"
#include "hs/widgets/panels/MeshPanel.h"
#include "hs/widgets/panels/PathologyPanel.h"
#include "hs/widgets/panels/PatientPanel.h"
#include "hs/widgets/panels/ReviewPanel.h"
#include "hs/widgets/panels/SceneTree.h"
#include "hs/widgets/panels/TexturePanel.h"
#include "hs/widgets/view/HysteroscopicPreview.h"
#include "hs/widgets/view/MeshDisplay.h"
#include "hs/widgets/view/SceneParts.h"
#include "hs/widgets/view/SurfaceHandles.h"
#include "hs/widgets/view/VariantsView.h"

#include <QAbstractButton>
#include <QAction>
#include <QCloseEvent>
#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMenuBar>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QToolBar>
#include <QtConcurrent/QtConcurrentRun>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <exception>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

namespace hs::workstation {

using widgets::FileDialog;
using widgets::MessageBox;

namespace {

constexpr double kBackgroundTop[3] = {0.32, 0.34, 0.43};
constexpr double kBackgroundBottom[3] = {0.08, 0.08, 0.12};
} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setObjectName("mainWindow");
    m_recoveryFolder = QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).filePath("recovery");

    m_view = new widgets::VtkView(this);
    m_view->setObjectName("view");
    m_view->renderer()->GradientBackgroundOn();
    m_view->renderer()->SetBackground(kBackgroundBottom[0], kBackgroundBottom[1], kBackgroundBottom[2]);
    m_view->renderer()->SetBackground2(kBackgroundTop[0], kBackgroundTop[1], kBackgroundTop[2]);
    setCentralWidget(m_view);
    m_display = std::make_unique<widgets::MeshDisplay>(m_view->renderer());
    m_parts = std::make_unique<widgets::SceneParts>(m_view->renderer(), *m_display);
    m_growth = std::make_unique<widgets::GrowthDisplay>(m_view->renderer());
    m_orientationMarker = std::make_unique<widgets::OrientationMarker>(*m_view);
    m_clipPlane = std::make_unique<widgets::ClipPlaneWidget>(*m_view, [this](const Vec3& origin, const Vec3& normal) {
        m_parts->setClipPlane(origin, normal);
        m_view->requestRender();
        updateStatus();
    });
    m_handles = new widgets::SurfaceHandles(m_view, this);

    createActions();
    createMenus();
    createStatusBar();
    createPanels();
    readSettings();
    rebuildRecentMenu();
    rebuildRecentCasesMenu();
    updateStatus();

    connect(&m_loadWatcher, &QFutureWatcher<LoadedMesh>::finished, this, &MainWindow::onLoadFinished);
    // Files another program changes: the case and the reviewed package, offered to reload, never mixed in.
    setAcceptDrops(true);
    m_diskTimer.setSingleShot(true);
    m_diskTimer.setInterval(300);
    connect(&m_diskWatcher, &QFileSystemWatcher::fileChanged, &m_diskTimer, qOverload<>(&QTimer::start));
    connect(&m_diskTimer, &QTimer::timeout, this, &MainWindow::onChangedOnDisk);
    connect(&m_document, &widgets::CaseDocument::filePathChanged, this, &MainWindow::watchFiles);
    connect(this, &MainWindow::reviewOpened, this, &MainWindow::watchFiles);
    connect(m_document.undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(&m_document, &widgets::CaseDocument::filePathChanged, this, &MainWindow::updateTitle);
    connect(&m_document, &widgets::CaseDocument::changed, this, &MainWindow::updateTitle);
    connect(&m_document, &widgets::CaseDocument::changed, this, [this] {
        if (!isReviewing()) // the reviewed package stays in the views whatever happens to the case
            m_currentFile.clear();
        updateOutOfDateMarks();
    });
    m_autosaveTimer.setInterval(kAutosaveMs);
    connect(&m_autosaveTimer, &QTimer::timeout, this, &MainWindow::autosave);
    m_autosaveTimer.start();
    updateTitle();
    connect(m_view, &widgets::VtkView::picked, this, &MainWindow::onPicked);
    connect(&m_session, &widgets::GenerationSession::resultsChanged, this, &MainWindow::onResultsChanged);
    // Grow shows the pathologies growing over the organ; the stage's result replaces them.
    connect(&m_session, &widgets::GenerationSession::growthFrame, this, [this](const pathology::GrowthFrame& frame) {
        if (!m_currentFile.isEmpty())
            return;
        m_growth->show(frame);
        m_view->requestRender();
    });
    connect(&m_session.runner(), &widgets::JobRunner::idle, this, [this] {
        m_growth->clear();
        m_view->requestRender();
    });
    connect(&m_session.runner(), &widgets::JobRunner::failed, this, &MainWindow::onJobFailed);
    connect(&m_reviewJobs, &widgets::JobRunner::failed, this, [this](const QString&, const Error& error) {
        // The package is untrusted: the details name the file, the field and the allowed range.
        MessageBox::critical(this, tr("Review Scene Package"),
                             error.code == ErrorCode::NotFound
                                 ? tr("The folder holds no scene package (no manifest.json).")
                                 : tr("The scene package cannot be read: a file is missing, changed or breaks its "
                                      "format (see the details)."),
                             QString::fromStdString(error.message()));
    });
    connect(&m_trialJobs, &widgets::JobRunner::failed, this, [this](const QString&, const Error& error) {
        // The report is untrusted too: the details name the file, the field and the allowed range.
        MessageBox::critical(this, tr("Review Trial Report"),
                             tr("The trial report cannot be read: it is missing or breaks its format (see the "
                                "details)."),
                             QString::fromStdString(error.message()));
    });
    connect(m_pathologyPanel, &widgets::PathologyPanel::placingChanged, this, &MainWindow::showResults);
    connect(m_pathologyPanel, &widgets::PathologyPanel::currentChanged, this, &MainWindow::updateHandles);
    // A handle dropped is one edit: the seat moves along the wall (seated as a click there is), or the size changes.
    connect(m_handles, &widgets::SurfaceHandles::seatMoved, this,
            [this](const QVector3D& point) { m_pathologyPanel->moveSeat(point); });
    connect(m_handles, &widgets::SurfaceHandles::sizeChanged, this,
            [this](double sizeMm) { m_pathologyPanel->resizeCurrent(sizeMm); });
    // The organ of the case the window starts with.
    m_session.runThrough(generate::Stage::Organ);
}

MainWindow::~MainWindow() {
    // The workers touch nothing of the window, but they should not outlive it either.
    m_loadWatcher.waitForFinished();
    m_session.runner().cancel();
    m_reviewJobs.cancel();
    m_trialJobs.cancel();
    // The undo stack clears itself as the document goes, after the window's actions and their list.
    m_document.undoStack()->disconnect(this);
}

void MainWindow::createActions() {
    m_newCaseAction = new QAction(tr("&New Case"), this);
    m_newCaseAction->setObjectName("actionNewCase");
    m_newCaseAction->setShortcut(QKeySequence::New);
    m_newCaseAction->setStatusTip(tr("Start a new case from the default patient"));
    connect(m_newCaseAction, &QAction::triggered, this, &MainWindow::onNewCase);

    m_openCaseAction = new QAction(tr("Open &Case..."), this);
    m_openCaseAction->setObjectName("actionOpenCase");
    m_openCaseAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O));
    m_openCaseAction->setStatusTip(tr("Open a case file (case.json)"));
    connect(m_openCaseAction, &QAction::triggered, this, &MainWindow::onOpenCase);

    m_saveCaseAction = new QAction(tr("&Save Case"), this);
    m_saveCaseAction->setObjectName("actionSaveCase");
    m_saveCaseAction->setShortcut(QKeySequence::Save);
    connect(m_saveCaseAction, &QAction::triggered, this, &MainWindow::onSaveCase);

    m_saveCaseAsAction = new QAction(tr("Save Case &As..."), this);
    m_saveCaseAsAction->setObjectName("actionSaveCaseAs");
    m_saveCaseAsAction->setShortcut(QKeySequence::SaveAs);
    connect(m_saveCaseAsAction, &QAction::triggered, this, &MainWindow::onSaveCaseAs);

    // Undo and redo of the case, enabled as the stack allows and never while a package is reviewed (the stack's own
    // actions would enable themselves whenever it changes).
    QUndoStack* stack = m_document.undoStack();
    m_undoAction = new QAction(tr("&Undo"), this);
    m_undoAction->setObjectName("actionUndo");
    m_undoAction->setShortcut(QKeySequence::Undo);
    connect(m_undoAction, &QAction::triggered, stack, &QUndoStack::undo);
    m_redoAction = new QAction(tr("&Redo"), this);
    m_redoAction->setObjectName("actionRedo");
    m_redoAction->setShortcut(QKeySequence::Redo);
    connect(m_redoAction, &QAction::triggered, stack, &QUndoStack::redo);
    connect(stack, &QUndoStack::canUndoChanged, this, &MainWindow::updateAuthoringActions);
    connect(stack, &QUndoStack::canRedoChanged, this, &MainWindow::updateAuthoringActions);
    connect(stack, &QUndoStack::undoTextChanged, this, &MainWindow::updateAuthoringActions);
    connect(stack, &QUndoStack::redoTextChanged, this, &MainWindow::updateAuthoringActions);

    m_openAction = new QAction(tr("&Open..."), this);
    m_openAction->setObjectName("actionOpen");
    m_openAction->setShortcut(QKeySequence::Open);
    m_openAction->setStatusTip(tr("Open a surface or tetrahedral mesh"));
    connect(m_openAction, &QAction::triggered, this, &MainWindow::onOpen);

    m_quitAction = new QAction(tr("&Quit"), this);
    m_quitAction->setObjectName("actionQuit");
    m_quitAction->setShortcut(QKeySequence::Quit);
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);

    m_clearRecentAction = new QAction(tr("&Clear Menu"), this);
    m_clearRecentAction->setObjectName("actionClearRecent");
    connect(m_clearRecentAction, &QAction::triggered, this, &MainWindow::onClearRecent);

    m_clipAction = new QAction(tr("&Clip"), this);
    m_clipAction->setObjectName("actionClip");
    m_clipAction->setCheckable(true);
    m_clipAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));
    m_clipAction->setStatusTip(tr("Cut the tetrahedral mesh open and show the tetrahedra on the cut"));
    m_clipAction->setEnabled(false);
    connect(m_clipAction, &QAction::toggled, this, &MainWindow::onClipToggled);

    m_resetCameraAction = new QAction(tr("&Reset Camera"), this);
    m_resetCameraAction->setObjectName("actionResetCamera");
    m_resetCameraAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    connect(m_resetCameraAction, &QAction::triggered, this, &MainWindow::onResetCamera);

    m_orientationMarkerAction = new QAction(tr("&Orientation Marker"), this);
    m_orientationMarkerAction->setObjectName("actionOrientationMarker");
    m_orientationMarkerAction->setCheckable(true);
    m_orientationMarkerAction->setChecked(true);
    m_orientationMarkerAction->setStatusTip(tr("Show the patient's directions in the corner of the 3-D view"));
    connect(m_orientationMarkerAction, &QAction::toggled, this, [this](bool on) {
        m_orientationMarker->setVisible(on);
        m_view->requestRender();
    });
    // The anatomical views, in the scene's frame; Ctrl+Alt+1..6 in the order of the menu.
    const struct {
        widgets::AnatomicalView view;
        const char* text;
        const char* name;
        const char* tip;
    } looks[] = {
        {widgets::AnatomicalView::Anterior, QT_TR_NOOP("&Anterior"), "actionLookAnterior",
         QT_TR_NOOP("Look at the organ from in front of the patient")},
        {widgets::AnatomicalView::Posterior, QT_TR_NOOP("&Posterior"), "actionLookPosterior",
         QT_TR_NOOP("Look at the organ from behind the patient")},
        {widgets::AnatomicalView::Left, QT_TR_NOOP("&Left"), "actionLookLeft",
         QT_TR_NOOP("Look at the organ from the patient's left")},
        {widgets::AnatomicalView::Right, QT_TR_NOOP("&Right"), "actionLookRight",
         QT_TR_NOOP("Look at the organ from the patient's right")},
        {widgets::AnatomicalView::Fundal, QT_TR_NOOP("&Fundal"), "actionLookFundal",
         QT_TR_NOOP("Look down the uterine axis from above the fundus")},
        {widgets::AnatomicalView::ExternalOs, QT_TR_NOOP("From the External &Os"), "actionLookExternalOs",
         QT_TR_NOOP("Look up the cervical canal from the external os, as the scope enters")},
    };
    int key = 0;
    for (const auto& look : looks) {
        auto* action = new QAction(tr(look.text), this);
        action->setObjectName(QString::fromLatin1(look.name));
        action->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key(Qt::Key_1 + key++)));
        action->setStatusTip(tr(look.tip));
        action->setToolTip(tr(look.tip));
        connect(action, &QAction::triggered, this, [this, view = look.view] { widgets::lookFrom(*m_view, view); });
        m_lookFromActions.push_back(action);
    }

    m_reviewAction = new QAction(tr("Revie&w Scene Package..."), this);
    m_reviewAction->setObjectName("actionReviewPackage");
    m_reviewAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    m_reviewAction->setStatusTip(tr("Open an exported scene package read-only and rate how real it looks"));
    connect(m_reviewAction, &QAction::triggered, this, &MainWindow::onReviewPackage);
    m_closeReviewAction = new QAction(tr("Close Re&view"), this);
    m_closeReviewAction->setObjectName("actionCloseReview");
    m_closeReviewAction->setEnabled(false);
    connect(m_closeReviewAction, &QAction::triggered, this, &MainWindow::onCloseReview);

    m_compareAction = new QAction(tr("Compare &Variants..."), this);
    m_compareAction->setObjectName("actionCompareVariants");
    m_compareAction->setStatusTip(tr("Show the variants of a case side by side, as the scope sees them"));
    connect(m_compareAction, &QAction::triggered, this, &MainWindow::onCompareVariants);

    m_trialReportAction = new QAction(tr("Review Trial Re&port..."), this);
    m_trialReportAction->setObjectName("actionReviewTrialReport");
    m_trialReportAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_T));
    m_trialReportAction->setStatusTip(tr("Show a simulator trial's metrics and plots from its report"));
    connect(m_trialReportAction, &QAction::triggered, this, &MainWindow::onReviewTrialReport);

    m_aboutAction = new QAction(tr("&About Hysteroscene"), this);
    m_aboutAction->setObjectName("actionAbout");
    m_aboutAction->setMenuRole(QAction::AboutRole);
    connect(m_aboutAction, &QAction::triggered, this, &MainWindow::onAbout);
}

void MainWindow::createMenus() {
    QMenu* fileMenu = menuBar()->addMenu(tr("&File"));
    fileMenu->setObjectName("menuFile");
    fileMenu->addAction(m_newCaseAction);
    fileMenu->addAction(m_openCaseAction);
    m_recentCasesMenu = fileMenu->addMenu(tr("Recen&t Cases"));
    m_recentCasesMenu->setObjectName("menuRecentCases");
    fileMenu->addAction(m_saveCaseAction);
    fileMenu->addAction(m_saveCaseAsAction);
    fileMenu->addSeparator();
    fileMenu->addAction(m_openAction);
    m_recentMenu = fileMenu->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName("menuRecent");
    fileMenu->addSeparator();
    fileMenu->addAction(m_reviewAction);
    fileMenu->addAction(m_closeReviewAction);
    fileMenu->addAction(m_compareAction);
    fileMenu->addAction(m_trialReportAction);
    fileMenu->addSeparator();
    fileMenu->addAction(m_quitAction);

    QMenu* editMenu = menuBar()->addMenu(tr("&Edit"));
    editMenu->setObjectName("menuEdit");
    editMenu->addAction(m_undoAction);
    editMenu->addAction(m_redoAction);

    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    viewMenu->setObjectName("menuView");
    viewMenu->addAction(m_clipAction);
    viewMenu->addAction(m_resetCameraAction);
    QMenu* lookMenu = viewMenu->addMenu(tr("Look &From"));
    lookMenu->setObjectName("menuLookFrom");
    QToolBar* views = addToolBar(tr("Views"));
    views->setObjectName("viewsToolBar"); // saveState() keeps it by name
    views->setToolButtonStyle(Qt::ToolButtonTextOnly);
    for (QAction* action : m_lookFromActions) {
        lookMenu->addAction(action);
        views->addAction(action);
    }
    viewMenu->addAction(m_orientationMarkerAction);
    viewMenu->addSeparator();
    m_panelsMenu = viewMenu->addMenu(tr("&Panels"));
    m_panelsMenu->setObjectName("menuPanels");

    // The stages' buttons as window actions: their shortcuts work whichever tab is raised (filled in createPanels).
    m_stagesMenu = menuBar()->addMenu(tr("&Stages"));
    m_stagesMenu->setObjectName("menuStages");

    QMenu* helpMenu = menuBar()->addMenu(tr("&Help"));
    helpMenu->setObjectName("menuHelp");
    helpMenu->addAction(m_aboutAction);
}

void MainWindow::createStatusBar() {
    m_pickLabel = new QLabel(this);
    m_pickLabel->setObjectName("pickLabel");
    m_countsLabel = new QLabel(this);
    m_countsLabel->setObjectName("countsLabel");
    m_fileLabel = new QLabel(this);
    m_fileLabel->setObjectName("fileLabel");
    m_fileLabel->setContentsMargins(12, 0, 4, 0);
    statusBar()->addWidget(m_pickLabel, 1);
    statusBar()->addPermanentWidget(new widgets::JobStatusWidget(m_session.runner(), this));
    statusBar()->addPermanentWidget(m_countsLabel);
    statusBar()->addPermanentWidget(m_fileLabel);
}

// --- Panels and results ------------------------------------------------------------------------------------------

QDockWidget* MainWindow::addPanel(QWidget* panel, const QString& title, const QString& name, Qt::DockWidgetArea area) {
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(panel);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name); // saveState() keeps the layout by object name
    dock->setWidget(scroll);
    addDockWidget(area, dock);
    m_panelsMenu->addAction(dock->toggleViewAction());
    return dock;
}

void MainWindow::createPanels() {
    // Left: what the case asks for (patient, pathologies, materials), one tab each.
    m_patientPanel = new widgets::PatientPanel(m_document, m_session, this);
    m_pathologyPanel = new widgets::PathologyPanel(m_document, m_session, this);
    m_materialsPanel = new widgets::MaterialsPanel(m_document, this);
    QDockWidget* patient = addPanel(m_patientPanel, tr("Patient"), "patientDock", Qt::LeftDockWidgetArea);
    QDockWidget* pathologies = addPanel(m_pathologyPanel, tr("Pathologies"), "pathologyDock", Qt::LeftDockWidgetArea);
    QDockWidget* materials = addPanel(m_materialsPanel, tr("Materials"), "materialsDock", Qt::LeftDockWidgetArea);
    // Below them the scene tree: what the 3-D view shows, part by part.
    m_sceneTree = new widgets::SceneTree(this);
    m_sceneTree->setParts(m_parts.get());
    // The tissue mesh is drawn when first shown: the Mesh panel then colours it and hides its regions as set.
    m_parts->setOnBuilt([this](const std::string& key) {
        if (key == "tissues")
            m_meshPanel->applyToDisplay();
    });
    m_sceneTree->setCurrentCheck([this](generate::Stage stage) { return m_session.isCurrent(stage); });
    QDockWidget* sceneDock = addPanel(m_sceneTree, tr("Scene"), "sceneDock", Qt::LeftDockWidgetArea);
    splitDockWidget(patient, sceneDock, Qt::Vertical); // before the tabs: a tabbed dock cannot be split
    tabifyDockWidget(patient, pathologies);
    tabifyDockWidget(pathologies, materials);
    patient->raise();

    // Right: the stages that make the scene (mesh, texture, export) and the review, as tabs over the hysteroscopic
    // view; the outside view keeps the centre.
    m_meshPanel = new widgets::MeshPanel(m_document, m_session, this);
    m_meshPanel->setDisplay(m_display.get(), m_view);
    m_texturePanel = new widgets::TexturePanel(m_document, m_session, this);
    m_exportPanel = new widgets::ExportPanel(m_document, m_session, this);
    m_reviewPanel = new widgets::ReviewPanel(this);
    m_preview = new widgets::HysteroscopicPreview(this);
    m_reviewPanel->setPreview(m_preview);
    QDockWidget* mesh = addPanel(m_meshPanel, tr("Mesh"), "meshDock", Qt::RightDockWidgetArea);
    QDockWidget* preview = addPanel(m_preview, tr("Hysteroscopic View"), "previewDock", Qt::RightDockWidgetArea);
    splitDockWidget(mesh, preview, Qt::Vertical); // before the tabs: a tabbed dock cannot be split
    QDockWidget* texture = addPanel(m_texturePanel, tr("Texture"), "textureDock", Qt::RightDockWidgetArea);
    QDockWidget* exportDock = addPanel(m_exportPanel, tr("Export"), "exportDock", Qt::RightDockWidgetArea);
    m_reviewDock = addPanel(m_reviewPanel, tr("Review"), "reviewDock", Qt::RightDockWidgetArea);
    tabifyDockWidget(mesh, texture);
    tabifyDockWidget(texture, exportDock);
    tabifyDockWidget(exportDock, m_reviewDock);
    mesh->raise();
    // The default split leaves the 3-D view its room on a 1366 x 768 screen: each side as wide as its widest panel
    // needs, no wider (readSettings restores the user's own layout over it).
    const auto widest = [](std::initializer_list<QDockWidget*> docks) {
        int width = 0;
        for (QDockWidget* dock : docks)
            if (auto* scroll = qobject_cast<QScrollArea*>(dock->widget()))
                width = std::max(width, scroll->widget()->minimumSizeHint().width() +
                                            scroll->verticalScrollBar()->sizeHint().width());
        return width;
    };
    resizeDocks({patient, mesh}, {widest({patient, pathologies, materials}), widest({mesh, texture, exportDock})},
                Qt::Horizontal);
    resizeDocks({patient, sceneDock}, {600, 200}, Qt::Vertical); // the panels first, the scene tree below

    m_authoringDocks = {patient, pathologies, materials, mesh, texture, exportDock};
    // The marks over the views an edit has outdated.
    const auto mark = [this](QWidget* over, const char* name) {
        auto* label = new QLabel(over);
        label->setObjectName(QString::fromLatin1(name));
        label->setWordWrap(true);
        label->setStyleSheet(QStringLiteral("QLabel { background: rgba(200, 110, 0, 220); color: white; "
                                            "padding: 4px; border-radius: 3px; }"));
        label->setAttribute(Qt::WA_TransparentForMouseEvents);
        label->move(8, 8);
        label->setFixedWidth(320);
        label->hide();
        return label;
    };
    m_viewOutOfDate = mark(m_view, "viewOutOfDate");
    m_previewOutOfDate = mark(m_preview, "previewOutOfDate");
    m_previewOutOfDate->setText(tr("Out of date: the case has changed since this scene was made."));
    m_previewOutOfDate->adjustSize();
    // One selection: the pathology list, the scene tree and a pick in 3-D.
    connect(m_pathologyPanel, &widgets::PathologyPanel::currentChanged, this,
            [this] { m_sceneTree->selectPathology(m_pathologyPanel->currentIndex()); });
    connect(m_sceneTree, &widgets::SceneTree::pathologySelected, this,
            [this](int index) { m_pathologyPanel->setCurrentIndex(index); });
    connect(m_sceneTree, &widgets::SceneTree::visibilityChanged, this, [this] {
        m_meshPanel->syncRegionChecks();
        syncClipPlane();
        updateStatus(); // the counts of what is shown now
    });
    connect(m_sceneTree, &widgets::SceneTree::displayChanged, m_view, &widgets::VtkView::requestRender);
    connect(m_meshPanel, &widgets::MeshPanel::displayChanged, m_sceneTree, &widgets::SceneTree::refreshChecks);
    connect(m_meshPanel, &widgets::MeshPanel::meshWanted, this, [this] {
        m_parts->setShown("tissues", true); // drawn now if it was not (the Mesh panel then colours it)
        m_sceneTree->refreshChecks();
    });
    connect(m_texturePanel, &widgets::TexturePanel::exemplarBrowseRequested, this, [this](int index) {
        const QString path = FileDialog::getOpenFileName(this, tr("Exemplar Image"), m_lastFolder,
                                                         tr("Images (*.png *.jpg *.jpeg *.exr *.tif *.tiff)") +
                                                             QStringLiteral(";;") + tr("All files (*)"));
        if (!path.isEmpty())
            m_texturePanel->setExemplar(index, path);
    });
    // The preview simulator, when it is installed beside the workstation.
    const QString simulator = QDir(QCoreApplication::applicationDirPath()).filePath("hysteroscene-sim");
    if (QFileInfo(simulator).isExecutable())
        m_exportPanel->setSimulatorPath(simulator);
    connect(m_exportPanel, &widgets::ExportPanel::browseRequested, this, [this] {
        const QString folder = FileDialog::getExistingDirectory(this, tr("Export Scene Package"), m_lastFolder);
        if (!folder.isEmpty())
            m_exportPanel->setFolder(folder);
    });
    // Each stage's button as a window action: its dock raised, its button clicked when the panel allows it.
    const auto stage = [this](const QString& text, const QKeySequence& keys, const char* name, QDockWidget* dock,
                              const char* button) {
        auto* action = new QAction(text, this);
        action->setObjectName(QString::fromLatin1(name));
        action->setShortcut(keys);
        connect(action, &QAction::triggered, this, [dock, button] {
            dock->show();
            dock->raise();
            if (auto* b = dock->findChild<QAbstractButton*>(QString::fromLatin1(button)); b && b->isEnabled())
                b->click();
        });
        m_stagesMenu->addAction(action);
        m_authoringActions.push_back(action);
    };
    stage(tr("&Place on the Wall"), QKeySequence(Qt::CTRL | Qt::Key_P), "actionPlace", pathologies, "placeButton");
    stage(tr("&Grow"), QKeySequence(Qt::CTRL | Qt::Key_G), "actionGrow", pathologies, "growButton");
    stage(tr("&Mesh"), QKeySequence(Qt::CTRL | Qt::Key_M), "actionMesh", mesh, "meshButton");
    stage(tr("&Texture"), QKeySequence(Qt::CTRL | Qt::Key_T), "actionTexture", texture, "textureButton");
    stage(tr("&Export"), QKeySequence(Qt::CTRL | Qt::Key_E), "actionExport", exportDock, "exportButton");
    // Esc leaves placing (the place button toggled off), wherever the focus is in the window.
    m_cancelPlacingAction = new QAction(tr("Cancel Placing"), this);
    m_cancelPlacingAction->setObjectName("actionCancelPlacing");
    m_cancelPlacingAction->setShortcut(QKeySequence(Qt::Key_Escape));
    connect(m_cancelPlacingAction, &QAction::triggered, this, [this] {
        if (auto* b = m_pathologyPanel->findChild<QAbstractButton*>(QStringLiteral("placeButton")); b && b->isChecked())
            b->click();
    });
    m_stagesMenu->addSeparator();
    m_stagesMenu->addAction(m_cancelPlacingAction);
    updateAuthoringActions();
}

void MainWindow::onJobFailed(const QString& title, const Error& error) {
    MessageBox::critical(this, title, widgets::describeError(error.code), QString::fromStdString(error.message()));
}

// --- Settings -----------------------------------------------------------------------------------------------------

void MainWindow::readSettings() {
    const QSettings settings;
    if (!restoreGeometry(settings.value(kGeometryKey).toByteArray()))
        resize(1100, 760);
    restoreState(settings.value(kStateKey).toByteArray());
    m_lastFolder = settings.value(kLastFolderKey, QDir::homePath()).toString();
}

void MainWindow::writeSettings() const {
    QSettings settings;
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kStateKey, saveState());
    settings.setValue(kLastFolderKey, m_lastFolder);
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSaveReview() || !maybeSave()) {
        event->ignore();
        return;
    }
    writeSettings();
    widgets::CaseDocument::discardRecovery(m_recoveryFolder); // a clean exit leaves nothing to recover
    event->accept();
}

void MainWindow::onAbout() {
    // Every library that shapes a scene (as scene.json records them), then the GUI's own.
    QStringList libraries;
    for (const auto& [name, version] : generate::toolVersionsFor(m_document.spec()))
        libraries << QStringLiteral("%1 %2").arg(QString::fromStdString(name), QString::fromStdString(version));
    libraries << QStringLiteral("qt %1").arg(QString::fromLatin1(qVersion()));
    MessageBox::about(this, tr("About Hysteroscene"),
                      tr("<h3>Hysteroscene %1</h3>"
                         "<p>A scenario authoring workstation for hysteroscopy training simulators.</p>"
                         "<p>Licensed under the GNU General Public License, version 3 or later.</p>"
                         "<p><small>Built with %2.</small></p>")
                          .arg(QStringLiteral(HS_VERSION), libraries.join(QStringLiteral(", ")).toHtmlEscaped()));
}

} // namespace hs::workstation
