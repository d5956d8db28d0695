// Qt Test for the Export panel: Export without a folder says so; with one, every stage runs, the package is written
// and verified (and zipped), the result names its files and the scope's passage, and "Open in Simulator" starts
// the simulator on it; variants go to variant-NNN.
#include "hs/scene/ScenePackage.h"
#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/jobs/GenerationSession.h"
#include "hs/widgets/panels/ExportPanel.h"
#include "hs/widgets/panels/SceneWarnings.h"

#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSet>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>

using hs::widgets::CaseDocument;
using hs::widgets::ExportPanel;
using hs::widgets::GenerationSession;

namespace {

void makeLight(CaseDocument& document) {
    document.edit("light", [](hs::scene::CaseSpec& s) {
        s.meshing.targetVertices = 4000;
        s.texture.sizePx = 256;
    });
}

} // namespace

class TestExportPanel : public QObject {
    Q_OBJECT

private slots:
    void asksForAFolderFirst();
    void writesAndValidatesThePackage();
    void writesOneFolderPerVariant();
    void eachWarningSaysWhatItMeans();
};

void TestExportPanel::asksForAFolderFirst() {
    CaseDocument document;
    GenerationSession session(document);
    session.setAutoUpdate(false);
    ExportPanel panel(document, session);
    panel.findChild<QPushButton*>("exportButton")->click();
    QVERIFY(!session.runner().isRunning());
    QVERIFY(panel.findChild<QLabel*>("exportResultLabel")->text().contains("folder"));
    QVERIFY(!panel.findChild<QPushButton*>("openInSimulatorButton")->isEnabled());
}

void TestExportPanel::writesAndValidatesThePackage() {
    QTemporaryDir dir;
    CaseDocument document;
    makeLight(document);
    GenerationSession session(document);
    session.setAutoUpdate(false);
    ExportPanel panel(document, session);
    const QString folder = dir.filePath("scene");
    panel.setFolder(folder);
    panel.findChild<QCheckBox*>("exportZipCheck")->setChecked(true);
    QVERIFY(!panel.findChild<QCheckBox*>("exportFormatsCheck")->isChecked()); // other tools' formats on request
    panel.findChild<QCheckBox*>("exportFormatsCheck")->setChecked(true);
    QSignalSpy exported(&session, &GenerationSession::exported);
    panel.findChild<QPushButton*>("exportButton")->click();
    QVERIFY(exported.wait(180000));
    QVERIFY(hs::scene::verifyScenePackage(QFile::encodeName(folder).toStdString()).ok());
    QVERIFY(QFile::exists(folder + ".zip"));
    for (const char* file : {"surface.glb", "mesh.msh", "surface.obj", "scene.scn"})
        QVERIFY2(QFile::exists(folder + "/" + file), file);
    const QString text = panel.findChild<QLabel*>("exportResultLabel")->text();
    QVERIFY2(text.contains("valid") && text.contains("scope"), qPrintable(text));
    // Every warning of the scene is listed, with what it means, not only counted.
    const auto result = exported.at(0).at(0).value<hs::widgets::ExportResult>();
    QCOMPARE(result.packages.size(), std::size_t{1});
    QVERIFY(result.packages[0].scope.checked);
    for (const std::string& w : result.packages[0].warnings) {
        QVERIFY2(text.contains(QString::fromStdString(w).toHtmlEscaped()), w.c_str());
        QVERIFY2(text.contains(hs::widgets::warningMeaning(w).toHtmlEscaped()), w.c_str());
    }
    QCOMPARE(panel.lastPackage(), folder);
    QVERIFY(session.isCurrent(hs::generate::Stage::Scene));

    // "Open in Simulator" starts the simulator (here a stand-in script that notes its arguments) on the package.
    auto* simulatorButton = panel.findChild<QPushButton*>("openInSimulatorButton");
    QVERIFY(!simulatorButton->isEnabled());
    const QString simulator = dir.filePath("hysteroscene-sim");
    const QString arguments = dir.filePath("simulator-arguments.txt");
    QFile script(simulator);
    QVERIFY(script.open(QIODevice::WriteOnly));
    script.write(QStringLiteral("#!/bin/sh\necho \"$@\" > '%1.tmp' && mv '%1.tmp' '%1'\n").arg(arguments).toUtf8());
    script.close();
    QVERIFY(script.setPermissions(script.permissions() | QFileDevice::ExeOwner));
    panel.setSimulatorPath(simulator);
    QVERIFY(simulatorButton->isEnabled());
    simulatorButton->click();
    QTRY_VERIFY(QFile::exists(arguments));
    QFile written(arguments);
    QVERIFY(written.open(QIODevice::ReadOnly));
    QCOMPARE(QString::fromUtf8(written.readAll()).trimmed(), folder);
}

void TestExportPanel::writesOneFolderPerVariant() {
    QTemporaryDir dir;
    CaseDocument document;
    makeLight(document);
    document.edit("no pathologies", [](hs::scene::CaseSpec& s) { s.pathologies.clear(); });
    GenerationSession session(document);
    session.setAutoUpdate(false);
    ExportPanel panel(document, session);
    panel.setFolder(dir.filePath("variants"));
    panel.findChild<QSpinBox*>("exportVariantsSpin")->setValue(2);
    QSignalSpy exported(&session, &GenerationSession::exported);
    panel.findChild<QPushButton*>("exportButton")->click();
    QVERIFY(exported.wait(240000));
    for (const char* name : {"variant-000", "variant-001"})
        QVERIFY2(hs::scene::verifyScenePackage(
                     QFile::encodeName(QDir(dir.filePath("variants")).filePath(name)).toStdString())
                     .ok(),
                 name);
    // Without the other tools' formats asked for, the package holds what the simulator and the workstation read.
    QVERIFY(!QFile::exists(QDir(dir.filePath("variants")).filePath("variant-000/surface.glb")));
}

// A warning's meaning follows the stage that wrote it (the text before ": "); each stage has its own, and a warning
// of no known stage points at the documentation instead of saying nothing.
void TestExportPanel::eachWarningSaysWhatItMeans() {
    using hs::widgets::warningMeaning;
    const std::vector<std::string> warnings{
        "pathology: polyp-1: at its nominal seat it would cover or hide the right tubal ostium",
        "merge: polyp-1: 3 % of its volume dropped",
        "meshing: 2 pinches opened",
        "descriptors: myoma-1: asked FIGO 1, the final body measures FIGO 2",
        "measurement: 213 of 1441 template vertices found no body surface",
        "seating: polyp-1: 45 % of its surface lies against tissue (sessile polyps: at most 40 %)",
        "hydrometra: from the organ before its pathologies (67.6 mL)",
        "simulation: 3 of 9000 visual surface points are bound up to 1.20 mm off their simulation tet",
        "texture: the exemplar could not be read; the bundled one is used",
        "mesh-hausdorff: 2.11 % of the diagonal (bar: at most 1 %)"};
    QSet<QString> meanings;
    for (const std::string& w : warnings) {
        const QString meaning = warningMeaning(w);
        QVERIFY2(!meaning.contains("docs/scene-format.md"), w.c_str());
        meanings.insert(meaning);
    }
    QCOMPARE(meanings.size(), int(warnings.size()));
    QCOMPARE(warningMeaning("mesh-min-dihedral: 8.1 deg"), warningMeaning("mesh-slivers: 3"));
    QVERIFY(warningMeaning("something new").contains("docs/scene-format.md"));
    const QString html = hs::widgets::warningsHtml({"seating: <b>polyp</b>"});
    QVERIFY2(html.contains("&lt;b&gt;polyp") && html.contains("<li>"), qPrintable(html));
    QVERIFY(hs::widgets::warningsHtml({}).isEmpty());
}

QTEST_MAIN(TestExportPanel)
#include "TestExportPanel.moc"
