#pragma once
/// The Review panel: a clinician rates how real a scene package looks. Each pathology of the package is listed
/// with Visit (the hysteroscopic preview looks at it from inside the cavity), a score 1-5 and a comment; each
/// texture (endometrium, myoma, polyp) likewise. Save writes the review beside the package (scene::reviewPathFor),
/// never inside it; the summary pools every review in the package's folder by pathology kind and growth model.
/// The package itself is read-only here.

#include "hs/scene/Review.h"
#include "hs/scene/Scene.h"

#include <QString>
#include <QWidget>

#include <functional>
#include <memory>

class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace hs::widgets {

class HysteroscopicPreview;

class ReviewPanel : public QWidget {
    Q_OBJECT

public:
    explicit ReviewPanel(QWidget* parent = nullptr);

    /// Where Visit points the scope; may be null.
    void setPreview(HysteroscopicPreview* preview) { m_preview = preview; }
    /// Starts reviewing `scene`, read from `packageFolder` whose manifest hashes to `packageSha256`: the review
    /// beside the package is read back when there is one for this package, else an empty one is started.
    void open(std::shared_ptr<const scene::Scene> scene, const QString& packageFolder, const QString& packageSha256);
    void close();
    bool isOpen() const { return m_scene != nullptr; }
    QString packageFolder() const { return m_folder; }
    /// The SHA-256 of the manifest of the package opened (the review names it so).
    QString packageSha256() const { return QString::fromStdString(m_review.packageSha256); }
    /// A line under the package's name (e.g. that the package changed on disk); empty clears it.
    void showNotice(const QString& text);
    const scene::Review& review() const { return m_review; }
    bool isModified() const { return m_modified; }

    /// Rates pathology row `row` (or texture row `row`): `score` 1-5, 0 for not rated.
    void ratePathology(int row, int score, const QString& comment);
    void rateTexture(int row, int score, const QString& comment);
    /// Visit: the preview looks at pathology `row`; false when it cannot (no preview, region not found).
    bool visitPathology(int row);
    /// Writes the review beside the package; false (with a message) when it cannot be written.
    bool save();

signals:
    void modifiedChanged(bool modified);

private:
    void fillTables();
    /// The score and comment cells of a rating at (row, scoreColumn) and (row, scoreColumn + 1); `rate` takes edits.
    void addRatingCells(QTableWidget* table, int row, int scoreColumn, const QString& prefix,
                        const scene::Rating& rating, const std::function<void(int, const QString&)>& rate);
    void refreshSummary();
    void setModified(bool modified);

    std::shared_ptr<const scene::Scene> m_scene;
    QString m_folder;
    QString m_foreignReview; ///< a review of another package (or unreadable) beside this one, kept when saving
    QString foreignReviewKeptAs() const;
    scene::Review m_review;
    bool m_modified = false;
    bool m_filling = false;
    HysteroscopicPreview* m_preview = nullptr;

    QLabel* m_packageLabel = nullptr;
    QLineEdit* m_reviewerEdit = nullptr;
    QTableWidget* m_pathologyTable = nullptr;
    QTableWidget* m_textureTable = nullptr;
    QPushButton* m_saveButton = nullptr;
    QLabel* m_messageLabel = nullptr;
    QTableWidget* m_summaryTable = nullptr;
};

} // namespace hs::widgets
