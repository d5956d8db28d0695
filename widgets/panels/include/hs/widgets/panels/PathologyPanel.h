#pragma once
/// The Pathologies panel: the case's pathologies as a list (add a myoma or a polyp, duplicate, remove) and an editor
/// for the selected one: kind, growth model, FIGO type, size, polyp attachment and stalk, and where it sits, by
/// clinical location or by a click on the organ wall in the 3-D view (pathology::seatAt turns the click into a seat
/// point and its normal). Grow and Merge run those stages in the background; what the pathology stage measured on
/// each grown pathology (FIGO type, size, Lasmar score) and the stage's warnings are shown beside the request.

#include "hs/scene/CaseSpec.h"

#include <QVector3D>
#include <QWidget>

#include <optional>

class QButtonGroup;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QRadioButton;
class QToolButton;

namespace hs::widgets {

class CaseDocument;
class GenerationSession;

class PathologyPanel : public QWidget {
    Q_OBJECT

public:
    PathologyPanel(CaseDocument& document, GenerationSession& session, QWidget* parent = nullptr);

    /// The selected pathology's index in the case; -1 when none.
    int currentIndex() const;
    void setCurrentIndex(int index);
    /// Whether the next click in the 3-D view places the selected pathology.
    bool isPlacing() const;
    /// The selected pathology's seat when it is placed at a point (the handles in the 3-D view show it).
    struct Seat {
        Vec3 pointMm;
        Vec3 normal;
        double sizeMm = 0.0;
    };
    std::optional<Seat> currentSeat() const;
    /// Resizes the selected pathology (a drag of the size handle); refused with a reason when out of range.
    void resizeCurrent(double sizeMm);

public slots:
    /// A click in the 3-D view while placing: `hit` false when it missed every surface; `point` in mm. Seats the
    /// pathology there and ends placing.
    void placeAt(bool hit, const QVector3D& point);
    /// The seat handle dropped at `point` (mm) while placing: seats the pathology there as a click does, and placing
    /// goes on (the handles stay for the next adjustment, as after the size handle).
    void moveSeat(const QVector3D& point);

signals:
    /// Placing by a click starts (the view shows the organ to click on) or ends.
    void placingChanged(bool placing);
    /// Another pathology was selected, or the selected one changed.
    void currentChanged();

private:
    void buildList();
    void buildEditor();
    void buildResults();
    void connectEditor();
    void refresh();
    void refreshEditor();
    void refreshResults();
    /// Marks, in the list, each myoma whose measured FIGO type (the final body's when the scene is current) differs
    /// from the requested one: red, with the measured type after its name.
    void markFigoMismatches();
    void setPlacing(bool placing);
    /// One edit of the selected pathology; refused with a reason when the case would break a rule.
    void editCurrent(const QString& text, const std::function<void(scene::PathologySpec&)>& change, int mergeKey = 0);
    void addPathology(clinical::PathologyKind kind);
    void duplicateCurrent();
    void removeCurrent();
    void showMessage(const QString& text);
    /// Seats the current pathology where a click or a drop landed; false (with the reason shown) when it cannot.
    bool seatAt(bool hit, const QVector3D& point);

    CaseDocument& m_document;
    GenerationSession& m_session;
    bool m_refreshing = false;
    bool m_placingAnnounced = false; ///< the state placingChanged last told

    QListWidget* m_list = nullptr;
    QPushButton* m_addMyomaButton = nullptr;
    QPushButton* m_addPolypButton = nullptr;
    QPushButton* m_duplicateButton = nullptr;
    QPushButton* m_removeButton = nullptr;

    QWidget* m_editor = nullptr;
    QLineEdit* m_idEdit = nullptr;
    QComboBox* m_kindCombo = nullptr;
    QComboBox* m_modelCombo = nullptr;
    QComboBox* m_figoCombo = nullptr;
    QDoubleSpinBox* m_sizeSpin = nullptr;
    QComboBox* m_attachmentCombo = nullptr;
    QDoubleSpinBox* m_stalkSpin = nullptr;
    QRadioButton* m_locationRadio = nullptr;
    QComboBox* m_locationCombo = nullptr;
    QRadioButton* m_pointRadio = nullptr;
    QToolButton* m_placeButton = nullptr;
    QLabel* m_pointLabel = nullptr;

    QPushButton* m_growButton = nullptr;
    QPushButton* m_mergeButton = nullptr;
    QLabel* m_resultLabel = nullptr;
    QLabel* m_warningsLabel = nullptr;
    QLabel* m_messageLabel = nullptr;
};

} // namespace hs::widgets
