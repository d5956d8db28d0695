// Qt Test for the workstation's main window, driven like a user through its seams (file dialog, message boxes).
// Needs a display (xvfb-run -a).
#include "GuiTestMeshes.h"
#include "LayoutCheck.h"
#include "hs/io/MeshIO.h"
#include "hs/sim/Metrics.h"
#include "hs/widgets/common/FileDialog.h"
#include "hs/widgets/common/MessageBox.h"
#include "hs/widgets/panels/TrialReportView.h"
#include "hs/widgets/view/ClipPlaneWidget.h"
#include "hs/widgets/view/MeshDisplay.h"
#include "hs/widgets/view/VtkView.h"
#include "hs/workstation/MainWindow.h"

#include <QAction>
#include <QApplication>
#include <QChartView>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QDropEvent>
#include <QFile>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QLineSeries>
#include <QListWidget>
#include <QLocale>
#include <QMenu>
#include <QMimeData>
#include <QPushButton>
#include <QScatterSeries>
#include <QScrollArea>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>
#include <QUrl>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <cmath>
#include <memory>

using hs::widgets::FileDialog;
using hs::widgets::MessageBox;
using hs::workstation::MainWindow;

namespace {

constexpr int kLoadTimeoutMs = 20000;
constexpr double kSphereRadius = 10.0;

QString count(std::size_t n) {
    return QLocale().toString(static_cast<qulonglong>(n));
}

} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void opensFileChosenInFileDialog();
    void cancelledDialogKeepsWindowAsItWas();
    void statusBarCountsMatchFile_data();
    void statusBarCountsMatchFile();
    void clipToggleShowsCutTetrahedra();
    void clipShortcutTogglesClip();
    void clickOnViewPicksSurfacePoint();
    void anatomicalViewsTurnTheCameraAndTheMarkerShowsTheSides();
    void recentFilesPersistInSettings();
    void badFileShowsErrorAndKeepsMesh();
    void missingRecentFileIsForgotten();
    void aboutGoesThroughMessageBox();
    void closingSavesWindowGeometry();
    void caseTitleShowsFileAndUnsavedMark();
    void theCommandLinesCaseFileOpensAsACase();
    void undoAndRedoActionsFollowTheDocument();
    void undoingEveryEditThroughTheEditMenuSavesTheOpenedBytes();
    void closingWithUnsavedChangesAsks();
    void savingAnInvalidCaseShowsTheFieldAndKeepsTheFile();
    void autosaveIsOfferedBackAfterACrash();
    void aDropOpensACaseOrAMeshAndSaysWhyItRefusesAnythingElse();
    void aCaseChangedOnDiskIsOfferedToReloadAndOurOwnSaveIsNot();
    void theHysteroscopicViewDetachesAndEnlarges();
    void aTrialReportShowsTheReportsFiguresInAWindowOfItsOwn();
    void aReviewedTrialReplaysInTheSimulator();
    void nothingIsCutOffOnASmallScreen_data();
    void nothingIsCutOffOnASmallScreen();

private:
    template <class T>
    T* find(const QString& name) const {
        return m_window->findChild<T*>(name);
    }
    QString fixture(const QString& name) const { return m_dir.filePath(name); }
    bool openThroughDialog(const QString& path);
    QImage viewImage() const { return m_window->view()->grabImage(); }

    QTemporaryDir m_dir;
    QTemporaryDir m_settingsDir;
    hs::SurfaceMesh m_sphere;
    hs::TetMesh m_cube;
    std::unique_ptr<MainWindow> m_window;
};

void TestMainWindow::initTestCase() {
    QVERIFY(m_dir.isValid() && m_settingsDir.isValid());
    // Settings go to a scratch folder, never to the user's configuration.
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    QCoreApplication::setOrganizationName("hysteroscene-test");
    QCoreApplication::setApplicationName("test_workstation");
    MessageBox::setRecording(true);

    m_sphere = hs::test::makeSphere(kSphereRadius);
    m_sphere.faceLabels.clear(); // OFF carries no labels
    QVERIFY(hs::io::writeSurface(m_sphere, fixture("sphere.off").toStdString()).ok());
    m_cube = hs::test::makeTetCube(5);
    QVERIFY(hs::io::writeTetMesh(m_cube, fixture("cube.vtu").toStdString()).ok());
    QFile bad(fixture("bad.off"));
    QVERIFY(bad.open(QIODevice::WriteOnly));
    bad.write("OFF\n4 2 0\n0 0 0\n1 0 0\n0 1\n"); // truncated in the middle of the points
    bad.close();
}

void TestMainWindow::init() {
    QSettings().clear();
    MessageBox::takeRecorded();
    m_window = std::make_unique<MainWindow>();
    m_window->setRecoveryFolder(m_dir.filePath("recovery"));
    m_window->resize(1280, 1000); // the panels take the sides; the view keeps the centre
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    QTRY_VERIFY(m_window->view()->renderCount() > 0);
}

void TestMainWindow::cleanup() {
    if (m_window)
        m_window->document().undoStack()->setClean(); // nothing left to ask about when the window goes
    m_window.reset();
    hs::widgets::CaseDocument::discardRecovery(m_dir.filePath("recovery"));
    QCOMPARE(MessageBox::takeRecorded().size(), 0); // no test leaves an unexpected message behind
}

// Each anatomical view (View > Look From, the Views tool bar, Ctrl+Alt+1..6) looks from its side of the patient in the
// scene's frame (+x right, +y anterior, +z up the canal) at the whole mesh; the orientation marker draws in the view's
// lower-left corner and goes with its action.
void TestMainWindow::anatomicalViewsTurnTheCameraAndTheMarkerShowsTheSides() {
    QVERIFY(openThroughDialog(fixture("sphere.off")));
    vtkCamera* camera = m_window->view()->renderer()->GetActiveCamera();
    const struct {
        const char* action;
        double towardsCamera[3];
        double up[3];
    } looks[] = {{"actionLookAnterior", {0, 1, 0}, {0, 0, 1}}, {"actionLookPosterior", {0, -1, 0}, {0, 0, 1}},
                 {"actionLookLeft", {-1, 0, 0}, {0, 0, 1}},    {"actionLookRight", {1, 0, 0}, {0, 0, 1}},
                 {"actionLookFundal", {0, 0, 1}, {0, 1, 0}},   {"actionLookExternalOs", {0, 0, -1}, {0, 1, 0}}};
    QCOMPARE(find<QMenu>("menuLookFrom")->actions().size(), 6);
    for (const auto& look : looks) {
        auto* action = find<QAction>(look.action);
        QVERIFY2(action && action->isEnabled(), look.action);
        action->trigger();
        double dop[3];
        camera->GetDirectionOfProjection(dop);
        double up[3];
        camera->GetViewUp(up);
        for (int k = 0; k < 3; ++k) {
            QVERIFY2(std::abs(dop[k] + look.towardsCamera[k]) < 1e-9, look.action);
            QVERIFY2(std::abs(up[k] - look.up[k]) < 1e-9, look.action);
        }
        // The whole sphere (centred at the origin) is in the picture: the camera looks at its centre.
        double focal[3];
        camera->GetFocalPoint(focal);
        QVERIFY2(std::abs(focal[0]) + std::abs(focal[1]) + std::abs(focal[2]) < 0.02 * kSphereRadius, look.action);
    }
    // The marker: its corner of the picture differs from the same corner with the marker hidden.
    auto* marker = find<QAction>("actionOrientationMarker");
    QVERIFY(marker->isChecked());
    const QImage with = viewImage();
    marker->setChecked(false);
    const QImage without = viewImage();
    const QRect corner(0, with.height() * 5 / 6, with.width() / 8, with.height() / 6);
    QVERIFY(with.copy(corner) != without.copy(corner));
    marker->setChecked(true);
}

bool TestMainWindow::openThroughDialog(const QString& path) {
    QSignalSpy loaded(m_window.get(), &MainWindow::fileLoaded);
    FileDialog::setNextFileName(path);
    find<QAction>("actionOpen")->trigger();
    return loaded.wait(kLoadTimeoutMs);
}

void TestMainWindow::opensFileChosenInFileDialog() {
    const QImage empty = viewImage();
    QVERIFY(openThroughDialog(fixture("sphere.off")));
    QCOMPARE(m_window->currentFile(), fixture("sphere.off"));
    QCOMPARE(find<QLabel>("fileLabel")->text(), QStringLiteral("sphere.off"));
    const QImage shown = viewImage();
    const int changed = hs::test::pixelsDifferentBetween(empty, shown);
    QVERIFY2(changed > shown.width() * shown.height() / 20, qPrintable(QString::number(changed)));
    QVERIFY(m_window->windowTitle().startsWith("Untitled")); // the title names the case, not the mesh shown
}

void TestMainWindow::cancelledDialogKeepsWindowAsItWas() {
    QVERIFY(openThroughDialog(fixture("sphere.off")));
    QSignalSpy loaded(m_window.get(), &MainWindow::fileLoaded);
    FileDialog::setNextFileName(QString());
    find<QAction>("actionOpen")->trigger();
    QVERIFY(!m_window->isLoading());
    QCOMPARE(loaded.count(), 0);
    QCOMPARE(m_window->currentFile(), fixture("sphere.off"));
}

void TestMainWindow::statusBarCountsMatchFile_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("expected"); // the counts, as the status bar should read them
    QTest::newRow("surface") << "sphere.off"
                             << QStringLiteral("Vertices: %1   Triangles: %2   Regions: 1")
                                    .arg(count(m_sphere.vertexCount()), count(m_sphere.faceCount()));
    QTest::newRow("tetrahedra") << "cube.vtu"
                                << QStringLiteral("Vertices: %1   Tetrahedra: %2   Regions: 2")
                                       .arg(count(m_cube.vertexCount()), count(m_cube.tetCount()));
}

void TestMainWindow::statusBarCountsMatchFile() {
    QFETCH(QString, file);
    QFETCH(QString, expected);
    QVERIFY(openThroughDialog(fixture(file)));
    QCOMPARE(find<QLabel>("countsLabel")->text(), expected);
    QCOMPARE(find<QLabel>("fileLabel")->text(), file);
}

void TestMainWindow::clipToggleShowsCutTetrahedra() {
    QVERIFY(openThroughDialog(fixture("cube.vtu")));
    auto* clip = find<QAction>("actionClip");
    QVERIFY(clip->isEnabled());
    QVERIFY(!clip->isChecked());
    const QImage whole = viewImage();
    QCOMPARE(m_window->display().visibleCellCount(), m_cube.tetCount());

    clip->trigger();
    QVERIFY(clip->isChecked());
    const std::size_t shown = m_window->display().visibleCellCount();
    QVERIFY2(shown > 0 && shown < m_cube.tetCount(), qPrintable(QString::number(shown)));
    QVERIFY(find<QLabel>("countsLabel")->text().endsWith(QStringLiteral("Shown: %1").arg(count(shown))));
    const QImage cut = viewImage();
    const int changed = hs::test::pixelsDifferentBetween(whole, cut);
    QVERIFY2(changed > 1000, qPrintable(QString::number(changed)));

    // The plane is a handle in the view: shown with the clip, at the display's plane (the mesh's centre, +x).
    hs::widgets::ClipPlaneWidget& plane = m_window->clipPlane();
    QVERIFY(plane.isVisible());
    QVERIFY(hs::distance(plane.origin(), m_window->display().clipOrigin()) < 1e-9);
    // Dragged towards -x, fewer tets are kept; tilted to +z, another half.
    const auto box = m_window->display().meshBounds();
    plane.moveTo({box[0] + 0.2 * (box[1] - box[0]), 0.5 * (box[2] + box[3]), 0.5 * (box[4] + box[5])}, {1, 0, 0});
    const std::size_t slid = m_window->display().visibleCellCount();
    QVERIFY2(slid > 0 && slid < shown, qPrintable(QString::number(slid)));
    QVERIFY(find<QLabel>("countsLabel")->text().endsWith(QStringLiteral("Shown: %1").arg(count(slid))));
    plane.moveTo({0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3]), 0.5 * (box[4] + box[5])}, {0, 0, 1});
    const std::size_t tilted = m_window->display().visibleCellCount();
    QVERIFY2(tilted > slid && tilted < m_cube.tetCount(), qPrintable(QString::number(tilted)));
    // A real drag of the plane with the mouse moves it (and the cut) too.
    const hs::Vec3 before = plane.origin();
    const QImage beforeDrag = viewImage();
    vtkRenderer* renderer = m_window->view()->renderer();
    renderer->SetWorldPoint(before.x, before.y, before.z, 1.0);
    renderer->WorldToDisplay();
    double display[3];
    renderer->GetDisplayPoint(display);
    const double ratio = m_window->view()->devicePixelRatioF();
    const QPoint at(int(display[0] / ratio), m_window->view()->height() - int(display[1] / ratio));
    QTest::mousePress(m_window->view(), Qt::LeftButton, Qt::NoModifier, at);
    for (int k = 1; k <= 10; ++k)
        QTest::mouseMove(m_window->view(), at + QPoint(0, 4 * k));
    QTest::mouseRelease(m_window->view(), Qt::LeftButton, Qt::NoModifier, at + QPoint(0, 40));
    QVERIFY2(hs::distance(plane.origin(), before) > 1e-6 || hs::distance(plane.normal(), {0, 0, 1}) > 1e-6,
             "the drag did not move the plane");
    QVERIFY(hs::test::pixelsDifferentBetween(beforeDrag, viewImage()) > 100);

    clip->trigger();
    QVERIFY(!plane.isVisible());
    QCOMPARE(m_window->display().visibleCellCount(), m_cube.tetCount());
    QVERIFY(hs::test::pixelsDifferentBetween(whole, viewImage()) < 50);
}

void TestMainWindow::clipShortcutTogglesClip() {
    QVERIFY(openThroughDialog(fixture("cube.vtu")));
    auto* clip = find<QAction>("actionClip");
    m_window->activateWindow();
    QTRY_VERIFY(m_window->isActiveWindow());
    QTest::keyClick(m_window.get(), Qt::Key_K, Qt::ControlModifier);
    QVERIFY(clip->isChecked());
    QTest::keyClick(m_window->view(), Qt::Key_K, Qt::ControlModifier);
    QVERIFY(!clip->isChecked());
}

void TestMainWindow::clickOnViewPicksSurfacePoint() {
    QVERIFY(openThroughDialog(fixture("sphere.off")));
    hs::widgets::VtkView* view = find<hs::widgets::VtkView>("view");
    QVERIFY(view);
    QSignalSpy picked(view, &hs::widgets::VtkView::picked);
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, view->rect().center() + QPoint(20, -15));
    QCOMPARE(picked.count(), 1);
    const auto result = picked.takeFirst().at(0).value<hs::widgets::PickResult>();
    QVERIFY(result.hit);
    QVERIFY(std::abs(double(result.point.length()) - kSphereRadius) < 0.05 * kSphereRadius);
    const QString text = find<QLabel>("pickLabel")->text();
    QVERIFY2(text.startsWith("Picked (") && text.endsWith(") mm"), qPrintable(text));

    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, QPoint(3, 3));
    QCOMPARE(find<QLabel>("pickLabel")->text(), QStringLiteral("Nothing picked"));
}

void TestMainWindow::recentFilesPersistInSettings() {
    QVERIFY(openThroughDialog(fixture("sphere.off")));
    QVERIFY(openThroughDialog(fixture("cube.vtu")));
    QVERIFY(openThroughDialog(fixture("sphere.off"))); // moves to the top, not listed twice
    const QStringList expected{fixture("sphere.off"), fixture("cube.vtu")};
    QCOMPARE(m_window->recentFiles(), expected);

    // A new window (a new session) reads the list back from the settings.
    m_window = std::make_unique<MainWindow>();
    QCOMPARE(m_window->recentFiles(), expected);
    QCOMPARE(QSettings().value("files/recent").toStringList(), expected);
    auto* menu = find<QMenu>("menuRecent");
    QVERIFY(menu);
    auto* second = menu->findChild<QAction*>("recentFile1");
    QVERIFY(second);
    QCOMPARE(second->data().toString(), fixture("cube.vtu"));
    QCOMPARE(QSettings().value("files/lastFolder").toString(), m_dir.path());

    QSignalSpy loaded(m_window.get(), &MainWindow::fileLoaded);
    second->trigger();
    QVERIFY(loaded.wait(kLoadTimeoutMs));
    QCOMPARE(m_window->currentFile(), fixture("cube.vtu"));
    QCOMPARE(m_window->recentFiles().first(), fixture("cube.vtu"));

    find<QAction>("actionClearRecent")->trigger();
    QVERIFY(m_window->recentFiles().isEmpty());
    QVERIFY(QSettings().value("files/recent").toStringList().isEmpty());
}

void TestMainWindow::badFileShowsErrorAndKeepsMesh() {
    QVERIFY(openThroughDialog(fixture("sphere.off")));
    const QString counts = find<QLabel>("countsLabel")->text();
    const QImage before = viewImage();

    QSignalSpy failed(m_window.get(), &MainWindow::loadFailed);
    FileDialog::setNextFileName(fixture("bad.off"));
    find<QAction>("actionOpen")->trigger();
    QVERIFY(failed.wait(kLoadTimeoutMs));

    const QList<MessageBox::Message> messages = MessageBox::takeRecorded();
    QCOMPARE(messages.size(), 1);
    QCOMPARE(messages.first().icon, MessageBox::Icon::Critical);
    QCOMPARE(messages.first().title, QStringLiteral("Open Mesh"));
    QVERIFY2(messages.first().text.contains("bad.off"), qPrintable(messages.first().text));
    QVERIFY(!messages.first().details.isEmpty());

    QCOMPARE(m_window->currentFile(), fixture("sphere.off"));
    QCOMPARE(find<QLabel>("countsLabel")->text(), counts);
    QVERIFY(hs::test::pixelsDifferentBetween(before, viewImage()) < 50);
    QVERIFY(!m_window->recentFiles().contains(fixture("bad.off")));
}

void TestMainWindow::missingRecentFileIsForgotten() {
    const QString gone = fixture("gone.off");
    QVERIFY(QFile::copy(fixture("sphere.off"), gone));
    QVERIFY(openThroughDialog(gone));
    QVERIFY(QFile::remove(gone));
    QSignalSpy failed(m_window.get(), &MainWindow::loadFailed);
    find<QMenu>("menuRecent")->findChild<QAction*>("recentFile0")->trigger();
    QVERIFY(failed.wait(kLoadTimeoutMs));
    const QList<MessageBox::Message> messages = MessageBox::takeRecorded();
    QCOMPARE(messages.size(), 1);
    QVERIFY(messages.first().text.contains("does not exist"));
    QVERIFY(!m_window->recentFiles().contains(gone));
}

void TestMainWindow::aboutGoesThroughMessageBox() {
    find<QAction>("actionAbout")->trigger();
    const QList<MessageBox::Message> messages = MessageBox::takeRecorded();
    QCOMPARE(messages.size(), 1);
    QVERIFY(messages.first().text.contains(QStringLiteral(HS_VERSION)));
    // The versions of the libraries that shape a scene, and Qt's.
    QVERIFY(messages.first().text.contains(QStringLiteral("vtk ")));
    QVERIFY(messages.first().text.contains(QStringLiteral("qt %1").arg(qVersion())));
}

void TestMainWindow::closingSavesWindowGeometry() {
    m_window->resize(700, 500);
    find<QAction>("actionQuit")->trigger();
    QVERIFY(!m_window->isVisible());
    QVERIFY(!QSettings().value("window/geometry").toByteArray().isEmpty());
    m_window = std::make_unique<MainWindow>();
    QCOMPARE(m_window->size(), QSize(700, 500));
}

void TestMainWindow::theCommandLinesCaseFileOpensAsACase() {
    // `hysteroscene case.json` opens the case (it used to be read as a mesh); a mesh still opens as a mesh.
    const QString path = fixture("argument.json");
    m_window->document().edit("Seed", [](hs::scene::CaseSpec& c) { c.seed = 5; });
    FileDialog::setNextFileName(path);
    find<QAction>("actionSaveCaseAs")->trigger();
    QVERIFY(QFileInfo::exists(path));
    m_window = std::make_unique<MainWindow>();
    m_window->openArgument(path);
    QCOMPARE(m_window->document().filePath(), QFileInfo(path).absoluteFilePath());
    QCOMPARE(m_window->document().spec().seed, std::uint64_t{5});
    QVERIFY(!m_window->isLoading()); // nothing went to the mesh reader
    // A package's manifest.json stands for its package: it goes to review (here a broken one, refused by name), not
    // to the case reader.
    const QString package = fixture("package");
    QVERIFY(QDir().mkpath(package));
    QFile manifest(package + "/manifest.json");
    QVERIFY(manifest.open(QIODevice::WriteOnly));
    manifest.write("{\"format\": \"hysteroscene-scene\", \"schemaVersion\": 1, \"files\": []}");
    manifest.close();
    m_window->openArgument(manifest.fileName());
    QList<MessageBox::Message> messages;
    QTRY_VERIFY_WITH_TIMEOUT((messages += MessageBox::takeRecorded(), !messages.isEmpty()), 20000);
    QVERIFY2(messages.first().title.contains("package", Qt::CaseInsensitive) ||
                 messages.first().text.contains("package", Qt::CaseInsensitive),
             qPrintable(messages.first().title + " / " + messages.first().text));
    QVERIFY2(messages.first().details.contains("manifest.json"), qPrintable(messages.first().details));
    QCOMPARE(m_window->document().filePath(), QFileInfo(path).absoluteFilePath()); // the case stays
    QVERIFY(!m_window->isLoading());
}

void TestMainWindow::caseTitleShowsFileAndUnsavedMark() {
    QCOMPARE(m_window->windowTitle(), QString("Untitled[*] - Hysteroscene"));
    QVERIFY(!m_window->isWindowModified());
    const QString path = fixture("authored.json");
    FileDialog::setNextFileName(path);
    find<QAction>("actionSaveCaseAs")->trigger();
    QVERIFY(QFileInfo::exists(path));
    QCOMPARE(m_window->windowTitle(), QString("authored.json[*] - Hysteroscene"));
    m_window->document().edit("Seed", [](hs::scene::CaseSpec& c) { c.seed = 3; });
    QVERIFY(m_window->isWindowModified());
    find<QAction>("actionSaveCase")->trigger(); // to the same file, no dialog
    QVERIFY(!m_window->isWindowModified());
    auto reread = hs::scene::loadCase(path.toStdString());
    QVERIFY(reread.ok());
    QCOMPARE(reread->seed, std::uint64_t{3});
    // Open Case reads it back; New Case starts untitled again.
    m_window->document().newCase();
    FileDialog::setNextFileName(path);
    find<QAction>("actionOpenCase")->trigger();
    QCOMPARE(m_window->document().spec().seed, std::uint64_t{3});
    QCOMPARE(m_window->document().filePath(), QFileInfo(path).absoluteFilePath());
    find<QAction>("actionNewCase")->trigger();
    QVERIFY(m_window->document().filePath().isEmpty());
    // Saved and opened cases are listed under Open Recent Case, and open from there (in the next session too).
    m_window = std::make_unique<MainWindow>();
    auto* recent = find<QAction>("recentCase0");
    QVERIFY(recent);
    QCOMPARE(recent->text(), QString("&1 authored.json"));
    recent->trigger();
    QTRY_COMPARE(m_window->document().filePath(), QFileInfo(path).absoluteFilePath());
    // A case that is gone says so and is dropped from the list, as a mesh is.
    m_window->document().newCase();
    QVERIFY(QFile::remove(path));
    find<QAction>("recentCase0")->trigger();
    QTRY_VERIFY(!find<QAction>("recentCase0"));
    const auto shown = MessageBox::takeRecorded();
    QCOMPARE(shown.size(), 1);
    QCOMPARE(shown.front().icon, MessageBox::Icon::Critical);
    QVERIFY(!find<QAction>("recentCase0"));
    QVERIFY(m_window->document().filePath().isEmpty());
}

void TestMainWindow::undoAndRedoActionsFollowTheDocument() {
    QAction* undo = find<QAction>("actionUndo");
    QAction* redo = find<QAction>("actionRedo");
    QVERIFY(undo && redo);
    QVERIFY(!undo->isEnabled());
    m_window->document().edit("Age", [](hs::scene::CaseSpec& c) { c.patient.ageYears = 41.0; });
    QVERIFY(undo->isEnabled());
    QVERIFY(undo->text().contains("Age"));
    undo->trigger();
    QCOMPARE(m_window->document().spec().patient.ageYears, 35.0);
    QVERIFY(!m_window->isWindowModified());
    QVERIFY(redo->isEnabled());
    m_window->activateWindow();
    QTRY_VERIFY(m_window->isActiveWindow());
    QTest::keySequence(m_window.get(), QKeySequence::Redo);
    QCOMPARE(m_window->document().spec().patient.ageYears, 41.0);
}

// Edits made in the panels' fields, undone one by one with Edit > Undo, then saved: the file is the opened one byte for
// byte; redone with Edit > Redo and saved: the edited case again, byte for byte.
void TestMainWindow::undoingEveryEditThroughTheEditMenuSavesTheOpenedBytes() {
    const QString path = fixture("bytes.json");
    FileDialog::setNextFileName(path);
    find<QAction>("actionSaveCaseAs")->trigger();
    const auto readAll = [](const QString& file) {
        QFile f(file);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    };
    const QByteArray opened = readAll(path);
    QVERIFY(!opened.isEmpty());
    m_window = std::make_unique<MainWindow>();
    m_window->openArgument(path);
    QCOMPARE(m_window->document().filePath(), QFileInfo(path).absoluteFilePath());
    find<QDoubleSpinBox>("ageSpin")->setValue(47.0);
    find<QSpinBox>("paritySpin")->setValue(0); // at most the gravidity (1)
    find<QDoubleSpinBox>("weightSpin")->setValue(71.0);
    find<QDoubleSpinBox>("heightSpin")->setValue(170.0);
    QVERIFY(m_window->isWindowModified());
    QAction* undo = find<QAction>("actionUndo");
    QAction* redo = find<QAction>("actionRedo");
    QVERIFY(find<QMenu>("menuEdit")->actions().contains(undo));
    int undone = 0;
    while (undo->isEnabled() && undone < 100) {
        undo->trigger();
        ++undone;
    }
    QCOMPARE(undone, 4);
    QVERIFY(!m_window->isWindowModified());
    find<QAction>("actionSaveCase")->trigger();
    QCOMPARE(readAll(path), opened);
    while (redo->isEnabled())
        redo->trigger();
    find<QAction>("actionSaveCase")->trigger();
    const QByteArray edited = readAll(path);
    QVERIFY(edited != opened);
    auto reread = hs::scene::loadCase(path.toStdString());
    QVERIFY(reread.ok());
    QCOMPARE(reread->patient.ageYears, 47.0);
    QCOMPARE(reread->patient.parity, 0);
    QCOMPARE(hs::scene::toJson(*reread), hs::scene::toJson(m_window->document().spec()));
}

void TestMainWindow::closingWithUnsavedChangesAsks() {
    m_window->document().edit("Age", [](hs::scene::CaseSpec& c) { c.patient.ageYears = 41.0; });
    MessageBox::setNextAnswer(MessageBox::Choice::Cancel);
    QVERIFY(!m_window->close());
    QVERIFY(m_window->isVisible());
    auto asked = MessageBox::takeRecorded();
    QCOMPARE(asked.size(), 1);
    QCOMPARE(asked.front().icon, MessageBox::Icon::Question);
    QVERIFY(asked.front().text.contains("Untitled"));
    MessageBox::setNextAnswer(MessageBox::Choice::Discard);
    QVERIFY(m_window->close());
    QCOMPARE(MessageBox::takeRecorded().size(), 1);
}

void TestMainWindow::savingAnInvalidCaseShowsTheFieldAndKeepsTheFile() {
    const QString path = fixture("valid.json");
    FileDialog::setNextFileName(path);
    find<QAction>("actionSaveCaseAs")->trigger();
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray before = file.readAll();
    file.close();
    m_window->document().edit("Age", [](hs::scene::CaseSpec& c) { c.patient.ageYears = 300.0; });
    find<QAction>("actionSaveCase")->trigger();
    const auto shown = MessageBox::takeRecorded();
    QCOMPARE(shown.size(), 1);
    QCOMPARE(shown.front().icon, MessageBox::Icon::Critical);
    QVERIFY(shown.front().details.contains("ageYears")); // the detail names the field
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), before);
    QVERIFY(m_window->isWindowModified());
}

void TestMainWindow::autosaveIsOfferedBackAfterACrash() {
    m_window->autosave(); // nothing unsaved: nothing written
    QVERIFY(!hs::widgets::CaseDocument::findRecovery(m_window->recoveryFolder()).has_value());
    m_window->document().edit("Age", [](hs::scene::CaseSpec& c) { c.patient.ageYears = 58.0; });
    m_window->autosave();
    QVERIFY(hs::widgets::CaseDocument::findRecovery(m_window->recoveryFolder()).has_value());
    // The session ends without closing (a crash): the next window offers the case back.
    m_window->document().undoStack()->setClean();
    auto next = std::make_unique<MainWindow>();
    next->setRecoveryFolder(m_window->recoveryFolder());
    MessageBox::setNextAnswer(MessageBox::Choice::Yes);
    next->offerRecovery();
    QCOMPARE(MessageBox::takeRecorded().size(), 1);
    QCOMPARE(next->document().spec().patient.ageYears, 58.0);
    QVERIFY(next->isWindowModified());
    QVERIFY(!hs::widgets::CaseDocument::findRecovery(next->recoveryFolder()).has_value());
    next->document().undoStack()->setClean();
}

/// Drags `path` over the window and drops it there, as a file manager does.
bool dropOn(QWidget* window, const QString& path) {
    QMimeData data;
    data.setUrls({QUrl::fromLocalFile(path)});
    const QPointF centre = QPointF(window->rect().center());
    QDragEnterEvent enter(centre.toPoint(), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(window, &enter);
    if (!enter.isAccepted())
        return false;
    QDropEvent drop(centre, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(window, &drop);
    return drop.isAccepted();
}

void TestMainWindow::aDropOpensACaseOrAMeshAndSaysWhyItRefusesAnythingElse() {
    // A case dropped opens as the case.
    const QString path = fixture("dropped.json");
    m_window->document().edit("Seed", [](hs::scene::CaseSpec& c) { c.seed = 11; });
    FileDialog::setNextFileName(path);
    find<QAction>("actionSaveCaseAs")->trigger();
    m_window->document().edit("Seed", [](hs::scene::CaseSpec& c) { c.seed = 12; });
    m_window->document().undoStack()->setClean();
    QVERIFY(dropOn(m_window.get(), path));
    QTRY_COMPARE(m_window->document().spec().seed, std::uint64_t{11});
    // A mesh dropped opens as a mesh.
    QSignalSpy loaded(m_window.get(), &MainWindow::fileLoaded);
    QVERIFY(dropOn(m_window.get(), fixture("sphere.off")));
    QVERIFY(loaded.wait(20000));
    QCOMPARE(m_window->currentFile(), fixture("sphere.off"));
    // Anything else is refused with the reason: what the program opens.
    MessageBox::takeRecorded();
    const QString text = fixture("notes.txt");
    QFile notes(text);
    QVERIFY(notes.open(QIODevice::WriteOnly));
    notes.write("not a mesh");
    notes.close();
    QVERIFY(dropOn(m_window.get(), text));
    QList<MessageBox::Message> messages;
    QTRY_VERIFY((messages += MessageBox::takeRecorded(), !messages.isEmpty()));
    QVERIFY2(messages.front().text.contains("notes.txt") && messages.front().text.contains(".json") &&
                 messages.front().text.contains(".off"),
             qPrintable(messages.front().text));
    QCOMPARE(m_window->currentFile(), fixture("sphere.off"));
    QVERIFY(!m_window->isLoading());
    // A folder without a package is refused as one.
    QVERIFY(dropOn(m_window.get(), m_dir.path()));
    messages.clear();
    QTRY_VERIFY((messages += MessageBox::takeRecorded(), !messages.isEmpty()));
    QVERIFY2(messages.front().text.contains("manifest.json"), qPrintable(messages.front().text));
}

void TestMainWindow::aCaseChangedOnDiskIsOfferedToReloadAndOurOwnSaveIsNot() {
    const QString path = fixture("watched.json");
    m_window->document().edit("Seed", [](hs::scene::CaseSpec& c) { c.seed = 21; });
    FileDialog::setNextFileName(path);
    find<QAction>("actionSaveCaseAs")->trigger();
    MessageBox::takeRecorded();
    // Our own save changes the file and asks nothing.
    m_window->document().edit("Seed", [](hs::scene::CaseSpec& c) { c.seed = 22; });
    find<QAction>("actionSaveCase")->trigger();
    QTest::qWait(800); // the watcher's delay (300 ms) and then some
    QVERIFY(MessageBox::takeRecorded().isEmpty());
    // Another program writes the case: the window asks, and Yes reloads it.
    hs::scene::CaseSpec other = m_window->document().spec();
    other.seed = 23;
    QVERIFY(hs::scene::saveCase(other, QFile::encodeName(path).toStdString()).ok());
    MessageBox::setNextAnswer(MessageBox::Choice::Yes);
    QList<MessageBox::Message> asked;
    QTRY_VERIFY_WITH_TIMEOUT((asked += MessageBox::takeRecorded(), !asked.isEmpty()), 5000);
    QCOMPARE(asked.front().icon, MessageBox::Icon::Question);
    QVERIFY2(asked.front().text.contains("watched.json"), qPrintable(asked.front().text));
    QCOMPARE(m_window->document().spec().seed, std::uint64_t{23});
    // Again, with unsaved changes, answered No: the case stays as it is in the window, never mixed.
    m_window->document().edit("Seed", [](hs::scene::CaseSpec& c) { c.seed = 24; });
    other.seed = 25;
    QVERIFY(hs::scene::saveCase(other, QFile::encodeName(path).toStdString()).ok());
    MessageBox::setNextAnswer(MessageBox::Choice::No);
    asked.clear();
    QTRY_VERIFY_WITH_TIMEOUT((asked += MessageBox::takeRecorded(), !asked.isEmpty()), 5000);
    QVERIFY2(asked.front().text.contains("unsaved"), qPrintable(asked.front().text));
    QCOMPARE(m_window->document().spec().seed, std::uint64_t{24});
    QVERIFY(m_window->isWindowModified());
}

void TestMainWindow::theHysteroscopicViewDetachesAndEnlarges() {
    // Its dock floats off the window (its title bar's button) and is then as large as the user makes it.
    auto* dock = find<QDockWidget>("previewDock");
    QVERIFY(dock->features().testFlag(QDockWidget::DockWidgetFloatable));
    const int docked = dock->widget()->width();
    dock->setFloating(true);
    dock->resize(900, 800);
    QTRY_VERIFY(dock->isFloating() && dock->isVisible());
    QTRY_VERIFY2(dock->widget()->width() > std::max(docked, 800), qPrintable(QString::number(dock->widget()->width())));
    dock->setFloating(false);
    QTRY_VERIFY(!dock->isFloating());
}

namespace {

/// An operative trial's report: two minutes of series with the pump raised half way, a resection, a surface.
hs::sim::TrialReport operativeReport() {
    hs::sim::TrialReport r;
    r.header.sceneSha256 = std::string(64, 'c');
    r.header.seed = 5;
    r.header.physics.engine = "corotational-fem/8";
    r.header.exercise = hs::sim::Exercise::Polypectomy;
    r.header.device = "demo";
    r.samples = 120000;
    r.metrics.timeS = 120.0;
    r.metrics.finalPumpPressureKpa = 12.0;
    r.metrics.resection.pathologies = {{"polyp-1", "polyp", 0.2410, 0.2393, 99.3}};
    r.metrics.resection.healthyRemovedMl = 0.060;
    r.metrics.resection.chipsLeft = 2;
    for (int i = 0; i <= 1200; ++i)
        r.series.push_back({i / 10.0, 0.1, 9.0, i * 0.1, i * 0.001, i < 600 ? 10.7 : 12.0});
    for (int i = 0; i < 500; ++i)
        r.surface.push_back({-180.0 + (i % 72) * 5.0, (i / 72) * 2.0, i % 3 != 0});
    return r;
}

/// The texts of `tree`'s rows below its section `section`, each row's columns joined by " | ".
QStringList sectionRows(QTreeWidget* tree, const QString& section) {
    QStringList rows;
    for (int i = 0; i < tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* top = tree->topLevelItem(i);
        if (top->text(0) != section)
            continue;
        for (int c = 0; c < top->childCount(); ++c) {
            QStringList columns;
            for (int k = 0; k < tree->columnCount(); ++k)
                if (!top->child(c)->text(k).isEmpty())
                    columns << top->child(c)->text(k);
            rows << columns.join(" | ");
        }
    }
    return rows;
}

} // namespace

void TestMainWindow::aTrialReportShowsTheReportsFiguresInAWindowOfItsOwn() {
    // File > Review Trial Report: the simulator's report, its tables and plots as the report's page has them, in a
    // window of its own beside whatever the workstation has open.
    const QString path = fixture("trial-report.json");
    QVERIFY(hs::sim::writeReport(operativeReport(), path.toStdString()).ok());
    QSignalSpy opened(m_window.get(), &MainWindow::trialReportOpened);
    FileDialog::setNextFileName(path);
    find<QAction>("actionReviewTrialReport")->trigger();
    QVERIFY(opened.wait(kLoadTimeoutMs));
    hs::widgets::TrialReportView* view = m_window->trialReportView();
    QVERIFY(view && view->isVisible() && view->isWindow());
    QVERIFY(view->windowTitle().contains("trial-report.json"));
    QCOMPARE(view->path(), QFileInfo(path).absoluteFilePath());
    // Every section of the report, with its rows.
    QStringList sections;
    for (int i = 0; i < view->metrics()->topLevelItemCount(); ++i)
        sections << view->metrics()->topLevelItem(i)->text(0);
    QCOMPARE(sections, QStringList({"Overview", "Exploration", "Safety", "Fluid", "Diagnosis", "Resection"}));
    const QStringList resection = sectionRows(view->metrics(), "Resection");
    QVERIFY2(resection.contains("polyp-1 | polyp | 0.241 mL | 0.239 mL | 99.3 %"), qPrintable(resection.join("\n")));
    QVERIFY2(resection.contains("healthy tissue removed | 0.060 mL"), qPrintable(resection.join("\n")));
    QVERIFY2(resection.contains("chips made / carried out / left in the cavity | 0 / 0 / 2"),
             qPrintable(resection.join("\n")));
    const QStringList fluid = sectionRows(view->metrics(), "Fluid");
    QVERIFY2(
        fluid.contains("pump pressure (set at the start / at the end) | 10.70 kPa (80 mmHg) / 12.00 kPa (90 mmHg)"),
        qPrintable(fluid.join("\n")));
    // Force, pressure, deficit and blood loss over time; the pump's line steps where the trainee raised it.
    QCOMPARE(view->plots().size(), 4);
    QChart* pressure = view->plots()[1]->chart();
    QCOMPARE(pressure->title(), QString("Intrauterine pressure"));
    auto* pump = qobject_cast<QLineSeries*>(pressure->series().value(2));
    QVERIFY(pump && pump->name() == "pump set pressure");
    QCOMPARE(pump->count(), 1201);
    QCOMPARE(pump->at(0).y(), 10.7);
    QCOMPARE(pump->at(1200).y(), 12.0);
    int surfacePoints = 0;
    for (QAbstractSeries* series : view->surfacePlot()->chart()->series())
        surfacePoints += qobject_cast<QScatterSeries*>(series)->count();
    QCOMPARE(surfacePoints, 500);
    QVERIFY2(view->sceneNote().contains("Review Scene Package"), qPrintable(view->sceneNote()));
    for (int tab = 0; tab < view->tabs()->count(); ++tab) { // each page paints
        view->tabs()->setCurrentIndex(tab);
        QTest::qWait(50);
    }

    // The command line's and a drop's report open as a report, not as a case.
    const std::string caseBefore = hs::scene::toJson(m_window->document().spec());
    m_window->openArgument(path);
    QVERIFY(opened.wait(kLoadTimeoutMs));
    QVERIFY(dropOn(m_window.get(), path));
    QVERIFY(opened.wait(kLoadTimeoutMs));
    QCOMPARE(hs::scene::toJson(m_window->document().spec()), caseBefore);

    // A report that breaks its format is refused with a message naming the file and the field; the shown report stays.
    QFile in(path);
    QVERIFY(in.open(QIODevice::ReadOnly));
    QByteArray bytes = in.readAll();
    in.close();
    bytes.replace("\"removedPercent\":99.299999999999997", "\"removedPercent\":199.3");
    const QString bad = fixture("bad-report.json");
    QFile out(bad);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(bytes);
    out.close();
    MessageBox::takeRecorded();
    m_window->openArgument(bad);
    QList<MessageBox::Message> messages;
    QTRY_VERIFY((messages += MessageBox::takeRecorded(), !messages.isEmpty()));
    QVERIFY2(messages.front().details.contains("bad-report.json") &&
                 messages.front().details.contains("/metrics/resection/pathologies/0/removedPercent: 199.3 is outside "
                                                   "0-100 %"),
             qPrintable(messages.front().details));
    QCOMPARE(view->path(), QFileInfo(path).absoluteFilePath());
    view->close();
}

void TestMainWindow::aReviewedTrialReplaysInTheSimulator() {
    // A report written with its trial (NAME.json and NAME.trial, as the simulator's End Trial writes them): the
    // review's "Replay in the Simulator" starts the simulator on the package the user names, with the trial.
    const QString report = fixture("replayed.json");
    QVERIFY(hs::sim::writeReport(operativeReport(), report.toStdString()).ok());
    QSignalSpy opened(m_window.get(), &MainWindow::trialReportOpened);
    m_window->openArgument(report);
    QVERIFY(opened.wait(kLoadTimeoutMs));
    hs::widgets::TrialReportView* view = m_window->trialReportView();
    QVERIFY(view);
    QVERIFY(!view->replayButton()->isEnabled()); // no trial beside it, and the button says why
    QVERIFY2(view->replayButton()->toolTip().contains("replayed.trial"), qPrintable(view->replayButton()->toolTip()));
    QFile trial(fixture("replayed.trial"));
    QVERIFY(trial.open(QIODevice::WriteOnly));
    trial.write("recorded\n");
    trial.close();
    m_window->openArgument(report);
    QVERIFY(opened.wait(kLoadTimeoutMs));
    QVERIFY(view->replayButton()->isEnabled());
    // The simulator here: a script that writes down its arguments.
    const QString arguments = fixture("simulator-arguments.txt");
    const QString simulator = fixture("fake-simulator.sh");
    QFile script(simulator);
    QVERIFY(script.open(QIODevice::WriteOnly));
    script.write(
        QString("#!/bin/sh\nprintf '%s\\n' \"$@\" > '%1.part' && mv '%1.part' '%1'\n").arg(arguments).toUtf8());
    script.close();
    QVERIFY(script.setPermissions(script.permissions() | QFileDevice::ExeOwner));
    m_window->setSimulatorProgram(simulator);
    const QString package = fixture("the-trials-package");
    QVERIFY(QDir().mkpath(package));
    FileDialog::setNextFileName(package); // not under review: the user names the trial's package
    view->replayButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo::exists(arguments), 10000);
    QFile written(arguments);
    QVERIFY(written.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(written.readAll()).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines, QStringList({package, "--replay", QFileInfo(trial.fileName()).absoluteFilePath()}));
    // No simulator where it is looked for: a message naming the place; nothing started.
    m_window->setSimulatorProgram(fixture("no-such-simulator"));
    MessageBox::takeRecorded();
    QVERIFY(!m_window->replayTrial(trial.fileName()));
    const QList<MessageBox::Message> messages = MessageBox::takeRecorded();
    QVERIFY(!messages.isEmpty());
    QVERIFY2(messages.front().details.contains("no-such-simulator"), qPrintable(messages.front().details));
    view->close();
}

void TestMainWindow::nothingIsCutOffOnASmallScreen_data() {
    QTest::addColumn<QSize>("size");
    QTest::addColumn<int>("viewWidth");                   // the least the 3-D view keeps, px
    QTest::newRow("1366x768") << QSize(1366, 768) << 400; // the smallest common laptop screen
    QTest::newRow("1280x1000") << QSize(1280, 1000) << 320;
}

void TestMainWindow::nothingIsCutOffOnASmallScreen() {
    // Every panel raised in turn: no table column and no panel is cut off (no horizontal scrolling), and the 3-D view
    // keeps a usable width.
    QFETCH(QSize, size);
    QFETCH(int, viewWidth);
    // The widest content the panels get: a pathology seated at a point (its coordinates beside the radio button).
    m_window->document().edit("Place", [](hs::scene::CaseSpec& c) {
        c.pathologies.front().placement = hs::clinical::SurfacePlacement{{-10.8, 16.0, 39.6}, {0.0, 1.0, 0.0}};
    });
    find<QWidget>("pathologyPanel")->findChild<QListWidget*>()->setCurrentRow(0);
    m_window->resize(size);
    QTRY_COMPARE(m_window->size(), size);
    const QStringList clipped = hs::test::clippedParts(m_window.get());
    if (!qEnvironmentVariableIsEmpty("HS_SCREENSHOT_DIR"))
        m_window->grab().save(QDir(qEnvironmentVariable("HS_SCREENSHOT_DIR"))
                                  .filePath(QStringLiteral("workstation-%1.png").arg(QTest::currentDataTag())));
    QVERIFY2(clipped.isEmpty(), qPrintable(clipped.join("; ")));
    qInfo("the 3-D view is %d px wide", m_window->view()->width());
    QVERIFY2(m_window->view()->width() >= viewWidth, qPrintable(QString::number(m_window->view()->width())));
}

int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(hs::widgets::VtkView::defaultFormat());
    QApplication app(argc, argv);
    TestMainWindow test;
    return QTest::qExec(&test, argc, argv);
}

#include "TestMainWindow.moc"
