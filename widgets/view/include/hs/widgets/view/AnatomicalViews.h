#pragma once
/// Where the patient is in the 3-D view: an orientation marker (a cube labelled with the patient's directions, in the
/// view's lower-left corner, turning with the camera) and the six anatomical views a supervisor asks for, in the
/// scene's frame (docs/anatomy.md: origin at the external os, +x the patient's right, +y anterior, +z up the cervical
/// canal towards the fundus).

#include <vtkSmartPointer.h>

#include <array>

class vtkOrientationMarkerWidget;

namespace hs::widgets {

class VtkView;

enum class AnatomicalView {
    Anterior,   ///< from in front of the patient
    Posterior,  ///< from behind
    Left,       ///< from the patient's left
    Right,      ///< from the patient's right
    Fundal,     ///< from above the fundus, down the uterine axis
    ExternalOs, ///< from the external os, up the cervical canal (as the scope enters)
};
inline constexpr std::array<AnatomicalView, 6> kAnatomicalViews{AnatomicalView::Anterior, AnatomicalView::Posterior,
                                                                AnatomicalView::Left,     AnatomicalView::Right,
                                                                AnatomicalView::Fundal,   AnatomicalView::ExternalOs};

/// Where the camera looks from and which way is up on the screen, as unit vectors of the scene's frame.
struct ViewDirection {
    std::array<double, 3> towardsCamera; ///< from the focal point to the camera
    std::array<double, 3> up;
};
ViewDirection directionOf(AnatomicalView view);

/// Turns `view`'s camera to look from `which` at what it shows, fitted, and renders.
void lookFrom(VtkView& view, AnatomicalView which);

/// The orientation marker of a view: a cube with R/L, A/P and S/I (superior: up the canal) on its faces, drawn in the
/// lower-left corner of the view and following its camera; not interactive (clicks go to the view).
class OrientationMarker {
public:
    explicit OrientationMarker(VtkView& view);
    ~OrientationMarker();
    OrientationMarker(const OrientationMarker&) = delete;
    OrientationMarker& operator=(const OrientationMarker&) = delete;

    void setVisible(bool visible);
    bool isVisible() const;

private:
    vtkSmartPointer<vtkOrientationMarkerWidget> m_widget;
};

} // namespace hs::widgets
