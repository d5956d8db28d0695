#pragma once
/// File dialogs behind a seam: tests set the next answer instead of driving a native dialog.

#include <QString>

class QWidget;

namespace hs::widgets {

class FileDialog {
public:
    /// The file the user chose, or an empty string when they cancelled.
    static QString getOpenFileName(QWidget* parent, const QString& caption, const QString& folder,
                                   const QString& filter);

    /// The file the user chose to save to, or an empty string when they cancelled.
    static QString getSaveFileName(QWidget* parent, const QString& caption, const QString& folder,
                                   const QString& filter);
    /// The folder the user chose, or an empty string when they cancelled.
    static QString getExistingDirectory(QWidget* parent, const QString& caption, const QString& folder);
    /// Test seam: the next getOpenFileName, getSaveFileName or getExistingDirectory returns `fileName` (empty: as if
    /// cancelled) without showing a dialog.
    static void setNextFileName(const QString& fileName);
};

} // namespace hs::widgets
