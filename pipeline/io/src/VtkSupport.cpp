#include "VtkSupport.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <mutex>

namespace hs::io::detail {
namespace {

thread_local VtkMessageCapture* tCapture = nullptr;

/// Routes VTK's messages to the capture of the calling thread. VTK calls the output window from whichever thread
/// raised the message, so a thread-local target keeps concurrent readers apart without a lock.
class RoutingOutputWindow : public vtkOutputWindow {
public:
    static RoutingOutputWindow* New();
    vtkTypeMacro(RoutingOutputWindow, vtkOutputWindow)

        void setPrevious(vtkOutputWindow* previous) {
        m_previous = previous;
    }

    void DisplayText(const char* text) override { route(text, false, &vtkOutputWindow::DisplayText); }
    void DisplayErrorText(const char* text) override { route(text, true, &vtkOutputWindow::DisplayErrorText); }
    void DisplayWarningText(const char* text) override { route(text, false, &vtkOutputWindow::DisplayWarningText); }
    void DisplayGenericWarningText(const char* text) override {
        route(text, false, &vtkOutputWindow::DisplayGenericWarningText);
    }
    void DisplayDebugText(const char* text) override { route(text, false, &vtkOutputWindow::DisplayDebugText); }

protected:
    RoutingOutputWindow() = default;
    ~RoutingOutputWindow() override = default;

private:
    void route(const char* text, bool isError, void (vtkOutputWindow::*forward)(const char*)) {
        if (tCapture)
            tCapture->add(text, isError);
        else if (m_previous)
            (m_previous.GetPointer()->*forward)(text);
    }

    vtkSmartPointer<vtkOutputWindow> m_previous;
};

vtkStandardNewMacro(RoutingOutputWindow);

void installRoutingWindow() {
    static std::once_flag once;
    std::call_once(once, [] {
        // VTK 9 also sends every message to its logger, which prints to stderr before the output window sees it.
        // Messages now reach stderr through the routing window instead: exactly once for threads without a
        // capture, and not at all for a read or write whose errors go into an Error.
        vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
        vtkNew<RoutingOutputWindow> window;
        window->setPrevious(vtkOutputWindow::GetInstance());
        vtkOutputWindow::SetInstance(window);
    });
}

/// Drops VTK's "ERROR: In /path/file.cxx, line N" prefix and the object address, keeps the message.
std::string cleanMessage(const std::string& raw) {
    std::string text = raw;
    if (text.rfind("ERROR: In ", 0) == 0 || text.rfind("Warning: In ", 0) == 0 ||
        text.rfind("Generic Warning: In ", 0) == 0) {
        const std::size_t newline = text.find('\n');
        text = newline == std::string::npos ? std::string() : text.substr(newline + 1);
    }
    // The executive's follow-up ("Algorithm X returned failure for request: <dump>") repeats nothing useful.
    if (text.find("returned failure for request") != std::string::npos)
        return {};
    const std::size_t close = text.find("): ");
    if (close != std::string::npos && close < 80 && text.find("(0x") != std::string::npos)
        text = text.substr(close + 3);
    std::string out;
    for (char c : text) {
        if (c == '\n' || c == '\r' || c == '\t')
            c = ' ';
        if (c == ' ' && (out.empty() || out.back() == ' '))
            continue;
        out += c;
    }
    while (!out.empty() && out.back() == ' ')
        out.pop_back();
    return out;
}

} // namespace

VtkMessageCapture::VtkMessageCapture() : m_outer(tCapture) {
    installRoutingWindow();
    tCapture = this;
}

VtkMessageCapture::~VtkMessageCapture() {
    tCapture = m_outer;
}

void VtkMessageCapture::add(const char* text, bool isError) {
    if (isError)
        ++m_errors;
    if (!text || m_text.size() > 1000)
        return;
    const std::string cleaned = cleanMessage(text);
    if (cleaned.empty())
        return;
    if (!m_text.empty())
        m_text += "; ";
    m_text += cleaned;
}

std::string VtkMessageCapture::text() const {
    return m_text.size() > 1000 ? m_text.substr(0, 1000) + "..." : m_text;
}

Status VtkMessageCapture::check(bool ok, const std::string& path, const char* action, ErrorCode code) const {
    if (ok && !hasErrors())
        return {};
    std::string detail = path + ": " + action + " failed";
    if (!m_text.empty())
        detail += ": " + text();
    return fail(code, detail);
}

vtkSmartPointer<vtkPoints> toVtkPoints(const std::vector<Vec3>& points) {
    auto out = vtkSmartPointer<vtkPoints>::New();
    out->SetDataTypeToDouble();
    out->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i)
        out->SetPoint(static_cast<vtkIdType>(i), points[i].x, points[i].y, points[i].z);
    return out;
}

void addLabelArrays(vtkDataSetAttributes* attributes, const LabelMap& labels) {
    for (const auto& [name, values] : labels) {
        if (values.empty())
            continue;
        vtkNew<vtkIntArray> array;
        array->SetName(name.c_str());
        array->SetNumberOfComponents(1);
        array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
        for (std::size_t i = 0; i < values.size(); ++i)
            array->SetValue(static_cast<vtkIdType>(i), values[i]);
        attributes->AddArray(array);
    }
}

namespace {

/// A cell array of fixed-size cells from a flat list of indices.
template <class Cells>
vtkSmartPointer<vtkCellArray> toCellArray(const Cells& cells) {
    constexpr std::size_t kCorners = std::tuple_size<typename Cells::value_type>::value;
    vtkNew<vtkIdTypeArray> offsets;
    vtkNew<vtkIdTypeArray> connectivity;
    offsets->SetNumberOfValues(static_cast<vtkIdType>(cells.size() + 1));
    connectivity->SetNumberOfValues(static_cast<vtkIdType>(cells.size() * kCorners));
    for (std::size_t c = 0; c <= cells.size(); ++c)
        offsets->SetValue(static_cast<vtkIdType>(c), static_cast<vtkIdType>(c * kCorners));
    for (std::size_t c = 0; c < cells.size(); ++c)
        for (std::size_t k = 0; k < kCorners; ++k)
            connectivity->SetValue(static_cast<vtkIdType>(c * kCorners + k), cells[c][k]);
    auto out = vtkSmartPointer<vtkCellArray>::New();
    out->SetData(offsets, connectivity);
    return out;
}

} // namespace

vtkSmartPointer<vtkPolyData> toPolyData(const SurfaceMesh& mesh, bool withLabels) {
    auto out = vtkSmartPointer<vtkPolyData>::New();
    out->SetPoints(toVtkPoints(mesh.points));
    out->SetPolys(toCellArray(mesh.triangles));
    if (withLabels) {
        addLabelArrays(out->GetPointData(), mesh.vertexLabels);
        addLabelArrays(out->GetCellData(), mesh.faceLabels);
    }
    return out;
}

namespace {

template <class Cells>
vtkSmartPointer<vtkUnstructuredGrid> toGrid(const std::vector<Vec3>& points, const Cells& cells, int cellType) {
    auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
    out->SetPoints(toVtkPoints(points));
    vtkNew<vtkUnsignedCharArray> types;
    types->SetNumberOfValues(static_cast<vtkIdType>(cells.size()));
    types->FillValue(static_cast<unsigned char>(cellType));
    out->SetCells(types, toCellArray(cells));
    return out;
}

} // namespace

vtkSmartPointer<vtkUnstructuredGrid> toUnstructuredGrid(const TetMesh& mesh) {
    auto out = toGrid(mesh.points, mesh.tets, VTK_TETRA);
    if (!mesh.regions.empty()) {
        LabelMap regions;
        regions["region"] = mesh.regions;
        addLabelArrays(out->GetCellData(), regions);
    }
    addLabelArrays(out->GetCellData(), mesh.tetLabels);
    addLabelArrays(out->GetPointData(), mesh.pointLabels);
    return out;
}

vtkSmartPointer<vtkUnstructuredGrid> toUnstructuredGrid(const SurfaceMesh& mesh) {
    auto out = toGrid(mesh.points, mesh.triangles, VTK_TRIANGLE);
    addLabelArrays(out->GetCellData(), mesh.faceLabels);
    addLabelArrays(out->GetPointData(), mesh.vertexLabels);
    return out;
}

} // namespace hs::io::detail
