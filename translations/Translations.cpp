#include "hs/translations/Translations.h"

#include <QDir>

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

} // namespace hs::translations
