#pragma once
/// Loads the user-interface translations: the requested language, else the system locale's, else English (the
/// strings in the source).

#include <QString>

class QCoreApplication;

namespace hs::workstation {

/// Installs the translators for `language` ("de", "fr_CH", ...; empty: the system locale's UI languages) on `app`.
/// Also sets the default QLocale to an explicitly requested language, so numbers read the same way as the text.
/// Returns the language loaded ("de", ...) or "en" when the English source strings are used.
QString installTranslators(QCoreApplication& app, const QString& language = {});

} // namespace hs::workstation
