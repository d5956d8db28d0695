// Qt Test for the Patient panel: accepted values become undoable edits (a run of steps is one), values outside
// their range or against another field are refused inline with the document unchanged, and the organ's dimensions
// are shown beside the patient's expected range once the organ is rebuilt.
#include "PanelTestSupport.h"
#include "hs/anatomy/Cohort.h"
#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/jobs/GenerationSession.h"
#include "hs/widgets/panels/PatientPanel.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>

#include <cmath>

using hs::widgets::CaseDocument;
using hs::widgets::GenerationSession;
using hs::widgets::PatientPanel;

class TestPatientPanel : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();
    void showsTheCase();
    void anAcceptedValueIsOneUndoableEdit();
    void refusesAnAgeOutOfRangeAndSaysWhy();
    void refusesAContradictionBetweenFields();
    void aMeasuredDimensionIsSetAndCleared();
    void showsTheOrgansDimensionsBesideTheExpectedRange();
    void flagsADimensionOutsideThePatientsRangeInPlace();

private:
    template <class T>
    T* find(const QString& name) const {
        return hs::test::child<T>(m_panel.get(), name);
    }

    std::unique_ptr<hs::test::PanelHarness> m_harness;
    CaseDocument* m_document = nullptr;
    GenerationSession* m_session = nullptr;
    std::unique_ptr<PatientPanel> m_panel;
};

void TestPatientPanel::init() {
    m_harness = std::make_unique<hs::test::PanelHarness>();
    m_document = &m_harness->document;
    m_session = &m_harness->session;
    m_panel = std::make_unique<PatientPanel>(*m_document, *m_session);
    m_panel->show();
}

void TestPatientPanel::cleanup() {
    m_panel.reset();
    m_harness.reset();
}

void TestPatientPanel::showsTheCase() {
    QCOMPARE(find<QDoubleSpinBox>("ageSpin")->value(), 35.0);
    QCOMPARE(find<QSpinBox>("paritySpin")->value(), 1);
    QCOMPARE(find<QLineEdit>("seedEdit")->text(), QString("1"));
    QVERIFY(!find<QCheckBox>("menopausalCheck")->isChecked());
    QVERIFY(!find<QLabel>("lengthExpectedLabel")->text().isEmpty());
}

void TestPatientPanel::anAcceptedValueIsOneUndoableEdit() {
    auto* age = find<QDoubleSpinBox>("ageSpin");
    age->setFocus();
    for (int i = 0; i < 5; ++i) // five steps of the spin box: one command
        age->stepUp();
    QCOMPARE(m_document->spec().patient.ageYears, 40.0);
    QCOMPARE(m_document->undoStack()->count(), 1);
    m_document->undoStack()->undo();
    QCOMPARE(m_document->spec().patient.ageYears, 35.0);
    QCOMPARE(age->value(), 35.0); // the field follows the document
}

void TestPatientPanel::refusesAnAgeOutOfRangeAndSaysWhy() {
    auto* age = find<QDoubleSpinBox>("ageSpin");
    age->setValue(130.0);
    QCOMPARE(m_document->spec().patient.ageYears, 35.0);
    QCOMPARE(m_document->undoStack()->count(), 0);
    auto* message = find<QLabel>("patientMessageLabel");
    QVERIFY(message->isVisibleTo(m_panel.get()));
    QVERIFY2(message->text().contains("Age") && message->text().contains("18") && message->text().contains("80"),
             qPrintable(message->text()));
    QVERIFY(age->property("invalid").toBool());
    age->setValue(50.0); // a good value clears the message
    QCOMPARE(m_document->spec().patient.ageYears, 50.0);
    QVERIFY(!message->isVisibleTo(m_panel.get()));
}

void TestPatientPanel::refusesAContradictionBetweenFields() {
    find<QSpinBox>("paritySpin")->setValue(3); // gravidity 1 < parity 3
    QCOMPARE(m_document->spec().patient.parity, 1);
    QVERIFY(find<QLabel>("patientMessageLabel")->text().contains("parity"));
    find<QCheckBox>("menopausalCheck")->setChecked(true); // a 35-year-old is premenopausal here
    QVERIFY(!m_document->spec().patient.menopausal);
    QVERIFY(!find<QCheckBox>("menopausalCheck")->isChecked());
    // An age beyond 60 makes the patient postmenopausal (no cycle); 45 lets either state be chosen.
    find<QDoubleSpinBox>("ageSpin")->setValue(62.0);
    QVERIFY(m_document->spec().patient.menopausal);
    QVERIFY(!m_document->spec().patient.cyclePhase.has_value());
    QVERIFY(find<QCheckBox>("menopausalCheck")->isChecked());
    find<QDoubleSpinBox>("ageSpin")->setValue(45.0);
    find<QCheckBox>("menopausalCheck")->setChecked(false);
    QVERIFY(!m_document->spec().patient.menopausal);
    QVERIFY(m_document->spec().patient.cyclePhase.has_value());
}

void TestPatientPanel::aMeasuredDimensionIsSetAndCleared() {
    auto* check = find<QCheckBox>("cavityLengthCheck");
    auto* spin = find<QDoubleSpinBox>("cavityLengthSpin");
    QVERIFY(!spin->isEnabled());
    check->setChecked(true); // starts from the value expected for the patient
    QVERIFY(m_document->spec().anatomy.dimensions.cavityLengthMm.has_value());
    QVERIFY(std::abs(*m_document->spec().anatomy.dimensions.cavityLengthMm -
                     hs::anatomy::expectedDimensions(m_document->spec().patient).cavityLengthMm.mean) < 0.05);
    spin->setValue(36.0);
    QCOMPARE(*m_document->spec().anatomy.dimensions.cavityLengthMm, 36.0);
    spin->setValue(80.0); // beyond 20 - 55 mm
    QCOMPARE(*m_document->spec().anatomy.dimensions.cavityLengthMm, 36.0);
    QVERIFY(find<QLabel>("patientMessageLabel")->text().contains("55"));
    check->setChecked(false);
    QVERIFY(!m_document->spec().anatomy.dimensions.cavityLengthMm.has_value());
}

void TestPatientPanel::showsTheOrgansDimensionsBesideTheExpectedRange() {
    auto* organ = find<QLabel>("cavityLengthOrganLabel");
    QCOMPARE(organ->text(), QStringLiteral("–"));
    QSignalSpy changed(m_session, &GenerationSession::resultsChanged);
    m_session->runThrough(hs::generate::Stage::Organ);
    QVERIFY(changed.wait(30000));
    QVERIFY2(organ->text().contains(" mm"), qPrintable(organ->text()));
    QVERIFY(organ->isEnabled());
    find<QDoubleSpinBox>("ageSpin")->setValue(45.0);
    QVERIFY(!organ->isEnabled()); // grey: the organ is of the case before the edit
}

// An organ fitted to a measured cavity length beyond the patient's expected 95 % range shows it, flagged where it
// stands (red, a sign and the word), not only in a tooltip.
void TestPatientPanel::flagsADimensionOutsideThePatientsRangeInPlace() {
    auto* organ = find<QLabel>("cavityLengthOrganLabel");
    const auto expected = hs::anatomy::expectedDimensions(m_document->spec().patient).cavityLengthMm;
    const double measured = std::ceil(expected.high()) + 6.0; // mm, whole (the field has one decimal); within 20 - 55
    QVERIFY(measured <= 55.0);
    find<QCheckBox>("cavityLengthCheck")->setChecked(true);
    find<QDoubleSpinBox>("cavityLengthSpin")->setValue(measured);
    QCOMPARE(*m_document->spec().anatomy.dimensions.cavityLengthMm, measured);
    QSignalSpy changed(m_session, &GenerationSession::resultsChanged);
    m_session->runThrough(hs::generate::Stage::Organ);
    QVERIFY(changed.wait(30000));
    QVERIFY2(organ->property("outside").toBool(), qPrintable(organ->text()));
    QVERIFY2(organ->text().contains(QStringLiteral("⚠")) && organ->text().contains("outside"),
             qPrintable(organ->text()));
    // Back to the organ the patient's relations give: within its range, nothing flagged.
    find<QCheckBox>("cavityLengthCheck")->setChecked(false);
    m_session->runThrough(hs::generate::Stage::Organ);
    QVERIFY(changed.wait(30000));
    const bool inside = !organ->property("outside").toBool();
    QVERIFY2(inside && !organ->text().contains(QStringLiteral("⚠")), qPrintable(organ->text()));
}

QTEST_MAIN(TestPatientPanel)
#include "TestPatientPanel.moc"
