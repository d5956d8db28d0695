#include "hs/widgets/panels/PathologyPanel.h"

#include "hs/pathology/Pathology.h"
#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/jobs/GenerationSession.h"
#include "hs/widgets/panels/CaseEdits.h"

#include <QBrush>
#include <QButtonGroup>
#include <QColor>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QLocale>
#include <QPushButton>
#include <QRadioButton>
#include <QRegularExpressionValidator>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <variant>

namespace hs::widgets {

namespace {

using clinical::FigoType;
using clinical::PathologyKind;
using scene::CaseSpec;
using scene::PathologySpec;

enum MergeKey { kSizeKey = 201, kStalkKey };

struct FigoChoice {
    FigoType type;
    const char* text;
};
// FIGO 8 (cervical, parasitic) is not modelled; hybrids X-Y with X in 1..3 and Y in 5..6.
const FigoChoice kFigoChoices[] = {
    {{0, -1}, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "0 – pedunculated, intracavitary")},
    {{1, -1}, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "1 – submucosal, < 50 % intramural")},
    {{2, -1}, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "2 – submucosal, ≥ 50 % intramural")},
    {{3, -1}, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "3 – intramural, touching the endometrium")},
    {{4, -1}, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "4 – intramural")},
    {{5, -1}, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "5 – subserosal, ≥ 50 % intramural")},
    {{6, -1}, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "6 – subserosal, < 50 % intramural")},
    {{7, -1}, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "7 – subserosal, pedunculated")},
    {{1, 5}, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "1-5 – hybrid, submucosal and subserosal")},
    {{2, 5}, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "2-5 – hybrid, submucosal and subserosal")},
    {{3, 5}, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "3-5 – hybrid, intramural and subserosal")},
};

struct LocationChoice {
    clinical::UterineLocation location;
    const char* text;
};
const LocationChoice kLocations[] = {
    {clinical::UterineLocation::Fundal, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "Fundus")},
    {clinical::UterineLocation::Anterior, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "Anterior wall")},
    {clinical::UterineLocation::Posterior, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "Posterior wall")},
    {clinical::UterineLocation::LeftLateral, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "Left lateral wall")},
    {clinical::UterineLocation::RightLateral, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "Right lateral wall")},
    {clinical::UterineLocation::CornualLeft, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "Left cornu")},
    {clinical::UterineLocation::CornualRight, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "Right cornu")},
    {clinical::UterineLocation::Isthmic, QT_TRANSLATE_NOOP("hs::widgets::PathologyPanel", "Isthmus")},
};

QString kindText(PathologyKind kind) {
    return kind == PathologyKind::Myoma ? PathologyPanel::tr("Myoma") : PathologyPanel::tr("Polyp");
}

/// "myoma-2": the first id of that stem not yet in the case.
std::string freshId(const CaseSpec& spec, const std::string& stem) {
    for (int n = 1;; ++n) {
        const std::string id = stem + "-" + std::to_string(n);
        if (std::none_of(spec.pathologies.begin(), spec.pathologies.end(),
                         [&](const PathologySpec& p) { return p.id == id; }))
            return id;
    }
}

/// The first wall no pathology of the case is placed at by location, so that a new one does not overlap.
clinical::UterineLocation freeLocation(const CaseSpec& spec, PathologyKind kind) {
    for (const LocationChoice& choice : kLocations) {
        const bool taken = std::any_of(spec.pathologies.begin(), spec.pathologies.end(), [&](const PathologySpec& p) {
            const auto* c = std::get_if<clinical::ClinicalPlacement>(&p.placement);
            return c && c->location == choice.location;
        });
        // Polyps hang into the cavity from its upper part; the isthmus is the last resort for either.
        if (!taken && !(kind == PathologyKind::Polyp && choice.location == clinical::UterineLocation::Isthmic))
            return choice.location;
    }
    return clinical::UterineLocation::Fundal;
}

QString itemText(const PathologySpec& p) {
    const QLocale locale;
    QString text = QStringLiteral("%1 – %2, %3 mm")
                       .arg(QString::fromStdString(p.id), kindText(p.kind), locale.toString(p.sizeMm, 'f', 0));
    if (p.figo)
        text += QStringLiteral(", FIGO %1").arg(QString::fromStdString(p.figo->toString()));
    return text;
}

} // namespace

PathologyPanel::PathologyPanel(CaseDocument& document, GenerationSession& session, QWidget* parent)
    : QWidget(parent), m_document(document), m_session(session) {
    setObjectName("pathologyPanel");
    auto* layout = new QVBoxLayout(this);
    (void)layout;
    buildList();
    buildEditor();
    buildResults();
    this->layout()->addWidget(m_messageLabel = new QLabel(this));
    m_messageLabel->setObjectName("pathologyMessageLabel");
    m_messageLabel->setWordWrap(true);
    m_messageLabel->setStyleSheet(QStringLiteral("color: #c0392b;"));
    m_messageLabel->setVisible(false);
    this->layout()->addItem(new QSpacerItem(0, 0, QSizePolicy::Minimum, QSizePolicy::Expanding));
    connectEditor();
    connect(&m_document, &CaseDocument::changed, this, &PathologyPanel::refresh);
    connect(&m_session, &GenerationSession::resultsChanged, this, &PathologyPanel::refreshResults);
    refresh();
    if (m_list->count() > 0)
        m_list->setCurrentRow(0);
}

void PathologyPanel::buildList() {
    m_list = new QListWidget(this);
    m_list->setObjectName("pathologyList");
    m_list->setMaximumHeight(120);
    m_addMyomaButton = new QPushButton(tr("Add &Myoma"), this);
    m_addMyomaButton->setObjectName("addMyomaButton");
    m_addMyomaButton->setToolTip(tr("Add a 20 mm FIGO 2 myoma at a free wall"));
    m_addPolypButton = new QPushButton(tr("Add &Polyp"), this);
    m_addPolypButton->setObjectName("addPolypButton");
    m_addPolypButton->setToolTip(tr("Add a 10 mm sessile polyp at a free wall"));
    m_duplicateButton = new QPushButton(tr("D&uplicate"), this);
    m_duplicateButton->setObjectName("duplicateButton");
    m_duplicateButton->setToolTip(tr("Copy the selected pathology to a free wall"));
    m_removeButton = new QPushButton(tr("&Remove"), this);
    m_removeButton->setObjectName("removeButton");
    // Two rows of two: the panel fits a side dock on a small screen in every language.
    auto* buttons = new QGridLayout;
    buttons->addWidget(m_addMyomaButton, 0, 0);
    buttons->addWidget(m_addPolypButton, 0, 1);
    buttons->addWidget(m_duplicateButton, 1, 0);
    buttons->addWidget(m_removeButton, 1, 1);
    layout()->addWidget(m_list);
    static_cast<QVBoxLayout*>(layout())->addLayout(buttons);
}

void PathologyPanel::buildEditor() {
    auto* group = new QGroupBox(tr("Selected pathology"), this);
    m_editor = group;
    auto* form = new QFormLayout(group);
    m_idEdit = new QLineEdit(group);
    m_idEdit->setObjectName("idEdit");
    m_idEdit->setValidator(
        new QRegularExpressionValidator(QRegularExpression(QStringLiteral("[A-Za-z0-9][A-Za-z0-9_-]{0,31}")), this));
    m_idEdit->setToolTip(tr("Names the pathology's region and files in the scene"));
    form->addRow(tr("&Id"), m_idEdit);

    m_kindCombo = new QComboBox(group);
    m_kindCombo->setObjectName("kindCombo");
    for (PathologyKind kind : clinical::kPathologyKinds)
        m_kindCombo->addItem(kindText(kind), static_cast<int>(kind));
    form->addRow(tr("&Kind"), m_kindCombo);

    m_modelCombo = new QComboBox(group);
    m_modelCombo->setObjectName("modelCombo");
    m_modelCombo->addItem(tr("Cellular automaton"), static_cast<int>(clinical::GrowthModel::CellularAutomaton));
    m_modelCombo->addItem(tr("Skeleton and contours"), static_cast<int>(clinical::GrowthModel::Skeleton));
    m_modelCombo->addItem(tr("Particles"), static_cast<int>(clinical::GrowthModel::Particles));
    m_modelCombo->setToolTip(tr("How the pathology grows (Sierra et al. 2004); the automaton grows myomas only"));
    form->addRow(tr("Gro&wth model"), m_modelCombo);

    m_figoCombo = new QComboBox(group);
    m_figoCombo->setObjectName("figoCombo");
    for (int i = 0; i < static_cast<int>(std::size(kFigoChoices)); ++i)
        m_figoCombo->addItem(tr(kFigoChoices[i].text), i);
    m_figoCombo->setToolTip(tr("FIGO type: how deep the myoma sits in the wall (myomas only)"));
    form->addRow(tr("&FIGO type"), m_figoCombo);

    m_sizeSpin = new QDoubleSpinBox(group);
    m_sizeSpin->setObjectName("sizeSpin");
    m_sizeSpin->setRange(0.0, 200.0);
    m_sizeSpin->setDecimals(1);
    m_sizeSpin->setSuffix(tr(" mm"));
    m_sizeSpin->setKeyboardTracking(false);
    m_sizeSpin->setToolTip(tr("Largest diameter in mm (a pedunculated polyp: of its head). Myomas 5 – 100 mm, "
                              "polyps 3 – 40 mm"));
    form->addRow(tr("Si&ze"), m_sizeSpin);

    m_attachmentCombo = new QComboBox(group);
    m_attachmentCombo->setObjectName("attachmentCombo");
    m_attachmentCombo->addItem(tr("Sessile"), static_cast<int>(clinical::PolypAttachment::Sessile));
    m_attachmentCombo->addItem(tr("Pedunculated"), static_cast<int>(clinical::PolypAttachment::Pedunculated));
    form->addRow(tr("&Attachment"), m_attachmentCombo);

    m_stalkSpin = new QDoubleSpinBox(group);
    m_stalkSpin->setObjectName("stalkSpin");
    m_stalkSpin->setRange(0.0, 100.0);
    m_stalkSpin->setDecimals(1);
    m_stalkSpin->setSuffix(tr(" mm"));
    m_stalkSpin->setKeyboardTracking(false);
    m_stalkSpin->setToolTip(tr("Stalk length in mm, %1 (pedunculated polyps)")
                                .arg(rangeText(scene::limits::kStalkLengthMm, QStringLiteral("mm"))));
    form->addRow(tr("S&talk"), m_stalkSpin);

    m_locationRadio = new QRadioButton(tr("Site"), group);
    m_locationRadio->setObjectName("locationRadio");
    m_locationCombo = new QComboBox(group);
    m_locationCombo->setObjectName("locationCombo");
    for (const LocationChoice& choice : kLocations)
        m_locationCombo->addItem(tr(choice.text), static_cast<int>(choice.location));
    auto* locationRow = new QHBoxLayout;
    locationRow->addWidget(m_locationRadio);
    locationRow->addWidget(m_locationCombo, 1);
    form->addRow(tr("Placement"), locationRow);

    m_pointRadio = new QRadioButton(tr("At a point"), group);
    m_pointRadio->setObjectName("pointRadio");
    m_pointLabel = new QLabel(group);
    m_pointLabel->setObjectName("pointLabel");
    m_pointLabel->setWordWrap(true); // the seat's coordinates wrap rather than widen the panel
    m_placeButton = new QToolButton(group);
    m_placeButton->setObjectName("placeButton");
    m_placeButton->setText(tr("Click on Wall"));
    m_placeButton->setCheckable(true);
    m_placeButton->setToolTip(tr("Then click on the organ's wall in the 3-D view to seat the pathology there "
                                 "(Ctrl+P; Esc cancels)"));
    auto* pointRow = new QHBoxLayout;
    pointRow->addWidget(m_pointRadio);
    pointRow->addWidget(m_pointLabel, 1);
    pointRow->addWidget(m_placeButton);
    form->addRow(QString(), pointRow);
    auto* placements = new QButtonGroup(this);
    placements->addButton(m_locationRadio);
    placements->addButton(m_pointRadio);
    layout()->addWidget(group);
}

void PathologyPanel::buildResults() {
    auto* group = new QGroupBox(tr("Grown"), this);
    auto* box = new QVBoxLayout(group);
    m_growButton = new QPushButton(tr("&Grow"), group);
    m_growButton->setObjectName("growButton");
    m_growButton->setToolTip(tr("Grow every pathology in the organ (Ctrl+G)"));
    m_mergeButton = new QPushButton(tr("M&erge"), group);
    m_mergeButton->setObjectName("mergeButton");
    m_mergeButton->setToolTip(tr("Merge the organ and the pathologies into one body with contact labels"));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_growButton);
    buttons->addWidget(m_mergeButton);
    box->addLayout(buttons);
    m_resultLabel = new QLabel(group);
    m_resultLabel->setObjectName("pathologyResultLabel");
    m_resultLabel->setWordWrap(true);
    m_resultLabel->setTextFormat(Qt::RichText);
    box->addWidget(m_resultLabel);
    m_warningsLabel = new QLabel(group);
    m_warningsLabel->setObjectName("pathologyWarningsLabel");
    m_warningsLabel->setWordWrap(true);
    m_warningsLabel->setTextFormat(Qt::RichText);
    m_warningsLabel->setStyleSheet(QStringLiteral("color: #8a5a00;"));
    box->addWidget(m_warningsLabel);
    layout()->addWidget(group);
}

void PathologyPanel::connectEditor() {
    connect(m_list, &QListWidget::currentRowChanged, this, [this] {
        setPlacing(false);
        refreshEditor();
        refreshResults();
        emit currentChanged();
    });
    connect(&m_document, &CaseDocument::changed, this, &PathologyPanel::currentChanged);
    connect(m_addMyomaButton, &QPushButton::clicked, this, [this] { addPathology(PathologyKind::Myoma); });
    connect(m_addPolypButton, &QPushButton::clicked, this, [this] { addPathology(PathologyKind::Polyp); });
    connect(m_duplicateButton, &QPushButton::clicked, this, &PathologyPanel::duplicateCurrent);
    connect(m_removeButton, &QPushButton::clicked, this, &PathologyPanel::removeCurrent);

    connect(m_idEdit, &QLineEdit::editingFinished, this, [this] {
        const std::string id = m_idEdit->text().toStdString();
        editCurrent(tr("Pathology id"), [id](PathologySpec& p) { p.id = id; });
    });
    connect(m_kindCombo, &QComboBox::currentIndexChanged, this, [this](int index) {
        const auto kind = static_cast<PathologyKind>(m_kindCombo->itemData(index).toInt());
        editCurrent(tr("Pathology kind"), [kind](PathologySpec& p) {
            if (p.kind == kind)
                return;
            p.kind = kind;
            if (kind == PathologyKind::Myoma) {
                p.figo = FigoType{2, -1};
                p.attachment.reset();
                p.stalkLengthMm.reset();
                p.sizeMm = std::max(p.sizeMm, scene::limits::kMyomaSizeMm.min);
            } else {
                p.figo.reset();
                p.attachment = clinical::PolypAttachment::Sessile;
                p.sizeMm = std::min(p.sizeMm, 10.0);
                if (p.growthModel == clinical::GrowthModel::CellularAutomaton)
                    p.growthModel = clinical::GrowthModel::Particles; // the automaton grows myomas only
            }
        });
    });
    connect(m_modelCombo, &QComboBox::currentIndexChanged, this, [this](int index) {
        const auto model = static_cast<clinical::GrowthModel>(m_modelCombo->itemData(index).toInt());
        editCurrent(tr("Growth model"), [model](PathologySpec& p) { p.growthModel = model; });
    });
    connect(m_figoCombo, &QComboBox::currentIndexChanged, this, [this](int index) {
        const FigoType figo = kFigoChoices[m_figoCombo->itemData(index).toInt()].type;
        editCurrent(tr("FIGO type"), [figo](PathologySpec& p) { p.figo = figo; });
    });
    connect(m_sizeSpin, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        editCurrent(
            tr("Pathology size"), [v](PathologySpec& p) { p.sizeMm = v; }, kSizeKey);
    });
    connect(m_attachmentCombo, &QComboBox::currentIndexChanged, this, [this](int index) {
        const auto attachment = static_cast<clinical::PolypAttachment>(m_attachmentCombo->itemData(index).toInt());
        editCurrent(tr("Polyp attachment"), [attachment](PathologySpec& p) {
            p.attachment = attachment;
            if (attachment == clinical::PolypAttachment::Pedunculated && !p.stalkLengthMm)
                p.stalkLengthMm = 10.0;
            if (attachment == clinical::PolypAttachment::Sessile)
                p.stalkLengthMm.reset();
        });
    });
    connect(m_stalkSpin, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        editCurrent(
            tr("Stalk length"), [v](PathologySpec& p) { p.stalkLengthMm = v; }, kStalkKey);
    });
    connect(m_locationRadio, &QRadioButton::toggled, this, [this](bool on) {
        if (on)
            editCurrent(tr("Placement"), [location = static_cast<clinical::UterineLocation>(
                                              m_locationCombo->currentData().toInt())](PathologySpec& p) {
                if (!std::holds_alternative<clinical::ClinicalPlacement>(p.placement))
                    p.placement = clinical::ClinicalPlacement{location};
            });
    });
    connect(m_locationCombo, &QComboBox::currentIndexChanged, this, [this](int index) {
        const auto location = static_cast<clinical::UterineLocation>(m_locationCombo->itemData(index).toInt());
        editCurrent(tr("Placement"),
                    [location](PathologySpec& p) { p.placement = clinical::ClinicalPlacement{location}; });
    });
    connect(m_pointRadio, &QRadioButton::toggled, this, [this](bool on) {
        if (on && !m_refreshing)
            setPlacing(true);
    });
    connect(m_placeButton, &QToolButton::toggled, this, [this](bool on) { setPlacing(on); });
    connect(m_growButton, &QPushButton::clicked, this, [this] { m_session.runThrough(generate::Stage::Pathology); });
    connect(m_mergeButton, &QPushButton::clicked, this, [this] { m_session.runThrough(generate::Stage::Merge); });
}

int PathologyPanel::currentIndex() const {
    return m_list->currentRow();
}

void PathologyPanel::setCurrentIndex(int index) {
    m_list->setCurrentRow(index);
}

bool PathologyPanel::isPlacing() const {
    return m_placeButton->isChecked();
}

std::optional<PathologyPanel::Seat> PathologyPanel::currentSeat() const {
    const int index = currentIndex();
    if (index < 0 || index >= static_cast<int>(m_document.spec().pathologies.size()))
        return std::nullopt;
    const PathologySpec& p = m_document.spec().pathologies[static_cast<std::size_t>(index)];
    const auto* s = std::get_if<clinical::SurfacePlacement>(&p.placement);
    if (!s)
        return std::nullopt;
    return Seat{s->pointMm, s->normal, p.sizeMm};
}

void PathologyPanel::resizeCurrent(double sizeMm) {
    editCurrent(tr("Pathology size"), [sizeMm](PathologySpec& p) { p.sizeMm = sizeMm; });
}

void PathologyPanel::setPlacing(bool placing) {
    if (placing && currentIndex() < 0)
        placing = false;
    if (m_placeButton->isChecked() != placing) {
        const QSignalBlocker blocker(m_placeButton);
        m_placeButton->setChecked(placing);
    }
    if (placing) {
        showMessage(QString());
        if (!m_session.isCurrent(generate::Stage::Organ))
            m_session.runThrough(generate::Stage::Organ);
    }
    // Only a change is news: selecting another pathology while not placing redraws nothing.
    if (placing != m_placingAnnounced) {
        m_placingAnnounced = placing;
        emit placingChanged(placing);
    }
}

void PathologyPanel::placeAt(bool hit, const QVector3D& point) {
    if (seatAt(hit, point))
        setPlacing(false);
}

void PathologyPanel::moveSeat(const QVector3D& point) {
    seatAt(true, point);
}

bool PathologyPanel::seatAt(bool hit, const QVector3D& point) {
    if (!isPlacing())
        return false;
    const int index = currentIndex();
    const auto results = m_session.results();
    if (index < 0)
        return false;
    if (!results || !m_session.isCurrent(generate::Stage::Organ)) {
        showMessage(tr("The organ is still being built: click again once it is shown."));
        return false;
    }
    if (!hit) {
        showMessage(tr("Nothing placed: the click missed the organ. Click on its wall."));
        return false;
    }
    const PathologySpec& spec = m_document.spec().pathologies[static_cast<std::size_t>(index)];
    auto seat = pathology::seatAt(results->organ->mesh, Vec3{point.x(), point.y(), point.z()}, spec.kind);
    if (!seat) {
        switch (seat.error().code) {
        case ErrorCode::Unsupported:
            showMessage(tr("Nothing placed: that is the cervix, where pathologies are not modelled."));
            break;
        default:
            showMessage(spec.kind == PathologyKind::Polyp
                            ? tr("Nothing placed: a polyp grows from the endometrium. Click on the cavity's wall "
                                 "(View > Clip opens the organ).")
                            : tr("Nothing placed: the click is not on the organ's wall."));
            break;
        }
        return false;
    }
    const clinical::SurfacePlacement placement = *seat;
    editCurrent(tr("Place on wall"), [placement](PathologySpec& p) { p.placement = placement; });
    return true;
}

void PathologyPanel::showMessage(const QString& text) {
    m_messageLabel->setText(text);
    m_messageLabel->setVisible(!text.isEmpty());
}

void PathologyPanel::editCurrent(const QString& text, const std::function<void(PathologySpec&)>& change, int mergeKey) {
    const int index = currentIndex();
    if (m_refreshing || index < 0)
        return;
    const auto i = static_cast<std::size_t>(index);
    tryEdit(
        m_document, text, [&change, i](CaseSpec& s) { change(s.pathologies[i]); },
        QStringLiteral("/pathologies/%1").arg(index), m_messageLabel, nullptr,
        mergeKey == 0 ? 0 : mergeKey + 1000 * index); // steps of one field of one pathology merge; other edits never
}

void PathologyPanel::addPathology(PathologyKind kind) {
    const CaseSpec& spec = m_document.spec();
    if (spec.pathologies.size() >= scene::kMaxPathologies) {
        showMessage(tr("A case holds at most %1 pathologies.").arg(scene::kMaxPathologies));
        return;
    }
    PathologySpec p;
    p.kind = kind;
    if (kind == PathologyKind::Myoma) {
        p.id = freshId(spec, "myoma");
        p.sizeMm = 20.0;
        p.figo = FigoType{2, -1};
    } else {
        p.id = freshId(spec, "polyp");
        p.sizeMm = 10.0;
        p.attachment = clinical::PolypAttachment::Sessile;
    }
    p.placement = clinical::ClinicalPlacement{freeLocation(spec, kind)};
    m_document.edit(kind == PathologyKind::Myoma ? tr("Add myoma") : tr("Add polyp"),
                    [p](CaseSpec& s) { s.pathologies.push_back(p); });
    m_list->setCurrentRow(m_list->count() - 1);
}

void PathologyPanel::duplicateCurrent() {
    const int index = currentIndex();
    const CaseSpec& spec = m_document.spec();
    if (index < 0 || spec.pathologies.size() >= scene::kMaxPathologies)
        return;
    PathologySpec copy = spec.pathologies[static_cast<std::size_t>(index)];
    copy.id = freshId(spec, copy.kind == PathologyKind::Myoma ? "myoma" : "polyp");
    copy.placement = clinical::ClinicalPlacement{freeLocation(spec, copy.kind)};
    m_document.edit(tr("Duplicate pathology"), [copy](CaseSpec& s) { s.pathologies.push_back(copy); });
    m_list->setCurrentRow(m_list->count() - 1);
}

void PathologyPanel::removeCurrent() {
    const int index = currentIndex();
    if (index < 0)
        return;
    m_document.edit(tr("Remove pathology"),
                    [index](CaseSpec& s) { s.pathologies.erase(s.pathologies.begin() + index); });
    m_list->setCurrentRow(std::min(index, m_list->count() - 1));
}

void PathologyPanel::refresh() {
    m_refreshing = true;
    const CaseSpec& spec = m_document.spec();
    const int row = m_list->currentRow();
    // Rebuild the list only when its length changed; otherwise update the texts in place (keeps the selection).
    if (m_list->count() != static_cast<int>(spec.pathologies.size())) {
        m_list->clear();
        for (const PathologySpec& p : spec.pathologies)
            m_list->addItem(itemText(p));
        m_list->setCurrentRow(
            std::clamp(row, spec.pathologies.empty() ? -1 : 0, static_cast<int>(spec.pathologies.size()) - 1));
    } else {
        for (std::size_t i = 0; i < spec.pathologies.size(); ++i)
            m_list->item(static_cast<int>(i))->setText(itemText(spec.pathologies[i]));
    }
    markFigoMismatches();
    m_duplicateButton->setEnabled(m_list->currentRow() >= 0);
    m_removeButton->setEnabled(m_list->currentRow() >= 0);
    m_refreshing = false;
    refreshEditor();
    refreshResults();
}

void PathologyPanel::refreshEditor() {
    const int index = currentIndex();
    const CaseSpec& spec = m_document.spec();
    m_editor->setEnabled(index >= 0);
    m_duplicateButton->setEnabled(index >= 0);
    m_removeButton->setEnabled(index >= 0);
    if (index < 0 || index >= static_cast<int>(spec.pathologies.size()))
        return;
    m_refreshing = true;
    const PathologySpec& p = spec.pathologies[static_cast<std::size_t>(index)];
    const bool myoma = p.kind == PathologyKind::Myoma;
    m_idEdit->setText(QString::fromStdString(p.id));
    m_kindCombo->setCurrentIndex(m_kindCombo->findData(static_cast<int>(p.kind)));
    m_modelCombo->setCurrentIndex(m_modelCombo->findData(static_cast<int>(p.growthModel)));
    m_figoCombo->setEnabled(myoma);
    if (p.figo) {
        for (int i = 0; i < static_cast<int>(std::size(kFigoChoices)); ++i)
            if (kFigoChoices[i].type == *p.figo)
                m_figoCombo->setCurrentIndex(i);
    }
    m_sizeSpin->setValue(p.sizeMm);
    m_attachmentCombo->setEnabled(!myoma);
    if (p.attachment)
        m_attachmentCombo->setCurrentIndex(m_attachmentCombo->findData(static_cast<int>(*p.attachment)));
    m_stalkSpin->setEnabled(p.stalkLengthMm.has_value());
    m_stalkSpin->setValue(p.stalkLengthMm.value_or(0.0));
    if (const auto* c = std::get_if<clinical::ClinicalPlacement>(&p.placement)) {
        m_locationRadio->setChecked(true);
        m_locationCombo->setEnabled(true);
        m_locationCombo->setCurrentIndex(m_locationCombo->findData(static_cast<int>(c->location)));
        m_pointLabel->setText(QString());
    } else {
        const auto& s = std::get<clinical::SurfacePlacement>(p.placement);
        m_pointRadio->setChecked(true);
        m_locationCombo->setEnabled(false);
        const QLocale locale;
        m_pointLabel->setText(tr("(%1, %2, %3) mm")
                                  .arg(locale.toString(s.pointMm.x, 'f', 1), locale.toString(s.pointMm.y, 'f', 1),
                                       locale.toString(s.pointMm.z, 'f', 1)));
    }
    m_refreshing = false;
}

namespace {

/// The FIGO type measured for pathology `id`: on the final body when the scene is current, else on the grown
/// pathology; nothing for a polyp or before growth.
std::optional<FigoType> measuredFigo(const generate::Generated& results, bool sceneCurrent, const std::string& id) {
    if (sceneCurrent && results.scene)
        for (const scene::PathologyDescriptor& d : results.scene->clinical.pathologies)
            if (d.id == id)
                return d.figo;
    if (results.pathologies)
        for (const pathology::GrownPathology& g : results.pathologies->pathologies)
            if (g.id == id && g.descriptors.kind == PathologyKind::Myoma)
                return g.descriptors.figo;
    return std::nullopt;
}

} // namespace

void PathologyPanel::markFigoMismatches() {
    const auto results = m_session.results();
    const bool sceneCurrent = m_session.isCurrent(generate::Stage::Scene);
    const auto& pathologies = m_document.spec().pathologies;
    for (int row = 0; row < m_list->count() && row < static_cast<int>(pathologies.size()); ++row) {
        const PathologySpec& p = pathologies[static_cast<std::size_t>(row)];
        QListWidgetItem* item = m_list->item(row);
        const auto measured = results ? measuredFigo(*results, sceneCurrent, p.id) : std::nullopt;
        const bool differs = p.figo && measured && *measured != *p.figo;
        item->setText(
            itemText(p) +
            (differs ? QStringLiteral("  ⚠ ") + tr("measured FIGO %1").arg(QString::fromStdString(measured->toString()))
                     : QString()));
        item->setForeground(differs ? QBrush(QColor(0xc0, 0x39, 0x2b)) : QBrush());
        item->setData(Qt::UserRole, differs);
    }
}

void PathologyPanel::refreshResults() {
    markFigoMismatches();
    const int index = currentIndex();
    const auto results = m_session.results();
    const bool grown = results && results->pathologies && m_session.isCurrent(generate::Stage::Pathology);
    m_mergeButton->setEnabled(!m_document.spec().pathologies.empty() || grown);
    if (index < 0 || !results || !results->pathologies) {
        m_resultLabel->setText(tr("Not grown yet."));
        m_warningsLabel->clear();
        return;
    }
    const PathologySpec& asked = m_document.spec().pathologies[static_cast<std::size_t>(index)];
    const std::string& id = asked.id;
    const auto& list = results->pathologies->pathologies;
    const auto it =
        std::find_if(list.begin(), list.end(), [&](const pathology::GrownPathology& g) { return g.id == id; });
    if (it == list.end()) {
        m_resultLabel->setText(tr("Not grown yet."));
        m_warningsLabel->clear();
        return;
    }
    const pathology::Descriptors& d = it->descriptors;
    const QLocale locale;
    QString text;
    if (d.kind == PathologyKind::Myoma) {
        text = tr("Measured: FIGO <b>%1</b>, %2 mm, %3 % in the wall, %4 % in the cavity")
                   .arg(QString::fromStdString(d.figo.toString()), locale.toString(d.sizeMm, 'f', 1),
                        locale.toString(100.0 * d.intramuralFraction, 'f', 0),
                        locale.toString(100.0 * d.cavityFraction, 'f', 0));
        if (d.lasmar.complete())
            text += QStringLiteral("<br>") +
                    tr("Lasmar score <b>%1</b> (size %2, topography %3, extension %4, penetration %5, wall %6)")
                        .arg(d.lasmar.total())
                        .arg(d.lasmar.size)
                        .arg(d.lasmar.topography)
                        .arg(d.lasmar.extension)
                        .arg(d.lasmar.penetration)
                        .arg(d.lasmar.wall);
        // The type the trainee meets is the final body's when the scene is current.
        const auto final = measuredFigo(*results, m_session.isCurrent(generate::Stage::Scene), id);
        if (final && !(*final == d.figo))
            text += QStringLiteral("<br>") +
                    tr("On the final body: FIGO <b>%1</b>").arg(QString::fromStdString(final->toString()));
        const auto shown = final ? *final : d.figo;
        if (asked.figo && !(shown == *asked.figo))
            text += QStringLiteral("<br><span style='color:#c0392b'>⚠ ") +
                    tr("Requested FIGO %1, measured FIGO %2: the trainee meets another type than the case asks for.")
                        .arg(QString::fromStdString(asked.figo->toString()), QString::fromStdString(shown.toString())) +
                    QStringLiteral("</span>");
    } else {
        text = d.pedunculated ? tr("Measured: a %1 mm head on a %2 mm stalk")
                                    .arg(locale.toString(d.sizeMm, 'f', 1), locale.toString(d.stalkLengthMm, 'f', 1))
                              : tr("Measured: sessile, %1 mm, base %2 mm")
                                    .arg(locale.toString(d.sizeMm, 'f', 1), locale.toString(d.baseWidthMm, 'f', 1));
    }
    if (!m_session.isCurrent(generate::Stage::Pathology))
        text += QStringLiteral("<br><i>") + tr("From before the last edit: grow again.") + QStringLiteral("</i>");
    m_resultLabel->setText(text);
    // The stage's notes name the pathology by id; they are technical English, shown as the stage wrote them, in
    // the panel (not behind a tooltip).
    QStringList notes;
    for (const std::string& w : results->pathologies->warnings)
        if (w.find(id) != std::string::npos)
            notes << QStringLiteral("• ") + QString::fromStdString(w).toHtmlEscaped();
    m_warningsLabel->setText(notes.isEmpty() ? QString()
                                             : tr("%n note(s) from the stage:", "", int(notes.size())) +
                                                   QStringLiteral("<br>") + notes.join(QStringLiteral("<br>")));
    m_warningsLabel->setToolTip(QString());
}

} // namespace hs::widgets
