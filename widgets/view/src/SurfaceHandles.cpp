#include "hs/widgets/view/SurfaceHandles.h"

#include "hs/widgets/view/VtkView.h"

#include <vtkActor.h>
#include <vtkCommand.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkHandleWidget.h>
#include <vtkPointHandleRepresentation3D.h>
#include <vtkPolygonalSurfacePointPlacer.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <algorithm>

namespace hs::widgets {

namespace {

/// Pixels of screen the handles' crosses span, whatever the zoom.
constexpr double kHandleSizePx = 14.0;
/// The smallest size the size handle gives (mm): the case's smallest pathology.
constexpr double kMinSizeMm = 3.0;

vtkSmartPointer<vtkPointHandleRepresentation3D> makeRepresentation(double r, double g, double b) {
    auto rep = vtkSmartPointer<vtkPointHandleRepresentation3D>::New();
    rep->AllOff(); // no outline nor shadows: only the cross of its axes
    rep->TranslationModeOn();
    rep->SetHandleSize(kHandleSizePx);
    rep->GetProperty()->SetColor(r, g, b);
    rep->GetProperty()->SetLineWidth(3.0f);
    rep->GetSelectedProperty()->SetColor(1.0, 1.0, 1.0);
    rep->GetSelectedProperty()->SetLineWidth(3.0f);
    rep->SetTolerance(12);
    return rep;
}

} // namespace

SurfaceHandles::SurfaceHandles(VtkView* view, QObject* parent)
    : QObject(parent), m_view(view), m_placer(vtkSmartPointer<vtkPolygonalSurfacePointPlacer>::New()),
      m_seatRepresentation(makeRepresentation(1.0, 0.85, 0.1)), m_seatWidget(vtkSmartPointer<vtkHandleWidget>::New()),
      m_sizeRepresentation(makeRepresentation(0.2, 0.8, 1.0)), m_sizeWidget(vtkSmartPointer<vtkHandleWidget>::New()) {
    m_seatRepresentation->SetPointPlacer(m_placer);
    m_seatWidget->SetRepresentation(m_seatRepresentation);
    m_sizeWidget->SetRepresentation(m_sizeRepresentation);
    for (vtkHandleWidget* widget : {m_seatWidget.Get(), m_sizeWidget.Get()}) {
        widget->SetInteractor(m_view->interactor());
        widget->SetCurrentRenderer(m_view->renderer());
        widget->SetPriority(1.0f); // before the camera's interactor style
        widget->EnableAxisConstraintOff();
    }
    m_seatWidget->AddObserver(vtkCommand::EndInteractionEvent, this, &SurfaceHandles::onSeatEnd);
    m_sizeWidget->AddObserver(vtkCommand::EndInteractionEvent, this, &SurfaceHandles::onSizeEnd);
}

SurfaceHandles::~SurfaceHandles() {
    m_seatWidget->Off();
    m_sizeWidget->Off();
}

void SurfaceHandles::show(vtkActor* surface, const Vec3& seatMm, const Vec3& normal, double sizeMm) {
    m_placer->RemoveAllProps();
    m_placer->AddProp(surface);
    m_seat = seatMm;
    double seat[3] = {seatMm.x, seatMm.y, seatMm.z};
    // The size handle sits on the pathology's rim in the wall's tangent plane, where it stays clear of the seat
    // handle when the wall is seen face on.
    const Vec3 n = norm(normal) > 0.0 ? normalized(normal) : Vec3{0.0, 0.0, 1.0};
    Vec3 tangent = cross(n, Vec3{0.0, 0.0, 1.0});
    if (norm(tangent) < 0.3)
        tangent = cross(n, Vec3{1.0, 0.0, 0.0});
    const Vec3 edge = seatMm + normalized(tangent) * (0.5 * sizeMm);
    double sizeAt[3] = {edge.x, edge.y, edge.z};
    m_seatWidget->On();
    m_sizeWidget->On();
    m_seatRepresentation->SetWorldPosition(seat);
    m_sizeRepresentation->SetWorldPosition(sizeAt);
    m_shown = true;
    m_view->requestRender();
}

void SurfaceHandles::hide() {
    m_seatWidget->Off();
    m_sizeWidget->Off();
    m_shown = false;
    m_view->requestRender();
}

Vec3 SurfaceHandles::seatPosition() const {
    double p[3];
    m_seatRepresentation->GetWorldPosition(p);
    return {p[0], p[1], p[2]};
}

Vec3 SurfaceHandles::sizePosition() const {
    double p[3];
    m_sizeRepresentation->GetWorldPosition(p);
    return {p[0], p[1], p[2]};
}

void SurfaceHandles::onSeatEnd(vtkObject*, unsigned long, void*) {
    const Vec3 p = seatPosition();
    emit seatMoved(QVector3D(float(p.x), float(p.y), float(p.z)));
}

void SurfaceHandles::onSizeEnd(vtkObject*, unsigned long, void*) {
    emit sizeChanged(std::max(kMinSizeMm, 2.0 * distance(sizePosition(), m_seat)));
}

} // namespace hs::widgets
