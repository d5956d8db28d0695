#pragma once
/// What the panel tests share: finding a widget by object name, and a document with its generation session.

#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/jobs/GenerationSession.h"

#include <QObject>
#include <QString>
#include <QtGlobal>

namespace hs::test {

/// The child of `parent` named `name`; the test stops with the name when there is none.
template <class T>
T* child(const QObject* parent, const QString& name) {
    T* found = parent->findChild<T*>(name);
    if (!found)
        qFatal("no widget %s", qPrintable(name));
    return found;
}

/// A case document (the bundled default case) and its session, without the automatic organ rebuild: a test runs
/// the stages it needs itself.
struct PanelHarness {
    widgets::CaseDocument document;
    widgets::GenerationSession session{document};
    PanelHarness() { session.setAutoUpdate(false); }
};

} // namespace hs::test
