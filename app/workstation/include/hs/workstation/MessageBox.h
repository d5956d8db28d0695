#pragma once
/// Message boxes behind a seam: a test records them instead of blocking on a modal dialog.

#include <QList>
#include <QString>

class QWidget;

namespace hs::workstation {

class MessageBox {
public:
    enum class Icon { Information, Warning, Critical };

    /// One message as it was (or would have been) shown.
    struct Message {
        Icon icon = Icon::Information;
        QString title;
        QString text;    ///< translated, for the user
        QString details; ///< the untranslated technical detail (shown folded under "Show Details...")
    };

    static void information(QWidget* parent, const QString& title, const QString& text);
    static void critical(QWidget* parent, const QString& title, const QString& text, const QString& details = {});
    /// The application's About box (rich text).
    static void about(QWidget* parent, const QString& title, const QString& text);

    /// Test seam: while on, messages are recorded and not shown.
    static void setRecording(bool recording);
    /// The messages recorded since the last call, oldest first.
    static QList<Message> takeRecorded();

private:
    static void show(QWidget* parent, const Message& message);
};

} // namespace hs::workstation
