// Qt Test for the simulator's window: it opens a package, the keys drive the scope (the drawn state follows), the
// view renders, and ending the trial writes the report, its page and the trial. With HS_SCREENSHOT_DIR set it saves
// the endoscopic view inside the cavity there (docs/simulator.md); HS_SIM_PACKAGE names a package to use instead of
// the light test case.
#include "hs/generate/Generate.h"
#include "hs/scene/ScenePackage.h"
#include "hs/simapp/SimWindow.h"
#include "hs/widgets/view/VtkView.h"
#include "hs/workstation/MessageBox.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using hs::simapp::KeyboardSource;
using hs::simapp::SimWindow;

class TestSimWindow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void listsTheKeys();
    void drivesTheScopeAndEndsTheTrial();

private:
    QTemporaryDir m_dir;
    QString m_package;
};

void TestSimWindow::initTestCase() {
    QElapsedTimer clock;
    clock.start();
    QVERIFY(m_dir.isValid());
    hs::workstation::MessageBox::setRecording(true);
    // HS_SIM_PACKAGE: a package to use instead (the docs' picture is taken in the default scene).
    m_package = qEnvironmentVariable("HS_SIM_PACKAGE");
    if (!m_package.isEmpty())
        return;
    auto spec = hs::scene::loadCase(
        QFile::encodeName(QDir(qEnvironmentVariable("HS_TEST_DATA_DIR")).filePath("batch/light-case.json"))
            .toStdString());
    QVERIFY(spec.ok());
    auto generated = hs::generate::generateScene(*spec, {});
    QVERIFY(generated.ok());
    m_package = m_dir.filePath("scene");
    QVERIFY(hs::scene::writeScenePackage(*generated->scene, QFile::encodeName(m_package).toStdString()).ok());
    qInfo("package generated in %lld ms", clock.elapsed());
}

void TestSimWindow::listsTheKeys() {
    const QString help = SimWindow::keyHelp();
    for (const char* key : {"W / S", "Q / E", "Z / X", "I / O", "Space"})
        QVERIFY2(help.contains(key), key);
}

void TestSimWindow::drivesTheScopeAndEndsTheTrial() {
    hs::simapp::SimOptions options;
    SimWindow window(options);
    window.resize(720, 600);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QSignalSpy started(&window, &SimWindow::sessionStarted);
    QSignalSpy failed(&window, &SimWindow::loadFailed);
    QElapsedTimer clock;
    clock.start();
    window.openPackage(m_package);
    QTRY_VERIFY_WITH_TIMEOUT(!started.isEmpty() || !failed.isEmpty(), 120000);
    if (!failed.isEmpty())
        QSKIP(qPrintable("the world does not load this package yet: " + failed.first().first().toString()));
    qInfo("loaded after %lld ms", clock.elapsed());
    QVERIFY(window.keyboard() != nullptr);
    QTRY_VERIFY(window.framesDrawn() > 2);
    const double before = window.drawnState().sample.insertionMm;
    // W held inserts the scope (15 mm/s of device time); the drawn state follows the physics.
    QTest::keyPress(window.view(), Qt::Key_W);
    QTRY_VERIFY_WITH_TIMEOUT(window.drawnState().sample.insertionMm > before + 3.0, 30000);
    QTest::keyRelease(window.view(), Qt::Key_W);
    qInfo("inserted after %lld ms, %d frames", clock.elapsed(), window.framesDrawn());
    QTest::keyClick(window.view(), Qt::Key_I); // inflow closed
    QTRY_COMPARE(window.drawnState().sample.inflow, 0.0);
    QTest::keyClick(window.view(), Qt::Key_I);
    // Into the cavity, turned towards an ostium, for the picture.
    const double target = window.keyboard()->current().insertionMm + 35.0;
    window.keyboard()->nudge(KeyboardSource::Axis::Insertion, 35.0);
    window.keyboard()->nudge(KeyboardSource::Axis::Roll, 70.0);
    QTRY_VERIFY_WITH_TIMEOUT(window.drawnState().sample.insertionMm > target - 0.5, 30000);
    QVERIFY(window.drawnState().inCavity);
    QTest::qWait(300);
    const hs::sim::WorldState& state = window.drawnState();
    qInfo("tip %.1f mm in, pressure %.2f kPa, turbidity %.2f, red-out %.2f, force %.2f N, perforated %d",
          state.sample.insertionMm, state.fluid.pressureKpa, state.fluid.turbidity, state.fluid.redOut,
          state.contact.forceN, int(state.contact.perforated));
    const QImage image = window.grabView();
    QVERIFY(!image.isNull());
    if (const QString folder = qEnvironmentVariable("HS_SCREENSHOT_DIR"); !folder.isEmpty())
        QVERIFY(image.save(QDir(folder).filePath("simulator-view.png")));
    QCOMPARE(image.pixelColor(2, 2), QColor(Qt::black)); // outside the optic's circle
    const QColor centre = image.pixelColor(image.width() / 2, image.height() / 2);
    QVERIFY2(centre.red() > 20, qPrintable(centre.name())); // lit tissue in the middle

    qInfo("in the cavity after %lld ms, %d frames", clock.elapsed(), window.framesDrawn());
    const QString report = m_dir.filePath("trial.json");
    QVERIFY(window.endTrial(report));
    QVERIFY(!window.isRunning());
    QVERIFY(QFile::exists(report));
    QVERIFY(QFile::exists(m_dir.filePath("trial.html")));
    QVERIFY(QFile::exists(m_dir.filePath("trial.trial")));
    qInfo("ended after %lld ms", clock.elapsed());
}

int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(hs::widgets::VtkView::defaultFormat());
    QApplication app(argc, argv);
    TestSimWindow test;
    return QTest::qExec(&test, argc, argv);
}

#include "TestSimWindow.moc"
