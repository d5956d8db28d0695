// The main window in review: a read-only session over a package, and two variants side by side.
#include "hs/workstation/MainWindow.h"

#include "MainWindowSettings.h"
#include "hs/scene/Review.h"
#include "hs/scene/ScenePackage.h"
#include "hs/widgets/common/FileDialog.h"
#include "hs/widgets/common/MessageBox.h"
#include "hs/widgets/panels/MaterialsPanel.h"
#include "hs/widgets/panels/ReviewPanel.h"
#include "hs/widgets/panels/TrialReportView.h"
#include "hs/widgets/view/HysteroscopicPreview.h"
#include "hs/widgets/view/MeshDisplay.h"
#include "hs/widgets/view/VariantsView.h"

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QMenu>
#include <QProcess>
#include <QStatusBar>

#include <map>
#include <memory>
#include <string>
#include <utility>

namespace hs::workstation {

using widgets::FileDialog;
using widgets::MessageBox;

bool MainWindow::isReviewing() const {
    return m_reviewPanel && m_reviewPanel->isOpen();
}

void MainWindow::updateAuthoringActions() {
    // Reviewing is a read-only session: nothing may replace the reviewed package or change the case behind it
    // except closing the review.
    if (!m_recentCasesMenu || !m_recentMenu)
        return; // still being built
    const bool authoring = !isReviewing();
    for (QAction* action : {m_newCaseAction, m_openCaseAction, m_saveCaseAction, m_saveCaseAsAction, m_openAction,
                            m_reviewAction, m_compareAction})
        action->setEnabled(authoring);
    for (QAction* action : m_authoringActions)
        action->setEnabled(authoring);
    m_recentCasesMenu->setEnabled(authoring && !m_recentCasesMenu->actions().isEmpty());
    m_recentMenu->setEnabled(authoring);
    QUndoStack* stack = m_document.undoStack();
    m_undoAction->setEnabled(authoring && stack->canUndo());
    m_redoAction->setEnabled(authoring && stack->canRedo());
    m_undoAction->setText(stack->canUndo() ? tr("&Undo %1").arg(stack->undoText()) : tr("&Undo"));
    m_redoAction->setText(stack->canRedo() ? tr("&Redo %1").arg(stack->redoText()) : tr("&Redo"));
    m_closeReviewAction->setEnabled(!authoring);
}

void MainWindow::onReviewPackage() {
    if (!maybeSaveReview())
        return;
    const QString folder = FileDialog::getExistingDirectory(this, tr("Review Scene Package"), m_lastFolder);
    if (!folder.isEmpty())
        reviewPackage(folder);
}

void MainWindow::reviewPackage(const QString& folder) {
    struct Opened {
        std::shared_ptr<const scene::Scene> scene;
        QString identity;
    };
    const QString absolute = QFileInfo(folder).absoluteFilePath();
    m_reviewJobs.start<Opened>(
        tr("Reading the scene package"), 0,
        [absolute](Progress&) -> Result<Opened> {
            const std::string path = QFile::encodeName(absolute).toStdString();
            auto read = scene::readScenePackage(path);
            if (!read)
                return read.failure();
            auto identity = scene::packageIdentity(path);
            if (!identity)
                return identity.failure();
            return Opened{std::make_shared<const scene::Scene>(std::move(read).value()),
                          QString::fromStdString(*identity)};
        },
        [this, absolute](Opened&& opened) {
            m_reviewPanel->open(opened.scene, absolute, opened.identity);
            for (QDockWidget* dock : m_authoringDocks)
                dock->setEnabled(false);
            m_reviewDock->show();
            m_reviewDock->raise();
            m_preview->setScene(opened.scene);
            m_preview->setInsertion(0.0);
            if (m_trialReportView)
                m_trialReportView->setOpenScene(opened.identity);
            std::map<std::int32_t, std::string> names; // the legend names the package's own regions
            for (const scene::SceneRegion& region : opened.scene->regions)
                names[region.id] = widgets::regionName(region).toStdString();
            m_currentFile = absolute;
            showOwnMesh();
            m_display->setRegionNames(names);
            m_display->showTetMesh(opened.scene->tets);
            syncClipPlane();
            updateAuthoringActions();
            onResetCamera();
            updateStatus();
            emit reviewOpened(absolute);
        });
}

bool MainWindow::maybeSaveReview() {
    if (!m_reviewPanel->isModified())
        return true;
    switch (MessageBox::askSaveDiscardCancel(this, tr("Unsaved Ratings"),
                                             tr("The review of %1 has unsaved ratings. Save them?")
                                                 .arg(QFileInfo(m_reviewPanel->packageFolder()).fileName()))) {
    case MessageBox::Choice::Save:
        return m_reviewPanel->save();
    case MessageBox::Choice::Discard:
        return true;
    default:
        return false;
    }
}

void MainWindow::onCompareVariants() {
    const QString folder = FileDialog::getExistingDirectory(this, tr("Compare Variants"), m_lastFolder);
    if (!folder.isEmpty())
        compareVariants(folder);
}

void MainWindow::compareVariants(const QString& folder) {
    struct Opened {
        std::vector<std::shared_ptr<const scene::Scene>> scenes;
        QStringList names;
    };
    const QString absolute = QFileInfo(folder).absoluteFilePath();
    m_reviewJobs.start<Opened>(
        tr("Reading the variants"), 0,
        [absolute](Progress& progress) -> Result<Opened> {
            Opened opened;
            const QDir dir(absolute);
            QStringList packages;
            for (const QString& name : dir.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name))
                if (QFileInfo::exists(dir.filePath(name + QStringLiteral("/manifest.json"))))
                    packages << name;
            if (packages.isEmpty())
                return fail(ErrorCode::NotFound,
                            QFile::encodeName(absolute).toStdString() + ": no scene package in its subfolders");
            for (const QString& name : packages.mid(0, widgets::VariantsView::kMaxVariants)) {
                HS_TRY(progress.check("reading the variants"));
                auto read = scene::readScenePackage(QFile::encodeName(dir.filePath(name)).toStdString());
                if (!read)
                    return read.failure();
                opened.scenes.push_back(std::make_shared<const scene::Scene>(std::move(read).value()));
                opened.names << name;
            }
            return opened;
        },
        [this, absolute](Opened&& opened) {
            if (!m_variantsView) {
                m_variantsView = new widgets::VariantsView(this);
                m_variantsView->setWindowFlag(Qt::Window);
                m_variantsView->resize(1000, 720);
            }
            m_variantsView->setWindowTitle(tr("Variants - %1").arg(QDir::toNativeSeparators(absolute)));
            m_variantsView->setScenes(opened.scenes, opened.names);
            m_variantsView->show();
            m_variantsView->raise();
            emit variantsOpened(m_variantsView->count());
        });
}

void MainWindow::onReviewTrialReport() {
    const QString path = FileDialog::getOpenFileName(this, tr("Review Trial Report"), m_lastFolder,
                                                     tr("Trial reports (*.json);;All files (*)"));
    if (!path.isEmpty())
        reviewTrialReport(path);
}

void MainWindow::reviewTrialReport(const QString& path) {
    // Beside a package under review or a case being authored: the report is read-only and changes neither.
    const QString absolute = QFileInfo(path).absoluteFilePath();
    m_trialJobs.start<sim::TrialReport>(
        tr("Reading the trial report"), 0,
        [absolute](Progress&) -> Result<sim::TrialReport> {
            return sim::readReport(QFile::encodeName(absolute).toStdString());
        },
        [this, absolute](sim::TrialReport&& report) {
            if (!m_trialReportView) {
                m_trialReportView = new widgets::TrialReportView(this);
                m_trialReportView->setWindowFlag(Qt::Window);
                m_trialReportView->resize(1100, 760);
                connect(m_trialReportView, &widgets::TrialReportView::replayRequested, this,
                        [this](const QString& trial) { replayTrial(trial); });
            }
            m_trialReportView->setWindowTitle(tr("Trial Report - %1").arg(QDir::toNativeSeparators(absolute)));
            m_trialReportView->showReport(std::move(report), absolute);
            m_trialReportView->setOpenScene(isReviewing() ? m_reviewPanel->packageSha256() : QString());
            m_trialReportView->show();
            m_trialReportView->raise();
            m_lastFolder = QFileInfo(absolute).absolutePath();
            emit trialReportOpened(absolute);
        });
}

QString MainWindow::simulatorProgram() const {
    return m_simulatorProgram.isEmpty() ? QDir(QCoreApplication::applicationDirPath()).filePath("hysteroscene-sim")
                                        : m_simulatorProgram;
}

bool MainWindow::replayTrial(const QString& trialPath) {
    const QString program = simulatorProgram();
    if (!QFileInfo(program).isExecutable()) {
        MessageBox::critical(m_trialReportView ? static_cast<QWidget*>(m_trialReportView) : this, tr("Replay"),
                             tr("The simulator is not installed beside the workstation."),
                             tr("No executable %1.").arg(QDir::toNativeSeparators(program)));
        return false;
    }
    // The trial's scene: the package under review when the trial ran on it, else the one the user names (the
    // simulator refuses a package whose scene is not the trial's, and says so).
    QString package;
    if (isReviewing() && m_trialReportView && m_trialReportView->ranOnOpenScene())
        package = m_reviewPanel->packageFolder();
    else
        package = FileDialog::getExistingDirectory(m_trialReportView ? static_cast<QWidget*>(m_trialReportView) : this,
                                                   tr("The Scene Package the Trial Ran On"),
                                                   QFileInfo(trialPath).absolutePath());
    if (package.isEmpty())
        return false;
    const QStringList arguments{package, QStringLiteral("--replay"), trialPath};
    if (!QProcess::startDetached(program, arguments)) {
        MessageBox::critical(m_trialReportView ? static_cast<QWidget*>(m_trialReportView) : this, tr("Replay"),
                             tr("The simulator did not start."),
                             QDir::toNativeSeparators(program) + QLatin1Char(' ') + arguments.join(QLatin1Char(' ')));
        return false;
    }
    statusBar()->showMessage(tr("Replaying %1 in the simulator.").arg(QFileInfo(trialPath).fileName()), 5000);
    return true;
}

void MainWindow::onCloseReview() {
    if (!maybeSaveReview())
        return;
    m_reviewPanel->close();
    if (m_trialReportView)
        m_trialReportView->setOpenScene({});
    for (QDockWidget* dock : m_authoringDocks)
        dock->setEnabled(true);
    updateAuthoringActions();
    m_currentFile.clear();
    watchFiles();
    showResults();
}

} // namespace hs::workstation
