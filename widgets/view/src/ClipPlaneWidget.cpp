#include "hs/widgets/view/ClipPlaneWidget.h"

#include "hs/widgets/view/VtkView.h"

#include <vtkCommand.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkImplicitPlaneRepresentation.h>
#include <vtkImplicitPlaneWidget2.h>
#include <vtkProperty.h>

namespace hs::widgets {

ClipPlaneWidget::ClipPlaneWidget(VtkView& view, std::function<void(const Vec3&, const Vec3&)> moved)
    : m_view(view), m_moved(std::move(moved)), m_representation(vtkSmartPointer<vtkImplicitPlaneRepresentation>::New()),
      m_widget(vtkSmartPointer<vtkImplicitPlaneWidget2>::New()) {
    m_representation->SetPlaceFactor(1.05);
    m_representation->OutlineTranslationOff(); // the box stays with the mesh; only the plane moves
    m_representation->ScaleEnabledOff();
    m_representation->DrawPlaneOn();
    m_representation->GetPlaneProperty()->SetOpacity(0.15);
    m_representation->GetOutlineProperty()->SetOpacity(0.4);
    m_widget->SetInteractor(view.interactor());
    m_widget->SetRepresentation(m_representation);
    m_widget->AddObserver(vtkCommand::InteractionEvent, this, &ClipPlaneWidget::onInteraction);
}

ClipPlaneWidget::~ClipPlaneWidget() {
    m_widget->SetEnabled(0);
}

void ClipPlaneWidget::show(const std::array<double, 6>& bounds, const Vec3& origin, const Vec3& normal) {
    double box[6] = {bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5]};
    m_representation->PlaceWidget(box);
    m_representation->SetOrigin(origin.x, origin.y, origin.z);
    m_representation->SetNormal(normal.x, normal.y, normal.z);
    m_widget->SetEnabled(1);
    m_view.requestRender();
}

void ClipPlaneWidget::hide() {
    m_widget->SetEnabled(0);
    m_view.requestRender();
}

bool ClipPlaneWidget::isVisible() const {
    return m_widget->GetEnabled() != 0;
}

void ClipPlaneWidget::moveTo(const Vec3& origin, const Vec3& normal) {
    m_representation->SetOrigin(origin.x, origin.y, origin.z);
    m_representation->SetNormal(normal.x, normal.y, normal.z);
    m_widget->InvokeEvent(vtkCommand::InteractionEvent, nullptr);
}

Vec3 ClipPlaneWidget::origin() const {
    double o[3];
    m_representation->GetOrigin(o);
    return {o[0], o[1], o[2]};
}

Vec3 ClipPlaneWidget::normal() const {
    double n[3];
    m_representation->GetNormal(n);
    return {n[0], n[1], n[2]};
}

void ClipPlaneWidget::onInteraction(vtkObject*, unsigned long, void*) {
    if (m_moved)
        m_moved(origin(), normal());
    m_view.requestRender();
}

} // namespace hs::widgets
