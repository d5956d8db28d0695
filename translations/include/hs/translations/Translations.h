#pragma once
/// The compiled user-interface translations (.qm), embedded as Qt resources.

#include <QString>
#include <QStringList>

namespace hs::translations {

/// The resource folder that holds hysteroscene_<lang>.qm.
QString resourceFolder();
/// The languages with a translation ("de", "fr", "it"); English is the source language and always available.
QStringList availableLanguages();

} // namespace hs::translations
