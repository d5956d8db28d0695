#pragma once
/// The Mesh panel: the meshing stage's parameters (method, target vertex count, seeding, relaxation), Mesh to run it
/// (with the wall's tissue layers) in the background, and the quality inspector of the result: histograms of the
/// radius ratio and the smallest dihedral angle, the tets coloured by either measure, each region shown or hidden,
/// and the worst tets listed, each with Show, which outlines it and frames the camera on it. Clip (View menu) cuts the
/// mesh open. The per-tet measures are computed by meshing::tetShapes in a job, never on the GUI thread.

#include "hs/meshing/Geometry.h"
#include "hs/widgets/jobs/JobRunner.h"

#include <QWidget>

#include <memory>
#include <vector>

class QCheckBox;
class QChartView;
class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;
class QVBoxLayout;

namespace hs::widgets {

class CaseDocument;
class GenerationSession;
class MeshDisplay;
class VtkView;

class MeshPanel : public QWidget {
    Q_OBJECT

public:
    MeshPanel(CaseDocument& document, GenerationSession& session, QWidget* parent = nullptr);

    /// Where the inspector colours, hides and outlines tets (the window's 3-D view showing the mesh).
    void setDisplay(MeshDisplay* display, VtkView* view);
    /// The tets listed as the worst, by index in the mesh.
    const std::vector<std::size_t>& worstTets() const { return m_worst; }
    /// Applies the inspector's colouring and hidden regions to the display again (after it showed a new mesh).
    /// Ticks each region's box as the display shows it (after the scene tree hid or showed a region).
    void syncRegionChecks();
    void applyToDisplay();
    /// Outlines worst tet `row` and frames the camera on it.
    void showWorstTet(int row);
    /// Rows listed in the worst-tet table.
    static constexpr int kWorstCount = 20;

signals:
    /// The inspector changed what the 3-D view shows (colours, hidden regions, outline).
    void displayChanged();
    /// The inspector needs the mesh in the 3-D view (a worst tet to outline while another part is shown).
    void meshWanted();

private:
    void buildParameters();
    void buildInspector();
    void refreshParameters();
    void onResults();
    void applyColouring();
    void applyRegionVisibility();
    void fillCharts();

    CaseDocument& m_document;
    GenerationSession& m_session;
    JobRunner m_inspectJobs;
    MeshDisplay* m_display = nullptr;
    VtkView* m_view = nullptr;
    std::shared_ptr<const std::vector<meshing::TetShape>> m_shapes; ///< of the mesh shown
    const void* m_shapesOf = nullptr;                               ///< the tissue mesh m_shapes belong to
    std::vector<std::size_t> m_worst;
    bool m_refreshing = false;

    QComboBox* m_methodCombo = nullptr;
    QSpinBox* m_verticesSpin = nullptr;
    QComboBox* m_seedingCombo = nullptr;
    QSpinBox* m_iterationsSpin = nullptr;
    QPushButton* m_meshButton = nullptr;
    QLabel* m_messageLabel = nullptr;
    QLabel* m_summaryLabel = nullptr;
    QChartView* m_radiusRatioChart = nullptr;
    QChartView* m_dihedralChart = nullptr;
    QComboBox* m_colourCombo = nullptr;
    QVBoxLayout* m_regionsLayout = nullptr;
    std::vector<QCheckBox*> m_regionChecks;
    QTableWidget* m_worstTable = nullptr;
};

} // namespace hs::widgets
