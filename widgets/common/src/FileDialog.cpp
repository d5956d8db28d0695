#include "hs/widgets/common/FileDialog.h"

#include <QFileDialog>

#include <optional>

namespace hs::widgets {
namespace {

std::optional<QString>& nextFileName() {
    static std::optional<QString> next;
    return next;
}

} // namespace

QString FileDialog::getOpenFileName(QWidget* parent, const QString& caption, const QString& folder,
                                    const QString& filter) {
    if (std::optional<QString>& next = nextFileName(); next.has_value()) {
        const QString answer = *next;
        next.reset();
        return answer;
    }
    return QFileDialog::getOpenFileName(parent, caption, folder, filter);
}

QString FileDialog::getSaveFileName(QWidget* parent, const QString& caption, const QString& folder,
                                    const QString& filter) {
    if (std::optional<QString>& next = nextFileName(); next.has_value()) {
        const QString answer = *next;
        next.reset();
        return answer;
    }
    return QFileDialog::getSaveFileName(parent, caption, folder, filter);
}

QString FileDialog::getExistingDirectory(QWidget* parent, const QString& caption, const QString& folder) {
    if (std::optional<QString>& next = nextFileName(); next.has_value()) {
        const QString answer = *next;
        next.reset();
        return answer;
    }
    return QFileDialog::getExistingDirectory(parent, caption, folder);
}

void FileDialog::setNextFileName(const QString& fileName) {
    nextFileName() = fileName;
}

} // namespace hs::widgets
