// The main window and the files it opens: a mesh on a worker thread, the command line's argument, recent files.
#include "hs/workstation/MainWindow.h"

#include "MainWindowSettings.h"
#include "hs/scene/ScenePackage.h"
#include "hs/widgets/common/FileDialog.h"
#include "hs/widgets/common/MessageBox.h"
#include "hs/widgets/view/MeshDisplay.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QSettings>
#include <QStatusBar>
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

void MainWindow::openArgument(const QString& path) {
    const QFileInfo info(path);
    if (info.isDir())
        reviewPackage(path);
    else if (info.fileName() == QLatin1String(scene::kManifestName.data(), int(scene::kManifestName.size())))
        reviewPackage(info.absolutePath()); // a package's manifest stands for its package, not for a case
    else if (info.suffix().compare(QStringLiteral("json"), Qt::CaseInsensitive) == 0)
        openCase(path);
    else
        openFile(path);
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
