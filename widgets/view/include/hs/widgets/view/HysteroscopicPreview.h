#pragma once
/// The hysteroscopic preview: the textured cavity as the trainee will see it, through a rigid scope whose tip stands
/// at the external os (or further in) and looks up the canal through an oblique optic, lit by a lamp at the tip whose
/// light falls off with distance. Insertion, optic and roll are set by the controls; the camera pose is
/// scene::scopeView's. The picture is the simulator's endoscopic view (hs::simrender::EndoscopicView: the maps, the
/// lamp, the clear fluid and the optic's circular field), so the simulator shows the same picture for the same pose.
/// A review visits a pathology by lookAtRegion().

#include "hs/scene/Scene.h"
#include "hs/scene/ScopePassage.h"

#include <QElapsedTimer>
#include <QImage>
#include <QWidget>

#include <memory>
#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSlider;
class QTimer;

namespace hs::simrender {
class EndoscopicView;
}

namespace hs::widgets {

class VtkView;

class HysteroscopicPreview : public QWidget {
    Q_OBJECT

public:
    explicit HysteroscopicPreview(QWidget* parent = nullptr);
    ~HysteroscopicPreview() override;

    /// Shows `scene` (null: nothing). Without the canal and ostium labels the preview says it cannot place the scope.
    void setScene(std::shared_ptr<const scene::Scene> scene);
    bool hasScene() const { return m_scene != nullptr && m_landmarks.has_value(); }

    /// mm beyond the external os (negative: outside it).
    void setInsertion(double mm);
    double insertion() const;
    /// degrees off the shaft: 0, 12, 30 (default) or 70.
    void setOptic(double degrees);
    /// degrees about the shaft; 0 looks anterior.
    void setRoll(double degrees);
    /// Looks at region `regionId` from `distanceMm` inside the cavity; false when the region has no tets.
    bool lookAtRegion(std::int32_t regionId, double distanceMm = 12.0);

    /// Hides the insertion, optic and roll controls (a side-by-side comparison drives them all at once).
    void setControlsVisible(bool visible);
    VtkView* view() const { return m_view; }
    /// The picture once the camera's exposure has settled on it (up to a second of the camera's time).
    QImage grabImage();

    /// The scope's field of view, degrees (office hysteroscopes see 70-110).
    static constexpr double kFieldOfViewDeg = 90.0;

private:
    void updateCamera();
    /// Draws the view again while the camera's exposure settles on a still picture.
    void render();
    void settleExposure();

    VtkView* m_view = nullptr;
    std::unique_ptr<simrender::EndoscopicView> m_endoscope;
    std::shared_ptr<const scene::Scene> m_scene;
    std::optional<scene::ScopeLandmarks> m_landmarks;
    QSlider* m_insertionSlider = nullptr;
    QComboBox* m_opticCombo = nullptr;
    QSlider* m_rollSlider = nullptr;
    QLabel* m_statusLabel = nullptr;
    QWidget* m_controls = nullptr;
    QTimer* m_settleTimer = nullptr;
    QElapsedTimer m_clock;   ///< the camera's clock
    double m_grabbedS = 0.0; ///< s of camera time grabImage() added while settling
    int m_settleFrames = 0;
};

} // namespace hs::widgets
