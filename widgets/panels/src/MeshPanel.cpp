#include "hs/widgets/panels/MeshPanel.h"

#include "hs/meshing/QualityReport.h"
#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/jobs/GenerationSession.h"
#include "hs/widgets/panels/CaseEdits.h"
#include "hs/widgets/panels/MaterialsPanel.h"
#include "hs/widgets/view/MeshDisplay.h"
#include "hs/widgets/view/VtkView.h"

#include <QBarCategoryAxis>
#include <QBarSeries>
#include <QBarSet>
#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QFont>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QValueAxis>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>

namespace hs::widgets {

namespace {

using scene::CaseSpec;

enum MergeKey { kVerticesKey = 301, kIterationsKey };
enum class Colouring { Tissue, RadiusRatio, MinDihedral };

QChartView* makeHistogram(QWidget* parent, const char* name, const QString& title, const QString& axisTitle) {
    auto* chart = new QChart;
    chart->setTitle(title);
    chart->legend()->hide();
    chart->setMargins(QMargins(2, 2, 2, 2));
    auto* view = new QChartView(chart, parent);
    view->setObjectName(name);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumHeight(200);
    view->setToolTip(axisTitle);
    return view;
}

/// Replaces the chart's series with one bar per bucket.
void setBars(QChartView* view, const QStringList& categories, const std::vector<std::size_t>& counts,
             const QString& axisTitle, const QColor& colour) {
    QChart* chart = view->chart();
    chart->removeAllSeries();
    for (QAbstractAxis* axis : chart->axes())
        chart->removeAxis(axis);
    auto* set = new QBarSet(axisTitle);
    set->setColor(colour);
    std::size_t highest = 1;
    for (std::size_t count : counts) {
        *set << static_cast<qreal>(count);
        highest = std::max(highest, count);
    }
    auto* series = new QBarSeries;
    series->append(set);
    series->setBarWidth(0.95);
    chart->addSeries(series);
    auto* x = new QBarCategoryAxis;
    x->append(categories);
    x->setTitleText(axisTitle);
    QFont small = x->labelsFont();
    small.setPointSizeF(small.pointSizeF() * 0.8);
    x->setLabelsFont(small);
    auto* y = new QValueAxis;
    y->setRange(0, static_cast<qreal>(highest));
    y->setLabelFormat(QStringLiteral("%d"));
    y->setTitleText(MeshPanel::tr("tets"));
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    series->attachAxis(x);
    series->attachAxis(y);
}

} // namespace

MeshPanel::MeshPanel(CaseDocument& document, GenerationSession& session, QWidget* parent)
    : QWidget(parent), m_document(document), m_session(session), m_inspectJobs(this) {
    setObjectName("meshPanel");
    auto* layout = new QVBoxLayout(this);
    (void)layout;
    buildParameters();
    buildInspector();
    static_cast<QVBoxLayout*>(this->layout())->addStretch(1);
    connect(&m_document, &CaseDocument::changed, this, &MeshPanel::refreshParameters);
    connect(&m_session, &GenerationSession::resultsChanged, this, &MeshPanel::onResults);
    refreshParameters();
    onResults();
}

void MeshPanel::setDisplay(MeshDisplay* display, VtkView* view) {
    m_display = display;
    m_view = view;
}

void MeshPanel::buildParameters() {
    auto* group = new QGroupBox(tr("Meshing"), this);
    auto* form = new QFormLayout(group);
    m_methodCombo = new QComboBox(group);
    m_methodCombo->setObjectName("methodCombo");
    m_methodCombo->addItem(tr("Particles (Sierra et al. 2004)"), static_cast<int>(scene::MeshingMethod::Particle));
    m_methodCombo->addItem(tr("TetGen"), static_cast<int>(scene::MeshingMethod::TetGen));
    m_methodCombo->addItem(tr("CGAL Mesh_3"), static_cast<int>(scene::MeshingMethod::Cgal));
    m_methodCombo->setToolTip(tr("The particle mesher is the method of the paper; TetGen and CGAL are baselines"));
    form->addRow(tr("Me&thod"), m_methodCombo);

    m_verticesSpin = new QSpinBox(group);
    m_verticesSpin->setObjectName("verticesSpin");
    m_verticesSpin->setRange(0, 2000000);
    m_verticesSpin->setSingleStep(1000);
    m_verticesSpin->setKeyboardTracking(false);
    m_verticesSpin->setGroupSeparatorShown(true);
    m_verticesSpin->setToolTip(
        tr("Vertices the mesh aims at: %1").arg(rangeText(scene::limits::kTargetVertices, QString())));
    form->addRow(tr("&Target vertices"), m_verticesSpin);

    m_seedingCombo = new QComboBox(group);
    m_seedingCombo->setObjectName("seedingCombo");
    m_seedingCombo->addItem(tr("Lattice"), static_cast<int>(scene::MeshingSeeding::Lattice));
    m_seedingCombo->addItem(tr("Random, 2 per voxel"), static_cast<int>(scene::MeshingSeeding::Random));
    m_seedingCombo->setToolTip(tr("How particles are seeded inside the body (particle method)"));
    form->addRow(tr("&Seeding"), m_seedingCombo);

    m_iterationsSpin = new QSpinBox(group);
    m_iterationsSpin->setObjectName("iterationsSpin");
    m_iterationsSpin->setRange(0, 5000);
    m_iterationsSpin->setKeyboardTracking(false);
    m_iterationsSpin->setToolTip(tr("Most relaxation iterations (%1); relaxation also stops when it converges")
                                     .arg(rangeText(scene::limits::kRelaxationIterations, QString())));
    form->addRow(tr("&Relaxation"), m_iterationsSpin);

    m_meshButton = new QPushButton(tr("&Mesh"), group);
    m_meshButton->setObjectName("meshButton");
    m_meshButton->setToolTip(tr("Mesh the merged body and split the wall into its tissues (Ctrl+M)"));
    form->addRow(m_meshButton);
    m_messageLabel = new QLabel(group);
    m_messageLabel->setObjectName("meshMessageLabel");
    m_messageLabel->setWordWrap(true);
    m_messageLabel->setStyleSheet(QStringLiteral("color: #c0392b;"));
    m_messageLabel->setVisible(false);
    form->addRow(m_messageLabel);
    layout()->addWidget(group);

    const QString prefix = QStringLiteral("/meshing");
    connect(m_methodCombo, &QComboBox::currentIndexChanged, this, [=](int index) {
        const auto method = static_cast<scene::MeshingMethod>(m_methodCombo->itemData(index).toInt());
        if (!m_refreshing)
            tryEdit(
                m_document, tr("Meshing method"), [method](CaseSpec& s) { s.meshing.method = method; }, prefix,
                m_messageLabel, m_methodCombo);
    });
    connect(m_verticesSpin, &QSpinBox::valueChanged, this, [=](int v) {
        if (!m_refreshing)
            tryEdit(
                m_document, tr("Target vertices"),
                [v](CaseSpec& s) {
                    s.meshing.targetVertices = v;
                    s.meshing.targetEdgeLengthMm.reset();
                },
                prefix, m_messageLabel, m_verticesSpin, kVerticesKey);
    });
    connect(m_seedingCombo, &QComboBox::currentIndexChanged, this, [=](int index) {
        const auto seeding = static_cast<scene::MeshingSeeding>(m_seedingCombo->itemData(index).toInt());
        if (!m_refreshing)
            tryEdit(
                m_document, tr("Seeding"),
                [seeding](CaseSpec& s) {
                    s.meshing.seeding = seeding;
                    s.meshing.particlesPerInnerVoxel =
                        seeding == scene::MeshingSeeding::Random ? std::optional(2) : std::nullopt;
                },
                prefix, m_messageLabel, m_seedingCombo);
    });
    connect(m_iterationsSpin, &QSpinBox::valueChanged, this, [=](int v) {
        if (!m_refreshing)
            tryEdit(
                m_document, tr("Relaxation iterations"), [v](CaseSpec& s) { s.meshing.relaxationIterations = v; },
                prefix, m_messageLabel, m_iterationsSpin, kIterationsKey);
    });
    connect(m_meshButton, &QPushButton::clicked, this, [this] { m_session.runThrough(generate::Stage::Tissue); });
}

void MeshPanel::buildInspector() {
    auto* group = new QGroupBox(tr("Quality"), this);
    auto* box = new QVBoxLayout(group);
    m_summaryLabel = new QLabel(tr("Not meshed yet."), group);
    m_summaryLabel->setObjectName("qualitySummaryLabel");
    m_summaryLabel->setWordWrap(true);
    box->addWidget(m_summaryLabel);
    m_radiusRatioChart = makeHistogram(group, "radiusRatioChart", tr("Radius ratio"),
                                       tr("3 × inradius / circumradius: 1 for the regular tetrahedron"));
    m_dihedralChart = makeHistogram(group, "dihedralChart", tr("Smallest dihedral angle"),
                                    tr("Degrees; below 10° a tet is a sliver"));
    box->addWidget(m_radiusRatioChart);
    box->addWidget(m_dihedralChart);

    auto* colourRow = new QHBoxLayout;
    colourRow->addWidget(new QLabel(tr("Colour by"), group));
    m_colourCombo = new QComboBox(group);
    m_colourCombo->setObjectName("colourCombo");
    m_colourCombo->addItem(tr("Tissue"), static_cast<int>(Colouring::Tissue));
    m_colourCombo->addItem(tr("Radius ratio"), static_cast<int>(Colouring::RadiusRatio));
    m_colourCombo->addItem(tr("Smallest dihedral"), static_cast<int>(Colouring::MinDihedral));
    m_colourCombo->setToolTip(tr("Blue: poor, red: good (radius ratio 0 – 1, dihedral 0 – 70.5°)"));
    colourRow->addWidget(m_colourCombo, 1);
    box->addLayout(colourRow);
    connect(m_colourCombo, &QComboBox::currentIndexChanged, this, &MeshPanel::applyColouring);

    auto* regions = new QGroupBox(tr("Regions shown"), group);
    m_regionsLayout = new QVBoxLayout(regions);
    box->addWidget(regions);

    m_worstTable = new QTableWidget(0, 4, group);
    m_worstTable->setObjectName("worstTetTable");
    m_worstTable->setHorizontalHeaderLabels({tr("Tet"), tr("Region"), tr("Radius ratio"), tr("Dihedral")});
    m_worstTable->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_worstTable->verticalHeader()->hide();
    m_worstTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_worstTable->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_worstTable->setSelectionMode(QAbstractItemView::SingleSelection);
    m_worstTable->setMinimumHeight(160);
    m_worstTable->setToolTip(tr("The worst tets by radius ratio; double-click or Show frames one in the view"));
    box->addWidget(m_worstTable);
    auto* showButton = new QPushButton(tr("&Show"), group);
    showButton->setObjectName("showTetButton");
    box->addWidget(showButton);
    connect(showButton, &QPushButton::clicked, this, [this] { showWorstTet(m_worstTable->currentRow()); });
    connect(m_worstTable, &QTableWidget::cellDoubleClicked, this, [this](int row, int) { showWorstTet(row); });
    layout()->addWidget(group);
}

void MeshPanel::refreshParameters() {
    m_refreshing = true;
    const scene::MeshingParams& m = m_document.spec().meshing;
    m_methodCombo->setCurrentIndex(m_methodCombo->findData(static_cast<int>(m.method)));
    if (!m_verticesSpin->property("invalid").toBool())
        m_verticesSpin->setValue(m.targetVertices.value_or(0));
    m_verticesSpin->setEnabled(m.targetVertices.has_value());
    m_seedingCombo->setCurrentIndex(m_seedingCombo->findData(static_cast<int>(m.seeding)));
    m_seedingCombo->setEnabled(m.method == scene::MeshingMethod::Particle);
    if (!m_iterationsSpin->property("invalid").toBool())
        m_iterationsSpin->setValue(m.relaxationIterations);
    m_iterationsSpin->setEnabled(m.method == scene::MeshingMethod::Particle);
    m_refreshing = false;
}

void MeshPanel::onResults() {
    const auto results = m_session.results();
    if (!results || !results->mesh || !results->tissue) {
        m_summaryLabel->setText(tr("Not meshed yet."));
        return;
    }
    const meshing::QualityReport& q = results->mesh->quality;
    const QLocale locale;
    m_summaryLabel->setText(
        tr("%1 vertices, %2 tets. Radius ratio: min %3, mean %4. Smallest dihedral %5°, %6 slivers. "
           "Boundary within %7 mm of the body; volume error %8 %.")
            .arg(locale.toString(qulonglong(q.vertexCount)), locale.toString(qulonglong(q.tetCount)),
                 locale.toString(q.minRadiusRatio, 'f', 3), locale.toString(q.meanRadiusRatio, 'f', 3),
                 locale.toString(q.minDihedralDeg, 'f', 1), locale.toString(qulonglong(q.sliverCount)),
                 locale.toString(q.hausdorffDistance, 'f', 2), locale.toString(100.0 * q.volumeError, 'f', 2)));
    fillCharts();

    // One check box per region of the tissue mesh; a region the user hid stays hidden in the next result.
    std::set<int> hidden;
    for (QCheckBox* check : m_regionChecks) {
        if (!check->isChecked())
            hidden.insert(check->property("regionId").toInt());
        delete check;
    }
    m_regionChecks.clear();
    for (const scene::SceneRegion& region : results->tissue->regions) {
        auto* check = new QCheckBox(regionName(region), this);
        check->setObjectName(QStringLiteral("regionCheck%1").arg(region.id));
        check->setChecked(hidden.count(region.id) == 0);
        check->setProperty("regionId", region.id);
        connect(check, &QCheckBox::toggled, this, &MeshPanel::applyRegionVisibility);
        m_regionsLayout->addWidget(check);
        m_regionChecks.push_back(check);
    }

    // The per-tet measures of this mesh, on a worker thread.
    const TetMesh* mesh = &results->tissue->tets;
    if (m_shapesOf == mesh)
        return;
    m_shapes.reset();
    m_worst.clear();
    m_worstTable->setRowCount(0);
    m_inspectJobs.start<std::shared_ptr<const std::vector<meshing::TetShape>>>(
        tr("Inspecting the mesh"), 0,
        [results, mesh](Progress&) -> Result<std::shared_ptr<const std::vector<meshing::TetShape>>> {
            return std::make_shared<const std::vector<meshing::TetShape>>(meshing::tetShapes(*mesh));
        },
        [this, results, mesh](std::shared_ptr<const std::vector<meshing::TetShape>>&& shapes) {
            if (m_session.results() != results)
                return; // a newer mesh arrived meanwhile
            m_shapes = std::move(shapes);
            m_shapesOf = mesh;
            std::vector<double> ratios(m_shapes->size());
            for (std::size_t i = 0; i < ratios.size(); ++i)
                ratios[i] = (*m_shapes)[i].radiusRatio;
            m_worst = meshing::worstTets(ratios, kWorstCount);
            const QLocale numbers;
            m_worstTable->setRowCount(static_cast<int>(m_worst.size()));
            for (int row = 0; row < static_cast<int>(m_worst.size()); ++row) {
                const std::size_t tet = m_worst[static_cast<std::size_t>(row)];
                const meshing::TetShape& shape = (*m_shapes)[tet];
                const auto& regions = results->tissue->tets.regions;
                m_worstTable->setItem(row, 0, new QTableWidgetItem(QString::number(tet)));
                m_worstTable->setItem(
                    row, 1, new QTableWidgetItem(tet < regions.size() ? QString::number(regions[tet]) : QString()));
                m_worstTable->setItem(row, 2, new QTableWidgetItem(numbers.toString(shape.radiusRatio, 'f', 3)));
                m_worstTable->setItem(row, 3, new QTableWidgetItem(numbers.toString(shape.minDihedral, 'f', 1)));
            }
            applyColouring();
        });
}

void MeshPanel::fillCharts() {
    const auto results = m_session.results();
    const meshing::QualityReport& q = results->mesh->quality;
    QStringList ratioBuckets;
    for (int i = 0; i < 10; ++i) // the bucket's lower bound: ".3" holds [0.3, 0.4)
        ratioBuckets << (i == 0 ? QStringLiteral("0") : QStringLiteral(".%1").arg(i));
    setBars(m_radiusRatioChart, ratioBuckets,
            std::vector<std::size_t>(q.radiusRatioHistogram.begin(), q.radiusRatioHistogram.end()), tr("radius ratio"),
            QColor(70, 130, 180));
    QStringList dihedralBuckets;
    for (int i = 0; i < 9; ++i)
        dihedralBuckets << QString::number(i * 10);
    setBars(m_dihedralChart, dihedralBuckets,
            std::vector<std::size_t>(q.minDihedralHistogram.begin(), q.minDihedralHistogram.end()),
            tr("smallest dihedral (°)"), QColor(205, 120, 70));
}

void MeshPanel::applyColouring() {
    if (!m_display || !m_display->isTetMesh())
        return;
    const auto colouring = static_cast<Colouring>(m_colourCombo->currentData().toInt());
    // The legend names the regions as their check boxes do.
    std::map<std::int32_t, std::string> names;
    for (QCheckBox* check : m_regionChecks)
        names[check->property("regionId").toInt()] = check->text().toStdString();
    m_display->setRegionNames(names);
    if (colouring == Colouring::Tissue || !m_shapes) {
        m_display->colourTets({}, 0.0, 1.0);
    } else {
        std::vector<double> values(m_shapes->size());
        for (std::size_t i = 0; i < values.size(); ++i)
            values[i] = colouring == Colouring::RadiusRatio ? (*m_shapes)[i].radiusRatio : (*m_shapes)[i].minDihedral;
        // 70.53 degrees: the regular tetrahedron's dihedral angle.
        m_display->colourTets(
            values, 0.0, colouring == Colouring::RadiusRatio ? 1.0 : 70.53,
            (colouring == Colouring::RadiusRatio ? tr("radius ratio") : tr("smallest dihedral (°)")).toStdString());
    }
    if (m_view)
        m_view->requestRender();
    emit displayChanged();
}

void MeshPanel::applyRegionVisibility() {
    if (!m_display)
        return;
    std::set<std::int32_t> hidden;
    for (QCheckBox* check : m_regionChecks)
        if (!check->isChecked())
            hidden.insert(check->property("regionId").toInt());
    m_display->setHiddenRegions(hidden);
    if (m_view)
        m_view->requestRender();
    emit displayChanged();
}

void MeshPanel::syncRegionChecks() {
    if (!m_display)
        return;
    for (QCheckBox* check : m_regionChecks) {
        const QSignalBlocker block(check);
        check->setChecked(m_display->hiddenRegions().count(check->property("regionId").toInt()) == 0);
    }
}

void MeshPanel::applyToDisplay() {
    applyColouring();
    applyRegionVisibility();
}

void MeshPanel::showWorstTet(int row) {
    if (!m_display || !m_view || row < 0 || row >= static_cast<int>(m_worst.size()))
        return;
    // The tet is outlined in the mesh: the view shows the mesh first when it shows another part (the textured
    // surface, after Texture).
    if (!m_display->isTetMesh() || !m_display->isShown())
        emit meshWanted();
    const std::array<double, 6> box =
        m_display->highlightTet(static_cast<std::int64_t>(m_worst[static_cast<std::size_t>(row)]));
    // Frame the tet with room around it: ten times its size, at least 5 mm.
    const double size = std::max({box[1] - box[0], box[3] - box[2], box[5] - box[4], 0.5});
    const double pad = 5.0 * size;
    double framed[6] = {box[0] - pad, box[1] + pad, box[2] - pad, box[3] + pad, box[4] - pad, box[5] + pad};
    m_view->renderer()->ResetCamera(framed);
    m_view->requestRender();
    m_worstTable->selectRow(row);
    emit displayChanged();
}

} // namespace hs::widgets
