#include "hs/widgets/view/VariantsView.h"

#include "hs/widgets/view/HysteroscopicPreview.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QLabel>
#include <QSlider>
#include <QVBoxLayout>

#include <cmath>

namespace hs::widgets {

VariantsView::VariantsView(QWidget* parent) : QWidget(parent) {
    setObjectName("variantsView");
    auto* layout = new QVBoxLayout(this);
    m_grid = new QGridLayout;
    layout->addLayout(m_grid, 1);
    auto* controls = new QFormLayout;
    m_insertionSlider = new QSlider(Qt::Horizontal, this);
    m_insertionSlider->setObjectName("variantsInsertionSlider");
    m_insertionSlider->setRange(-10, 140); // half millimetres, as the single view
    m_insertionSlider->setToolTip(tr("How far every scope's tip is beyond its external os (mm)"));
    controls->addRow(tr("&Insertion"), m_insertionSlider);
    m_opticCombo = new QComboBox(this);
    m_opticCombo->setObjectName("variantsOpticCombo");
    for (int optic : {0, 12, 30, 70})
        m_opticCombo->addItem(tr("%1°").arg(optic), optic);
    m_opticCombo->setCurrentIndex(2);
    controls->addRow(tr("&Optic"), m_opticCombo);
    m_rollSlider = new QSlider(Qt::Horizontal, this);
    m_rollSlider->setObjectName("variantsRollSlider");
    m_rollSlider->setRange(-180, 180);
    controls->addRow(tr("&Roll"), m_rollSlider);
    layout->addLayout(controls);
    connect(m_insertionSlider, &QSlider::valueChanged, this, &VariantsView::apply);
    connect(m_opticCombo, &QComboBox::currentIndexChanged, this, &VariantsView::apply);
    connect(m_rollSlider, &QSlider::valueChanged, this, &VariantsView::apply);
}

void VariantsView::setScenes(const std::vector<std::shared_ptr<const scene::Scene>>& scenes, const QStringList& names) {
    for (HysteroscopicPreview* p : m_previews)
        delete p;
    for (QLabel* t : m_titles)
        delete t;
    m_previews.clear();
    m_titles.clear();
    const int n = std::min<int>(kMaxVariants, static_cast<int>(scenes.size()));
    const int columns = n <= 2 ? n : (n <= 4 ? 2 : 3);
    for (int i = 0; i < n; ++i) {
        auto* title = new QLabel(names.value(i), this);
        title->setObjectName(QStringLiteral("variantTitle%1").arg(i));
        auto* preview = new HysteroscopicPreview(this);
        preview->setObjectName(QStringLiteral("variantPreview%1").arg(i));
        preview->setControlsVisible(false);
        preview->setScene(scenes[static_cast<std::size_t>(i)]);
        const int row = columns > 0 ? i / columns : 0;
        const int column = columns > 0 ? i % columns : 0;
        m_grid->addWidget(title, 2 * row, column);
        m_grid->addWidget(preview, 2 * row + 1, column);
        m_previews.push_back(preview);
        m_titles.push_back(title);
    }
    apply();
}

void VariantsView::setInsertion(double mm) {
    m_insertionSlider->setValue(static_cast<int>(std::lround(mm * 2.0)));
}

void VariantsView::apply() {
    for (HysteroscopicPreview* p : m_previews) {
        p->setInsertion(m_insertionSlider->value() / 2.0);
        p->setOptic(m_opticCombo->currentData().toDouble());
        p->setRoll(m_rollSlider->value());
    }
}

} // namespace hs::widgets
