#pragma once
/// Handles to move a pathology along the organ's wall and to size it, in a VtkView (3D Slicer's markups do the same:
/// drag to move, the edit taken when the drag ends). The seat handle is a vtkHandleWidget whose
/// vtkPointHandleRepresentation3D is constrained to the shown surface by a vtkPolygonalSurfacePointPlacer; the size
/// handle sits on the pathology's rim, half its size from the seat in the wall's tangent plane, and gives the size as
/// twice its distance from the seat. VTK has no undo: each handle reports once, when its interaction ends, so a drag is
/// one edit of the document.

#include "hs/core/Vec3.h"

#include <QObject>
#include <QVector3D>

#include <vtkSmartPointer.h>

class vtkActor;
class vtkHandleWidget;
class vtkObject;
class vtkPointHandleRepresentation3D;
class vtkPolygonalSurfacePointPlacer;

namespace hs::widgets {

class VtkView;

class SurfaceHandles : public QObject {
    Q_OBJECT

public:
    explicit SurfaceHandles(VtkView* view, QObject* parent = nullptr);
    ~SurfaceHandles() override;

    /// Shows both handles for a pathology seated at `seatMm` with outward normal `normal` and size `sizeMm`, the seat
    /// handle constrained to `surface` (the actor showing the organ).
    void show(vtkActor* surface, const Vec3& seatMm, const Vec3& normal, double sizeMm);
    void hide();
    bool isShown() const { return m_shown; }

    /// Where the handles are now (mm), for tests and the status bar.
    Vec3 seatPosition() const;
    Vec3 sizePosition() const;

signals:
    /// The seat handle was dropped at `point` (on the surface).
    void seatMoved(const QVector3D& point);
    /// The size handle was dropped: the pathology's size in mm.
    void sizeChanged(double sizeMm);

private:
    void onSeatEnd(vtkObject* caller, unsigned long eventId, void* callData);
    void onSizeEnd(vtkObject* caller, unsigned long eventId, void* callData);

    VtkView* m_view;
    vtkSmartPointer<vtkPolygonalSurfacePointPlacer> m_placer;
    vtkSmartPointer<vtkPointHandleRepresentation3D> m_seatRepresentation;
    vtkSmartPointer<vtkHandleWidget> m_seatWidget;
    vtkSmartPointer<vtkPointHandleRepresentation3D> m_sizeRepresentation;
    vtkSmartPointer<vtkHandleWidget> m_sizeWidget;
    Vec3 m_seat;
    bool m_shown = false;
};

} // namespace hs::widgets
