// Qt Test of the whole authoring flow in the workstation, as a supervisor does it, finding widgets by object name:
// a new case, the patient's values, a myoma placed by a click on the organ's wall in the 3-D view, grow, merge,
// mesh, the quality histogram, texture, export, the package validated; a running mesh job cancelled from the status
// bar; a clinician's review written beside the package. Needs a display (xvfb-run -a).
#include "LayoutCheck.h"
#include "hs/scene/Review.h"
#include "hs/scene/ScenePackage.h"
#include "hs/sim/Metrics.h"
#include "hs/widgets/common/FileDialog.h"
#include "hs/widgets/common/MessageBox.h"
#include "hs/widgets/jobs/GenerationSession.h"
#include "hs/widgets/panels/PathologyPanel.h"
#include "hs/widgets/panels/ReviewPanel.h"
#include "hs/widgets/panels/SceneTree.h"
#include "hs/widgets/panels/TrialReportView.h"
#include "hs/widgets/view/HysteroscopicPreview.h"
#include "hs/widgets/view/MeshDisplay.h"
#include "hs/widgets/view/SceneParts.h"
#include "hs/widgets/view/SurfaceHandles.h"
#include "hs/widgets/view/VariantsView.h"
#include "hs/widgets/view/VtkView.h"
#include "hs/workstation/MainWindow.h"

#include <QAction>
#include <QApplication>
#include <QBarSeries>
#include <QBarSet>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QDropEvent>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMimeData>
#include <QMouseEvent>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QTreeWidget>
#include <QUrl>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <variant>

using hs::widgets::FileDialog;
using hs::widgets::MessageBox;
using hs::workstation::MainWindow;

namespace {

constexpr int kStageTimeoutMs = 180000;

} // namespace

class TestAuthoringFlow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();
    void authorsTheDefaultCaseFromNewToAValidatedPackage();
    void cancelsARunningMeshJobFromTheStatusBar();
    void placesFromAnyTabAndEscapeCancelsPlacing();
    void refusesAnOutOfRangeValueAndKeepsTheCase();
    void aClinicianReviewsTheExportedPackage();
    void aBrokenPackageOpensWithAMessageAndChangesNothing();
    void showsTwoVariantsSideBySide();

private:
    template <class T>
    T* find(const QString& name) const {
        T* child = m_window->findChild<T*>(name);
        if (!child)
            qFatal("no widget %s", qPrintable(name));
        return child;
    }
    /// Clicks `button` and waits until the session's job has ended with new results.
    bool runStage(const QString& button);
    hs::widgets::GenerationSession& session() { return m_window->session(); }
    /// With HS_SCREENSHOT_DIR set, saves the window (with `dock` raised) there as `name`.png: the docs' pictures.
    void shot(const QString& name, const QString& dock = {});

    QTemporaryDir m_dir;
    QTemporaryDir m_settingsDir;
    std::unique_ptr<MainWindow> m_window;
    QString m_exported; ///< the package the first test wrote, for the review test
};

void TestAuthoringFlow::initTestCase() {
    QVERIFY(m_dir.isValid() && m_settingsDir.isValid());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    QCoreApplication::setOrganizationName("hysteroscene-test");
    QCoreApplication::setApplicationName("test_authoring_flow");
    MessageBox::setRecording(true);
}

void TestAuthoringFlow::init() {
    QSettings().clear();
    MessageBox::takeRecorded();
    m_window = std::make_unique<MainWindow>();
    m_window->setRecoveryFolder(m_dir.filePath("recovery"));
    m_window->resize(1280, 1000);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    // The window builds the organ of its case on its own.
    QTRY_VERIFY_WITH_TIMEOUT(session().isCurrent(hs::generate::Stage::Organ), 60000);
}

void TestAuthoringFlow::cleanup() {
    if (m_window)
        m_window->document().undoStack()->setClean();
    m_window.reset();
    hs::widgets::CaseDocument::discardRecovery(m_dir.filePath("recovery"));
}

/// Where the world point `p` (mm) is on `view`, in its logical pixels.
QPoint onScreen(hs::widgets::VtkView* view, const hs::Vec3& p) {
    vtkRenderer* renderer = view->renderer();
    renderer->SetWorldPoint(p.x, p.y, p.z, 1.0);
    renderer->WorldToDisplay();
    double d[3];
    renderer->GetDisplayPoint(d);
    const double ratio = view->devicePixelRatioF();
    return QPoint(int(d[0] / ratio), int((view->height() * ratio - d[1]) / ratio));
}

/// Looks at `target` (mm) from 200 mm along `direction`, z up.
void aim(hs::widgets::VtkView* view, const hs::Vec3& target, const hs::Vec3& direction) {
    vtkCamera* camera = view->renderer()->GetActiveCamera();
    camera->SetFocalPoint(target.x, target.y, target.z);
    camera->SetPosition(target.x + 200.0 * direction.x, target.y + 200.0 * direction.y, target.z + 200.0 * direction.z);
    camera->SetViewUp(0.0, 0.0, 1.0);
    view->renderer()->ResetCameraClippingRange();
    view->requestRender();
}

/// A left-button drag on `view` from `from` to `to`, in small steps, as a hand does it.
void drag(QWidget* view, const QPoint& from, const QPoint& to) {
    const auto send = [view](QEvent::Type type, const QPoint& at, Qt::MouseButton button, Qt::MouseButtons buttons) {
        QMouseEvent event(type, QPointF(at), view->mapToGlobal(QPointF(at)), button, buttons, Qt::NoModifier);
        QApplication::sendEvent(view, &event);
    };
    send(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    for (int i = 1; i <= 8; ++i)
        send(QEvent::MouseMove, from + (to - from) * i / 8, Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
}

/// Shortcuts go to the active window: makes the window it (a display without a window manager activates nothing).
void activate(QWidget* window) {
    window->activateWindow();
    QApplication::setActiveWindow(window);
    QTRY_VERIFY(QApplication::activeWindow() == window);
}

void TestAuthoringFlow::shot(const QString& name, const QString& dock) {
    const QString folder = qEnvironmentVariable("HS_SCREENSHOT_DIR");
    if (folder.isEmpty())
        return;
    if (!dock.isEmpty())
        find<QDockWidget>(dock)->raise();
    QTest::qWait(200); // let the raised dock and the views paint
    QVERIFY(m_window->saveScreenshot(QDir(folder).filePath(name + ".png")));
}

bool TestAuthoringFlow::runStage(const QString& button) {
    QSignalSpy idle(&session().runner(), &hs::widgets::JobRunner::idle);
    QSignalSpy failed(&session().runner(), &hs::widgets::JobRunner::failed);
    find<QPushButton>(button)->click();
    if (!idle.wait(kStageTimeoutMs))
        return false;
    if (!failed.isEmpty())
        qWarning("%s failed: %s", qPrintable(button), failed.at(0).at(1).value<hs::Error>().message().c_str());
    return failed.isEmpty();
}

void TestAuthoringFlow::authorsTheDefaultCaseFromNewToAValidatedPackage() {
    find<QAction>("actionNewCase")->trigger();
    // The patient: a 42-year-old multipara.
    find<QDoubleSpinBox>("ageSpin")->setValue(42.0);
    find<QSpinBox>("graviditySpin")->setValue(3);
    find<QSpinBox>("paritySpin")->setValue(2);
    QCOMPARE(m_window->document().spec().patient.parity, 2);
    // A lighter mesh and smaller maps keep the test short; the flow is the same.
    find<QSpinBox>("verticesSpin")->setValue(6000);
    auto* size = find<QComboBox>("textureSizeCombo");
    size->setCurrentIndex(size->findData(256));
    QTRY_VERIFY_WITH_TIMEOUT(session().isCurrent(hs::generate::Stage::Organ), 60000);

    // A myoma placed by a click on the organ's wall.
    const auto before = m_window->document().spec().pathologies.size();
    find<QPushButton>("addMyomaButton")->click();
    auto* figo = find<QComboBox>("figoCombo");
    figo->setCurrentIndex(4); // FIGO 4: intramural
    find<QDoubleSpinBox>("sizeSpin")->setValue(15.0);
    find<QToolButton>("placeButton")->click();
    QVERIFY(m_window->shownLayer() == hs::widgets::ResultLayer::Organ);
    // Turn the view to the anterior wall (+y) of the upper corpus, as the supervisor does, and click its middle.
    const hs::Bounds box = hs::bounds(session().results()->organ->mesh);
    const hs::Vec3 target{box.center().x, box.center().y, box.min.z + 0.65 * (box.max.z - box.min.z)};
    hs::widgets::VtkView* view = m_window->view();
    vtkCamera* camera = view->renderer()->GetActiveCamera();
    camera->SetFocalPoint(target.x, target.y, target.z);
    camera->SetPosition(target.x, target.y + 200.0, target.z);
    camera->SetViewUp(0.0, 0.0, 1.0);
    view->renderer()->ResetCameraClippingRange();
    view->requestRender();
    shot("workstation-place", "pathologyDock");
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, view->rect().center());
    const auto& added = m_window->document().spec().pathologies.back();
    QCOMPARE(m_window->document().spec().pathologies.size(), before + 1);
    QVERIFY2(std::holds_alternative<hs::clinical::SurfacePlacement>(added.placement),
             qPrintable(find<QLabel>("pathologyMessageLabel")->text()));

    // Placing again shows the seat and size handles on the organ; dragging the size handle resizes the myoma, as
    // one edit when the drag ends.
    find<QToolButton>("placeButton")->click();
    QVERIFY(m_window->handles()->isShown());
    QVERIFY(hs::distance(m_window->handles()->seatPosition(),
                         std::get<hs::clinical::SurfacePlacement>(added.placement).pointMm) < 1e-6);
    const int renders = view->renderCount();
    QTRY_VERIFY(view->renderCount() > renders); // the handles are drawn where the press will find them
    const QPoint grip = onScreen(view, m_window->handles()->sizePosition());
    const QPoint seatOnScreen = onScreen(view, m_window->handles()->seatPosition());
    QVERIFY((grip - seatOnScreen).manhattanLength() > 20); // the two handles apart on the screen
    const int editsBefore = m_window->document().undoStack()->count();
    const QPoint outward = (grip - seatOnScreen) * 16 / std::max(1, (grip - seatOnScreen).manhattanLength());
    drag(view, grip, grip + outward); // pulled away from the seat: bigger
    QCOMPARE(m_window->document().undoStack()->count(), editsBefore + 1);
    const double resized = m_window->document().spec().pathologies.back().sizeMm;
    QVERIFY2(resized > 15.0 && resized <= 100.0, qPrintable(QString::number(resized)));
    // Dragging the seat handle down the anterior wall (the view's up is +z) seats the myoma there: one edit, the
    // seat lower on the wall, the handle with it, and placing goes on (as after a resize).
    const hs::Vec3 seatBefore =
        std::get<hs::clinical::SurfacePlacement>(m_window->document().spec().pathologies.back().placement).pointMm;
    const int editsBeforeSeat = m_window->document().undoStack()->count();
    drag(view, seatOnScreen, seatOnScreen + QPoint(0, 24));
    QCOMPARE(m_window->document().undoStack()->count(), editsBeforeSeat + 1);
    const auto& moved = m_window->document().spec().pathologies.back();
    QVERIFY(std::holds_alternative<hs::clinical::SurfacePlacement>(moved.placement));
    const hs::Vec3 seatAfter = std::get<hs::clinical::SurfacePlacement>(moved.placement).pointMm;
    QVERIFY2(seatAfter.z < seatBefore.z - 1.0 && std::abs(seatAfter.x - seatBefore.x) < 1.0,
             qPrintable(QStringLiteral("(%1, %2, %3) -> (%4, %5, %6)")
                            .arg(seatBefore.x)
                            .arg(seatBefore.y)
                            .arg(seatBefore.z)
                            .arg(seatAfter.x)
                            .arg(seatAfter.y)
                            .arg(seatAfter.z)));
    QVERIFY(hs::distance(m_window->handles()->seatPosition(), seatAfter) < 1e-6);
    QVERIFY(find<hs::widgets::PathologyPanel>("pathologyPanel")->isPlacing());
    QVERIFY(m_window->handles()->isShown());
    // Undone, the seat is where the click put it (lower down, the myoma would touch the case's first one).
    find<QAction>("actionUndo")->trigger();
    QVERIFY(
        hs::distance(
            std::get<hs::clinical::SurfacePlacement>(m_window->document().spec().pathologies.back().placement).pointMm,
            seatBefore) < 1e-9);
    find<QToolButton>("placeButton")->click(); // done placing
    QVERIFY(!m_window->handles()->isShown());
    find<QDoubleSpinBox>("sizeSpin")->setValue(15.0);

    // Grow shows the pathologies growing (frames of each model over the organ), then the grown result.
    QSignalSpy frames(&session(), &hs::widgets::GenerationSession::growthFrame);
    std::size_t largestCloud = 0;
    const QMetaObject::Connection watchGrowth =
        connect(&session(), &hs::widgets::GenerationSession::growthFrame, this,
                [&] { largestCloud = std::max(largestCloud, m_window->growthDisplay().pointCount()); });
    QVERIFY(runStage("growButton"));
    disconnect(watchGrowth);
    QVERIFY2(frames.count() >= 3, qPrintable(QString::number(frames.count())));
    QVERIFY(largestCloud > 0);
    QCOMPARE(m_window->growthDisplay().pointCount(), std::size_t{0});
    QVERIFY(session().isCurrent(hs::generate::Stage::Pathology));
    QVERIFY(find<QLabel>("pathologyResultLabel")->text().contains("FIGO"));
    shot("workstation-pathologies", "pathologyDock");

    // The scene tree lists every part; the growth is shown, the organ of the shape model hidden.
    hs::widgets::SceneTree* tree = m_window->sceneTree();
    hs::widgets::SceneParts& parts = m_window->sceneParts();
    auto* list = find<hs::widgets::PathologyPanel>("pathologyPanel");
    const int myoma = static_cast<int>(m_window->document().spec().pathologies.size()) - 1;
    const std::string grown = "growth/" + std::to_string(myoma + 1);
    QVERIFY(tree->itemOf("organ") && tree->itemOf("growth/organ") && tree->itemOf(grown));
    QVERIFY(parts.isShown(grown) && parts.isShown("growth/organ") && !parts.isShown("organ"));
    QCOMPARE(tree->itemOf("organ")->checkState(0), Qt::Unchecked);
    // Watched inside a translucent organ: where the (intramural) myoma's centre is on the screen, the opaque organ
    // hides it; at 30 % opacity the myoma's colour shows through.
    const hs::Bounds myomaBox = hs::bounds(session().results()->pathologies->pathologies.back().surface);
    aim(view, myomaBox.center(), {0.0, 1.0, 0.0});
    const QPoint myomaOnScreen = onScreen(view, myomaBox.center());
    const QColor opaque = view->grabImage().pixelColor(myomaOnScreen * view->devicePixelRatioF());
    find<QSpinBox>("opacity:growth/organ")->setValue(30);
    QCOMPARE(parts.display("growth/organ")->opacity(), 0.3);
    QCOMPARE(parts.display(grown)->opacity(), 1.0);
    const QColor translucent = view->grabImage().pixelColor(myomaOnScreen * view->devicePixelRatioF());
    QVERIFY2(std::abs(opaque.red() - translucent.red()) + std::abs(opaque.green() - translucent.green()) +
                     std::abs(opaque.blue() - translucent.blue()) >
                 30,
             qPrintable(opaque.name() + " " + translucent.name()));
    // Unticking the displaced organ hides it; a click on the myoma selects it in the list and the tree.
    tree->itemOf("growth/organ")->setCheckState(0, Qt::Unchecked);
    QVERIFY(!parts.isShown("growth/organ") && parts.isShown("growth"));
    list->setCurrentIndex(0 == myoma ? -1 : 0);
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, myomaOnScreen);
    QVERIFY2(list->currentIndex() == myoma, qPrintable(find<QLabel>("pickLabel")->text()));
    QCOMPARE(tree->selectedPathology(), myoma);
    QCOMPARE(parts.highlightedPathology(), myoma);
    // Selected in the tree: the list follows.
    if (myoma > 0) {
        const std::string other = "growth/" + std::to_string(myoma);
        QTest::mouseClick(tree->tree()->viewport(), Qt::LeftButton, Qt::NoModifier,
                          tree->tree()->visualItemRect(tree->itemOf(other)).center());
        QCOMPARE(list->currentIndex(), myoma - 1);
        list->setCurrentIndex(myoma);
        QCOMPARE(tree->selectedPathology(), myoma);
    }
    find<QSpinBox>("opacity:growth/organ")->setValue(100);
    tree->itemOf("growth/organ")->setCheckState(0, Qt::Checked);

    QVERIFY(runStage("mergeButton"));
    QVERIFY(m_window->shownLayer() == hs::widgets::ResultLayer::Body);
    QVERIFY(runStage("meshButton"));
    QVERIFY(m_window->shownLayer() == hs::widgets::ResultLayer::Tissues);
    // The tissues are the mesh's regions; with all but the myoma's hidden in the tree, a click on it picks its
    // region and selects it.
    QVERIFY(tree->itemOf("tissues") && tree->itemOf("surface") == nullptr);
    std::int32_t myomaRegion = -1;
    for (const hs::widgets::ScenePart& part : parts.parts())
        if (part.kind == hs::widgets::PartKind::TissueRegion) {
            if (part.pathology == myoma)
                myomaRegion = part.region;
            else
                tree->itemOf(part.key)->setCheckState(0, Qt::Unchecked);
        }
    QVERIFY(myomaRegion >= 0);
    QVERIFY(!m_window->display().hiddenRegions().count(myomaRegion));
    QVERIFY(find<QCheckBox>(QStringLiteral("regionCheck%1").arg(myomaRegion))->isChecked()); // the Mesh panel agrees
    const auto regionBox = m_window->display().regionBounds(myomaRegion);
    const hs::Vec3 regionCentre{(regionBox[0] + regionBox[1]) / 2, (regionBox[2] + regionBox[3]) / 2,
                                (regionBox[4] + regionBox[5]) / 2};
    aim(view, regionCentre, {0.0, 1.0, 0.0});
    list->setCurrentIndex(0 == myoma ? -1 : 0);
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, onScreen(view, regionCentre));
    QCOMPARE(list->currentIndex(), myoma);
    QVERIFY(m_window->findChild<QLabel*>("pickLabel")
                ->text()
                .contains(QString::fromStdString(m_window->document().spec().pathologies.back().id)));
    // The mesh hidden and shown again: every tissue in it, the Mesh panel's boxes too.
    tree->itemOf("tissues")->setCheckState(0, Qt::Unchecked);
    QVERIFY(!m_window->display().isShown());
    tree->itemOf("tissues")->setCheckState(0, Qt::Checked);
    QVERIFY(m_window->display().isShown() && m_window->display().hiddenRegions().empty());
    for (const hs::widgets::ScenePart& part : parts.parts())
        if (part.kind == hs::widgets::PartKind::TissueRegion)
            QVERIFY(find<QCheckBox>(QStringLiteral("regionCheck%1").arg(part.region))->isChecked());
    auto* histogram = qobject_cast<QBarSeries*>(find<QChartView>("radiusRatioChart")->chart()->series().value(0));
    QVERIFY(histogram && histogram->barSets().value(0)->sum() > 0);
    find<QAction>("actionResetCamera")->trigger();
    find<QAction>("actionClip")->trigger();
    shot("workstation-mesh", "meshDock");
    find<QAction>("actionClip")->trigger();
    QVERIFY(runStage("textureButton"));
    QVERIFY(m_window->shownLayer() == hs::widgets::ResultLayer::Textured);
    QVERIFY(m_window->preview()->hasScene());
    // The textured surface is shown (the status bar counts its triangles), the mesh not drawn; a worst tet chosen in
    // the Mesh panel shows the mesh with it.
    QVERIFY2(find<QLabel>("countsLabel")->text().contains("Triangles"),
             qPrintable(find<QLabel>("countsLabel")->text()));
    QVERIFY(!m_window->display().isShown());
    auto* worst = find<QTableWidget>("worstTetTable");
    QTRY_VERIFY_WITH_TIMEOUT(worst->rowCount() > 0, 20000);
    worst->setCurrentCell(0, 0);
    find<QPushButton>("showTetButton")->click();
    QVERIFY(m_window->display().isShown() && m_window->display().isTetMesh());
    QCOMPARE(tree->itemOf("tissues")->checkState(0), Qt::Checked);
    tree->itemOf("tissues")->setCheckState(0, Qt::Unchecked);
    find<QAction>("actionResetCamera")->trigger(); // the tet was framed: back to the whole organ
    m_window->preview()->setInsertion(25.0);
    shot("workstation-texture", "textureDock");
    shot("workstation-materials", "materialsDock");

    // An edit outdates the stages that read it: the cycle phase is read by the tissue layers, so the mesh, the
    // surface, the simulation mesh and the views showing them are marked until they rerun; the organ is not.
    auto* phase = find<QComboBox>("cyclePhaseCombo");
    const int phaseBefore = phase->currentIndex();
    phase->setCurrentIndex(phaseBefore == 0 ? 1 : 0);
    const auto outOfDate = [&](const char* key) { return tree->itemOf(key)->data(0, Qt::UserRole + 2).toBool(); };
    QVERIFY(outOfDate("tissues") && outOfDate("surface") && outOfDate("simulation"));
    QVERIFY(!outOfDate("organ") && !outOfDate("growth") && !outOfDate("body"));
    QVERIFY(find<QLabel>("viewOutOfDate")->isVisible());
    QVERIFY(find<QLabel>("previewOutOfDate")->isVisible());
    shot("workstation-out-of-date");
    QVERIFY(runStage("textureButton"));
    QVERIFY(!outOfDate("tissues") && !outOfDate("surface") && !outOfDate("simulation"));
    QVERIFY(!find<QLabel>("viewOutOfDate")->isVisible());
    QVERIFY(!find<QLabel>("previewOutOfDate")->isVisible());

    // Export: the folder comes from the file dialog seam.
    // HS_EXPORT_DIR keeps the package (to open it in other tools); by default it goes with the test's folder.
    m_exported = qEnvironmentVariableIsEmpty("HS_EXPORT_DIR") ? m_dir.filePath("authored")
                                                              : qEnvironmentVariable("HS_EXPORT_DIR");
    FileDialog::setNextFileName(m_exported);
    find<QPushButton>("exportBrowseButton")->click();
    QCOMPARE(find<QLineEdit>("exportFolderEdit")->text(), m_exported);
    QSignalSpy exported(&session(), &hs::widgets::GenerationSession::exported);
    find<QPushButton>("exportButton")->click();
    QVERIFY(exported.wait(kStageTimeoutMs));
    QVERIFY(hs::scene::verifyScenePackage(QFile::encodeName(m_exported).toStdString()).ok());
    QVERIFY(find<QLabel>("exportResultLabel")->text().contains("valid"));
    find<QDockWidget>("patientDock")->raise();
    shot("workstation-export", "exportDock");
    QCOMPARE(MessageBox::takeRecorded().size(), 0);
}

void TestAuthoringFlow::cancelsARunningMeshJobFromTheStatusBar() {
    hs::widgets::JobRunner& runner = session().runner();
    QSignalSpy cancelled(&runner, &hs::widgets::JobRunner::cancelled);
    QString key;
    const QMetaObject::Connection watch =
        connect(&runner, &hs::widgets::JobRunner::progressChanged, this, [&](double, const QString& k) { key = k; });
    // Started by its shortcut with its panel closed: the stages' shortcuts are window actions (a button's own
    // shortcut fires only while the button shows).
    find<QDockWidget>("meshDock")->hide();
    QTRY_VERIFY(!find<QPushButton>("meshButton")->isVisible());
    activate(m_window.get());
    QTest::keyClick(m_window.get(), Qt::Key_M, Qt::ControlModifier);
    QTRY_VERIFY_WITH_TIMEOUT(key.startsWith("meshing"), 60000);
    QVERIFY(find<QPushButton>("meshButton")->isVisible()); // its dock shown and raised
    auto* cancel = find<QToolButton>("jobCancelButton");
    QVERIFY(cancel->isVisible());
    cancel->click();
    QVERIFY(cancelled.wait(10000));
    qInfo("cancel latency of the mesh job: %.1f ms", cancelled.at(0).at(1).toDouble());
    QVERIFY(!session().isCurrent(hs::generate::Stage::Meshing));
    QTRY_VERIFY(!find<QToolButton>("jobCancelButton")->isVisible());
    QCOMPARE(MessageBox::takeRecorded().size(), 0); // a cancel is no error
    disconnect(watch);
}

void TestAuthoringFlow::placesFromAnyTabAndEscapeCancelsPlacing() {
    auto* panel = find<hs::widgets::PathologyPanel>("pathologyPanel");
    find<QDockWidget>("pathologyDock")->hide();
    QTRY_VERIFY(!panel->isVisible());
    activate(m_window.get());
    QTest::keyClick(m_window.get(), Qt::Key_P, Qt::ControlModifier);
    QTRY_VERIFY(panel->isPlacing());
    QVERIFY(panel->isVisible()); // its dock shown and raised
    QTest::keyClick(m_window.get(), Qt::Key_Escape);
    QVERIFY(!panel->isPlacing());
}

void TestAuthoringFlow::refusesAnOutOfRangeValueAndKeepsTheCase() {
    const std::string before = hs::scene::toJson(m_window->document().spec());
    find<QDoubleSpinBox>("weightSpin")->setValue(250.0);
    QVERIFY(find<QLabel>("patientMessageLabel")->text().contains("160"));
    QCOMPARE(hs::scene::toJson(m_window->document().spec()), before);
    QVERIFY(!m_window->isWindowModified());
}

void TestAuthoringFlow::aClinicianReviewsTheExportedPackage() {
    if (m_exported.isEmpty())
        QSKIP("the authoring test did not export a package");
    // An edit to undo in the case being authored when the review opens.
    m_window->document().edit("seed", [](hs::scene::CaseSpec& spec) { spec.seed += 1; });
    QVERIFY(find<QAction>("actionUndo")->isEnabled());
    QSignalSpy opened(m_window.get(), &MainWindow::reviewOpened);
    FileDialog::setNextFileName(m_exported);
    find<QAction>("actionReviewPackage")->trigger();
    QVERIFY(opened.wait(60000));
    QVERIFY(m_window->isReviewing());
    QVERIFY(!find<QPushButton>("meshButton")->isEnabled()); // the package is read-only
    // A read-only session: no route replaces the reviewed package or changes the case behind it.
    for (const char* name : {"actionUndo", "actionRedo", "actionNewCase", "actionOpenCase", "actionSaveCase",
                             "actionSaveCaseAs", "actionOpen", "actionReviewPackage", "actionCompareVariants"})
        QVERIFY2(!find<QAction>(name)->isEnabled(), name);
    QVERIFY(!find<QMenu>("menuRecentCases")->isEnabled());
    QVERIFY(!find<QMenu>("menuRecent")->isEnabled());
    QVERIFY(find<QAction>("actionCloseReview")->isEnabled());
    const std::string caseBefore = hs::scene::toJson(m_window->document().spec());
    QVERIFY(m_window->document().undoStack()->canUndo()); // the authoring left edits to undo
    activate(m_window.get());
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    QTest::keyClick(m_window.get(), Qt::Key_N, Qt::ControlModifier);
    FileDialog::setNextFileName(m_exported);
    QTest::keyClick(m_window.get(), Qt::Key_O, Qt::ControlModifier);
    QTest::keyClick(m_window.get(), Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
    QTest::qWait(200);
    FileDialog::setNextFileName(QString()); // whatever a dialog would have been asked, none was
    // Nor a drop: a package or a case dropped on the window is refused, and the message says why.
    MessageBox::takeRecorded();
    for (const QString& dropped : {m_exported, m_dir.filePath("recovery")}) {
        QMimeData data;
        data.setUrls({QUrl::fromLocalFile(dropped)});
        QDragEnterEvent enter(m_window->rect().center(), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(m_window.get(), &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(QPointF(m_window->rect().center()), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(m_window.get(), &drop);
    }
    QList<MessageBox::Message> refusals;
    QTRY_VERIFY((refusals += MessageBox::takeRecorded(), refusals.size() == 2));
    for (const MessageBox::Message& refusal : refusals)
        QVERIFY2(refusal.text.contains("review"), qPrintable(refusal.text));
    QCOMPARE(hs::scene::toJson(m_window->document().spec()), caseBefore);
    QVERIFY(m_window->isReviewing());
    QCOMPARE(find<hs::widgets::ReviewPanel>("reviewPanel")->packageFolder(), QFileInfo(m_exported).absoluteFilePath());
    QVERIFY(find<QPushButton>("visitButton0")->isEnabled());
    // Visit turns the hysteroscopic view to the pathology: the camera aims at the centre of its tets (measured 43.5
    // degrees off it before the click, 0.0 after).
    auto reviewed = hs::scene::readScenePackage(QFile::encodeName(m_exported).toStdString());
    QVERIFY(reviewed.ok());
    std::int32_t regionId = -1;
    for (const hs::scene::SceneRegion& region : reviewed->regions)
        if (region.pathologyId == reviewed->clinical.pathologies[0].id)
            regionId = region.id;
    QVERIFY(regionId >= 0);
    hs::Vec3 centre{};
    std::size_t tets = 0;
    for (std::size_t t = 0; t < reviewed->tets.tets.size(); ++t)
        if (reviewed->tets.regions[t] == regionId) {
            for (const auto i : reviewed->tets.tets[t])
                centre = centre + reviewed->tets.points[static_cast<std::size_t>(i)] * 0.25;
            ++tets;
        }
    QVERIFY(tets > 0);
    centre = centre * (1.0 / double(tets));
    vtkCamera* camera = find<hs::widgets::VtkView>("previewView")->renderer()->GetActiveCamera();
    const auto angleToPathology = [&] {
        double position[3], direction[3];
        camera->GetPosition(position);
        camera->GetDirectionOfProjection(direction);
        const hs::Vec3 to = hs::normalized(centre - hs::Vec3{position[0], position[1], position[2]});
        const double c = to.x * direction[0] + to.y * direction[1] + to.z * direction[2];
        return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI;
    };
    const double before = angleToPathology();
    find<QPushButton>("visitButton0")->click();
    const double after = angleToPathology();
    qInfo("Visit: the camera %.1f deg off the pathology's centre before, %.1f after", before, after);
    QVERIFY2(after < 1.0 && before > 1.0, qPrintable(QStringLiteral("%1 -> %2 deg").arg(before).arg(after)));
    QVERIFY2(find<QLabel>("previewStatusLabel")->text().contains(QStringLiteral("region %1").arg(regionId)),
             qPrintable(find<QLabel>("previewStatusLabel")->text()));
    find<QSpinBox>("pathologyScore0")->setValue(5);
    find<QSpinBox>("textureScore0")->setValue(4);
    find<QPushButton>("saveReviewButton")->click();
    auto review = hs::scene::loadReview(hs::scene::reviewPathFor(QFile::encodeName(m_exported).toStdString()));
    QVERIFY(review.ok());
    QCOMPARE(*review->pathologies[0].rating.score, 5);
    QVERIFY(hs::scene::verifyScenePackage(QFile::encodeName(m_exported).toStdString()).ok());
    shot("workstation-review", "reviewDock");
    // A trial on this scene (its report names the package's manifest by its SHA-256), dropped during the review: it
    // opens in its own window beside the review, which stays, and says that it ran on the scene under review.
    auto identity = hs::scene::packageIdentity(QFile::encodeName(m_exported).toStdString());
    QVERIFY(identity.ok());
    hs::sim::TrialReport trial;
    trial.header.sceneSha256 = *identity;
    trial.header.physics.engine = "corotational-fem/8";
    const QString trialReport = m_dir.filePath("trial-report.json");
    QVERIFY(hs::sim::writeReport(trial, trialReport.toStdString()).ok());
    QSignalSpy reportOpened(m_window.get(), &MainWindow::trialReportOpened);
    {
        QMimeData data;
        data.setUrls({QUrl::fromLocalFile(trialReport)});
        QDragEnterEvent enter(m_window->rect().center(), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(m_window.get(), &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(QPointF(m_window->rect().center()), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(m_window.get(), &drop);
    }
    QVERIFY(reportOpened.wait(20000));
    QVERIFY(m_window->isReviewing());
    QCOMPARE(m_window->trialReportView()->sceneNote(), QString("This trial ran on the scene under review."));
    // The review's tables, filled, fit a 1366 x 768 screen as every other panel does.
    m_window->resize(1366, 768);
    QTRY_COMPARE(m_window->size(), QSize(1366, 768));
    const QStringList clipped = hs::test::clippedParts(m_window.get());
    QVERIFY2(clipped.isEmpty(), qPrintable(clipped.join("; ")));
    m_window->resize(1280, 1000);
    // The package changed on disk by another program (its manifest rewritten): the window asks; kept (No), the
    // panel says the ratings are of the version opened. Put back, nothing is asked.
    QFile manifest(QDir(m_exported).filePath("manifest.json"));
    QVERIFY(manifest.open(QIODevice::ReadOnly));
    const QByteArray manifestBytes = manifest.readAll();
    manifest.close();
    const auto rewrite = [&](const QByteArray& bytes) {
        QVERIFY(manifest.open(QIODevice::WriteOnly | QIODevice::Truncate));
        manifest.write(bytes);
        manifest.close();
    };
    MessageBox::takeRecorded();
    MessageBox::setNextAnswer(MessageBox::Choice::No);
    rewrite(manifestBytes + "\n");
    QList<MessageBox::Message> asked;
    QTRY_VERIFY_WITH_TIMEOUT((asked += MessageBox::takeRecorded(), !asked.isEmpty()), 5000);
    QVERIFY2(asked.front().text.contains(QFileInfo(m_exported).fileName()), qPrintable(asked.front().text));
    QVERIFY(find<QLabel>("reviewMessageLabel")->text().contains("changed on disk"));
    QVERIFY(m_window->isReviewing());
    rewrite(manifestBytes);
    QTest::qWait(800);
    QVERIFY(MessageBox::takeRecorded().isEmpty());
    find<QAction>("actionCloseReview")->trigger();
    QVERIFY(!m_window->isReviewing());
    QVERIFY2(m_window->trialReportView()->sceneNote().contains("Review Scene Package"),
             qPrintable(m_window->trialReportView()->sceneNote()));
    m_window->trialReportView()->close();
    QVERIFY(find<QPushButton>("meshButton")->isEnabled());
    QVERIFY(find<QAction>("actionUndo")->isEnabled());
    QVERIFY(find<QAction>("actionNewCase")->isEnabled());
    QVERIFY(!find<QAction>("actionCloseReview")->isEnabled());
}

void TestAuthoringFlow::aBrokenPackageOpensWithAMessageAndChangesNothing() {
    const QString broken = m_dir.filePath("broken");
    QVERIFY(QDir().mkpath(broken));
    QFile manifest(QDir(broken).filePath("manifest.json"));
    QVERIFY(manifest.open(QIODevice::WriteOnly));
    manifest.write("{\"format\": \"hysteroscene-scene\", \"schemaVersion\": 1, \"files\": []}");
    manifest.close();
    const std::string before = hs::scene::toJson(m_window->document().spec());
    m_window->reviewPackage(broken);
    QList<MessageBox::Message> messages;
    QTRY_VERIFY_WITH_TIMEOUT((messages += MessageBox::takeRecorded(), !messages.isEmpty()), 20000);
    // The message names the file and what is wrong with it (under Show Details).
    QVERIFY2(messages.first().details.contains("manifest.json"), qPrintable(messages.first().details));
    QVERIFY(!m_window->isReviewing());
    QCOMPARE(hs::scene::toJson(m_window->document().spec()), before);
}

void TestAuthoringFlow::showsTwoVariantsSideBySide() {
    // Two variants of a light case, exported from the Export panel.
    find<QSpinBox>("verticesSpin")->setValue(4000);
    auto* size = find<QComboBox>("textureSizeCombo");
    size->setCurrentIndex(size->findData(256));
    const QString folder = m_dir.filePath("variants");
    find<QLineEdit>("exportFolderEdit")->setText(folder);
    find<QSpinBox>("exportVariantsSpin")->setValue(2);
    QSignalSpy exported(&session(), &hs::widgets::GenerationSession::exported);
    find<QPushButton>("exportButton")->click();
    QVERIFY(exported.wait(kStageTimeoutMs));

    QSignalSpy opened(m_window.get(), &MainWindow::variantsOpened);
    FileDialog::setNextFileName(folder);
    find<QAction>("actionCompareVariants")->trigger();
    QVERIFY(opened.wait(60000));
    QCOMPARE(opened.at(0).at(0).toInt(), 2);
    hs::widgets::VariantsView* variants = m_window->variantsView();
    QVERIFY(variants->isVisible());
    variants->setInsertion(30.0);
    QVERIFY(variants->preview(0)->hasScene() && variants->preview(1)->hasScene());
    QCOMPARE(variants->preview(1)->insertion(), 30.0);
    // Two patients: the two views differ.
    QVERIFY(variants->preview(0)->grabImage() != variants->preview(1)->grabImage());
    if (!qEnvironmentVariable("HS_SCREENSHOT_DIR").isEmpty())
        QVERIFY(variants->grab().save(
            QDir(qEnvironmentVariable("HS_SCREENSHOT_DIR")).filePath("workstation-variants.png")));
}

QTEST_MAIN(TestAuthoringFlow)
#include "TestAuthoringFlow.moc"
