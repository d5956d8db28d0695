// The main window and the files it opens: a mesh on a worker thread, the command line's argument, recent files.
#include "hs/workstation/MainWindow.h"

#include "MainWindowSettings.h"
#include "hs/generate/Generate.h"
#include "hs/scene/Review.h"
#include "hs/scene/ScenePackage.h"
#include "hs/widgets/common/FileDialog.h"
#include "hs/widgets/common/MessageBox.h"
#include "hs/widgets/panels/ReviewPanel.h"
#include "hs/widgets/view/MeshDisplay.h"

#include <QAction>
#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMimeData>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QUrl>
#include <QtConcurrent/QtConcurrentRun>

#include <exception>
#include <memory>
#include <string>
#include <utility>

namespace hs::workstation {

using widgets::FileDialog;
using widgets::MessageBox;

namespace {

/// Runs on a worker thread: reads the file and carries a result or an error (never an exception) back.
LoadedMesh loadMesh(const QString& path) {
    LoadedMesh loaded;
    loaded.path = path;
    try {
        Result<io::AnyMesh> result = io::readMesh(QFile::encodeName(path).toStdString());
        if (result.ok())
            loaded.mesh = std::make_shared<const io::AnyMesh>(std::move(result).value());
        else
            loaded.error = result.error();
    } catch (const std::exception& e) {
        // Not expected (readers return errors), but a worker must not take the application down with it.
        loaded.error = Error{ErrorCode::Internal, e.what()};
    }
    return loaded;
}

QString patternsOf(const QStringList& extensions) {
    QStringList patterns;
    for (const QString& extension : extensions)
        patterns.append(QLatin1Char('*') + extension);
    return patterns.join(QLatin1Char(' '));
}

} // namespace

bool MainWindow::saveScreenshot(const QString& path) {
    m_view->requestRender();
    return grab().save(path);
}

// --- Opening files ------------------------------------------------------------------------------------------------

QString MainWindow::openFilter() const {
    QStringList all;
    QStringList surfaces;
    QStringList volumes;
    for (const std::string& extension : io::supportedExtensions()) {
        const QString qExtension = QString::fromStdString(extension);
        all.append(qExtension);
        const Result<io::MeshFormat> format = io::formatFromPath("mesh" + extension);
        if (format.ok() && io::isTetFormat(*format))
            volumes.append(qExtension);
        else
            surfaces.append(qExtension);
    }
    return QStringList{tr("All meshes (%1)").arg(patternsOf(all)), tr("Surface meshes (%1)").arg(patternsOf(surfaces)),
                       tr("Tetrahedral meshes (%1)").arg(patternsOf(volumes)), tr("All files (*)")}
        .join(QStringLiteral(";;"));
}

void MainWindow::onOpen() {
    const QString path = FileDialog::getOpenFileName(this, tr("Open Mesh"), m_lastFolder, openFilter());
    if (path.isEmpty())
        return; // cancelled
    m_lastFolder = QFileInfo(path).absolutePath();
    QSettings().setValue(kLastFolderKey, m_lastFolder);
    openFile(path);
}

bool MainWindow::isTrialReport(const QString& path) {
    const QFileInfo info(path);
    if (info.isDir() || info.suffix().compare(QStringLiteral("json"), Qt::CaseInsensitive) != 0)
        return false;
    QFile file(info.absoluteFilePath());
    if (!file.open(QIODevice::ReadOnly))
        return false;
    const QByteArray head = file.read(256).simplified().replace(' ', QByteArray());
    return head.startsWith(QByteArrayLiteral("{\"format\":\"hysteroscene-trial-report\""));
}

void MainWindow::openArgument(const QString& path) {
    const QFileInfo info(path);
    if (isTrialReport(path))
        reviewTrialReport(path);
    else if (info.isDir())
        reviewPackage(path);
    else if (info.fileName() == QLatin1String(scene::kManifestName.data(), int(scene::kManifestName.size())))
        reviewPackage(info.absolutePath()); // a package's manifest stands for its package, not for a case
    else if (info.suffix().compare(QStringLiteral("json"), Qt::CaseInsensitive) == 0)
        openCase(path);
    else
        openFile(path);
}

bool MainWindow::openDropped(const QString& path) {
    const QFileInfo info(path);
    const QString name = QDir::toNativeSeparators(info.absoluteFilePath());
    if (isTrialReport(path)) { // read-only beside the review or the case: always welcome
        reviewTrialReport(path);
        return true;
    }
    if (isReviewing()) {
        MessageBox::information(this, tr("Open"),
                                tr("A scene package is being reviewed, read-only: close the review (File > Close "
                                   "Review) before opening %1.")
                                    .arg(name));
        return false;
    }
    const bool package =
        info.isDir() ? QFileInfo::exists(QDir(path).filePath(
                           QString::fromLatin1(scene::kManifestName.data(), int(scene::kManifestName.size()))))
                     : info.fileName() == QLatin1String(scene::kManifestName.data(), int(scene::kManifestName.size()));
    const bool caseFile = !info.isDir() && info.suffix().compare(QStringLiteral("json"), Qt::CaseInsensitive) == 0;
    bool mesh = false;
    for (const std::string& extension : io::supportedExtensions())
        mesh =
            mesh || (!info.isDir() && info.fileName().endsWith(QString::fromStdString(extension), Qt::CaseInsensitive));
    if (!package && !caseFile && !mesh) {
        QStringList meshes;
        for (const std::string& extension : io::supportedExtensions())
            meshes.append(QString::fromStdString(extension));
        MessageBox::information(this, tr("Open"),
                                info.isDir() ? tr("The folder %1 holds no scene package (no manifest.json).").arg(name)
                                             : tr("%1 is not a file this program opens: it opens cases (.json), scene "
                                                  "packages (a folder with a manifest.json) and meshes (%2).")
                                                   .arg(name, meshes.join(QStringLiteral(", "))));
        return false;
    }
    if (caseFile && !package && !maybeSave())
        return false;
    openArgument(path);
    return true;
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    // One local file or folder; what it is is decided (and explained) on the drop.
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.size() == 1 && urls.front().isLocalFile())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.size() != 1 || !urls.front().isLocalFile())
        return;
    event->acceptProposedAction();
    // After the drop has returned: a message box must not block the drag's own event loop.
    const QString path = urls.front().toLocalFile();
    QTimer::singleShot(0, this, [this, path] { openDropped(path); });
}

void MainWindow::watchFiles() {
    if (!m_diskWatcher.files().isEmpty())
        m_diskWatcher.removePaths(m_diskWatcher.files());
    QStringList paths;
    if (!m_document.filePath().isEmpty())
        paths.append(m_document.filePath());
    if (isReviewing())
        paths.append(QDir(m_reviewPanel->packageFolder())
                         .filePath(QString::fromLatin1(scene::kManifestName.data(), int(scene::kManifestName.size()))));
    for (const QString& path : paths)
        if (QFileInfo::exists(path))
            m_diskWatcher.addPath(path);
}

void MainWindow::onChangedOnDisk() {
    // A package under review: its manifest names its files and their checksums, so a changed manifest is a
    // changed package. The ratings belong to the version opened; they are never attached to another.
    if (isReviewing()) {
        const QString folder = m_reviewPanel->packageFolder();
        const auto identity = scene::packageIdentity(QFile::encodeName(folder).toStdString());
        if (!identity || QString::fromStdString(*identity) != m_reviewPanel->packageSha256()) {
            const QString name = QDir::toNativeSeparators(folder);
            if (MessageBox::askYesNo(this, tr("Package Changed on Disk"),
                                     tr("The scene package %1 has changed on disk since it was opened for review. "
                                        "Reload it? The ratings stay with the version you opened.")
                                         .arg(name)) == MessageBox::Choice::Yes &&
                maybeSaveReview()) {
                m_reviewPanel->close();
                reviewPackage(folder);
            } else {
                m_reviewPanel->showNotice(tr("The package has changed on disk since it was opened: what is shown, "
                                             "and rated, is the version opened."));
            }
        }
    }
    // The case: a save of our own leaves the file as the document is, and asks nothing.
    const QString path = m_document.filePath();
    if (!path.isEmpty() && QFileInfo::exists(path)) {
        const auto onDisk = scene::loadCase(QFile::encodeName(path).toStdString());
        const scene::CaseSpec& mine = m_document.spec();
        const bool same = onDisk && !generate::firstChangedStage(mine, *onDisk) && onDisk->title == mine.title;
        if (!same) {
            const QString name = QDir::toNativeSeparators(path);
            const QString question =
                m_document.isModified()
                    ? tr("The case %1 has changed on disk, and you have unsaved changes. Reload it from disk? Your "
                         "changes are lost.")
                          .arg(name)
                    : tr("The case %1 has changed on disk. Reload it?").arg(name);
            if (MessageBox::askYesNo(this, tr("Case Changed on Disk"), question) == MessageBox::Choice::Yes) {
                if (const Status opened = m_document.open(path); !opened)
                    showCaseError(tr("Open Case"), opened.error());
            } else {
                statusBar()->showMessage(
                    tr("The case on disk differs from the one open; Save writes this one over it."), 10000);
            }
        }
    } else if (!path.isEmpty()) {
        statusBar()->showMessage(
            tr("The case file %1 is gone from disk; Save writes it again.").arg(QDir::toNativeSeparators(path)), 10000);
    }
    watchFiles(); // a file replaced by a rename is a new file to watch
}

void MainWindow::openFile(const QString& path) {
    const QString absolutePath = QFileInfo(path).absoluteFilePath();
    statusBar()->showMessage(tr("Opening %1...").arg(QDir::toNativeSeparators(absolutePath)));
    // A newer request replaces the one being watched; the older result is dropped.
    m_loadWatcher.setFuture(QtConcurrent::run(loadMesh, absolutePath));
}

bool MainWindow::isLoading() const {
    return m_loadWatcher.isRunning();
}

void MainWindow::onLoadFinished() {
    statusBar()->clearMessage();
    const LoadedMesh loaded = m_loadWatcher.result();
    if (loaded.error) {
        showLoadError(loaded.path, *loaded.error);
        emit loadFailed(loaded.path);
        return;
    }
    showMesh(loaded);
    emit fileLoaded(loaded.path);
}

void MainWindow::showMesh(const LoadedMesh& loaded) {
    m_currentFile = loaded.path;
    showOwnMesh();
    std::visit(
        [this](const auto& mesh) {
            if constexpr (std::is_same_v<std::decay_t<decltype(mesh)>, SurfaceMesh>)
                m_display->showSurface(mesh);
            else
                m_display->showTetMesh(mesh);
        },
        *loaded.mesh);
    m_clipAction->setEnabled(m_display->isTetMesh());
    syncClipPlane();
    onResetCamera();
    m_pickLabel->clear();
    addRecentFile(loaded.path);
    updateStatus();
}

void MainWindow::showLoadError(const QString& path, const Error& error) {
    const QString name = QDir::toNativeSeparators(path);
    QString text;
    switch (error.code) {
    case ErrorCode::NotFound:
        text = tr("The file %1 does not exist.").arg(name);
        removeRecentFile(path);
        break;
    case ErrorCode::IoError:
        text = tr("The file %1 could not be read.").arg(name);
        break;
    case ErrorCode::Unsupported:
        text = tr("The file %1 is in a format or version this program does not read.").arg(name);
        break;
    case ErrorCode::LimitExceeded:
        text = tr("The file %1 is larger than this program accepts.").arg(name);
        break;
    case ErrorCode::InvalidInput:
        text = tr("The file %1 is not a valid mesh.").arg(name);
        break;
    default:
        text = tr("The file %1 could not be opened.").arg(name);
        break;
    }
    MessageBox::critical(this, tr("Open Mesh"), text, QString::fromStdString(error.message()));
}

// --- Recent files -------------------------------------------------------------------------------------------------

QStringList MainWindow::recentFiles() const {
    return widgets::recentFiles(QSettings(), kRecentFilesKey);
}

void MainWindow::addRecentFile(const QString& path) {
    QSettings settings;
    widgets::addRecentFile(settings, kRecentFilesKey, path);
    rebuildRecentMenu();
}

void MainWindow::removeRecentFile(const QString& path) {
    QSettings settings;
    widgets::removeRecentFile(settings, kRecentFilesKey, path);
    rebuildRecentMenu();
}

void MainWindow::fillRecentMenu(QMenu* menu, const QStringList& files, const QString& prefix,
                                void (MainWindow::*slot)()) {
    menu->clear();
    for (int i = 0; i < files.size(); ++i) {
        const QString& path = files.at(i);
        QAction* action = menu->addAction(QStringLiteral("&%1 %2").arg(i + 1).arg(QFileInfo(path).fileName()));
        action->setObjectName(prefix + QString::number(i));
        action->setData(path);
        action->setToolTip(QDir::toNativeSeparators(path));
        connect(action, &QAction::triggered, this, slot);
    }
}

void MainWindow::rebuildRecentMenu() {
    const QStringList files = recentFiles();
    fillRecentMenu(m_recentMenu, files, QStringLiteral("recentFile"), &MainWindow::onOpenRecent);
    m_recentMenu->addSeparator();
    m_recentMenu->addAction(m_clearRecentAction);
    m_clearRecentAction->setEnabled(!files.isEmpty());
    updateAuthoringActions();
}

void MainWindow::onOpenRecent() {
    if (const auto* action = qobject_cast<QAction*>(sender()))
        openFile(action->data().toString());
}

void MainWindow::onClearRecent() {
    QSettings().remove(kRecentFilesKey);
    rebuildRecentMenu();
}

// --- View ---------------------------------------------------------------------------------------------------------

} // namespace hs::workstation
