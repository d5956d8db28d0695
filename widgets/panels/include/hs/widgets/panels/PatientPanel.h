#pragma once
/// The Patient panel: what a gynaecologist knows of the patient (age, parity, gravidity, height, weight, menopausal
/// state, cycle phase), the organ mode and the seed, and optional measured dimensions. Each field shows its allowed
/// range; a value outside it, or one that contradicts another field, is refused inline and the case stays as it
/// was. Every accepted value is one undoable edit of the document (a run of spin-box steps merges into one), after
/// which the session rebuilds the organ in the background. Beside each dimension: the organ's own, once built, and
/// the 95 % range the published relations give for this patient.

#include <QWidget>

#include <array>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace hs::widgets {

class CaseDocument;
class GenerationSession;

class PatientPanel : public QWidget {
    Q_OBJECT

public:
    PatientPanel(CaseDocument& document, GenerationSession& session, QWidget* parent = nullptr);

    /// The measured dimensions this panel offers, in row order.
    static constexpr int kDimensionCount = 7;

private:
    void buildPatientForm();
    void buildDimensionTable();
    void connectFields();
    /// Shows the document's case in the fields without editing it.
    void refresh();
    /// Shows the organ's own dimensions and this patient's expected ranges.
    void refreshDimensions();

    CaseDocument& m_document;
    GenerationSession& m_session;

    QDoubleSpinBox* m_ageSpin = nullptr;
    QSpinBox* m_paritySpin = nullptr;
    QSpinBox* m_graviditySpin = nullptr;
    QDoubleSpinBox* m_heightSpin = nullptr;
    QDoubleSpinBox* m_weightSpin = nullptr;
    QCheckBox* m_menopausalCheck = nullptr;
    QComboBox* m_cyclePhaseCombo = nullptr;
    QComboBox* m_shapeCombo = nullptr;
    QLineEdit* m_seedEdit = nullptr;
    QPushButton* m_newSeedButton = nullptr;
    QLabel* m_messageLabel = nullptr;

    struct DimensionRow {
        QLabel* organLabel = nullptr;
        QLabel* expectedLabel = nullptr;
        QCheckBox* setCheck = nullptr;
        QDoubleSpinBox* valueSpin = nullptr;
    };
    std::array<DimensionRow, kDimensionCount> m_dimensions{};
    bool m_refreshing = false;
};

} // namespace hs::widgets
