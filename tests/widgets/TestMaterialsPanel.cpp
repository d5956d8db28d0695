// Qt Test for the Materials panel: the literature defaults shown, an override stored in the case, a value beyond the
// tissue's range refused, Default clearing the overrides.
#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/panels/MaterialsPanel.h"

#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QTest>

using hs::widgets::CaseDocument;
using hs::widgets::MaterialsPanel;

class TestMaterialsPanel : public QObject {
    Q_OBJECT

private slots:
    void showsTheDefaults();
    void storesAnOverrideAndRefusesOneOutOfRange();
    void defaultClearsTheOverrides();
};

void TestMaterialsPanel::showsTheDefaults() {
    CaseDocument document;
    MaterialsPanel panel(document);
    const auto myoma = static_cast<int>(hs::clinical::Tissue::Myoma);
    QCOMPARE(panel.field(myoma, MaterialsPanel::kYoungsColumn)->value(), 65.0);
    QCOMPARE(panel.field(0, MaterialsPanel::kPoissonColumn)->value(), 0.47);
    QCOMPARE(panel.findChild<QDoubleSpinBox*>("hydrometraSpin")->value(), 8.0);
}

void TestMaterialsPanel::storesAnOverrideAndRefusesOneOutOfRange() {
    CaseDocument document;
    MaterialsPanel panel(document);
    const auto myoma = static_cast<std::size_t>(hs::clinical::Tissue::Myoma);
    QDoubleSpinBox* youngs = panel.field(int(myoma), MaterialsPanel::kYoungsColumn);
    youngs->setValue(100.0);
    QCOMPARE(*document.spec().scene.materials[myoma].youngsModulusKpa, 100.0);
    youngs->setValue(500.0); // the myoma's range is 13 - 206 kPa
    QCOMPARE(*document.spec().scene.materials[myoma].youngsModulusKpa, 100.0);
    const QString message = panel.findChild<QLabel*>("materialsMessageLabel")->text();
    QVERIFY2(message.contains("206"), qPrintable(message));
    panel.findChild<QDoubleSpinBox*>("hydrometraSpin")->setValue(40.0);
    QCOMPARE(document.spec().scene.hydrometraPressureKpa, 8.0);
}

void TestMaterialsPanel::defaultClearsTheOverrides() {
    CaseDocument document;
    MaterialsPanel panel(document);
    const auto polyp = static_cast<std::size_t>(hs::clinical::Tissue::Polyp);
    panel.field(int(polyp), MaterialsPanel::kDensityColumn)->setValue(1060.0);
    QVERIFY(document.spec().scene.materials[polyp].densityKgPerM3.has_value());
    panel.findChild<QPushButton*>("polypResetButton")->click();
    QVERIFY(!document.spec().scene.materials[polyp].densityKgPerM3.has_value());
    QCOMPARE(panel.field(int(polyp), MaterialsPanel::kDensityColumn)->value(), 1050.0);
}

QTEST_MAIN(TestMaterialsPanel)
#include "TestMaterialsPanel.moc"
