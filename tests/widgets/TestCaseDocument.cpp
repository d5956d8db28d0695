// Qt Test for hs::widgets::CaseDocument: undo and redo of edits, merged drags, undo back to byte-identical
// case.json, the modified mark and title, Save refusing an invalid case, recovery after a crash, recent files.
#include "hs/widgets/document/CaseDocument.h"

#include <QFile>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using hs::widgets::CaseDocument;

namespace {

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestCaseDocument : public QObject {
    Q_OBJECT

private slots:
    void startsUntitledAndClean();
    void editsUndoAndRedo();
    void unchangedEditPushesNothing();
    void aDragIsOneCommand();
    void undoToTheStartGivesTheFileBackByteForByte();
    void saveRefusesAnInvalidCaseAndKeepsTheFile();
    void openFailureKeepsTheDocument();
    void recoveryRestoresUnsavedEdits();
    void recentFilesNewestFirstEachOnce();
};

void TestCaseDocument::startsUntitledAndClean() {
    CaseDocument doc;
    QVERIFY(doc.filePath().isEmpty());
    QVERIFY(!doc.isModified());
    QCOMPARE(doc.displayName(), QString("Untitled"));
    QCOMPARE(doc.windowTitle(), QString("Untitled[*] - Hysteroscene"));
    QCOMPARE(QString::fromStdString(hs::scene::toJson(doc.spec())),
             QString::fromStdString(hs::scene::toJson(hs::scene::defaultCase())));
    QVERIFY(!doc.save().ok()); // nowhere to save yet
}

void TestCaseDocument::editsUndoAndRedo() {
    CaseDocument doc;
    QSignalSpy changed(&doc, &CaseDocument::changed);
    doc.edit("Age", [](hs::scene::CaseSpec& s) { s.patient.ageYears = 52.0; });
    doc.edit("Seed", [](hs::scene::CaseSpec& s) { s.seed = 7; });
    QCOMPARE(doc.undoStack()->count(), 2);
    QVERIFY(doc.isModified());
    QCOMPARE(doc.spec().seed, std::uint64_t{7});
    doc.undoStack()->undo();
    QCOMPARE(doc.spec().seed, std::uint64_t{1});
    QCOMPARE(doc.spec().patient.ageYears, 52.0);
    doc.undoStack()->undo();
    QCOMPARE(doc.spec().patient.ageYears, 35.0);
    QVERIFY(!doc.isModified());
    doc.undoStack()->redo();
    QCOMPARE(doc.spec().patient.ageYears, 52.0);
    QCOMPARE(changed.count(), 5); // two edits, two undos, one redo
}

void TestCaseDocument::unchangedEditPushesNothing() {
    CaseDocument doc;
    doc.edit("Seed", [](hs::scene::CaseSpec& s) { s.seed = 1; }); // already 1
    QCOMPARE(doc.undoStack()->count(), 0);
    QVERIFY(!doc.isModified());
}

void TestCaseDocument::aDragIsOneCommand() {
    CaseDocument doc;
    constexpr int kAgeSlider = 101;
    for (double age = 36.0; age <= 60.0; age += 1.0) // one slider drag: 25 value changes
        doc.edit(
            "Age", [age](hs::scene::CaseSpec& s) { s.patient.ageYears = age; }, kAgeSlider);
    QCOMPARE(doc.undoStack()->count(), 1);
    QCOMPARE(doc.spec().patient.ageYears, 60.0);
    doc.edit("Seed", [](hs::scene::CaseSpec& s) { s.seed = 9; }); // another control ends the drag
    doc.edit(
        "Age", [](hs::scene::CaseSpec& s) { s.patient.ageYears = 61.0; }, kAgeSlider);
    QCOMPARE(doc.undoStack()->count(), 3);
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QCOMPARE(doc.spec().patient.ageYears, 35.0);
    // A drag that ends where it began leaves nothing to undo.
    doc.edit(
        "Age", [](hs::scene::CaseSpec& s) { s.patient.ageYears = 40.0; }, kAgeSlider);
    doc.edit(
        "Age", [](hs::scene::CaseSpec& s) { s.patient.ageYears = 35.0; }, kAgeSlider);
    QVERIFY(!doc.isModified());
}

void TestCaseDocument::undoToTheStartGivesTheFileBackByteForByte() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString original = dir.filePath("case.json");
    QVERIFY(QFile::copy(HS_DEFAULT_CASE_FILE, original));
    CaseDocument doc;
    QSignalSpy moved(&doc, &CaseDocument::filePathChanged);
    QVERIFY(doc.open(original).ok());
    QCOMPARE(moved.count(), 1);
    QCOMPARE(doc.windowTitle(), QString("case.json[*] - Hysteroscene"));
    doc.edit("Age", [](hs::scene::CaseSpec& s) { s.patient.ageYears = 44.0; });
    doc.edit("Myoma size", [](hs::scene::CaseSpec& s) { s.pathologies.at(0).sizeMm = 31.0; });
    doc.edit("Remove polyp", [](hs::scene::CaseSpec& s) { s.pathologies.pop_back(); });
    QVERIFY(doc.saveAs(dir.filePath("edited.json")).ok());
    QVERIFY(!doc.isModified());
    QVERIFY(readAll(dir.filePath("edited.json")) != readAll(original));
    while (doc.undoStack()->canUndo())
        doc.undoStack()->undo();
    QVERIFY(doc.isModified()); // away from the state last saved
    QVERIFY(doc.saveAs(dir.filePath("undone.json")).ok());
    QCOMPARE(readAll(dir.filePath("undone.json")), readAll(original));
}

void TestCaseDocument::saveRefusesAnInvalidCaseAndKeepsTheFile() {
    QTemporaryDir dir;
    const QString path = dir.filePath("case.json");
    CaseDocument doc;
    QVERIFY(doc.saveAs(path).ok());
    const QByteArray before = readAll(path);
    doc.edit("Age", [](hs::scene::CaseSpec& s) { s.patient.ageYears = 300.0; });
    const hs::Status saved = doc.save();
    QVERIFY(!saved.ok());
    QVERIFY2(QString::fromStdString(saved.error().message()).contains("ageYears"),
             saved.error().message().c_str()); // names the field
    QCOMPARE(readAll(path), before);
    QVERIFY(doc.isModified());
}

void TestCaseDocument::openFailureKeepsTheDocument() {
    QTemporaryDir dir;
    const QString broken = dir.filePath("broken.json");
    QFile f(broken);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("{ \"format\": \"hysteroscene-case\", ");
    f.close();
    CaseDocument doc;
    doc.edit("Seed", [](hs::scene::CaseSpec& s) { s.seed = 5; });
    const hs::Status opened = doc.open(broken);
    QVERIFY(!opened.ok());
    QVERIFY(QString::fromStdString(opened.error().message()).contains("broken.json"));
    QCOMPARE(doc.spec().seed, std::uint64_t{5});
    QCOMPARE(doc.undoStack()->count(), 1);
}

void TestCaseDocument::recoveryRestoresUnsavedEdits() {
    QTemporaryDir dir;
    const QString file = dir.filePath("case.json");
    const QString recovery = dir.filePath("recovery");
    {
        CaseDocument doc;
        QVERIFY(doc.saveAs(file).ok());
        doc.edit("Age", [](hs::scene::CaseSpec& s) { s.patient.ageYears = 47.0; });
        QVERIFY(doc.writeRecovery(recovery).ok());
        // ... and the session ends without saving or discarding (a crash).
    }
    const auto found = CaseDocument::findRecovery(recovery);
    QVERIFY(found.has_value());
    QCOMPARE(found->origin, QFileInfo(file).absoluteFilePath());
    CaseDocument doc;
    QVERIFY(doc.restore(*found).ok());
    QCOMPARE(doc.filePath(), QFileInfo(file).absoluteFilePath());
    QCOMPARE(doc.spec().patient.ageYears, 47.0);
    QVERIFY(doc.isModified()); // the recovered edit is unsaved, and undoable
    doc.undoStack()->undo();
    QCOMPARE(doc.spec().patient.ageYears, 35.0);
    CaseDocument::discardRecovery(recovery);
    QVERIFY(!CaseDocument::findRecovery(recovery).has_value());
}

void TestCaseDocument::recentFilesNewestFirstEachOnce() {
    QTemporaryDir dir;
    QSettings settings(dir.filePath("settings.ini"), QSettings::IniFormat);
    for (int i = 0; i < 10; ++i)
        hs::widgets::addRecentFile(settings, hs::widgets::kRecentCasesKey,
                                   dir.filePath(QString("case-%1.json").arg(i)));
    hs::widgets::addRecentFile(settings, hs::widgets::kRecentCasesKey, dir.filePath("case-5.json"));
    const QStringList recent = hs::widgets::recentFiles(settings, hs::widgets::kRecentCasesKey);
    QCOMPARE(recent.size(), hs::widgets::kMaxRecentFiles);
    QVERIFY(recent.front().endsWith("case-5.json"));
    QVERIFY(recent.at(1).endsWith("case-9.json"));
    QCOMPARE(recent.filter("case-5.json").size(), 1);
    hs::widgets::removeRecentFile(settings, hs::widgets::kRecentCasesKey, dir.filePath("case-9.json"));
    QCOMPARE(hs::widgets::recentFiles(settings, hs::widgets::kRecentCasesKey).filter("case-9.json").size(), 0);
}

QTEST_GUILESS_MAIN(TestCaseDocument)
#include "TestCaseDocument.moc"
