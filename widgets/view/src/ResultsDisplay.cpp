#include "hs/widgets/view/ResultsDisplay.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <array>

namespace hs::widgets {

SurfaceMesh combineRegions(const std::vector<std::pair<const SurfaceMesh*, int>>& parts) {
    SurfaceMesh combined;
    std::vector<std::int32_t>& regions = combined.faceLabels["region"];
    for (const auto& [part, region] : parts) {
        const auto offset = static_cast<std::int32_t>(combined.points.size());
        combined.points.insert(combined.points.end(), part->points.begin(), part->points.end());
        for (const Triangle& t : part->triangles) {
            combined.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
            regions.push_back(region);
        }
    }
    return combined;
}

bool hasLayer(const generate::Generated& results, ResultLayer layer) {
    switch (layer) {
    case ResultLayer::Organ:
        return results.organ.has_value();
    case ResultLayer::Pathologies:
        return results.pathologies.has_value();
    case ResultLayer::Body:
        return results.body.has_value();
    case ResultLayer::Tissues:
        return results.tissue.has_value();
    case ResultLayer::Textured:
        return results.appearance.has_value();
    case ResultLayer::None:
        break;
    }
    return false;
}

GrowthDisplay::GrowthDisplay(vtkRenderer* renderer)
    : m_renderer(renderer), m_actor(vtkSmartPointer<vtkActor>::New()), m_points(vtkSmartPointer<vtkPolyData>::New()) {
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(m_points);
    mapper->SetColorModeToDirectScalars();
    m_actor->SetMapper(mapper);
    m_actor->GetProperty()->SetPointSize(4.0f);
    m_actor->GetProperty()->RenderPointsAsSpheresOn();
    m_actor->VisibilityOff();
    m_renderer->AddActor(m_actor);
}

GrowthDisplay::~GrowthDisplay() {
    m_renderer->RemoveActor(m_actor);
}

void GrowthDisplay::show(const pathology::GrowthFrame& frame) {
    m_latest[frame.pathology] = frame.points;
    rebuild();
}

void GrowthDisplay::clear() {
    m_latest.clear();
    rebuild();
}

std::size_t GrowthDisplay::pointCount() const {
    std::size_t n = 0;
    for (const auto& [index, points] : m_latest)
        n += points.size();
    return n;
}

void GrowthDisplay::rebuild() {
    // One colour per pathology, as the merged body shows its regions (pathology i is region i + 1).
    constexpr std::array<std::array<unsigned char, 3>, 4> kColours{
        {{240, 210, 120}, {130, 180, 230}, {150, 210, 140}, {200, 140, 210}}};
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto verts = vtkSmartPointer<vtkCellArray>::New();
    auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colours->SetNumberOfComponents(3);
    for (const auto& [index, cloud] : m_latest) {
        const auto& c = kColours[index % kColours.size()];
        for (const Vec3& p : cloud) {
            const vtkIdType id = points->InsertNextPoint(p.x, p.y, p.z);
            verts->InsertNextCell(1, &id);
            colours->InsertNextTypedTuple(c.data());
        }
    }
    m_points->SetPoints(points);
    m_points->SetVerts(verts);
    m_points->GetPointData()->SetScalars(colours);
    m_points->Modified();
    m_actor->SetVisibility(points->GetNumberOfPoints() > 0);
}

} // namespace hs::widgets
