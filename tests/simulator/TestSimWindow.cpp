// Qt Test for the simulator's window: it opens a package, the keys drive the scope (the drawn state follows), the
// view renders, and ending the trial writes the report, its page and the trial. With HS_SCREENSHOT_DIR set it saves
// the endoscopic view inside the cavity there (docs/simulator.md).
#include "hs/generate/Generate.h"
#include "hs/scene/ScenePackage.h"
#include "hs/simapp/SimWindow.h"
#include "hs/widgets/view/VtkView.h"
#include "hs/workstation/MessageBox.h"

#include <QDir>
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
    QVERIFY(m_dir.isValid());
    hs::workstation::MessageBox::setRecording(true);
    auto spec = hs::scene::loadCase(
        QFile::encodeName(QDir(qEnvironmentVariable("HS_TEST_DATA_DIR")).filePath("batch/light-case.json"))
            .toStdString());
    QVERIFY(spec.ok());
    auto generated = hs::generate::generateScene(*spec, {});
    QVERIFY(generated.ok());
    m_package = m_dir.filePath("scene");
    QVERIFY(hs::scene::writeScenePackage(*generated->scene, QFile::encodeName(m_package).toStdString()).ok());
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
    window.openPackage(m_package);
    QTRY_VERIFY_WITH_TIMEOUT(!started.isEmpty() || !failed.isEmpty(), 120000);
    if (!failed.isEmpty())
        QSKIP(qPrintable("the world does not load this package yet: " + failed.first().first().toString()));
    QVERIFY(window.keyboard() != nullptr);
    QTRY_VERIFY(window.framesDrawn() > 2);
    const double before = window.drawnState().sample.insertionMm;
    // W held for half a second inserts the scope; the drawn state follows the physics.
    QTest::keyPress(window.view(), Qt::Key_W);
    QTest::qWait(500);
    QTest::keyRelease(window.view(), Qt::Key_W);
    QTRY_VERIFY(window.drawnState().sample.insertionMm > before + 3.0);
    QTest::keyClick(window.view(), Qt::Key_I); // inflow closed
    QTRY_COMPARE(window.drawnState().sample.inflow, 0.0);
    QTest::keyClick(window.view(), Qt::Key_I);
    // Into the cavity, turned towards an ostium, for the picture.
    window.keyboard()->nudge(KeyboardSource::Axis::Insertion, 38.0);
    window.keyboard()->nudge(KeyboardSource::Axis::Roll, 70.0);
    QTRY_VERIFY(window.drawnState().inCavity);
    QTest::qWait(300);
    const QImage image = window.grabView();
    QVERIFY(!image.isNull());
    QCOMPARE(image.pixelColor(2, 2), QColor(Qt::black)); // outside the optic's circle
    const QColor centre = image.pixelColor(image.width() / 2, image.height() / 2);
    QVERIFY2(centre.red() > 20, qPrintable(centre.name())); // lit tissue in the middle
    if (const QString folder = qEnvironmentVariable("HS_SCREENSHOT_DIR"); !folder.isEmpty())
        QVERIFY(image.save(QDir(folder).filePath("simulator-view.png")));

    const QString report = m_dir.filePath("trial.json");
    QVERIFY(window.endTrial(report));
    QVERIFY(!window.isRunning());
    QVERIFY(QFile::exists(report));
    QVERIFY(QFile::exists(m_dir.filePath("trial.html")));
    QVERIFY(QFile::exists(m_dir.filePath("trial.trial")));
}

int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(hs::widgets::VtkView::defaultFormat());
    QApplication app(argc, argv);
    TestSimWindow test;
    return QTest::qExec(&test, argc, argv);
}

#include "TestSimWindow.moc"
