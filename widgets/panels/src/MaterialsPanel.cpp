#include "hs/widgets/panels/MaterialsPanel.h"

#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/panels/CaseEdits.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace hs::widgets {

namespace {

using scene::CaseSpec;
using scene::MaterialOverride;

constexpr int kMergeBase = 400;

std::optional<double> MaterialOverride::*overrideOf(int column) {
    switch (column) {
    case MaterialsPanel::kYoungsColumn:
        return &MaterialOverride::youngsModulusKpa;
    case MaterialsPanel::kPoissonColumn:
        return &MaterialOverride::poissonRatio;
    case MaterialsPanel::kDensityColumn:
        return &MaterialOverride::densityKgPerM3;
    default:
        return &MaterialOverride::heterogeneity;
    }
}

/// The default of a column (heterogeneity: homogeneous) and its allowed range.
std::pair<double, scene::Range> defaultAndRange(clinical::Tissue tissue, int column) {
    const scene::TissueMaterial d = scene::defaultMaterial(tissue);
    switch (column) {
    case MaterialsPanel::kYoungsColumn:
        return {d.youngsModulusKpa, scene::youngsModulusRangeKpa(tissue)};
    case MaterialsPanel::kPoissonColumn:
        return {d.poissonRatio, scene::limits::kPoissonRatio};
    case MaterialsPanel::kDensityColumn:
        return {d.densityKgPerM3, scene::limits::kDensityKgPerM3};
    default:
        return {0.0, scene::limits::kHeterogeneity};
    }
}

} // namespace

QString tissueName(clinical::Tissue tissue) {
    switch (tissue) {
    case clinical::Tissue::Myometrium:
        return MaterialsPanel::tr("Myometrium");
    case clinical::Tissue::Endometrium:
        return MaterialsPanel::tr("Endometrium");
    case clinical::Tissue::Cervix:
        return MaterialsPanel::tr("Cervix");
    case clinical::Tissue::Myoma:
        return MaterialsPanel::tr("Myoma");
    case clinical::Tissue::Polyp:
        break;
    }
    return MaterialsPanel::tr("Polyp");
}

QString regionName(const scene::SceneRegion& region) {
    return region.pathologyId.empty() ? tissueName(region.tissue) : QString::fromStdString(region.name);
}

MaterialsPanel::MaterialsPanel(CaseDocument& document, QWidget* parent) : QWidget(parent), m_document(document) {
    setObjectName("materialsPanel");
    auto* layout = new QVBoxLayout(this);
    m_table = new QTableWidget(static_cast<int>(clinical::kTissues.size()), kColumnCount, this);
    m_table->setObjectName("materialsTable");
    // Short headers (the symbols of the literature) with the full names in their tooltips, spin boxes without
    // arrows (the keys and the wheel step them): the table fits a 1366 x 768 screen's side panel.
    const std::array<std::pair<QString, QString>, kColumnCount> headers{{
        {tr("E (kPa)"), tr("Young's modulus (kPa)")},
        {tr("ν"), tr("Poisson ratio")},
        {tr("ρ (kg/m³)"), tr("Density (kg/m³)")},
        {tr("CV of E"), tr("Heterogeneity: the coefficient of variation of Young's modulus per tetrahedron")},
        {QString(), QString()},
    }};
    for (int column = 0; column < kColumnCount; ++column) {
        auto* header = new QTableWidgetItem(headers[static_cast<std::size_t>(column)].first);
        header->setToolTip(headers[static_cast<std::size_t>(column)].second);
        m_table->setHorizontalHeaderItem(column, header);
    }
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->horizontalHeader()->setSectionResizeMode(kResetColumn, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setMinimumSectionSize(40);
    m_table->setMinimumHeight(200);
    const QLocale locale;
    for (std::size_t row = 0; row < clinical::kTissues.size(); ++row) {
        const clinical::Tissue tissue = clinical::kTissues[row];
        const QString key = QString::fromLatin1(clinical::toString(tissue).data());
        m_table->setVerticalHeaderItem(static_cast<int>(row), new QTableWidgetItem(tissueName(tissue)));
        for (int column = 0; column < kResetColumn; ++column) {
            const auto [value, range] = defaultAndRange(tissue, column);
            auto* spin = new QDoubleSpinBox(m_table);
            spin->setObjectName(QStringLiteral("%1Spin%2").arg(key).arg(column));
            spin->setDecimals(column == kPoissonColumn || column == kHeterogeneityColumn ? 3 : 1);
            spin->setRange(0.0, range.max * 4.0 + 1.0); // out-of-range values are typed, then refused with a reason
            spin->setSingleStep(column == kPoissonColumn ? 0.005 : column == kHeterogeneityColumn ? 0.05 : 1.0);
            spin->setKeyboardTracking(false);
            spin->setButtonSymbols(QAbstractSpinBox::NoButtons);
            spin->setToolTip(tr("%1: default %2; allowed %3")
                                 .arg(headers[static_cast<std::size_t>(column)].second)
                                 .arg(locale.toString(value, 'f', spin->decimals()))
                                 .arg(rangeText(range, {}, spin->decimals())));
            m_table->setCellWidget(static_cast<int>(row), column, spin);
            const auto member = overrideOf(column);
            connect(spin, &QDoubleSpinBox::valueChanged, this, [this, spin, row, member, column](double v) {
                if (m_refreshing)
                    return;
                tryEdit(
                    m_document, tr("Material"), [row, member, v](CaseSpec& s) { s.scene.materials[row].*member = v; },
                    QStringLiteral("/scene/materials"), m_messageLabel, spin,
                    kMergeBase + int(row) * kColumnCount + column);
            });
        }
        auto* reset = new QPushButton(QStringLiteral("↺"), m_table);
        reset->setObjectName(QStringLiteral("%1ResetButton").arg(key));
        reset->setToolTip(tr("Default: use the literature values for this tissue"));
        reset->setAccessibleName(tr("Default values for %1").arg(tissueName(tissue)));
        reset->setMaximumWidth(reset->fontMetrics().horizontalAdvance(QStringLiteral("↺")) + 16);
        m_table->setCellWidget(static_cast<int>(row), kResetColumn, reset);
        connect(reset, &QPushButton::clicked, this, [this, row] {
            m_document.edit(tr("Default material"),
                            [row](CaseSpec& s) { s.scene.materials[row] = MaterialOverride{}; });
        });
    }
    layout->addWidget(m_table);

    auto* form = new QFormLayout;
    m_pressureSpin = new QDoubleSpinBox(this);
    m_pressureSpin->setObjectName("hydrometraSpin");
    m_pressureSpin->setRange(0.0, 100.0);
    m_pressureSpin->setDecimals(1);
    m_pressureSpin->setSuffix(tr(" kPa"));
    m_pressureSpin->setKeyboardTracking(false);
    m_pressureSpin->setToolTip(tr("Distension pressure the scene's hydrometra curve is computed for, %1 "
                                  "(8 kPa = 60 mmHg)")
                                   .arg(rangeText(scene::limits::kHydrometraPressureKpa, QStringLiteral("kPa"))));
    form->addRow(tr("&Hydrometra pressure"), m_pressureSpin);
    layout->addLayout(form);
    connect(m_pressureSpin, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (!m_refreshing)
            tryEdit(
                m_document, tr("Hydrometra pressure"), [v](CaseSpec& s) { s.scene.hydrometraPressureKpa = v; },
                QStringLiteral("/scene/hydrometraPressureKpa"), m_messageLabel, m_pressureSpin, kMergeBase - 1);
    });

    m_messageLabel = new QLabel(this);
    m_messageLabel->setObjectName("materialsMessageLabel");
    m_messageLabel->setWordWrap(true);
    m_messageLabel->setStyleSheet(QStringLiteral("color: #c0392b;"));
    m_messageLabel->setVisible(false);
    layout->addWidget(m_messageLabel);
    auto* source = new QLabel(tr("Defaults: myometrium 30 kPa, endometrium 26.2 kPa (proliferative), myoma 65 kPa, "
                                 "polyp 15 kPa; Poisson ratio 0.47; 1050 kg/m³ (see docs/scene-format.md)."),
                              this);
    source->setWordWrap(true);
    source->setEnabled(false);
    layout->addWidget(source);
    layout->addStretch(1);
    connect(&m_document, &CaseDocument::changed, this, &MaterialsPanel::refresh);
    refresh();
}

QDoubleSpinBox* MaterialsPanel::field(int tissue, int column) const {
    return qobject_cast<QDoubleSpinBox*>(m_table->cellWidget(tissue, column));
}

void MaterialsPanel::refresh() {
    m_refreshing = true;
    const scene::SceneParams& params = m_document.spec().scene;
    for (std::size_t row = 0; row < clinical::kTissues.size(); ++row) {
        const clinical::Tissue tissue = clinical::kTissues[row];
        for (int column = 0; column < kResetColumn; ++column) {
            QDoubleSpinBox* spin = field(static_cast<int>(row), column);
            const std::optional<double>& value = params.materials[row].*overrideOf(column);
            if (spin->property("invalid").toBool())
                continue; // a refused value stays until the user changes it
            spin->setValue(value.value_or(defaultAndRange(tissue, column).first));
            // Bold: an override stored in the case; plain: the literature default.
            QFont font = spin->font();
            font.setBold(value.has_value());
            spin->setFont(font);
        }
    }
    m_pressureSpin->setValue(params.hydrometraPressureKpa);
    m_refreshing = false;
}

} // namespace hs::widgets
