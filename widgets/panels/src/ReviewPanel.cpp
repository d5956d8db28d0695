#include "hs/widgets/panels/ReviewPanel.h"

#include "hs/widgets/view/HysteroscopicPreview.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace hs::widgets {

namespace {

enum PathologyColumn { kIdColumn, kKindColumn, kModelColumn, kVisitColumn, kScoreColumn, kCommentColumn };
enum TextureColumn { kAppearanceColumn, kTextureScoreColumn, kTextureCommentColumn };

QString modelName(clinical::GrowthModel model) {
    switch (model) {
    case clinical::GrowthModel::CellularAutomaton:
        return ReviewPanel::tr("cellular automaton");
    case clinical::GrowthModel::Skeleton:
        return ReviewPanel::tr("skeleton");
    case clinical::GrowthModel::Particles:
        break;
    }
    return ReviewPanel::tr("particles");
}

/// A texture's appearance ("endometrium", "myoma", "polyp") in the user's language.
QString appearanceName(const std::string& appearance) {
    if (appearance == "endometrium")
        return ReviewPanel::tr("endometrium");
    if (appearance == "myoma")
        return ReviewPanel::tr("myoma");
    if (appearance == "polyp")
        return ReviewPanel::tr("polyp");
    return QString::fromStdString(appearance);
}

/// A summary group ("myoma / particles", "texture / endometrium"; scene::summarize) in the user's language.
QString groupName(const std::string& group) {
    const std::size_t slash = group.find(" / ");
    if (slash == std::string::npos)
        return QString::fromStdString(group);
    const std::string head = group.substr(0, slash), tail = group.substr(slash + 3);
    if (head == "texture")
        return ReviewPanel::tr("texture / %1").arg(appearanceName(tail));
    clinical::GrowthModel model = clinical::GrowthModel::Particles;
    const QString kind = appearanceName(head);
    if (tail == clinical::toString(clinical::GrowthModel::CellularAutomaton))
        model = clinical::GrowthModel::CellularAutomaton;
    else if (tail == clinical::toString(clinical::GrowthModel::Skeleton))
        model = clinical::GrowthModel::Skeleton;
    else if (tail != clinical::toString(clinical::GrowthModel::Particles))
        return QString::fromStdString(group);
    return ReviewPanel::tr("%1 / %2").arg(kind, modelName(model));
}

QSpinBox* scoreSpin(QWidget* parent, const QString& name) {
    auto* spin = new QSpinBox(parent);
    spin->setObjectName(name);
    spin->setRange(0, 5);
    spin->setSpecialValueText(ReviewPanel::tr("–"));
    spin->setToolTip(ReviewPanel::tr("1: not realistic … 5: indistinguishable from a real one; – not rated"));
    return spin;
}

QTableWidget* makeTable(QWidget* parent, const char* name, const QStringList& headers) {
    auto* table = new QTableWidget(0, int(headers.size()), parent);
    table->setObjectName(name);
    table->setHorizontalHeaderLabels(headers);
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->horizontalHeader()->setStretchLastSection(true);
    table->verticalHeader()->hide();
    table->setSelectionMode(QAbstractItemView::NoSelection);
    return table;
}

} // namespace

ReviewPanel::ReviewPanel(QWidget* parent) : QWidget(parent) {
    setObjectName("reviewPanel");
    auto* layout = new QVBoxLayout(this);
    m_packageLabel = new QLabel(tr("No package opened for review (File > Review Scene Package)."), this);
    m_packageLabel->setObjectName("reviewPackageLabel");
    m_packageLabel->setWordWrap(true);
    layout->addWidget(m_packageLabel);
    auto* reviewerRow = new QHBoxLayout;
    reviewerRow->addWidget(new QLabel(tr("Reviewer"), this));
    m_reviewerEdit = new QLineEdit(this);
    m_reviewerEdit->setObjectName("reviewerEdit");
    m_reviewerEdit->setMaxLength(200);
    reviewerRow->addWidget(m_reviewerEdit, 1);
    layout->addLayout(reviewerRow);

    auto* pathologies = new QGroupBox(tr("Pathologies"), this);
    auto* pathologyBox = new QVBoxLayout(pathologies);
    m_pathologyTable = makeTable(pathologies, "reviewPathologyTable",
                                 {tr("Id"), tr("Kind"), tr("Growth"), QString(), tr("Realism"), tr("Comment")});
    pathologyBox->addWidget(m_pathologyTable);
    layout->addWidget(pathologies);
    auto* textures = new QGroupBox(tr("Textures"), this);
    auto* textureBox = new QVBoxLayout(textures);
    m_textureTable = makeTable(textures, "reviewTextureTable", {tr("Appearance"), tr("Realism"), tr("Comment")});
    textureBox->addWidget(m_textureTable);
    layout->addWidget(textures);

    m_saveButton = new QPushButton(tr("Save &Review"), this);
    m_saveButton->setObjectName("saveReviewButton");
    m_saveButton->setToolTip(tr("Write the ratings beside the package (the package itself is not changed)"));
    layout->addWidget(m_saveButton);
    m_messageLabel = new QLabel(this);
    m_messageLabel->setObjectName("reviewMessageLabel");
    m_messageLabel->setWordWrap(true);
    layout->addWidget(m_messageLabel);

    auto* summary = new QGroupBox(tr("All reviews in this folder"), this);
    auto* summaryBox = new QVBoxLayout(summary);
    m_summaryTable =
        makeTable(summary, "reviewSummaryTable", {tr("Group"), tr("Ratings"), tr("Mean"), tr("Lowest"), tr("Highest")});
    summaryBox->addWidget(m_summaryTable);
    layout->addWidget(summary);
    layout->addStretch(1);
    setEnabled(false);

    connect(m_saveButton, &QPushButton::clicked, this, &ReviewPanel::save);
    connect(m_reviewerEdit, &QLineEdit::textEdited, this, [this](const QString& text) {
        m_review.reviewer = text.toStdString();
        setModified(true);
    });
}

void ReviewPanel::open(std::shared_ptr<const scene::Scene> scene, const QString& packageFolder,
                       const QString& packageSha256) {
    m_scene = std::move(scene);
    m_folder = packageFolder;
    m_review = scene::emptyReview(*m_scene, packageSha256.toStdString());
    m_messageLabel->clear();
    m_messageLabel->setToolTip(QString());
    m_foreignReview.clear();
    // A review of this very package (same manifest) is read back. One of another package, or one that cannot be
    // read, is refused by name and kept: saving moves it aside (foreignReviewKeptAs) before writing this one.
    const std::string reviewPath = scene::reviewPathFor(QFile::encodeName(packageFolder).toStdString());
    const QString reviewFile = QDir::toNativeSeparators(QString::fromStdString(reviewPath));
    if (QFileInfo::exists(QString::fromStdString(reviewPath))) {
        auto saved = scene::loadReview(reviewPath);
        if (saved && saved->packageSha256 == m_review.packageSha256) {
            m_review = std::move(saved).value();
        } else {
            m_foreignReview = QString::fromStdString(reviewPath);
            const QString keptAs = QDir::toNativeSeparators(foreignReviewKeptAs());
            if (saved)
                m_messageLabel->setText(
                    tr("<span style='color:#c0392b'>The review %1 is of another package (manifest SHA-256 %2…, this "
                       "package's %3…): it is not loaded. Saving keeps it as %4.</span>")
                        .arg(reviewFile.toHtmlEscaped(), QString::fromStdString(saved->packageSha256.substr(0, 12)),
                             QString::fromStdString(m_review.packageSha256.substr(0, 12)), keptAs.toHtmlEscaped()));
            else
                m_messageLabel->setText(tr("<span style='color:#c0392b'>The review %1 cannot be read: it is not "
                                           "loaded. Saving keeps it as %2.</span>")
                                            .arg(reviewFile.toHtmlEscaped(), keptAs.toHtmlEscaped()));
            if (!saved)
                m_messageLabel->setToolTip(QString::fromStdString(saved.error().message()));
        }
    }
    m_packageLabel->setText(tr("Reviewing %1 (read-only)").arg(QDir::toNativeSeparators(packageFolder)));
    m_reviewerEdit->setText(QString::fromStdString(m_review.reviewer));
    fillTables();
    refreshSummary();
    setEnabled(true);
    setModified(false);
}

QString ReviewPanel::foreignReviewKeptAs() const {
    // "<folder>.review.json.other-N": out of the folder's summary (*.review.json), never over another kept one.
    for (int n = 1;; ++n) {
        const QString candidate = m_foreignReview + QStringLiteral(".other-%1").arg(n);
        if (!QFileInfo::exists(candidate))
            return candidate;
    }
}

void ReviewPanel::showNotice(const QString& text) {
    m_messageLabel->setText(
        text.isEmpty() ? QString() : QStringLiteral("<span style='color:#c0392b'>%1</span>").arg(text.toHtmlEscaped()));
}

void ReviewPanel::close() {
    m_foreignReview.clear();
    m_scene.reset();
    m_folder.clear();
    m_review = {};
    m_pathologyTable->setRowCount(0);
    m_textureTable->setRowCount(0);
    m_packageLabel->setText(tr("No package opened for review (File > Review Scene Package)."));
    setEnabled(false);
    setModified(false);
}

void ReviewPanel::fillTables() {
    m_filling = true;
    m_pathologyTable->setRowCount(int(m_review.pathologies.size()));
    for (int row = 0; row < int(m_review.pathologies.size()); ++row) {
        const scene::PathologyRating& p = m_review.pathologies[std::size_t(row)];
        m_pathologyTable->setItem(row, kIdColumn, new QTableWidgetItem(QString::fromStdString(p.id)));
        m_pathologyTable->setItem(
            row, kKindColumn,
            new QTableWidgetItem(p.kind == clinical::PathologyKind::Myoma ? tr("myoma") : tr("polyp")));
        m_pathologyTable->setItem(row, kModelColumn, new QTableWidgetItem(modelName(p.growthModel)));
        auto* visit = new QPushButton(tr("Visit"), m_pathologyTable);
        visit->setObjectName(QStringLiteral("visitButton%1").arg(row));
        visit->setToolTip(tr("Look at this pathology from inside the cavity"));
        connect(visit, &QPushButton::clicked, this, [this, row] { visitPathology(row); });
        m_pathologyTable->setCellWidget(row, kVisitColumn, visit);
        addRatingCells(m_pathologyTable, row, kScoreColumn, QStringLiteral("pathology"), p.rating,
                       [this, row](int score, const QString& comment) { ratePathology(row, score, comment); });
    }
    m_textureTable->setRowCount(int(m_review.textures.size()));
    for (int row = 0; row < int(m_review.textures.size()); ++row) {
        const scene::TextureRating& t = m_review.textures[std::size_t(row)];
        m_textureTable->setItem(row, kAppearanceColumn, new QTableWidgetItem(appearanceName(t.appearance)));
        addRatingCells(m_textureTable, row, kTextureScoreColumn, QStringLiteral("texture"), t.rating,
                       [this, row](int score, const QString& comment) { rateTexture(row, score, comment); });
    }
    m_filling = false;
}

void ReviewPanel::addRatingCells(QTableWidget* table, int row, int scoreColumn, const QString& prefix,
                                 const scene::Rating& rating, const std::function<void(int, const QString&)>& rate) {
    QSpinBox* score = scoreSpin(table, QStringLiteral("%1Score%2").arg(prefix).arg(row));
    score->setValue(rating.score.value_or(0));
    table->setCellWidget(row, scoreColumn, score);
    auto* comment = new QLineEdit(QString::fromStdString(rating.comment), table);
    comment->setObjectName(QStringLiteral("%1Comment%2").arg(prefix).arg(row));
    comment->setMaxLength(int(scene::kMaxReviewCommentLength));
    table->setCellWidget(row, scoreColumn + 1, comment); // the comment follows the score
    const auto update = [this, score, comment, rate] {
        if (!m_filling)
            rate(score->value(), comment->text());
    };
    connect(score, &QSpinBox::valueChanged, this, update);
    connect(comment, &QLineEdit::textEdited, this, update);
}

void ReviewPanel::ratePathology(int row, int score, const QString& comment) {
    if (row < 0 || row >= int(m_review.pathologies.size()))
        return;
    scene::Rating& r = m_review.pathologies[std::size_t(row)].rating;
    r.score = score >= 1 && score <= 5 ? std::optional(score) : std::nullopt;
    r.comment = comment.toStdString();
    setModified(true);
}

void ReviewPanel::rateTexture(int row, int score, const QString& comment) {
    if (row < 0 || row >= int(m_review.textures.size()))
        return;
    scene::Rating& r = m_review.textures[std::size_t(row)].rating;
    r.score = score >= 1 && score <= 5 ? std::optional(score) : std::nullopt;
    r.comment = comment.toStdString();
    setModified(true);
}

bool ReviewPanel::visitPathology(int row) {
    if (!m_scene || !m_preview || row < 0 || row >= int(m_review.pathologies.size()))
        return false;
    const std::string& id = m_review.pathologies[std::size_t(row)].id;
    for (const scene::SceneRegion& region : m_scene->regions)
        if (region.pathologyId == id)
            return m_preview->lookAtRegion(region.id);
    m_messageLabel->setText(tr("The pathology %1 is not a region of this scene.").arg(QString::fromStdString(id)));
    return false;
}

bool ReviewPanel::save() {
    if (!m_scene)
        return false;
    const std::string path = scene::reviewPathFor(QFile::encodeName(m_folder).toStdString());
    // The review of another package that stood here is kept, never overwritten.
    if (!m_foreignReview.isEmpty() && QFileInfo::exists(m_foreignReview)) {
        const QString keptAs = foreignReviewKeptAs();
        if (!QFile::rename(m_foreignReview, keptAs)) {
            m_messageLabel->setText(tr("<span style='color:#c0392b'>The review of another package, %1, could not "
                                       "be moved to %2: nothing was saved.</span>")
                                        .arg(QDir::toNativeSeparators(m_foreignReview).toHtmlEscaped(),
                                             QDir::toNativeSeparators(keptAs).toHtmlEscaped()));
            return false;
        }
    }
    m_foreignReview.clear();
    if (const Status saved = scene::saveReview(m_review, path); !saved) {
        m_messageLabel->setText(tr("<span style='color:#c0392b'>The review could not be written beside the "
                                   "package (is the folder read-only?).</span>"));
        m_messageLabel->setToolTip(QString::fromStdString(saved.error().message()));
        return false;
    }
    m_messageLabel->setText(tr("Saved to %1.").arg(QDir::toNativeSeparators(QString::fromStdString(path))));
    setModified(false);
    refreshSummary();
    return true;
}

void ReviewPanel::refreshSummary() {
    // Every review in the package's folder: the variants of a case, or a curriculum's packages.
    std::vector<scene::Review> reviews;
    const QDir folder = QFileInfo(m_folder).dir();
    for (const QString& name : folder.entryList({QStringLiteral("*.review.json")}, QDir::Files, QDir::Name)) {
        auto review = scene::loadReview(QFile::encodeName(folder.filePath(name)).toStdString());
        if (review)
            reviews.push_back(std::move(review).value());
    }
    const std::vector<scene::RatingSummary> rows = scene::summarize(reviews);
    const QLocale locale;
    m_summaryTable->setRowCount(int(rows.size()));
    for (int i = 0; i < int(rows.size()); ++i) {
        const scene::RatingSummary& r = rows[std::size_t(i)];
        m_summaryTable->setItem(i, 0, new QTableWidgetItem(groupName(r.group)));
        m_summaryTable->setItem(i, 1, new QTableWidgetItem(QString::number(r.count)));
        m_summaryTable->setItem(i, 2, new QTableWidgetItem(locale.toString(r.mean, 'f', 2)));
        m_summaryTable->setItem(i, 3, new QTableWidgetItem(QString::number(r.lowest)));
        m_summaryTable->setItem(i, 4, new QTableWidgetItem(QString::number(r.highest)));
    }
}

void ReviewPanel::setModified(bool modified) {
    if (m_modified == modified)
        return;
    m_modified = modified;
    emit modifiedChanged(modified);
}

} // namespace hs::widgets
