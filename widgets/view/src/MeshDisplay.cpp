#include "hs/widgets/view/MeshDisplay.h"

#include <vtkActor.h>
#include <vtkCell.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkClipPolyData.h>
#include <vtkCommand.h>
#include <vtkCoordinate.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkExtractCells.h>
#include <vtkExtractGeometry.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkLegendBoxActor.h>
#include <vtkLookupTable.h>
#include <vtkPlane.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
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
/// The legends' size in pixels (placeLegends).
constexpr double kLegendWidthPx = 180.0;
constexpr double kLegendLinePx = 18.0;
constexpr double kColourBarWidthPx = 260.0;
constexpr double kColourBarHeightPx = 60.0;

Rgb regionColour(std::int32_t region) {
    const auto n = static_cast<std::int32_t>(kRegionPalette.size());
    return kRegionPalette[static_cast<std::size_t>(((region % n) + n) % n)];
}

/// The blue - white - red diverging scale (Moreland 2009) through its three anchor colours, at t in [0, 1]; 0-255.
std::array<double, 3> divergingColour(double t) {
    t = std::clamp(t, 0.0, 1.0);
    const double a = t < 0.5 ? t * 2.0 : (t - 0.5) * 2.0;
    const std::array<double, 3> from =
        t < 0.5 ? std::array<double, 3>{59, 76, 192} : std::array<double, 3>{221, 221, 221};
    const std::array<double, 3> to = t < 0.5 ? std::array<double, 3>{221, 221, 221} : std::array<double, 3>{180, 4, 38};
    std::array<double, 3> rgb{};
    for (std::size_t c = 0; c < 3; ++c)
        rgb[c] = from[c] + a * (to[c] - from[c]);
    return rgb;
}

/// The same scale as a lookup table, for the colour bar.
vtkSmartPointer<vtkLookupTable> divergingTable() {
    auto table = vtkSmartPointer<vtkLookupTable>::New();
    constexpr int kColours = 256;
    table->SetNumberOfTableValues(kColours);
    for (int i = 0; i < kColours; ++i) {
        const std::array<double, 3> rgb = divergingColour(double(i) / double(kColours - 1));
        table->SetTableValue(i, rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0, 1.0);
    }
    table->SetRange(0.0, 1.0);
    return table;
}

/// A unit square, the legend's swatch.
vtkSmartPointer<vtkPolyData> squareSymbol() {
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->InsertNextPoint(0.0, 0.0, 0.0);
    points->InsertNextPoint(1.0, 0.0, 0.0);
    points->InsertNextPoint(1.0, 1.0, 0.0);
    points->InsertNextPoint(0.0, 1.0, 0.0);
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    const vtkIdType square[4] = {0, 1, 2, 3};
    polys->InsertNextCell(4, square);
    auto symbol = vtkSmartPointer<vtkPolyData>::New();
    symbol->SetPoints(points);
    symbol->SetPolys(polys);
    return symbol;
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
      m_gridSurface(vtkSmartPointer<vtkDataSetSurfaceFilter>::New()),
      m_surfaceClip(vtkSmartPointer<vtkClipPolyData>::New()), m_regionFilter(vtkSmartPointer<vtkExtractCells>::New()),
      m_highlight(vtkSmartPointer<vtkActor>::New()), m_legend(vtkSmartPointer<vtkLegendBoxActor>::New()),
      m_colourBar(vtkSmartPointer<vtkScalarBarActor>::New()) {
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
    m_surfaceClip->SetClipFunction(m_plane);
    m_surfaceClip->InsideOutOn(); // keep the side opposite the normal, as the tet clip does
    m_highlight->VisibilityOff();
    m_highlight->GetProperty()->SetRepresentationToWireframe();
    m_highlight->GetProperty()->SetColor(1.0, 0.1, 0.1);
    m_highlight->GetProperty()->SetLineWidth(3.0);
    m_highlight->GetProperty()->LightingOff();
    m_renderer->AddActor(m_highlight);
    // The legends sit in the view's lower-right corner (the orientation marker has the lower-left).
    // Sized in pixels before each render (placeLegends), so its text stays readable in a narrow view.
    m_legend->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    m_legend->GetPosition2Coordinate()->SetCoordinateSystemToNormalizedViewport();
    m_legendObserver = m_renderer->AddObserver(vtkCommand::StartEvent, this, &MeshDisplay::placeLegends);
    m_legend->BorderOff();
    m_legend->UseBackgroundOn();
    m_legend->SetBackgroundColor(0.1, 0.1, 0.12);
    m_legend->SetBackgroundOpacity(0.6);
    m_legend->VisibilityOff();
    m_renderer->AddViewProp(m_legend);
    m_colourBar->SetLookupTable(divergingTable());
    m_colourBar->SetOrientationToHorizontal();
    m_colourBar->SetNumberOfLabels(3);
    m_colourBar->VisibilityOff();
    m_renderer->AddViewProp(m_colourBar);
}

MeshDisplay::~MeshDisplay() {
    m_renderer->RemoveActor(m_actor);
    m_renderer->RemoveActor(m_highlight);
    m_renderer->RemoveViewProp(m_legend);
    m_renderer->RemoveViewProp(m_colourBar);
    m_renderer->RemoveObserver(m_legendObserver);
}

void MeshDisplay::setRegionNames(const std::map<std::int32_t, std::string>& names) {
    m_regionNames = names;
    updateLegend();
}

void MeshDisplay::updateLegend() {
    const bool tets = m_kind == Kind::Tets;
    m_colourBar->SetVisibility(m_shown && tets && m_colouredByValue);
    std::vector<std::pair<std::int32_t, std::string>> entries;
    if (tets && !m_colouredByValue && m_grid)
        if (auto* regions = vtkIntArray::SafeDownCast(m_grid->GetCellData()->GetArray(kRegionLabel))) {
            std::set<std::int32_t> present;
            for (vtkIdType i = 0; i < regions->GetNumberOfTuples(); ++i)
                present.insert(regions->GetValue(i));
            for (const auto& [id, name] : m_regionNames)
                if (present.count(id) != 0)
                    entries.emplace_back(id, name);
        }
    m_legend->SetNumberOfEntries(static_cast<int>(entries.size()));
    static const vtkSmartPointer<vtkPolyData> swatch = squareSymbol();
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const Rgb rgb = regionColour(entries[i].first);
        double colour[3] = {rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0};
        m_legend->SetEntry(static_cast<int>(i), swatch, entries[i].second.c_str(), colour);
    }
    m_legend->SetVisibility(m_shown && !entries.empty());
}

void MeshDisplay::placeLegends(vtkObject*, unsigned long, void*) {
    // A line of 18 px per region, 180 px wide, in the lower-right corner; at most the whole view.
    const int* size = m_renderer->GetSize();
    if (size[0] <= 0 || size[1] <= 0)
        return;
    const double width = std::min(0.98, kLegendWidthPx / double(size[0]));
    const double height =
        std::min(0.9, kLegendLinePx * double(std::max(1, m_legend->GetNumberOfEntries())) / double(size[1]));
    m_legend->GetPositionCoordinate()->SetValue(0.99 - width, 0.01);
    m_legend->GetPosition2Coordinate()->SetValue(width, height);
    const double barWidth = std::min(0.98, kColourBarWidthPx / double(size[0]));
    m_colourBar->SetPosition(0.99 - barWidth, 0.01);
    m_colourBar->SetWidth(barWidth);
    m_colourBar->SetHeight(std::min(0.5, kColourBarHeightPx / double(size[1])));
}

std::vector<std::string> MeshDisplay::legendEntries() const {
    std::vector<std::string> names;
    if (m_legend->GetVisibility())
        for (int i = 0; i < m_legend->GetNumberOfEntries(); ++i)
            names.emplace_back(m_legend->GetEntryString(i));
    return names;
}

std::string MeshDisplay::colourBarTitle() const {
    return m_colourBar->GetVisibility() && m_colourBar->GetTitle() ? std::string(m_colourBar->GetTitle()) : "";
}

vtkActor* MeshDisplay::actor() const {
    return m_actor;
}

void MeshDisplay::setShown(bool shown) {
    m_shown = shown;
    m_actor->SetVisibility(shown && m_kind != Kind::None);
    if (!shown)
        m_highlight->VisibilityOff();
    updateLegend();
}

void MeshDisplay::setOpacity(double opacity) {
    m_actor->GetProperty()->SetOpacity(std::clamp(opacity, 0.0, 1.0));
}

double MeshDisplay::opacity() const {
    return m_actor->GetProperty()->GetOpacity();
}

void MeshDisplay::setWireframe(bool wireframe) {
    if (wireframe)
        m_actor->GetProperty()->SetRepresentationToWireframe();
    else
        m_actor->GetProperty()->SetRepresentationToSurface();
}

void MeshDisplay::showTexturedSurface(const SurfaceMesh& mesh, const std::vector<std::array<float, 2>>& uvs,
                                      const std::vector<Vec3>& normals, const ImageU8& albedo) {
    showSurface(mesh);
    if (uvs.size() != mesh.points.size() || albedo.empty() || albedo.channels() < 3)
        return;
    auto tcoords = vtkSmartPointer<vtkFloatArray>::New();
    tcoords->SetName("uv");
    tcoords->SetNumberOfComponents(2);
    tcoords->SetNumberOfTuples(static_cast<vtkIdType>(uvs.size()));
    for (std::size_t i = 0; i < uvs.size(); ++i) // VTK's texture origin is the image's bottom left
        tcoords->SetTuple2(static_cast<vtkIdType>(i), uvs[i][0], 1.0f - uvs[i][1]);
    m_surface->GetPointData()->SetTCoords(tcoords);
    if (normals.size() == mesh.points.size()) {
        auto n = vtkSmartPointer<vtkFloatArray>::New();
        n->SetName("normals");
        n->SetNumberOfComponents(3);
        n->SetNumberOfTuples(static_cast<vtkIdType>(normals.size()));
        for (std::size_t i = 0; i < normals.size(); ++i)
            n->SetTuple3(static_cast<vtkIdType>(i), normals[i].x, normals[i].y, normals[i].z);
        m_surface->GetPointData()->SetNormals(n);
    }
    // The colours by region would tint the texture: the albedo alone gives the colour.
    m_surface->GetCellData()->SetScalars(nullptr);
    m_surface->GetPointData()->SetScalars(nullptr);
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(albedo.width(), albedo.height(), 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto* pixels = static_cast<unsigned char*>(image->GetScalarPointer());
    for (int y = 0; y < albedo.height(); ++y)
        for (int x = 0; x < albedo.width(); ++x)
            for (int c = 0; c < 3; ++c)
                pixels[(static_cast<std::size_t>(albedo.height() - 1 - y) * static_cast<std::size_t>(albedo.width()) +
                        static_cast<std::size_t>(x)) *
                           3 +
                       static_cast<std::size_t>(c)] = albedo.at(x, y, c);
    m_texture = vtkSmartPointer<vtkTexture>::New();
    m_texture->SetInputData(image);
    m_texture->InterpolateOn();
    m_texture->MipmapOn();
    m_texture->RepeatOff();
    m_actor->SetTexture(m_texture);
    m_actor->GetProperty()->SetColor(1.0, 1.0, 1.0);
    m_actor->GetProperty()->SetSpecular(0.25);
    m_actor->GetProperty()->SetSpecularPower(30.0);
    m_textured = true;
    connectSurfacePipeline();
}

void MeshDisplay::showSurface(const SurfaceMesh& mesh) {
    m_actor->SetTexture(nullptr);
    m_textured = false;
    m_surface = toPolyData(mesh);
    m_grid = nullptr;
    m_kind = Kind::Surface;
    m_counts = countsOf(mesh);
    m_highlight->VisibilityOff();
    const Bounds box = bounds(mesh);
    setClipPlane(box.empty() ? Vec3{} : box.center(), {0.0, 1.0, 0.0});
    connectSurfacePipeline();
    setUniformLook(m_actor->GetProperty());
    m_actor->GetProperty()->EdgeVisibilityOff();
    m_actor->SetVisibility(m_shown);
    updateLegend();
}

void MeshDisplay::showTetMesh(const TetMesh& mesh) {
    m_actor->SetTexture(nullptr);
    m_textured = false;
    m_colouredByValue = false;
    m_grid = toUnstructuredGrid(mesh);
    m_kind = Kind::Tets;
    m_highlight->VisibilityOff();
    m_hiddenRegions.clear();
    m_counts = countsOf(mesh);
    const Bounds box = bounds(mesh);
    setClipPlane(box.empty() ? Vec3{} : box.center(), {1.0, 0.0, 0.0});
    setUniformLook(m_actor->GetProperty());
    m_actor->GetProperty()->SetEdgeColor(kEdgeColour[0], kEdgeColour[1], kEdgeColour[2]);
    connectTetPipeline();
    m_actor->SetVisibility(m_shown);
    updateLegend();
}

void MeshDisplay::clear() {
    m_mapper->RemoveAllInputConnections(0);
    m_grid = nullptr;
    m_kind = Kind::None;
    m_counts = {};
    m_actor->VisibilityOff();
    updateLegend();
}

void MeshDisplay::setClipEnabled(bool enabled) {
    m_clipEnabled = enabled;
    if (m_kind == Kind::Tets)
        connectTetPipeline();
    else if (m_kind == Kind::Surface)
        connectSurfacePipeline();
}

void MeshDisplay::connectSurfacePipeline() {
    if (m_clipEnabled) {
        m_surfaceClip->SetInputData(m_surface);
        m_surfaceNormals->SetInputConnection(m_surfaceClip->GetOutputPort());
    } else {
        m_surfaceNormals->SetInputDataObject(m_surface);
    }
    m_mapper->SetInputConnection(m_surfaceNormals->GetOutputPort());
}

void MeshDisplay::colourTets(const std::vector<double>& values, double low, double high, const std::string& title) {
    if (m_kind != Kind::Tets)
        return;
    m_colouredByValue = values.size() == static_cast<std::size_t>(m_grid->GetNumberOfCells());
    m_colourBar->SetTitle(title.c_str());
    m_colourBar->GetLookupTable()->SetRange(low, high);
    vtkCellData* cells = m_grid->GetCellData();
    if (values.size() != static_cast<std::size_t>(m_grid->GetNumberOfCells())) {
        auto* regions = vtkIntArray::SafeDownCast(cells->GetArray(kRegionLabel));
        std::vector<std::int32_t> ids(static_cast<std::size_t>(regions ? regions->GetNumberOfTuples() : 0));
        for (std::size_t i = 0; i < ids.size(); ++i)
            ids[i] = regions->GetValue(static_cast<vtkIdType>(i));
        cells->SetScalars(toColours(ids));
    } else {
        auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
        colours->SetName("colour");
        colours->SetNumberOfComponents(3);
        colours->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
        const double span = high > low ? high - low : 1.0;
        for (std::size_t i = 0; i < values.size(); ++i) {
            const std::array<double, 3> rgb = divergingColour((values[i] - low) / span);
            for (int c = 0; c < 3; ++c)
                colours->SetComponent(static_cast<vtkIdType>(i), c, rgb[static_cast<std::size_t>(c)]);
        }
        cells->SetScalars(colours);
    }
    m_grid->Modified();
    updateLegend();
}

void MeshDisplay::setHiddenRegions(const std::set<std::int32_t>& regions) {
    m_hiddenRegions = regions;
    if (m_kind == Kind::Tets)
        connectTetPipeline();
}

std::array<double, 6> MeshDisplay::highlightTet(std::int64_t tet) {
    std::array<double, 6> box{0, 0, 0, 0, 0, 0};
    if (m_kind != Kind::Tets || tet < 0 || tet >= m_grid->GetNumberOfCells()) {
        m_highlight->VisibilityOff();
        return box;
    }
    auto one = vtkSmartPointer<vtkExtractCells>::New();
    one->SetInputData(m_grid);
    auto ids = vtkSmartPointer<vtkIdList>::New();
    ids->InsertNextId(static_cast<vtkIdType>(tet));
    one->SetCellList(ids);
    auto surface = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
    surface->SetInputConnection(one->GetOutputPort());
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(surface->GetOutputPort());
    mapper->ScalarVisibilityOff();
    m_highlight->SetMapper(mapper);
    m_highlight->VisibilityOn();
    m_grid->GetCell(static_cast<vtkIdType>(tet))->GetBounds(box.data());
    return box;
}

std::array<double, 6> MeshDisplay::meshBounds() const {
    std::array<double, 6> box{};
    if (m_kind == Kind::Tets && m_grid)
        m_grid->GetBounds(box.data());
    else if (m_kind == Kind::Surface && m_surface)
        m_surface->GetBounds(box.data());
    return box;
}

std::array<double, 6> MeshDisplay::regionBounds(std::int32_t region) const {
    std::array<double, 6> box{1.0, -1.0, 1.0, -1.0, 1.0, -1.0};
    if (m_kind != Kind::Tets || !m_grid)
        return box;
    auto* regions = vtkIntArray::SafeDownCast(m_grid->GetCellData()->GetArray(kRegionLabel));
    if (!regions)
        return box;
    bool any = false;
    for (vtkIdType c = 0; c < m_grid->GetNumberOfCells(); ++c) {
        if (regions->GetValue(c) != region)
            continue;
        double cell[6];
        m_grid->GetCellBounds(c, cell);
        for (int axis = 0; axis < 3; ++axis) {
            box[2 * axis] = any ? std::min(box[2 * axis], cell[2 * axis]) : cell[2 * axis];
            box[2 * axis + 1] = any ? std::max(box[2 * axis + 1], cell[2 * axis + 1]) : cell[2 * axis + 1];
        }
        any = true;
    }
    return box;
}

Vec3 MeshDisplay::clipOrigin() const {
    double o[3];
    m_plane->GetOrigin(o);
    return {o[0], o[1], o[2]};
}

Vec3 MeshDisplay::clipNormal() const {
    double n[3];
    m_plane->GetNormal(n);
    return {n[0], n[1], n[2]};
}

void MeshDisplay::setClipPlane(const Vec3& origin, const Vec3& normal) {
    m_plane->SetOrigin(origin.x, origin.y, origin.z);
    m_plane->SetNormal(normal.x, normal.y, normal.z);
}

void MeshDisplay::connectTetPipeline() {
    vtkSmartPointer<vtkAlgorithm> source;
    if (!m_hiddenRegions.empty()) {
        auto* regions = vtkIntArray::SafeDownCast(m_grid->GetCellData()->GetArray(kRegionLabel));
        auto keep = vtkSmartPointer<vtkIdList>::New();
        for (vtkIdType c = 0; c < m_grid->GetNumberOfCells(); ++c)
            if (!regions || m_hiddenRegions.count(regions->GetValue(c)) == 0)
                keep->InsertNextId(c);
        m_regionFilter->SetInputData(m_grid);
        m_regionFilter->SetCellList(keep);
        source = m_regionFilter;
    }
    if (m_clipEnabled) {
        if (source)
            m_clip->SetInputConnection(source->GetOutputPort());
        else
            m_clip->SetInputData(m_grid);
        m_gridSurface->SetInputConnection(m_clip->GetOutputPort());
    } else if (source) {
        m_gridSurface->SetInputConnection(source->GetOutputPort());
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
        if (m_clipEnabled) {
            m_clip->Update();
            return static_cast<std::size_t>(m_clip->GetOutput()->GetNumberOfCells());
        }
        if (!m_hiddenRegions.empty()) {
            m_regionFilter->Update();
            return static_cast<std::size_t>(m_regionFilter->GetOutput()->GetNumberOfCells());
        }
        return m_counts.tets;
    }
    return 0;
}

} // namespace hs::widgets
