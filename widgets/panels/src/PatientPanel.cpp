#include "hs/widgets/panels/PatientPanel.h"

#include "hs/anatomy/Cohort.h"
#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/jobs/GenerationSession.h"
#include "hs/widgets/panels/CaseEdits.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QRandomGenerator>
#include <QRegularExpressionValidator>
#include <QSpinBox>
#include <QVBoxLayout>

#include <limits>

namespace hs::widgets {

namespace {

using scene::CaseSpec;

// Merge keys: a run of steps of one field is one undo command.
enum MergeKey { kAgeKey = 101, kParityKey, kGravidityKey, kHeightKey, kWeightKey, kDimensionKey = 120 };

/// Spin boxes accept values beyond the allowed range, so that a typed value can be refused with a reason.
constexpr double kTypingMargin = 100.0;

struct DimensionInfo {
    const char* label;
    const char* objectName;
    std::optional<double> scene::UterusDimensions::*caseField;
    double anatomy::UterusDimensions::*organField;
    anatomy::ExpectedDimension anatomy::ExpectedDimensions::*expected;
    scene::Range range;
};

const std::array<DimensionInfo, PatientPanel::kDimensionCount> kDimensions{{
    {QT_TRANSLATE_NOOP("hs::widgets::PatientPanel", "Uterine length"), "length", &scene::UterusDimensions::lengthMm,
     &anatomy::UterusDimensions::lengthMm, &anatomy::ExpectedDimensions::lengthMm, scene::limits::kLengthMm},
    {QT_TRANSLATE_NOOP("hs::widgets::PatientPanel", "Width"), "width", &scene::UterusDimensions::widthMm,
     &anatomy::UterusDimensions::widthMm, &anatomy::ExpectedDimensions::widthMm, scene::limits::kWidthMm},
    {QT_TRANSLATE_NOOP("hs::widgets::PatientPanel", "AP depth"), "ap", &scene::UterusDimensions::apMm,
     &anatomy::UterusDimensions::apDepthMm, &anatomy::ExpectedDimensions::apDepthMm, scene::limits::kApMm},
    {QT_TRANSLATE_NOOP("hs::widgets::PatientPanel", "Cavity length"), "cavityLength",
     &scene::UterusDimensions::cavityLengthMm, &anatomy::UterusDimensions::cavityLengthMm,
     &anatomy::ExpectedDimensions::cavityLengthMm, scene::limits::kCavityLengthMm},
    {QT_TRANSLATE_NOOP("hs::widgets::PatientPanel", "Cavity width"), "cavityWidth",
     &scene::UterusDimensions::cavityWidthMm, &anatomy::UterusDimensions::cavityWidthMm,
     &anatomy::ExpectedDimensions::cavityWidthMm, scene::limits::kCavityWidthMm},
    {QT_TRANSLATE_NOOP("hs::widgets::PatientPanel", "Fundal wall thickness"), "fundalWall",
     &scene::UterusDimensions::fundalWallThicknessMm, &anatomy::UterusDimensions::fundalWallMm,
     &anatomy::ExpectedDimensions::fundalWallMm, scene::limits::kFundalWallThicknessMm},
    {QT_TRANSLATE_NOOP("hs::widgets::PatientPanel", "Cervix length"), "cervixLength",
     &scene::UterusDimensions::cervixLengthMm, &anatomy::UterusDimensions::cervixLengthMm,
     &anatomy::ExpectedDimensions::cervixLengthMm, scene::limits::kCervixLengthMm},
}};

QDoubleSpinBox* makeDoubleSpin(QWidget* parent, const char* name, const scene::Range& range, int decimals, double step,
                               const QString& suffix, const QString& tip) {
    auto* spin = new QDoubleSpinBox(parent);
    spin->setObjectName(name);
    spin->setDecimals(decimals);
    spin->setRange(std::max(0.0, range.min - kTypingMargin), range.max + kTypingMargin);
    spin->setSingleStep(step);
    spin->setSuffix(suffix);
    spin->setToolTip(tip);
    spin->setKeyboardTracking(false); // one value per typed number, not one per key
    return spin;
}

QSpinBox* makeIntSpin(QWidget* parent, const char* name, const scene::Range& range, const QString& tip) {
    auto* spin = new QSpinBox(parent);
    spin->setObjectName(name);
    spin->setRange(0, static_cast<int>(range.max) + 20);
    spin->setToolTip(tip);
    spin->setKeyboardTracking(false);
    return spin;
}

QLabel* rangeLabel(QWidget* parent, const QString& text) {
    auto* label = new QLabel(text, parent);
    label->setEnabled(false); // greyed: a hint, not a value
    return label;
}

} // namespace

PatientPanel::PatientPanel(CaseDocument& document, GenerationSession& session, QWidget* parent)
    : QWidget(parent), m_document(document), m_session(session) {
    setObjectName("patientPanel");
    auto* layout = new QVBoxLayout(this);
    buildPatientForm();
    buildDimensionTable();
    layout->addStretch(1);
    connectFields();
    connect(&m_document, &CaseDocument::changed, this, &PatientPanel::refresh);
    connect(&m_session, &GenerationSession::resultsChanged, this, &PatientPanel::refreshDimensions);
    refresh();
}

void PatientPanel::buildPatientForm() {
    auto* group = new QGroupBox(tr("Patient"), this);
    auto* form = new QFormLayout(group);
    const auto addRow = [&](const QString& label, QWidget* field, const QString& range) {
        auto* row = new QHBoxLayout;
        row->addWidget(field, 1);
        row->addWidget(rangeLabel(group, range));
        auto* name = new QLabel(label, group); // a label of a layout row needs its buddy for its shortcut
        name->setBuddy(field);
        form->addRow(name, row);
    };
    namespace lim = scene::limits;
    m_ageSpin = makeDoubleSpin(group, "ageSpin", lim::kAgeYears, 1, 1.0, tr(" years"), tr("Age in years"));
    addRow(tr("&Age"), m_ageSpin, rangeText(lim::kAgeYears, tr("years")));
    m_paritySpin = makeIntSpin(group, "paritySpin", lim::kParity, tr("Births after 20 weeks of gestation"));
    addRow(tr("&Parity"), m_paritySpin, rangeText(lim::kParity, tr("births")));
    m_graviditySpin = makeIntSpin(group, "graviditySpin", lim::kGravidity,
                                  tr("Pregnancies, including those that ended in a birth (at least the parity)"));
    addRow(tr("&Gravidity"), m_graviditySpin, rangeText(lim::kGravidity, tr("pregnancies")));
    m_heightSpin = makeDoubleSpin(group, "heightSpin", lim::kHeightCm, 0, 1.0, tr(" cm"), tr("Height in centimetres"));
    addRow(tr("&Height"), m_heightSpin, rangeText(lim::kHeightCm, tr("cm")));
    m_weightSpin = makeDoubleSpin(group, "weightSpin", lim::kWeightKg, 0, 1.0, tr(" kg"), tr("Weight in kilograms"));
    addRow(tr("&Weight"), m_weightSpin, rangeText(lim::kWeightKg, tr("kg")));

    m_menopausalCheck = new QCheckBox(tr("Postmenopausal"), group);
    m_menopausalCheck->setObjectName("menopausalCheck");
    m_menopausalCheck->setToolTip(tr("Postmenopausal patients are 40 years or older; premenopausal ones at most 60"));
    form->addRow(QString(), m_menopausalCheck);

    m_cyclePhaseCombo = new QComboBox(group);
    m_cyclePhaseCombo->setObjectName("cyclePhaseCombo");
    m_cyclePhaseCombo->addItem(tr("Menstrual"), QVariant::fromValue(static_cast<int>(clinical::CyclePhase::Menstrual)));
    m_cyclePhaseCombo->addItem(tr("Proliferative"),
                               QVariant::fromValue(static_cast<int>(clinical::CyclePhase::Proliferative)));
    m_cyclePhaseCombo->addItem(tr("Secretory"), QVariant::fromValue(static_cast<int>(clinical::CyclePhase::Secretory)));
    m_cyclePhaseCombo->setToolTip(tr("Phase of the cycle on the day of the hysteroscopy; it sets the endometrium's "
                                     "thickness (premenopausal patients only)"));
    form->addRow(tr("C&ycle phase"), m_cyclePhaseCombo);

    m_shapeCombo = new QComboBox(group);
    m_shapeCombo->setObjectName("shapeCombo");
    m_shapeCombo->addItem(tr("Sample for this patient"), static_cast<int>(scene::ShapeMode::Sample));
    m_shapeCombo->addItem(tr("Mean for this patient"), static_cast<int>(scene::ShapeMode::Mean));
    m_shapeCombo->setToolTip(tr("A seeded organ of the statistical shape model, or the model's mean for the patient"));
    form->addRow(tr("&Organ"), m_shapeCombo);

    m_seedEdit = new QLineEdit(group);
    m_seedEdit->setObjectName("seedEdit");
    m_seedEdit->setValidator(new QRegularExpressionValidator(QRegularExpression(QStringLiteral("\\d{1,19}")), this));
    m_seedEdit->setToolTip(tr("Every random choice of every stage derives from the seed: the same seed gives the "
                              "same scene"));
    m_newSeedButton = new QPushButton(tr("New"), group);
    m_newSeedButton->setObjectName("newSeedButton");
    m_newSeedButton->setToolTip(tr("Draw a new seed: a new patient of the same description"));
    auto* seedRow = new QHBoxLayout;
    seedRow->addWidget(m_seedEdit, 1);
    seedRow->addWidget(m_newSeedButton);
    auto* seedLabel = new QLabel(tr("&Seed"), group);
    seedLabel->setBuddy(m_seedEdit);
    form->addRow(seedLabel, seedRow);

    m_messageLabel = new QLabel(group);
    m_messageLabel->setObjectName("patientMessageLabel");
    m_messageLabel->setWordWrap(true);
    m_messageLabel->setStyleSheet(QStringLiteral("color: #c0392b;"));
    m_messageLabel->setVisible(false);
    form->addRow(m_messageLabel);
    layout()->addWidget(group);
}

void PatientPanel::buildDimensionTable() {
    auto* group = new QGroupBox(tr("Dimensions"), this);
    group->setToolTip(tr("Set a dimension to a measured value (ultrasound) and the organ is fitted to it"));
    auto* grid = new QGridLayout(group);
    grid->addWidget(new QLabel(tr("This organ"), group), 0, 1);
    grid->addWidget(new QLabel(tr("Expected (95 %)"), group), 0, 2);
    grid->addWidget(new QLabel(tr("Measured"), group), 0, 3, 1, 2);
    for (int i = 0; i < kDimensionCount; ++i) {
        const DimensionInfo& info = kDimensions[static_cast<std::size_t>(i)];
        DimensionRow& row = m_dimensions[static_cast<std::size_t>(i)];
        const QString name = QString::fromLatin1(info.objectName);
        // Names and flagged values wrap rather than widen the panel (a 1366 x 768 screen has room for 450 px).
        auto* label = new QLabel(tr(info.label), group);
        label->setWordWrap(true);
        grid->addWidget(label, i + 1, 0);
        row.organLabel = new QLabel(QStringLiteral("–"), group);
        row.organLabel->setWordWrap(true);
        row.organLabel->setObjectName(name + "OrganLabel");
        grid->addWidget(row.organLabel, i + 1, 1);
        row.expectedLabel = new QLabel(group);
        row.expectedLabel->setObjectName(name + "ExpectedLabel");
        row.expectedLabel->setToolTip(tr("The published relations for this patient, mean ± 1.96 SD"));
        grid->addWidget(row.expectedLabel, i + 1, 2);
        row.setCheck = new QCheckBox(group);
        row.setCheck->setObjectName(name + "Check");
        row.setCheck->setToolTip(tr("Fit the organ to a measured value"));
        grid->addWidget(row.setCheck, i + 1, 3);
        row.valueSpin = makeDoubleSpin(group, "", info.range, 1, 0.5, tr(" mm"),
                                       tr("Allowed: %1").arg(rangeText(info.range, "mm")));
        row.valueSpin->setObjectName(name + "Spin");
        grid->addWidget(row.valueSpin, i + 1, 4);
    }
    layout()->addWidget(group);
}

void PatientPanel::connectFields() {
    const QString prefix = QStringLiteral("/patient");
    const auto patientEdit = [this, prefix](QWidget* field, const QString& text, int key,
                                            std::function<void(CaseSpec&)> change) {
        if (!m_refreshing)
            tryEdit(m_document, text, change, prefix, m_messageLabel, field, key);
    };
    connect(m_ageSpin, &QDoubleSpinBox::valueChanged, this, [=](double v) {
        patientEdit(m_ageSpin, tr("Age"), kAgeKey, [v](CaseSpec& s) {
            // An age only one menopausal state allows brings that state along (with the cycle it implies).
            s.patient.ageYears = v;
            if (v > scene::limits::kPremenopausalMaxAgeYears && !s.patient.menopausal) {
                s.patient.menopausal = true;
                s.patient.cyclePhase.reset();
            } else if (v < scene::limits::kMenopausalMinAgeYears && s.patient.menopausal) {
                s.patient.menopausal = false;
                s.patient.cyclePhase = clinical::CyclePhase::Proliferative;
            }
        });
    });
    connect(m_paritySpin, &QSpinBox::valueChanged, this, [=](int v) {
        patientEdit(m_paritySpin, tr("Parity"), kParityKey, [v](CaseSpec& s) { s.patient.parity = v; });
    });
    connect(m_graviditySpin, &QSpinBox::valueChanged, this, [=](int v) {
        patientEdit(m_graviditySpin, tr("Gravidity"), kGravidityKey, [v](CaseSpec& s) { s.patient.gravidity = v; });
    });
    connect(m_heightSpin, &QDoubleSpinBox::valueChanged, this, [=](double v) {
        patientEdit(m_heightSpin, tr("Height"), kHeightKey, [v](CaseSpec& s) { s.patient.heightCm = v; });
    });
    connect(m_weightSpin, &QDoubleSpinBox::valueChanged, this, [=](double v) {
        patientEdit(m_weightSpin, tr("Weight"), kWeightKey, [v](CaseSpec& s) { s.patient.weightKg = v; });
    });
    connect(m_menopausalCheck, &QCheckBox::toggled, this, [=](bool on) {
        // A postmenopausal patient has no cycle; a premenopausal one is in the phase hysteroscopy is done in.
        patientEdit(m_menopausalCheck, tr("Menopausal state"), 0, [on](CaseSpec& s) {
            s.patient.menopausal = on;
            s.patient.cyclePhase = on ? std::nullopt : std::optional(clinical::CyclePhase::Proliferative);
        });
        if (m_document.spec().patient.menopausal != on)
            refresh(); // refused: show the case's state again
    });
    connect(m_cyclePhaseCombo, &QComboBox::currentIndexChanged, this, [=](int index) {
        const auto phase = static_cast<clinical::CyclePhase>(m_cyclePhaseCombo->itemData(index).toInt());
        patientEdit(m_cyclePhaseCombo, tr("Cycle phase"), 0, [phase](CaseSpec& s) { s.patient.cyclePhase = phase; });
    });
    connect(m_shapeCombo, &QComboBox::currentIndexChanged, this, [=](int index) {
        const auto mode = static_cast<scene::ShapeMode>(m_shapeCombo->itemData(index).toInt());
        if (!m_refreshing)
            tryEdit(
                m_document, tr("Organ mode"), [mode](CaseSpec& s) { s.anatomy.shape = mode; },
                QStringLiteral("/anatomy"), m_messageLabel, m_shapeCombo);
    });
    connect(m_seedEdit, &QLineEdit::editingFinished, this, [=] {
        bool ok = false;
        const auto seed = m_seedEdit->text().toULongLong(&ok);
        if (ok && !m_refreshing)
            m_document.edit(tr("Seed"), [seed](CaseSpec& s) { s.seed = seed; });
    });
    connect(m_newSeedButton, &QPushButton::clicked, this, [=] {
        const std::uint64_t seed = QRandomGenerator::global()->generate64() >> 11; // 53 bits: exact in JSON numbers
        m_document.edit(tr("New seed"), [seed](CaseSpec& s) { s.seed = seed; });
    });

    for (int i = 0; i < kDimensionCount; ++i) {
        const DimensionInfo& info = kDimensions[static_cast<std::size_t>(i)];
        DimensionRow& row = m_dimensions[static_cast<std::size_t>(i)];
        const auto field = info.caseField;
        const QString text = tr(info.label);
        const auto apply = [this, field, text, &row, i] {
            if (m_refreshing)
                return;
            const std::optional<double> value =
                row.setCheck->isChecked() ? std::optional(row.valueSpin->value()) : std::nullopt;
            tryEdit(
                m_document, text, [field, value](CaseSpec& s) { s.anatomy.dimensions.*field = value; },
                QStringLiteral("/anatomy/dimensions"), m_messageLabel, row.valueSpin, kDimensionKey + i);
            refresh();
        };
        connect(row.setCheck, &QCheckBox::toggled, this, apply);
        connect(row.valueSpin, &QDoubleSpinBox::valueChanged, this, apply);
    }
}

void PatientPanel::refresh() {
    m_refreshing = true;
    const CaseSpec& spec = m_document.spec();
    const auto& p = spec.patient;
    // A refused value stays in its field (marked) until the user changes it; an accepted one shows the case.
    if (!m_ageSpin->property("invalid").toBool())
        m_ageSpin->setValue(p.ageYears);
    if (!m_paritySpin->property("invalid").toBool())
        m_paritySpin->setValue(p.parity);
    if (!m_graviditySpin->property("invalid").toBool())
        m_graviditySpin->setValue(p.gravidity);
    if (!m_heightSpin->property("invalid").toBool())
        m_heightSpin->setValue(p.heightCm);
    if (!m_weightSpin->property("invalid").toBool())
        m_weightSpin->setValue(p.weightKg);
    m_menopausalCheck->setChecked(p.menopausal);
    m_cyclePhaseCombo->setEnabled(!p.menopausal);
    if (p.cyclePhase)
        m_cyclePhaseCombo->setCurrentIndex(m_cyclePhaseCombo->findData(static_cast<int>(*p.cyclePhase)));
    m_shapeCombo->setCurrentIndex(m_shapeCombo->findData(static_cast<int>(spec.anatomy.shape)));
    m_seedEdit->setText(QString::number(spec.seed));
    const anatomy::ExpectedDimensions expected = anatomy::expectedDimensions(p);
    for (std::size_t i = 0; i < kDimensions.size(); ++i) {
        const std::optional<double>& value = spec.anatomy.dimensions.*(kDimensions[i].caseField);
        DimensionRow& row = m_dimensions[i];
        row.setCheck->setChecked(value.has_value());
        row.valueSpin->setEnabled(value.has_value());
        if (row.valueSpin->property("invalid").toBool())
            continue;
        // Unset: the spin box holds the value expected for this patient, where a measurement starts from.
        row.valueSpin->setValue(value ? *value : (expected.*(kDimensions[i].expected)).mean);
    }
    m_refreshing = false;
    refreshDimensions();
}

void PatientPanel::refreshDimensions() {
    const QLocale locale;
    const anatomy::ExpectedDimensions expected = anatomy::expectedDimensions(m_document.spec().patient);
    const auto results = m_session.results();
    const bool current = m_session.isCurrent(generate::Stage::Organ);
    for (std::size_t i = 0; i < kDimensions.size(); ++i) {
        const DimensionInfo& info = kDimensions[i];
        DimensionRow& row = m_dimensions[i];
        const anatomy::ExpectedDimension& e = expected.*(info.expected);
        row.expectedLabel->setText(
            tr("%1 – %2 mm").arg(locale.toString(e.low(), 'f', 1), locale.toString(e.high(), 'f', 1)));
        if (results && results->organ) {
            const double value = results->organ->dimensions.*(info.organField);
            // Outside the patient's expected range: flagged in place (red, a sign and the word), not only on hover.
            const bool outside = value < e.low() || value > e.high();
            const QString text = tr("%1 mm").arg(locale.toString(value, 'f', 1));
            row.organLabel->setText(
                outside ? QStringLiteral("<span style='color:#c0392b'>⚠ %1 %2</span>").arg(text, tr("(outside)"))
                        : text);
            row.organLabel->setProperty("outside", outside);
            // Grey while the organ is being rebuilt for the edited case.
            row.organLabel->setEnabled(current);
            row.organLabel->setToolTip(outside ? tr("Outside the expected range for this patient") : QString());
        } else {
            row.organLabel->setText(QStringLiteral("–"));
            row.organLabel->setProperty("outside", false);
        }
    }
}

} // namespace hs::widgets
