#pragma once
/// The Materials panel: per tissue (myometrium, endometrium, cervix, myoma, polyp) the Young's modulus (kPa), the
/// Poisson ratio, the density (kg/m³) and the myoma's heterogeneity, each with the literature default and the
/// allowed range (scene::defaultMaterial, youngsModulusRangeKpa, limits). A value the user sets is stored in the
/// case as an override; Default clears the tissue's overrides. Also the hydrometra pressure of the scene.

#include "hs/clinical/Tissue.h"
#include "hs/scene/Scene.h"

#include <QString>
#include <QWidget>

#include <array>

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace hs::widgets {

class CaseDocument;

/// A tissue's name in the user's language.
QString tissueName(clinical::Tissue tissue);
/// A scene region's name for the user: its tissue's, or the case's pathology id for a pathology.
QString regionName(const scene::SceneRegion& region);

class MaterialsPanel : public QWidget {
    Q_OBJECT

public:
    explicit MaterialsPanel(CaseDocument& document, QWidget* parent = nullptr);

    /// Columns of the table.
    enum Column { kYoungsColumn, kPoissonColumn, kDensityColumn, kHeterogeneityColumn, kResetColumn, kColumnCount };
    /// The spin box of `tissue`'s row (clinical::Tissue order) and `column`.
    QDoubleSpinBox* field(int tissue, int column) const;

private:
    void refresh();

    CaseDocument& m_document;
    QTableWidget* m_table = nullptr;
    QDoubleSpinBox* m_pressureSpin = nullptr;
    QLabel* m_messageLabel = nullptr;
    bool m_refreshing = false;
};

} // namespace hs::widgets
