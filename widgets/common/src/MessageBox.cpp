#include "hs/widgets/common/MessageBox.h"

#include <QMessageBox>

#include <optional>
#include <utility>

namespace hs::widgets {
namespace {

struct Recorder {
    bool recording = false;
    QList<MessageBox::Message> messages;
    std::optional<MessageBox::Choice> answer;
};

Recorder& recorder() {
    static Recorder instance;
    return instance;
}

} // namespace

void MessageBox::information(QWidget* parent, const QString& title, const QString& text) {
    show(parent, {Icon::Information, title, text, {}});
}

void MessageBox::critical(QWidget* parent, const QString& title, const QString& text, const QString& details) {
    show(parent, {Icon::Critical, title, text, details});
}

void MessageBox::about(QWidget* parent, const QString& title, const QString& text) {
    if (recorder().recording) {
        recorder().messages.append({Icon::Information, title, text, {}});
        return;
    }
    QMessageBox::about(parent, title, text);
}

MessageBox::Choice MessageBox::askSaveDiscardCancel(QWidget* parent, const QString& title, const QString& text) {
    if (recorder().recording) {
        recorder().messages.append({Icon::Question, title, text, {}});
        return std::exchange(recorder().answer, std::nullopt).value_or(Choice::Cancel);
    }
    const auto answer = QMessageBox::warning(
        parent, title, text, QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    return answer == QMessageBox::Save ? Choice::Save
                                       : (answer == QMessageBox::Discard ? Choice::Discard : Choice::Cancel);
}

MessageBox::Choice MessageBox::askYesNo(QWidget* parent, const QString& title, const QString& text) {
    if (recorder().recording) {
        recorder().messages.append({Icon::Question, title, text, {}});
        return std::exchange(recorder().answer, std::nullopt).value_or(Choice::No);
    }
    return QMessageBox::question(parent, title, text, QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes) ==
                   QMessageBox::Yes
               ? Choice::Yes
               : Choice::No;
}

void MessageBox::setRecording(bool recording) {
    recorder().recording = recording;
    recorder().messages.clear();
    recorder().answer.reset();
}

void MessageBox::setNextAnswer(Choice answer) {
    recorder().answer = answer;
}

QList<MessageBox::Message> MessageBox::takeRecorded() {
    return std::exchange(recorder().messages, {});
}

void MessageBox::show(QWidget* parent, const Message& message) {
    if (recorder().recording) {
        recorder().messages.append(message);
        return;
    }
    QMessageBox box(parent);
    switch (message.icon) {
    case Icon::Information:
        box.setIcon(QMessageBox::Information);
        break;
    case Icon::Warning:
        box.setIcon(QMessageBox::Warning);
        break;
    case Icon::Critical:
        box.setIcon(QMessageBox::Critical);
        break;
    case Icon::Question:
        box.setIcon(QMessageBox::Question);
        break;
    }
    box.setWindowTitle(message.title);
    box.setText(message.text);
    if (!message.details.isEmpty())
        box.setDetailedText(message.details);
    box.setStandardButtons(QMessageBox::Ok);
    box.exec();
}

} // namespace hs::widgets
