#include "hs/widgets/view/AnatomicalViews.h"

#include "hs/widgets/view/VtkView.h"

#include <vtkAnnotatedCubeActor.h>
#include <vtkCamera.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkOrientationMarkerWidget.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace hs::widgets {

ViewDirection directionOf(AnatomicalView view) {
    switch (view) {
    case AnatomicalView::Anterior:
        return {{0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
    case AnatomicalView::Posterior:
        return {{0.0, -1.0, 0.0}, {0.0, 0.0, 1.0}};
    case AnatomicalView::Left:
        return {{-1.0, 0.0, 0.0}, {0.0, 0.0, 1.0}};
    case AnatomicalView::Right:
        return {{1.0, 0.0, 0.0}, {0.0, 0.0, 1.0}};
    case AnatomicalView::Fundal:
        return {{0.0, 0.0, 1.0}, {0.0, 1.0, 0.0}};
    case AnatomicalView::ExternalOs:
        break;
    }
    return {{0.0, 0.0, -1.0}, {0.0, 1.0, 0.0}};
}

void lookFrom(VtkView& view, AnatomicalView which) {
    const ViewDirection d = directionOf(which);
    vtkCamera* camera = view.renderer()->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(d.towardsCamera[0], d.towardsCamera[1], d.towardsCamera[2]);
    camera->SetViewUp(d.up[0], d.up[1], d.up[2]);
    view.resetCamera(); // fits the visible props along that direction and renders
}

OrientationMarker::OrientationMarker(VtkView& view) : m_widget(vtkSmartPointer<vtkOrientationMarkerWidget>::New()) {
    auto cube = vtkSmartPointer<vtkAnnotatedCubeActor>::New();
    cube->SetXPlusFaceText("R");
    cube->SetXMinusFaceText("L");
    cube->SetYPlusFaceText("A");
    cube->SetYMinusFaceText("P");
    cube->SetZPlusFaceText("S");
    cube->SetZMinusFaceText("I");
    cube->SetFaceTextScale(0.55);
    cube->GetCubeProperty()->SetColor(0.86, 0.80, 0.76);
    cube->GetTextEdgesProperty()->SetColor(0.3, 0.3, 0.3);
    // The face letters coloured by axis (lateral red, anteroposterior green, along the canal blue), as in 3-D viewers.
    cube->GetXPlusFaceProperty()->SetColor(0.75, 0.15, 0.15);
    cube->GetXMinusFaceProperty()->SetColor(0.75, 0.15, 0.15);
    cube->GetYPlusFaceProperty()->SetColor(0.15, 0.55, 0.15);
    cube->GetYMinusFaceProperty()->SetColor(0.15, 0.55, 0.15);
    cube->GetZPlusFaceProperty()->SetColor(0.15, 0.25, 0.75);
    cube->GetZMinusFaceProperty()->SetColor(0.15, 0.25, 0.75);
    m_widget->SetOrientationMarker(cube);
    m_widget->SetInteractor(view.interactor());
    m_widget->SetViewport(0.0, 0.0, 0.22, 0.22);
    m_widget->SetEnabled(1);
    m_widget->InteractiveOff();
}

OrientationMarker::~OrientationMarker() {
    m_widget->SetEnabled(0);
}

void OrientationMarker::setVisible(bool visible) {
    m_widget->SetEnabled(visible ? 1 : 0);
    if (visible)
        m_widget->InteractiveOff();
}

bool OrientationMarker::isVisible() const {
    return m_widget->GetEnabled() != 0;
}

} // namespace hs::widgets
