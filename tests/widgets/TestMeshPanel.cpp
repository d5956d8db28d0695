// Qt Test for the Mesh panel: parameters refused out of range, Mesh runs in the background, then the quality
// inspector: both histograms filled from the quality report, the worst tets listed and framed, tets coloured by a
// measure, a region hidden.
#include "PanelTestSupport.h"
#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/jobs/GenerationSession.h"
#include "hs/widgets/panels/MaterialsPanel.h"
#include "hs/widgets/panels/MeshPanel.h"
#include "hs/widgets/view/MeshDisplay.h"
#include "hs/widgets/view/ResultsDisplay.h"
#include "hs/widgets/view/VtkView.h"

#include <QBarSeries>
#include <QBarSet>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>

#include <vtkCamera.h>
#include <vtkRenderer.h>

using hs::widgets::CaseDocument;
using hs::widgets::GenerationSession;
using hs::widgets::MeshPanel;

class TestMeshPanel : public QObject {
    Q_OBJECT

private slots:
    void init();
    void cleanup();
    void refusesTooFewVertices();
    void meshesAndInspectsTheResult();

private:
    template <class T>
    T* find(const QString& name) const {
        return hs::test::child<T>(m_panel.get(), name);
    }

    std::unique_ptr<hs::test::PanelHarness> m_harness;
    CaseDocument* m_document = nullptr;
    GenerationSession* m_session = nullptr;
    std::unique_ptr<hs::widgets::VtkView> m_view;
    std::unique_ptr<hs::widgets::MeshDisplay> m_display;
    std::unique_ptr<MeshPanel> m_panel;
};

void TestMeshPanel::init() {
    m_harness = std::make_unique<hs::test::PanelHarness>();
    m_document = &m_harness->document;
    m_session = &m_harness->session;
    m_view = std::make_unique<hs::widgets::VtkView>();
    m_view->resize(400, 300);
    m_view->show();
    m_display = std::make_unique<hs::widgets::MeshDisplay>(m_view->renderer());
    m_panel = std::make_unique<MeshPanel>(*m_document, *m_session);
    m_panel->setDisplay(m_display.get(), m_view.get());
    m_panel->show();
}

void TestMeshPanel::cleanup() {
    m_panel.reset();
    m_display.reset();
    m_view.reset();
    m_harness.reset();
}

void TestMeshPanel::refusesTooFewVertices() {
    auto* vertices = find<QSpinBox>("verticesSpin");
    QCOMPARE(vertices->value(), 30000);
    vertices->setValue(100);
    QCOMPARE(*m_document->spec().meshing.targetVertices, 30000);
    QVERIFY(find<QLabel>("meshMessageLabel")->text().contains("500"));
    vertices->setValue(4000);
    QCOMPARE(*m_document->spec().meshing.targetVertices, 4000);
}

void TestMeshPanel::meshesAndInspectsTheResult() {
    find<QSpinBox>("verticesSpin")->setValue(4000); // a small mesh keeps the test short
    QSignalSpy changed(m_session, &GenerationSession::resultsChanged);
    find<QPushButton>("meshButton")->click();
    QVERIFY(changed.wait(120000));
    QVERIFY(m_session->isCurrent(hs::generate::Stage::Tissue));
    QVERIFY(find<QLabel>("qualitySummaryLabel")->text().contains("tets"));

    // Both histograms hold the report's buckets.
    const auto& report = m_session->results()->mesh->quality;
    auto* ratios = qobject_cast<QBarSeries*>(find<QChartView>("radiusRatioChart")->chart()->series().value(0));
    QVERIFY(ratios);
    QCOMPARE(ratios->barSets().value(0)->count(), 10);
    qreal total = 0;
    for (int i = 0; i < 10; ++i)
        total += ratios->barSets()[0]->at(i);
    QCOMPARE(qulonglong(total), qulonglong(report.tetCount));
    QVERIFY(find<QChartView>("dihedralChart")->chart()->series().size() == 1);

    // The display shows the mesh; the inspector lists the worst tets once their measures are in.
    m_display->showTetMesh(m_session->results()->tissue->tets);
    m_panel->applyToDisplay();
    auto* table = find<QTableWidget>("worstTetTable");
    QTRY_COMPARE_WITH_TIMEOUT(table->rowCount(), MeshPanel::kWorstCount, 20000);
    const double worst = table->item(0, 2)->text().toDouble();
    QVERIFY(worst <= table->item(1, 2)->text().toDouble() + 1e-9);
    QVERIFY(std::abs(worst - report.minRadiusRatio) < 1e-3);

    double before[3];
    m_view->renderer()->GetActiveCamera()->GetFocalPoint(before);
    find<QTableWidget>("worstTetTable")->setCurrentCell(0, 0);
    find<QPushButton>("showTetButton")->click();
    double after[3];
    m_view->renderer()->GetActiveCamera()->GetFocalPoint(after);
    QVERIFY(before[0] != after[0] || before[1] != after[1] || before[2] != after[2]);

    auto* colour = find<QComboBox>("colourCombo");
    colour->setCurrentIndex(1); // radius ratio
    const std::size_t all = m_display->visibleCellCount();
    // One check box per region of the tissue mesh; the first is the myometrium.
    const auto& regions = m_session->results()->tissue->regions;
    QVERIFY(!regions.empty());
    auto* myometrium = find<QCheckBox>(QStringLiteral("regionCheck%1").arg(regions.front().id));
    // Named in the user's language, as the Materials panel names the tissue.
    QCOMPARE(myometrium->text(), hs::widgets::tissueName(regions.front().tissue));
    QCOMPARE(myometrium->text(), QStringLiteral("Myometrium"));
    myometrium->setChecked(false);
    QVERIFY(m_display->visibleCellCount() < all);
    QCOMPARE(m_display->hiddenRegions().count(regions.front().id), std::size_t{1});
}

QTEST_MAIN(TestMeshPanel)
#include "TestMeshPanel.moc"
