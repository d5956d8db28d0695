#include "hs/widgets/view/MeshDisplay.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkExtractGeometry.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkPlane.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <array>
#include <cstdint>
#include <set>
#include <vector>

namespace hs::widgets {
namespace {

using Rgb = std::array<unsigned char, 3>;

/// Region colours: region 0 is uterine tissue pink, the next ones are far apart so neighbouring regions read
/// clearly (myoma, polyp, cavity, ...).
constexpr std::array<Rgb, 8> kRegionPalette{{
    {224, 150, 150},
    {240, 210, 120},
    {130, 180, 230},
    {150, 210, 140},
    {200, 140, 210},
    {250, 170, 90},
    {120, 200, 200},
    {210, 210, 210},
}};
constexpr double kEdgeColour[3] = {0.25, 0.12, 0.12};
const char* const kRegionLabel = "region";

Rgb regionColour(std::int32_t region) {
    const auto n = static_cast<std::int32_t>(kRegionPalette.size());
    return kRegionPalette[static_cast<std::size_t>(((region % n) + n) % n)];
}

vtkSmartPointer<vtkPoints> toPoints(const std::vector<Vec3>& points) {
    auto vtkPts = vtkSmartPointer<vtkPoints>::New();
    vtkPts->SetDataTypeToDouble();
    vtkPts->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i)
        vtkPts->SetPoint(static_cast<vtkIdType>(i), points[i].x, points[i].y, points[i].z);
    return vtkPts;
}

/// Cells of a fixed size from index tuples (triangles, tetrahedra), built from offsets and connectivity in one go.
template <std::size_t N>
vtkSmartPointer<vtkCellArray> toCells(const std::vector<std::array<std::int32_t, N>>& cells) {
    auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
    auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
    offsets->SetNumberOfValues(static_cast<vtkIdType>(cells.size() + 1));
    connectivity->SetNumberOfValues(static_cast<vtkIdType>(cells.size() * N));
    vtkIdType next = 0;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        offsets->SetValue(static_cast<vtkIdType>(c), next);
        for (std::int32_t index : cells[c])
            connectivity->SetValue(next++, index);
    }
    offsets->SetValue(static_cast<vtkIdType>(cells.size()), next);
    auto array = vtkSmartPointer<vtkCellArray>::New();
    array->SetData(offsets, connectivity);
    return array;
}

vtkSmartPointer<vtkIntArray> toIntArray(const std::vector<std::int32_t>& values, const char* name) {
    auto array = vtkSmartPointer<vtkIntArray>::New();
    array->SetName(name);
    array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i)
        array->SetValue(static_cast<vtkIdType>(i), values[i]);
    return array;
}

vtkSmartPointer<vtkUnsignedCharArray> toColours(const std::vector<std::int32_t>& regions) {
    auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colours->SetName("colour");
    colours->SetNumberOfComponents(3);
    colours->SetNumberOfTuples(static_cast<vtkIdType>(regions.size()));
    for (std::size_t i = 0; i < regions.size(); ++i) {
        const Rgb rgb = regionColour(regions[i]);
        for (int k = 0; k < 3; ++k)
            colours->SetComponent(static_cast<vtkIdType>(i), k, rgb[static_cast<std::size_t>(k)]);
    }
    return colours;
}

const std::vector<std::int32_t>* findLabel(const LabelMap& labels, std::size_t expectedSize) {
    const auto found = labels.find(kRegionLabel);
    if (found == labels.end() || found->second.size() != expectedSize || expectedSize == 0)
        return nullptr;
    return &found->second;
}

std::size_t distinctCount(const std::vector<std::int32_t>& values) {
    return std::set<std::int32_t>(values.begin(), values.end()).size();
}

void setUniformLook(vtkProperty* property) {
    property->SetColor(kRegionPalette[0][0] / 255.0, kRegionPalette[0][1] / 255.0, kRegionPalette[0][2] / 255.0);
    property->SetSpecular(0.2);
    property->SetSpecularPower(20.0);
}

} // namespace

vtkSmartPointer<vtkPolyData> toPolyData(const SurfaceMesh& mesh) {
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(toPoints(mesh.points));
    poly->SetPolys(toCells(mesh.triangles));
    if (const auto* faceRegions = findLabel(mesh.faceLabels, mesh.faceCount())) {
        poly->GetCellData()->AddArray(toIntArray(*faceRegions, kRegionLabel));
        poly->GetCellData()->SetScalars(toColours(*faceRegions));
    } else if (const auto* vertexRegions = findLabel(mesh.vertexLabels, mesh.vertexCount())) {
        poly->GetPointData()->AddArray(toIntArray(*vertexRegions, kRegionLabel));
        poly->GetPointData()->SetScalars(toColours(*vertexRegions));
    }
    return poly;
}

vtkSmartPointer<vtkUnstructuredGrid> toUnstructuredGrid(const TetMesh& mesh) {
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    grid->SetPoints(toPoints(mesh.points));
    grid->SetCells(VTK_TETRA, toCells(mesh.tets));
    std::vector<std::int32_t> regions(mesh.tetCount());
    for (std::size_t t = 0; t < regions.size(); ++t)
        regions[t] = mesh.regionOf(t);
    grid->GetCellData()->AddArray(toIntArray(regions, kRegionLabel));
    grid->GetCellData()->SetScalars(toColours(regions));
    return grid;
}

MeshCounts countsOf(const SurfaceMesh& mesh) {
    MeshCounts counts;
    counts.vertices = mesh.vertexCount();
    counts.triangles = mesh.faceCount();
    if (const auto* faceRegions = findLabel(mesh.faceLabels, mesh.faceCount()))
        counts.regions = distinctCount(*faceRegions);
    else if (const auto* vertexRegions = findLabel(mesh.vertexLabels, mesh.vertexCount()))
        counts.regions = distinctCount(*vertexRegions);
    else
        counts.regions = mesh.faceCount() > 0 ? 1 : 0;
    return counts;
}

MeshCounts countsOf(const TetMesh& mesh) {
    MeshCounts counts;
    counts.vertices = mesh.vertexCount();
    counts.tets = mesh.tetCount();
    if (mesh.regions.size() == mesh.tetCount() && mesh.tetCount() > 0)
        counts.regions = distinctCount(mesh.regions);
    else
        counts.regions = mesh.tetCount() > 0 ? 1 : 0;
    return counts;
}

MeshDisplay::MeshDisplay(vtkRenderer* renderer)
    : m_renderer(renderer), m_actor(vtkSmartPointer<vtkActor>::New()),
      m_mapper(vtkSmartPointer<vtkPolyDataMapper>::New()), m_plane(vtkSmartPointer<vtkPlane>::New()),
      m_clip(vtkSmartPointer<vtkExtractGeometry>::New()),
      m_gridSurface(vtkSmartPointer<vtkDataSetSurfaceFilter>::New()) {
    // Whole tetrahedra with any point on the kept side stay: the cut shows the tets themselves, not sliced ones.
    m_clip->SetImplicitFunction(m_plane);
    m_clip->ExtractInsideOn();
    m_clip->ExtractBoundaryCellsOn();
    auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
    normals->SplittingOff(); // keep one point per input point: picked cell ids stay those of the mesh
    normals->ConsistencyOff();
    m_surfaceNormals = normals;
    m_mapper->SetColorModeToDirectScalars();
    m_mapper->SetScalarModeToDefault();
    m_actor->SetMapper(m_mapper);
    m_actor->VisibilityOff();
    m_renderer->AddActor(m_actor);
}

MeshDisplay::~MeshDisplay() {
    m_renderer->RemoveActor(m_actor);
}

vtkActor* MeshDisplay::actor() const {
    return m_actor;
}

void MeshDisplay::showSurface(const SurfaceMesh& mesh) {
    m_surfaceNormals->SetInputDataObject(toPolyData(mesh));
    m_mapper->SetInputConnection(m_surfaceNormals->GetOutputPort());
    m_grid = nullptr;
    m_kind = Kind::Surface;
    m_counts = countsOf(mesh);
    setUniformLook(m_actor->GetProperty());
    m_actor->GetProperty()->EdgeVisibilityOff();
    m_actor->VisibilityOn();
}

void MeshDisplay::showTetMesh(const TetMesh& mesh) {
    m_grid = toUnstructuredGrid(mesh);
    m_kind = Kind::Tets;
    m_counts = countsOf(mesh);
    const Bounds box = bounds(mesh);
    setClipPlane(box.empty() ? Vec3{} : box.center(), {1.0, 0.0, 0.0});
    setUniformLook(m_actor->GetProperty());
    m_actor->GetProperty()->SetEdgeColor(kEdgeColour[0], kEdgeColour[1], kEdgeColour[2]);
    connectTetPipeline();
    m_actor->VisibilityOn();
}

void MeshDisplay::clear() {
    m_mapper->RemoveAllInputConnections(0);
    m_grid = nullptr;
    m_kind = Kind::None;
    m_counts = {};
    m_actor->VisibilityOff();
}

void MeshDisplay::setClipEnabled(bool enabled) {
    m_clipEnabled = enabled;
    if (m_kind == Kind::Tets)
        connectTetPipeline();
}

void MeshDisplay::setClipPlane(const Vec3& origin, const Vec3& normal) {
    m_plane->SetOrigin(origin.x, origin.y, origin.z);
    m_plane->SetNormal(normal.x, normal.y, normal.z);
}

void MeshDisplay::connectTetPipeline() {
    if (m_clipEnabled) {
        m_clip->SetInputData(m_grid);
        m_gridSurface->SetInputConnection(m_clip->GetOutputPort());
    } else {
        m_gridSurface->SetInputData(m_grid);
    }
    m_mapper->SetInputConnection(m_gridSurface->GetOutputPort());
    // With the cut open the individual tetrahedra are what the user inspects: draw their edges.
    m_actor->GetProperty()->SetEdgeVisibility(m_clipEnabled);
}

std::size_t MeshDisplay::visibleCellCount() const {
    switch (m_kind) {
    case Kind::None:
        return 0;
    case Kind::Surface:
        return m_counts.triangles;
    case Kind::Tets:
        if (!m_clipEnabled)
            return m_counts.tets;
        m_clip->Update();
        return static_cast<std::size_t>(m_clip->GetOutput()->GetNumberOfCells());
    }
    return 0;
}

} // namespace hs::widgets
