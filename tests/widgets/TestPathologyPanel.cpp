// Qt Test for the Pathologies panel: add, duplicate and remove; edits of the selected pathology refused when out of
// range; placement by a click on the organ's wall (and nothing placed by a click that misses or lands on the
// cervix); Grow shows what the pathology stage measured.
#include "PanelTestSupport.h"
#include "hs/clinical/Tissue.h"
#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/jobs/GenerationSession.h"
#include "hs/widgets/panels/PathologyPanel.h"

#include <QColor>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QToolButton>

#include <variant>

using hs::widgets::CaseDocument;
using hs::widgets::GenerationSession;
using hs::widgets::PathologyPanel;

namespace {

/// The centre of the first face of `organ` with surface tissue `tissue`.
QVector3D centreOfFirst(const hs::SurfaceMesh& organ, hs::clinical::SurfaceTissue tissue) {
    const auto& labels = organ.faceLabels.at(hs::clinical::kSurfaceTissueLabel);
    for (std::size_t f = 0; f < labels.size(); ++f)
        if (labels[f] == hs::clinical::labelValue(tissue)) {
            const hs::Triangle& t = organ.triangles[f];
            const hs::Vec3 c =
                (organ.points[static_cast<std::size_t>(t[0])] + organ.points[static_cast<std::size_t>(t[1])] +
                 organ.points[static_cast<std::size_t>(t[2])]) /
                3.0;
            return QVector3D(float(c.x), float(c.y), float(c.z));
        }
    return {};
}

} // namespace

class TestPathologyPanel : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();
    void listsTheCasesPathologies();
    void addsDuplicatesAndRemoves();
    void refusesASizeOutOfRange();
    void switchingTheKindKeepsTheCaseValid();
    void differentEditsAreDifferentUndoSteps();
    void placesByAClickOnTheWall();
    void growShowsTheMeasuredDescriptors();
    void flagsAMeasuredFigoTypeOtherThanTheRequestedOne();

private:
    template <class T>
    T* find(const QString& name) const {
        return hs::test::child<T>(m_panel.get(), name);
    }
    void buildOrgan();

    std::unique_ptr<hs::test::PanelHarness> m_harness;
    CaseDocument* m_document = nullptr;
    GenerationSession* m_session = nullptr;
    std::unique_ptr<PathologyPanel> m_panel;
};

void TestPathologyPanel::init() {
    m_harness = std::make_unique<hs::test::PanelHarness>();
    m_document = &m_harness->document;
    m_session = &m_harness->session;
    m_panel = std::make_unique<PathologyPanel>(*m_document, *m_session);
    m_panel->show();
}

void TestPathologyPanel::cleanup() {
    m_panel.reset();
    m_harness.reset();
}

void TestPathologyPanel::buildOrgan() {
    QSignalSpy changed(m_session, &GenerationSession::resultsChanged);
    m_session->runThrough(hs::generate::Stage::Organ);
    QVERIFY(changed.wait(30000));
}

void TestPathologyPanel::listsTheCasesPathologies() {
    auto* list = find<QListWidget>("pathologyList");
    QCOMPARE(list->count(), int(m_document->spec().pathologies.size()));
    QCOMPARE(m_panel->currentIndex(), 0);
    QVERIFY(list->item(0)->text().contains("FIGO 2"));
}

void TestPathologyPanel::addsDuplicatesAndRemoves() {
    const auto before = m_document->spec().pathologies.size();
    find<QPushButton>("addMyomaButton")->click();
    QCOMPARE(m_document->spec().pathologies.size(), before + 1);
    const auto& added = m_document->spec().pathologies.back();
    QVERIFY(added.kind == hs::clinical::PathologyKind::Myoma);
    QVERIFY(hs::scene::checkCase(m_document->spec()).empty());
    QCOMPARE(m_panel->currentIndex(), int(before));
    find<QPushButton>("duplicateButton")->click();
    QCOMPARE(m_document->spec().pathologies.size(), before + 2);
    QVERIFY(m_document->spec().pathologies[before].id != m_document->spec().pathologies[before + 1].id);
    find<QPushButton>("removeButton")->click();
    find<QPushButton>("removeButton")->click();
    QCOMPARE(m_document->spec().pathologies.size(), before);
    m_document->undoStack()->undo();
    QCOMPARE(m_document->spec().pathologies.size(), before + 1);
}

void TestPathologyPanel::refusesASizeOutOfRange() {
    m_panel->setCurrentIndex(0); // the default myoma, 20 mm
    auto* size = find<QDoubleSpinBox>("sizeSpin");
    size->setValue(150.0);
    QCOMPARE(m_document->spec().pathologies[0].sizeMm, 20.0);
    QVERIFY(find<QLabel>("pathologyMessageLabel")->text().contains("100"));
    size->setValue(25.0);
    QCOMPARE(m_document->spec().pathologies[0].sizeMm, 25.0);
}

void TestPathologyPanel::switchingTheKindKeepsTheCaseValid() {
    m_panel->setCurrentIndex(0);
    auto* kind = find<QComboBox>("kindCombo");
    kind->setCurrentIndex(kind->findData(static_cast<int>(hs::clinical::PathologyKind::Polyp)));
    const auto& p = m_document->spec().pathologies[0];
    QVERIFY(p.kind == hs::clinical::PathologyKind::Polyp);
    QVERIFY(!p.figo.has_value());
    QVERIFY(p.attachment.has_value());
    QVERIFY(hs::scene::checkCase(m_document->spec()).empty());
    QVERIFY(!find<QComboBox>("figoCombo")->isEnabled());
}

void TestPathologyPanel::differentEditsAreDifferentUndoSteps() {
    m_panel->setCurrentIndex(0);
    auto* model = find<QComboBox>("modelCombo");
    model->setCurrentIndex(model->findData(static_cast<int>(hs::clinical::GrowthModel::Particles)));
    auto* figo = find<QComboBox>("figoCombo");
    figo->setCurrentIndex(3);
    auto* size = find<QDoubleSpinBox>("sizeSpin");
    size->stepUp();
    size->stepUp(); // steps of the size merge into one
    QCOMPARE(m_document->undoStack()->count(), 3);
    m_document->undoStack()->undo();
    QCOMPARE(m_document->spec().pathologies[0].sizeMm, 20.0);
    QVERIFY(m_document->spec().pathologies[0].figo->type == 3);
}

void TestPathologyPanel::placesByAClickOnTheWall() {
    buildOrgan();
    const hs::SurfaceMesh& organ = m_session->results()->organ->mesh;
    m_panel->setCurrentIndex(0);
    QSignalSpy placing(m_panel.get(), &PathologyPanel::placingChanged);
    find<QToolButton>("placeButton")->click();
    QVERIFY(m_panel->isPlacing());
    QCOMPARE(placing.count(), 1);

    m_panel->placeAt(false, {}); // a click beside the organ
    QVERIFY(m_panel->isPlacing());
    QVERIFY(find<QLabel>("pathologyMessageLabel")->text().contains("missed"));
    m_panel->placeAt(true, centreOfFirst(organ, hs::clinical::SurfaceTissue::CervicalCanal));
    QVERIFY(find<QLabel>("pathologyMessageLabel")->text().contains("cervix"));
    QVERIFY(std::holds_alternative<hs::clinical::ClinicalPlacement>(m_document->spec().pathologies[0].placement));

    const QVector3D wall = centreOfFirst(organ, hs::clinical::SurfaceTissue::Serosa);
    m_panel->placeAt(true, wall);
    QVERIFY(!m_panel->isPlacing());
    const auto* seat = std::get_if<hs::clinical::SurfacePlacement>(&m_document->spec().pathologies[0].placement);
    QVERIFY(seat);
    QCOMPARE(float(seat->pointMm.x), wall.x());
    QVERIFY(find<QLabel>("pointLabel")->text().endsWith("mm"));
}

void TestPathologyPanel::growShowsTheMeasuredDescriptors() {
    m_panel->setCurrentIndex(0);
    QSignalSpy changed(m_session, &GenerationSession::resultsChanged);
    find<QPushButton>("growButton")->click();
    QVERIFY(changed.wait(60000));
    QVERIFY(m_session->isCurrent(hs::generate::Stage::Pathology));
    const QString text = find<QLabel>("pathologyResultLabel")->text();
    QVERIFY2(text.contains("FIGO") && text.contains("Lasmar"), qPrintable(text));
}

// An 8 mm FIGO 7 (stalked subserosal) myoma on the posterior wall grows into a 14.6 mm FIGO 6: the list marks it in
// red with the measured type, the measurements say it, and the stage's notes stand in the panel, not in a tooltip.
void TestPathologyPanel::flagsAMeasuredFigoTypeOtherThanTheRequestedOne() {
    m_document->edit("FIGO 7", [](hs::scene::CaseSpec& s) {
        auto& myoma = s.pathologies[0];
        myoma.figo = hs::clinical::FigoType{7, -1};
        myoma.sizeMm = 8.0;
        myoma.placement = hs::clinical::ClinicalPlacement{hs::clinical::UterineLocation::Posterior};
    });
    m_panel->setCurrentIndex(0);
    auto* list = find<QListWidget>("pathologyList");
    QVERIFY(!list->item(0)->data(Qt::UserRole).toBool()); // nothing measured yet
    QSignalSpy changed(m_session, &GenerationSession::resultsChanged);
    find<QPushButton>("growButton")->click();
    QVERIFY(changed.wait(60000));
    QVERIFY(list->item(0)->data(Qt::UserRole).toBool());
    QVERIFY2(list->item(0)->text().contains("measured FIGO 6"), qPrintable(list->item(0)->text()));
    QCOMPARE(list->item(0)->foreground().color(), QColor(0xc0, 0x39, 0x2b));
    QVERIFY(!list->item(1)->data(Qt::UserRole).toBool()); // the polyp has no FIGO type
    const QString text = find<QLabel>("pathologyResultLabel")->text();
    QVERIFY2(text.contains("Requested FIGO 7, measured FIGO 6"), qPrintable(text));
    const QString notes = find<QLabel>("pathologyWarningsLabel")->text();
    QVERIFY2(notes.contains("requested FIGO 7, measured 6"), qPrintable(notes));
    QVERIFY(find<QLabel>("pathologyWarningsLabel")->toolTip().isEmpty());
    // Asking for what grew clears the mark.
    m_document->edit("FIGO 6", [](hs::scene::CaseSpec& s) { s.pathologies[0].figo = hs::clinical::FigoType{6, -1}; });
    QVERIFY(!list->item(0)->data(Qt::UserRole).toBool());
}

QTEST_MAIN(TestPathologyPanel)
#include "TestPathologyPanel.moc"
