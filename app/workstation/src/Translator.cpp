#include "hs/workstation/Translator.h"

#include "hs/translations/Translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

namespace hs::workstation {

QString installTranslators(QCoreApplication& app, const QString& language) {
    const QLocale locale = language.isEmpty() ? QLocale::system() : QLocale(language);
    if (!language.isEmpty())
        QLocale::setDefault(locale);

    // Qt's own strings (standard dialog buttons); absent on systems without the Qt translations package.
    auto* qtTranslator = new QTranslator(&app);
    if (qtTranslator->load(locale, "qtbase", "_", QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qtTranslator);
    else
        delete qtTranslator;

    // QTranslator tries each of the locale's UI languages in turn ("de_CH", "de", ...).
    auto* translator = new QTranslator(&app);
    if (!translator->load(locale, "hysteroscene", "_", translations::resourceFolder())) {
        delete translator;
        return QStringLiteral("en");
    }
    QCoreApplication::installTranslator(translator);
    return translator->language();
}

} // namespace hs::workstation
