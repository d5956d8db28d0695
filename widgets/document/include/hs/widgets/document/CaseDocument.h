#pragma once
// The workstation's document: one case (scene::CaseSpec) with its file and its undo history. Every edit is a
// QUndoCommand on the document's QUndoStack; edits with the same merge key in a row (one slider drag) become one
// command. The document holds no pipeline logic: it reads and writes case.json through scene::loadCase / toJson and
// leaves validation to scene::checkCase (Save refuses a case it rejects, naming the field and the allowed range).
#include "hs/core/Result.h"
#include "hs/scene/CaseSpec.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <QUndoStack>

#include <cstdint>
#include <functional>
#include <optional>

class QSettings;

namespace hs::widgets {

/// What an autosave left behind: the case as it was being edited, and the file it belongs to (empty: never saved).
struct Recovery {
    QString casePath; ///< the recovery file itself (a valid case.json)
    QString origin;   ///< the document's file when it was written, empty for an untitled case
};

class CaseDocument : public QObject {
    Q_OBJECT

public:
    /// An untitled document holding the bundled default case (scene::defaultCase()).
    explicit CaseDocument(QObject* parent = nullptr);

    const scene::CaseSpec& spec() const { return m_spec; }
    QUndoStack* undoStack() { return &m_undo; }
    /// Counts every change of the case (edit, undo, redo, open, new): results computed for another revision are
    /// stale.
    std::uint64_t revision() const { return m_revision; }
    /// The case.json the document was read from or last saved to; empty for an untitled case.
    QString filePath() const { return m_path; }
    /// The file's name, or "Untitled" (translated).
    QString displayName() const;
    /// Unsaved changes: the undo stack is away from the state last opened or saved.
    bool isModified() const { return !m_undo.isClean(); }
    /// "name[*] - Hysteroscene", for QWidget::setWindowTitle with setWindowModified(isModified()).
    QString windowTitle() const;

    /// One undoable edit: `change` edits a copy of the case. Nothing is pushed when it leaves the case as it was.
    /// Consecutive edits with the same nonzero `mergeKey` merge into one command (the first one's "before", the last
    /// one's "after"), so a slider drag undoes in one step; one that ends where its first began disappears.
    void edit(const QString& text, const std::function<void(scene::CaseSpec&)>& change, int mergeKey = 0);

    /// Replaces the document with an untitled default case; the history is cleared.
    void newCase();
    /// Reads `path` (scene::loadCase); on failure the document is left as it was.
    [[nodiscard]] Status open(const QString& path);
    /// Writes the case to filePath() (InvalidInput for an untitled document: use saveAs).
    [[nodiscard]] Status save();
    /// Writes the case to `path` (atomically, scene::saveCase) and makes it the document's file.
    [[nodiscard]] Status saveAs(const QString& path);

    /// Autosave: writes the case as it is now to `dir`/recovery.json (atomically) with the file it belongs to beside
    /// it (recovery.origin), whether or not there are unsaved changes. discardRecovery() removes both (a clean exit).
    [[nodiscard]] Status writeRecovery(const QString& dir) const;
    static void discardRecovery(const QString& dir);
    /// What the last session left in `dir`, if anything (after a crash).
    static std::optional<Recovery> findRecovery(const QString& dir);
    /// Takes a recovery's case as an edit of the document opened from its origin (or of an untitled one), so the
    /// document shows unsaved changes and Save writes them to the origin.
    [[nodiscard]] Status restore(const Recovery& recovery);

signals:
    /// The case changed: an edit, undo, redo, open, new or restore.
    void changed();
    void filePathChanged(const QString& path);

private:
    friend class EditCommand;
    void setSpec(const scene::CaseSpec& spec);
    void reset(const scene::CaseSpec& spec, const QString& path);

    scene::CaseSpec m_spec;
    QString m_path;
    QUndoStack m_undo;
    std::uint64_t m_revision = 0;
};

/// A list of recently used files in QSettings under `key` (absolute paths), newest first, at most kMaxRecentFiles,
/// each once: the recent cases (kRecentCasesKey) and the window's recent meshes keep theirs so.
inline constexpr const char* kRecentCasesKey = "cases/recent";
inline constexpr int kMaxRecentFiles = 8;
QStringList recentFiles(const QSettings& settings, const QString& key);
void addRecentFile(QSettings& settings, const QString& key, const QString& path);
/// Drops `path` from the list (a file that no longer exists).
void removeRecentFile(QSettings& settings, const QString& key, const QString& path);

} // namespace hs::widgets
