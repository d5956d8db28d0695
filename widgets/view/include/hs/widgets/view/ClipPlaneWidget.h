#pragma once
/// The 3-D view's clip plane as a handle the user moves (vtkImplicitPlaneWidget2, as 3D Slicer's and ParaView's clip
/// planes): drag the plane to slide it along its normal, drag its arrow to tilt it; every move reports the plane, and
/// the view's MeshDisplay cuts there. Shown while View > Clip is on.

#include "hs/core/Vec3.h"

#include <vtkSmartPointer.h>

#include <array>
#include <functional>

class vtkImplicitPlaneRepresentation;
class vtkImplicitPlaneWidget2;
class vtkObject;

namespace hs::widgets {

class VtkView;

class ClipPlaneWidget {
public:
    /// `moved` gets the plane's origin (mm) and unit normal after each move, on the GUI thread.
    ClipPlaneWidget(VtkView& view, std::function<void(const Vec3& origin, const Vec3& normal)> moved);
    ~ClipPlaneWidget();
    ClipPlaneWidget(const ClipPlaneWidget&) = delete;
    ClipPlaneWidget& operator=(const ClipPlaneWidget&) = delete;

    /// Shows the plane at `origin` with `normal`, its handles sized to `bounds` (xmin, xmax, ymin, ymax, zmin, zmax).
    void show(const std::array<double, 6>& bounds, const Vec3& origin, const Vec3& normal);
    void hide();
    bool isVisible() const;

    /// Moves the plane as a drag does (the representation, then `moved`): for keys and tests.
    void moveTo(const Vec3& origin, const Vec3& normal);
    Vec3 origin() const;
    Vec3 normal() const;

private:
    void onInteraction(vtkObject*, unsigned long, void*);

    VtkView& m_view;
    std::function<void(const Vec3&, const Vec3&)> m_moved;
    vtkSmartPointer<vtkImplicitPlaneRepresentation> m_representation;
    vtkSmartPointer<vtkImplicitPlaneWidget2> m_widget;
};

} // namespace hs::widgets
