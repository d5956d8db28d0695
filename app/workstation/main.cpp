// hysteroscene: the workstation. Opens the mesh given on the command line.
#include "hs/translations/Translations.h"
#include "hs/widgets/common/MessageBox.h"
#include "hs/widgets/panels/TrialReportView.h"
#include "hs/widgets/view/VtkView.h"
#include "hs/workstation/MainWindow.h"

#include <QAction>
#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>
#include <QTabWidget>
#include <QTextStream>
#include <QTimer>

namespace {

/// The value of --lang (also --lang=xx), else HS_LANG; empty: the system locale decides.
QString requestedLanguage(const QStringList& arguments) {
    for (int i = 1; i < arguments.size(); ++i) {
        if (arguments.at(i) == QStringLiteral("--lang") && i + 1 < arguments.size())
            return hs::translations::requestedLanguage(arguments.at(i + 1));
        if (arguments.at(i).startsWith(QStringLiteral("--lang=")))
            return hs::translations::requestedLanguage(arguments.at(i).mid(7));
    }
    return hs::translations::requestedLanguage();
}

/// Lets the view finish its first frames, saves the window to `path` and ends the application.
void screenshotAndQuit(hs::workstation::MainWindow& window, const QString& path, bool loaded) {
    QTimer::singleShot(300, &window, [&window, path, loaded] {
        const bool saved = window.saveScreenshot(path);
        for (const auto& message : hs::widgets::MessageBox::takeRecorded())
            QTextStream(stderr) << message.text << '\n' << message.details << '\n';
        QCoreApplication::exit(saved && loaded ? 0 : 1);
    });
}

} // namespace

int main(int argc, char** argv) {
    // VTK needs an OpenGL 3.2 core context; Qt's windows share contexts, so the format is set for all of them.
    QSurfaceFormat::setDefaultFormat(hs::widgets::VtkView::defaultFormat());
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("hysteroscene"));
    QCoreApplication::setApplicationName(QStringLiteral("hysteroscene"));
    QCoreApplication::setApplicationVersion(QStringLiteral(HS_VERSION));

    // The language is needed before the parser's help texts are written, so it is looked up first.
    hs::translations::installTranslators(app, requestedLanguage(QCoreApplication::arguments()));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QCoreApplication::translate("main", "Scenario authoring workstation for hysteroscopy training"));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(
        QCoreApplication::translate("main", "file"),
        QCoreApplication::translate("main",
                                    "A case file (.json) to author, a scene package (a folder) or a simulator's "
                                    "trial report (.json) to review, or a surface or tetrahedral mesh to "
                                    "open."));
    const QCommandLineOption languageOption(
        QStringLiteral("lang"),
        QCoreApplication::translate("main", "User-interface language (de, fr, it, en); default: HS_LANG, else the "
                                            "system locale."),
        QCoreApplication::translate("main", "language"));
    QCommandLineOption screenshotOption(
        QStringLiteral("screenshot"),
        QCoreApplication::translate("main", "Save the window to an image after loading, then quit."),
        QCoreApplication::translate("main", "image"));
    screenshotOption.setFlags(QCommandLineOption::HiddenFromHelp);
    QCommandLineOption clipOption(QStringLiteral("clip"),
                                  QCoreApplication::translate("main", "Open a tetrahedral mesh cut open."));
    clipOption.setFlags(QCommandLineOption::HiddenFromHelp);
    parser.addOption(languageOption);
    parser.addOption(screenshotOption);
    parser.addOption(clipOption);
    parser.process(app);

    hs::workstation::MainWindow window;
    window.show();
    const QString file = parser.positionalArguments().value(0);
    if (parser.isSet(screenshotOption)) {
        const QString image = parser.value(screenshotOption);
        hs::widgets::MessageBox::setRecording(true); // nobody is there to close a message box
        QObject::connect(&window, &hs::workstation::MainWindow::fileLoaded, &window,
                         [&window, image] { screenshotAndQuit(window, image, true); });
        QObject::connect(&window, &hs::workstation::MainWindow::loadFailed, &window,
                         [&window, image] { screenshotAndQuit(window, image, false); });
        QObject::connect(&window, &hs::workstation::MainWindow::reviewOpened, &window,
                         [&window, image] { screenshotAndQuit(window, image, true); });
        // A trial report: the picture is of its own window.
        QObject::connect(&window, &hs::workstation::MainWindow::trialReportOpened, &window, [&window, image] {
            // The metrics to `image`, the plots over time beside it ("<image>-over-time.png").
            QTimer::singleShot(300, &window, [&window, image] {
                hs::widgets::TrialReportView* view = window.trialReportView();
                bool saved = view->grab().save(image);
                view->tabs()->setCurrentIndex(1);
                QTimer::singleShot(300, &window, [view, image, saved] {
                    const QFileInfo info(image);
                    const QString plots =
                        info.dir().filePath(info.completeBaseName() + QStringLiteral("-over-time.") + info.suffix());
                    QCoreApplication::exit(saved && view->grab().save(plots) ? 0 : 1);
                });
            });
        });
        if (hs::workstation::MainWindow::isTrialReport(file)) // a report that cannot be read: its message, and out
            QTimer::singleShot(30000, &window, [&window, image] { screenshotAndQuit(window, image, false); });
        // A case opens at once: the picture once the window has drawn it.
        if (file.isEmpty() || (QFileInfo(file).suffix().compare(QStringLiteral("json"), Qt::CaseInsensitive) == 0 &&
                               !hs::workstation::MainWindow::isTrialReport(file)))
            QTimer::singleShot(500, &window, [&window, image] { screenshotAndQuit(window, image, true); });
    }
    if (parser.isSet(clipOption))
        QObject::connect(&window, &hs::workstation::MainWindow::fileLoaded, &window, [&window] {
            if (auto* clip = window.findChild<QAction*>(QStringLiteral("actionClip")); clip && clip->isEnabled())
                clip->setChecked(true);
        });
    if (!file.isEmpty())
        window.openArgument(file);
    if (!parser.isSet(screenshotOption)) // after a crash, the case being edited is offered back
        QTimer::singleShot(0, &window, [&window] { window.offerRecovery(); });
    return QApplication::exec();
}
