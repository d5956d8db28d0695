// Qt Test for the Export panel: Export without a folder says so; with one, every stage runs, the package is written
// and verified (and zipped), the result names its files and the scope's passage, and "Open in Simulator" starts
// the simulator on it; variants go to variant-NNN.
#include "hs/scene/ScenePackage.h"
#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/jobs/GenerationSession.h"
#include "hs/widgets/panels/ExportPanel.h"

#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
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

QTEST_MAIN(TestExportPanel)
#include "TestExportPanel.moc"
