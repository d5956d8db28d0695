// Qt Test for the simulator's window: it speaks the language --lang chooses (English when there is no translation),
// it opens a package, the keys drive the scope (the drawn state follows), the view renders, and ending the trial
// writes the report, its page and the trial. With HS_SCREENSHOT_DIR set it saves
// the endoscopic view inside the cavity there (docs/simulator.md); HS_SIM_PACKAGE names a package to use instead of
// the light test case.
#include "hs/generate/Generate.h"
#include "hs/scene/ScenePackage.h"
#include "hs/simapp/SimOptions.h"
#include "hs/simapp/SimWindow.h"
#include "hs/translations/Translations.h"
#include "hs/widgets/common/MessageBox.h"
#include "hs/widgets/view/VtkView.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>
#include <cmath>

using hs::simapp::KeyboardSource;
using hs::simapp::SimWindow;

class TestSimWindow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanup();
    void listsTheKeys();
    void readsTheLanguageOption();
    void readsTheMediumAndThePatient();
    void theKeyboardDrivesTheLoopAndThePump();
    void speaksTheChosenLanguage_data();
    void speaksTheChosenLanguage();
    void drivesTheScopeAndEndsTheTrial();

private:
    QTemporaryDir m_dir;
    QString m_package;
};

void TestSimWindow::initTestCase() {
    QElapsedTimer clock;
    clock.start();
    QVERIFY(m_dir.isValid());
    hs::widgets::MessageBox::setRecording(true);
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

void TestSimWindow::cleanup() {
    // A test that installed translators leaves the next one in English.
    const auto translators = QCoreApplication::instance()->findChildren<QTranslator*>();
    for (QTranslator* translator : translators) {
        QCoreApplication::removeTranslator(translator);
        delete translator;
    }
    QLocale::setDefault(QLocale::c());
}

void TestSimWindow::listsTheKeys() {
    const QString help = SimWindow::keyHelp();
    for (const char* key : {"W / S", "Q / E", "Z / X", "I / O", "Space", "R / F", "C, held", "V, held", "+ / -"})
        QVERIFY2(help.contains(key), key);
}

void TestSimWindow::readsTheLanguageOption() {
    const auto parse = [](std::vector<const char*> arguments) {
        arguments.insert(arguments.begin(), "hysteroscene-sim");
        return hs::simapp::parseCommandLine(static_cast<int>(arguments.size()), arguments.data());
    };
    const auto none = parse({"scene"});
    QVERIFY(none.options);
    QCOMPARE(none.options->language, std::string());
    const auto lang = parse({"scene", "--lang", "de"});
    QVERIFY(lang.options);
    QCOMPARE(lang.options->language, std::string("de"));
    const auto language = parse({"--language=fr", "scene"});
    QVERIFY(language.options);
    QCOMPARE(language.options->language, std::string("fr"));
}

void TestSimWindow::readsTheMediumAndThePatient() {
    const auto parse = [](std::vector<const char*> arguments) {
        arguments.insert(arguments.begin(), "hysteroscene-sim");
        return hs::simapp::parseCommandLine(static_cast<int>(arguments.size()), arguments.data());
    };
    const auto saline = parse({"scene"});
    QVERIFY(saline.options);
    QVERIFY(saline.options->world.fluid.medium == hs::sim::DistensionMedium::Saline);
    QCOMPARE(saline.options->world.fluid.deficitLimitMl, 2500.0);
    const auto glycine = parse({"scene", "--medium", "glycine", "--elderly-or-comorbid"});
    QVERIFY(glycine.options);
    QVERIFY(glycine.options->world.fluid.medium == hs::sim::DistensionMedium::Glycine);
    QVERIFY(glycine.options->world.fluid.elderlyOrComorbid);
    QCOMPARE(glycine.options->world.fluid.deficitLimitMl, 750.0);
    QCOMPARE(glycine.options->world.fluid.deficitWarningMl, 500.0);
    const auto unknown = parse({"scene", "--medium", "sorbitol"});
    QVERIFY(!unknown.options);
    QVERIFY(unknown.message.find("--medium") != std::string::npos);
}

void TestSimWindow::theKeyboardDrivesTheLoopAndThePump() {
    KeyboardSource keyboard;
    keyboard.setInstrument(hs::sim::kInstrumentLoop);
    std::vector<hs::sim::DeviceSample> out(500);
    // R held for half a second: the loop goes out at 10 mm/s; C held: the cutting pedal with it.
    keyboard.setHeld(KeyboardSource::Axis::WorkingElement, 1);
    keyboard.setButtonHeld(hs::sim::kButtonCut, true);
    QVERIFY(keyboard.next(0, out.size(), out.data()));
    QVERIFY(std::abs(out.back().workingElementMm - 5.0) < 1e-9);
    QVERIFY(out.back().buttons & hs::sim::kButtonCut);
    QCOMPARE(out.back().instrument, std::uint32_t{hs::sim::kInstrumentLoop});
    keyboard.setHeld(KeyboardSource::Axis::WorkingElement, 0);
    keyboard.setButtonHeld(hs::sim::kButtonCut, false);
    // + pressed once: the pump's up button for kMarkTicks ticks, then up again (one press, one step).
    keyboard.press(hs::sim::kButtonPumpUp);
    QVERIFY(keyboard.next(500, out.size(), out.data()));
    QVERIFY(out.front().buttons & hs::sim::kButtonPumpUp);
    QVERIFY(!(out.back().buttons & hs::sim::kButtonPumpUp));
    QCOMPARE(out.back().buttons & hs::sim::kButtonCut, 0u);
    // The loop put down: drawn in, and the pedals energise nothing.
    keyboard.setInstrument(hs::sim::kInstrumentNone);
    keyboard.setButtonHeld(hs::sim::kButtonCoagulate, true);
    QVERIFY(keyboard.next(1000, out.size(), out.data()));
    QCOMPARE(out.back().workingElementMm, 0.0);
    QCOMPARE(out.back().buttons, 0u);
    for (const hs::sim::DeviceSample& sample : out)
        QVERIFY(hs::sim::isValid(sample));
}

void TestSimWindow::speaksTheChosenLanguage_data() {
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("loaded");
    QTest::addColumn<QString>("title");
    QTest::addColumn<QStringList>("menus");
    QTest::addColumn<QString>("openPackage");
    QTest::newRow("German") << "de"
                            << "de"
                            << "hysteroscene-Simulator" << QStringList{"&Datei", "Hystero&skop", "Ü&bung", "&Hilfe"}
                            << "Paket ö&ffnen...";
    QTest::newRow("French") << "fr"
                            << "fr"
                            << "Simulateur hysteroscene"
                            << QStringList{"&Fichier", "&Hystéroscope", "&Exercice", "A&ide"} << "&Ouvrir un paquet...";
    QTest::newRow("Italian") << "it"
                             << "it"
                             << "Simulatore hysteroscene"
                             << QStringList{"&File", "&Isteroscopio", "&Esercizio", "&Aiuto"} << "&Apri pacchetto...";
    QTest::newRow("unknown: English") << "tlh"
                                      << "en"
                                      << "hysteroscene simulator"
                                      << QStringList{"&File", "&Scope", "&Exercise", "&Help"} << "&Open Package...";
}

void TestSimWindow::speaksTheChosenLanguage() {
    QFETCH(QString, language);
    QFETCH(QString, loaded);
    QFETCH(QString, title);
    QFETCH(QStringList, menus);
    QFETCH(QString, openPackage);
    QCOMPARE(hs::translations::installTranslators(*QCoreApplication::instance(), language), loaded);
    SimWindow window(hs::simapp::SimOptions{});
    QCOMPARE(window.windowTitle(), title);
    QStringList shown;
    for (const QAction* menu : window.menuBar()->actions())
        shown.append(menu->text());
    QCOMPARE(shown, menus);
    auto* open = window.findChild<QAction*>(QStringLiteral("actionOpenPackage"));
    QVERIFY(open);
    QCOMPARE(open->text(), openPackage);
    auto* status = window.findChild<QLabel*>(QStringLiteral("simStatusLabel"));
    QVERIFY(status);
    QCOMPARE(status->text() == QStringLiteral("Open a scene package (File > Open)."), loaded == QStringLiteral("en"));
    // The key help is translated, its keys' names kept.
    QVERIFY(SimWindow::keyHelp().contains(QStringLiteral("W / S")));
    QCOMPARE(SimWindow::keyHelp().contains(QStringLiteral("mouse wheel")), loaded == QStringLiteral("en"));
    // Each language's decimal separator in the diameters.
    auto* diameter = window.findChild<QAction*>(QStringLiteral("actionDiameter-2.9"));
    QVERIFY(diameter);
    QCOMPARE(diameter->text(), loaded == QStringLiteral("en") ? QStringLiteral("2.9 mm") : QStringLiteral("2,9 mm"));
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
