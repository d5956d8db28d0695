#include "hs/translations/Translations.h"

#include <QCoreApplication>
#include <QDir>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

namespace hs::translations {

QString resourceFolder() {
    return QStringLiteral(":/i18n");
}

QStringList availableLanguages() {
    QStringList languages;
    const QStringList files = QDir(resourceFolder()).entryList({QStringLiteral("hysteroscene_*.qm")}, QDir::Files);
    for (const QString& file : files)
        languages.append(file.mid(13, file.size() - 13 - 3)); // between "hysteroscene_" and ".qm"
    return languages;
}

QString requestedLanguage(const QString& option) {
    return option.isEmpty() ? qEnvironmentVariable("HS_LANG") : option;
}

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
    if (!translator->load(locale, "hysteroscene", "_", resourceFolder())) {
        delete translator;
        return QStringLiteral("en");
    }
    QCoreApplication::installTranslator(translator);
    return translator->language();
}

} // namespace hs::translations
