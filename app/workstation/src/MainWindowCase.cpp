// The main window and the case being authored: new, open, save, recent cases, autosave and recovery.
#include "hs/workstation/MainWindow.h"

#include "MainWindowSettings.h"
#include "hs/widgets/common/FileDialog.h"
#include "hs/widgets/common/MessageBox.h"

#include <QAction>
#include <QCloseEvent>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>

#include <string>

namespace hs::workstation {

using widgets::FileDialog;
using widgets::MessageBox;

void MainWindow::updateTitle() {
    setWindowTitle(m_document.windowTitle());
    setWindowModified(m_document.isModified());
}

bool MainWindow::maybeSave() {
    if (!m_document.isModified())
        return true;
    switch (MessageBox::askSaveDiscardCancel(
        this, tr("Unsaved Changes"), tr("The case %1 has unsaved changes. Save them?").arg(m_document.displayName()))) {
    case MessageBox::Choice::Save:
        return onSaveCase();
    case MessageBox::Choice::Discard:
        return true;
    default:
        return false;
    }
}

void MainWindow::showCaseError(const QString& title, const Error& error) {
    QString text;
    switch (error.code) {
    case ErrorCode::NotFound:
        text = tr("The case file does not exist.");
        break;
    case ErrorCode::IoError:
        text = tr("The case file could not be read or written.");
        break;
    case ErrorCode::Unsupported:
        text = tr("The case file is of a version this program does not read.");
        break;
    case ErrorCode::LimitExceeded:
        text = tr("The case file is larger than this program accepts.");
        break;
    case ErrorCode::InvalidInput:
        text = tr("The case is not valid: a value is outside its allowed range (see the details).");
        break;
    default:
        text = tr("The case could not be opened or saved.");
        break;
    }
    MessageBox::critical(this, title, text, QString::fromStdString(error.message()));
}

void MainWindow::onNewCase() {
    if (maybeSave())
        m_document.newCase();
}

void MainWindow::onOpenCase() {
    if (!maybeSave())
        return;
    const QString path = FileDialog::getOpenFileName(this, tr("Open Case"), m_lastFolder,
                                                     tr("Cases (*.json)") + QStringLiteral(";;") + tr("All files (*)"));
    if (path.isEmpty())
        return;
    m_lastFolder = QFileInfo(path).absolutePath();
    openCase(path);
}

void MainWindow::onOpenRecentCase() {
    const auto* action = qobject_cast<QAction*>(sender());
    if (!action || !maybeSave())
        return;
    // Opening rebuilds this menu, which deletes the action that is still delivering its signal: open right after.
    QMetaObject::invokeMethod(
        this, [this, path = action->data().toString()] { openCase(path); }, Qt::QueuedConnection);
}

void MainWindow::openCase(const QString& path) {
    QSettings settings;
    if (const Status opened = m_document.open(path); !opened) {
        if (opened.error().code == ErrorCode::NotFound)
            widgets::removeRecentFile(settings, widgets::kRecentCasesKey, path);
        rebuildRecentCasesMenu();
        showCaseError(tr("Open Case"), opened.error());
        return;
    }
    widgets::addRecentFile(settings, widgets::kRecentCasesKey, m_document.filePath());
    rebuildRecentCasesMenu();
}

void MainWindow::rebuildRecentCasesMenu() {
    const QStringList cases = widgets::recentFiles(QSettings(), widgets::kRecentCasesKey);
    fillRecentMenu(m_recentCasesMenu, cases, QStringLiteral("recentCase"), &MainWindow::onOpenRecentCase);
    updateAuthoringActions();
}

bool MainWindow::onSaveCase() {
    if (m_document.filePath().isEmpty())
        return onSaveCaseAs();
    if (const Status saved = m_document.save(); !saved) {
        showCaseError(tr("Save Case"), saved.error());
        return false;
    }
    return true;
}

bool MainWindow::onSaveCaseAs() {
    const QString path = FileDialog::getSaveFileName(this, tr("Save Case"), m_lastFolder,
                                                     tr("Cases (*.json)") + QStringLiteral(";;") + tr("All files (*)"));
    if (path.isEmpty())
        return false;
    m_lastFolder = QFileInfo(path).absolutePath();
    if (const Status saved = m_document.saveAs(path); !saved) {
        showCaseError(tr("Save Case"), saved.error());
        return false;
    }
    QSettings settings;
    widgets::addRecentFile(settings, widgets::kRecentCasesKey, m_document.filePath());
    rebuildRecentCasesMenu();
    return true;
}

void MainWindow::autosave() {
    if (!m_document.isModified())
        return;
    if (const Status written = m_document.writeRecovery(m_recoveryFolder); !written)
        statusBar()->showMessage(tr("Autosave failed: %1").arg(QString::fromStdString(written.error().message())));
}

void MainWindow::offerRecovery() {
    const auto found = widgets::CaseDocument::findRecovery(m_recoveryFolder);
    if (!found)
        return;
    const QString name = found->origin.isEmpty() ? tr("Untitled") : QFileInfo(found->origin).fileName();
    if (MessageBox::askYesNo(
            this, tr("Recover Unsaved Changes"),
            tr("The last session ended with unsaved changes to the case %1. Recover them?").arg(name)) ==
        MessageBox::Choice::Yes) {
        if (const Status restored = m_document.restore(*found); !restored) {
            showCaseError(tr("Recover Unsaved Changes"), restored.error());
            return;
        }
    }
    widgets::CaseDocument::discardRecovery(m_recoveryFolder);
}

} // namespace hs::workstation
