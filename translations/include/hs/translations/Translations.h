#pragma once
/// The compiled user-interface translations (.qm), embedded as Qt resources, and their installation. Both the
/// workstation and the simulator load them: the requested language, else the system locale's, else English (the
/// strings in the source).

#include <QString>
#include <QStringList>

class QCoreApplication;

namespace hs::translations {

/// The resource folder that holds hysteroscene_<lang>.qm.
QString resourceFolder();
/// The languages with a translation ("de", "fr", "it"); English is the source language and always available.
QStringList availableLanguages();

/// The language a user asked for: `option` (the command line's --lang) when given, else the HS_LANG environment
/// variable; empty when neither is set (the system locale decides).
QString requestedLanguage(const QString& option = {});

/// Installs the translators for `language` ("de", "fr_CH", ...; empty: the system locale's UI languages) on `app`.
/// Also sets the default QLocale to an explicitly requested language, so numbers read the same way as the text.
/// Returns the language loaded ("de", ...) or "en" when the English source strings are used.
QString installTranslators(QCoreApplication& app, const QString& language = {});

} // namespace hs::translations
