#include "hs/widgets/document/CaseDocument.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <QSettings>
#include <QUndoCommand>

namespace hs::widgets {

namespace {

constexpr const char* kRecoveryCase = "recovery.json";
constexpr const char* kRecoveryOrigin = "recovery.origin";

bool sameCase(const scene::CaseSpec& a, const scene::CaseSpec& b) {
    return scene::toJson(a) == scene::toJson(b);
}

Status writeAtomically(const QString& path, const QByteArray& bytes) {
    QSaveFile file(path); // written to a temporary name, renamed into place on commit
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit())
        return fail(ErrorCode::IoError, path.toStdString() + ": " + file.errorString().toStdString());
    return {};
}

} // namespace

/// One edit of the case: the whole case before and after (a case is a few kB), so undo gives back exactly the
/// case that was there, byte for byte when written.
class EditCommand : public QUndoCommand {
public:
    EditCommand(CaseDocument* doc, const QString& text, scene::CaseSpec before, scene::CaseSpec after, int key)
        : QUndoCommand(text), m_doc(doc), m_before(std::move(before)), m_after(std::move(after)), m_key(key) {}
    void redo() override { m_doc->setSpec(m_after); }
    void undo() override { m_doc->setSpec(m_before); }
    int id() const override { return m_key != 0 ? m_key : -1; }
    bool mergeWith(const QUndoCommand* other) override {
        if (other->id() != id())
            return false;
        m_after = static_cast<const EditCommand*>(other)->m_after;
        setObsolete(sameCase(m_before, m_after)); // a drag back to where it began leaves no command
        return true;
    }

private:
    CaseDocument* m_doc;
    scene::CaseSpec m_before, m_after;
    int m_key;
};

CaseDocument::CaseDocument(QObject* parent) : QObject(parent), m_spec(scene::defaultCase()) {}

QString CaseDocument::displayName() const {
    return m_path.isEmpty() ? tr("Untitled") : QFileInfo(m_path).fileName();
}

QString CaseDocument::windowTitle() const {
    return tr("%1[*] - Hysteroscene").arg(displayName());
}

void CaseDocument::edit(const QString& text, const std::function<void(scene::CaseSpec&)>& change, int mergeKey) {
    scene::CaseSpec after = m_spec;
    change(after);
    if (sameCase(after, m_spec))
        return;
    m_undo.push(new EditCommand(this, text, m_spec, std::move(after), mergeKey));
}

void CaseDocument::setSpec(const scene::CaseSpec& spec) {
    m_spec = spec;
    ++m_revision;
    emit changed();
}

void CaseDocument::reset(const scene::CaseSpec& spec, const QString& path) {
    m_undo.clear();
    m_spec = spec;
    ++m_revision;
    const bool moved = path != m_path;
    m_path = path;
    m_undo.setClean();
    if (moved)
        emit filePathChanged(m_path);
    emit changed();
}

void CaseDocument::newCase() {
    reset(scene::defaultCase(), QString());
}

Status CaseDocument::open(const QString& path) {
    auto spec = scene::loadCase(QDir::toNativeSeparators(path).toStdString());
    if (!spec)
        return spec.failure();
    reset(*spec, QFileInfo(path).absoluteFilePath());
    return {};
}

Status CaseDocument::save() {
    if (m_path.isEmpty())
        return fail(ErrorCode::InvalidInput, "the case has no file yet: save it as a new file");
    return saveAs(m_path);
}

Status CaseDocument::saveAs(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    HS_TRY(scene::saveCase(m_spec, absolute.toStdString()));
    const bool moved = absolute != m_path;
    m_path = absolute;
    m_undo.setClean();
    if (moved)
        emit filePathChanged(m_path);
    return {};
}

Status CaseDocument::writeRecovery(const QString& dir) const {
    if (!QDir().mkpath(dir))
        return fail(ErrorCode::IoError, dir.toStdString() + ": cannot create the recovery folder");
    const QDir d(dir);
    HS_TRY(writeAtomically(d.filePath(kRecoveryOrigin), m_path.toUtf8()));
    return writeAtomically(d.filePath(kRecoveryCase), QByteArray::fromStdString(scene::toJson(m_spec)));
}

void CaseDocument::discardRecovery(const QString& dir) {
    const QDir d(dir);
    QFile::remove(d.filePath(kRecoveryCase));
    QFile::remove(d.filePath(kRecoveryOrigin));
}

std::optional<Recovery> CaseDocument::findRecovery(const QString& dir) {
    const QDir d(dir);
    if (!QFileInfo::exists(d.filePath(kRecoveryCase)))
        return std::nullopt;
    Recovery r;
    r.casePath = d.filePath(kRecoveryCase);
    QFile origin(d.filePath(kRecoveryOrigin));
    if (origin.open(QIODevice::ReadOnly))
        r.origin = QString::fromUtf8(origin.readAll());
    return r;
}

Status CaseDocument::restore(const Recovery& recovery) {
    auto recovered = scene::loadCase(recovery.casePath.toStdString());
    if (!recovered)
        return recovered.failure();
    if (!recovery.origin.isEmpty() && QFileInfo::exists(recovery.origin)) {
        HS_TRY(open(recovery.origin));
    } else {
        newCase();
    }
    const scene::CaseSpec spec = *recovered;
    edit(tr("Recover unsaved changes"), [&](scene::CaseSpec& s) { s = spec; });
    return {};
}

QStringList recentFiles(const QSettings& settings, const QString& key) {
    QStringList files = settings.value(key).toStringList();
    files.removeDuplicates();
    while (files.size() > kMaxRecentFiles)
        files.removeLast();
    return files;
}

void addRecentFile(QSettings& settings, const QString& key, const QString& path) {
    QStringList files = recentFiles(settings, key);
    const QString absolute = QFileInfo(path).absoluteFilePath();
    files.removeAll(absolute);
    files.prepend(absolute);
    while (files.size() > kMaxRecentFiles)
        files.removeLast();
    settings.setValue(key, files);
}

void removeRecentFile(QSettings& settings, const QString& key, const QString& path) {
    QStringList files = recentFiles(settings, key);
    if (files.removeAll(QFileInfo(path).absoluteFilePath()) > 0)
        settings.setValue(key, files);
}

} // namespace hs::widgets
