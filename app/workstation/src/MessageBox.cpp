#include "hs/workstation/MessageBox.h"

#include <QMessageBox>

#include <utility>

namespace hs::workstation {
namespace {

struct Recorder {
    bool recording = false;
    QList<MessageBox::Message> messages;
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

void MessageBox::setRecording(bool recording) {
    recorder().recording = recording;
    recorder().messages.clear();
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
    }
    box.setWindowTitle(message.title);
    box.setText(message.text);
    if (!message.details.isEmpty())
        box.setDetailedText(message.details);
    box.setStandardButtons(QMessageBox::Ok);
    box.exec();
}

} // namespace hs::workstation
