#pragma once
/// Message boxes behind a seam: a test records them instead of blocking on a modal dialog.

#include <QList>
#include <QString>

class QWidget;

namespace hs::widgets {

class MessageBox {
public:
    enum class Icon { Information, Warning, Critical, Question };
    /// The buttons a question offers, and the answer.
    enum class Choice { Save, Discard, Cancel, Yes, No };

    /// One message as it was (or would have been) shown.
    struct Message {
        Icon icon = Icon::Information;
        QString title;
        QString text;    ///< translated, for the user
        QString details; ///< the untranslated technical detail (shown folded under "Show Details...")
    };

    static void information(QWidget* parent, const QString& title, const QString& text);
    static void critical(QWidget* parent, const QString& title, const QString& text, const QString& details = {});
    /// Asks with Save / Discard / Cancel, or with Yes / No; Cancel (or No) when the user closes the box.
    static Choice askSaveDiscardCancel(QWidget* parent, const QString& title, const QString& text);
    static Choice askYesNo(QWidget* parent, const QString& title, const QString& text);
    /// The application's About box (rich text).
    static void about(QWidget* parent, const QString& title, const QString& text);

    /// Test seam: while on, messages are recorded and not shown; a question is answered by the next answer set
    /// (Cancel, or No, when none is).
    static void setRecording(bool recording);
    static void setNextAnswer(Choice answer);
    /// The messages recorded since the last call, oldest first.
    static QList<Message> takeRecorded();

private:
    static void show(QWidget* parent, const Message& message);
};

} // namespace hs::widgets
