// hysteroscene-sim: the preview simulator. Headless runs need no display (and speak English); the window needs
// OpenGL 3.2 and speaks the language --lang, HS_LANG or the system locale chooses.
#include "hs/simapp/Headless.h"
#include "hs/simapp/SimOptions.h"
#include "hs/simapp/SimWindow.h"
#include "hs/translations/Translations.h"
#include "hs/widgets/view/VtkView.h"

#include "hs/core/ExitCode.h"

#include <QApplication>
#include <QSurfaceFormat>
#include <QTimer>

#include <iostream>

int main(int argc, char** argv) {
    const hs::simapp::ParsedCommandLine parsed = hs::simapp::parseCommandLine(argc, argv);
    if (!parsed.options) {
        (parsed.exitCode == 0 ? std::cout : std::cerr) << parsed.message;
        return parsed.exitCode;
    }
    const hs::simapp::SimOptions& options = *parsed.options;
    if (!options.writeDemoPath.empty())
        return hs::simapp::writeDemonstration(options);
    if (options.headless)
        return hs::simapp::runHeadless(options);
    // VTK needs an OpenGL 3.2 core context; Qt's windows share contexts, so the format is set for all of them.
    QSurfaceFormat::setDefaultFormat(hs::widgets::VtkView::defaultFormat());
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("hysteroscene"));
    QCoreApplication::setApplicationName(QStringLiteral("hysteroscene-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(HS_VERSION));
    hs::translations::installTranslators(app,
                                         hs::translations::requestedLanguage(QString::fromStdString(options.language)));
    hs::simapp::SimWindow window(options);
    window.show();
    if (!options.scene.empty())
        window.openPackage(QString::fromStdString(options.scene));
    if (!options.screenshotPath.empty())
        QTimer::singleShot(static_cast<int>(options.screenshotAfterS * 1000.0), &window, [&window, &options] {
            const bool saved = window.grab().save(QString::fromStdString(options.screenshotPath));
            if (!saved)
                std::cerr << "hysteroscene-sim: could not write " << options.screenshotPath << '\n';
            QCoreApplication::exit(saved ? 0 : 4);
        });
    return QApplication::exec();
}
