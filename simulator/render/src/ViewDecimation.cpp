// The endoscopic view's lighter surface: vtkDecimatePro on the inner and the outer faces, the kept points traced back
// to the visual surface's through a point array.
#include "hs/simrender/ViewDecimation.h"

#include <vtkCellArray.h>
#include <vtkDecimatePro.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <unordered_map>

namespace hs::simrender {

namespace {

constexpr const char* kSourceArray = "source";

/// The faces of `mesh` whose flag in `outer` equals `wanted`, over their own points (each carrying its source id).
vtkSmartPointer<vtkPolyData> facesOf(const SurfaceMesh& mesh, const std::vector<bool>& outer, bool wanted) {
    std::vector<vtkIdType> local(mesh.points.size(), -1);
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    auto source = vtkSmartPointer<vtkIdTypeArray>::New();
    source->SetName(kSourceArray);
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        if ((!outer.empty() && outer[f]) != wanted)
            continue;
        vtkIdType ids[3];
        for (std::size_t k = 0; k < 3; ++k) {
            const auto p = static_cast<std::size_t>(mesh.triangles[f][k]);
            if (local[p] < 0) {
                local[p] = points->InsertNextPoint(mesh.points[p].x, mesh.points[p].y, mesh.points[p].z);
                source->InsertNextValue(static_cast<vtkIdType>(p));
            }
            ids[k] = local[p];
        }
        cells->InsertNextCell(3, ids);
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetPolys(cells);
    poly->GetPointData()->AddArray(source);
    return poly;
}

vtkSmartPointer<vtkPolyData> decimated(vtkPolyData* faces, double reduction) {
    if (faces->GetNumberOfPolys() == 0 || reduction <= 0.0)
        return faces;
    auto decimate = vtkSmartPointer<vtkDecimatePro>::New();
    decimate->SetInputData(faces);
    decimate->SetTargetReduction(reduction);
    decimate->PreserveTopologyOn();        // no holes opened, no pieces joined
    decimate->BoundaryVertexDeletionOff(); // borders and the texture's seams stay where they are
    decimate->SplittingOff();
    decimate->Update();
    return decimate->GetOutput();
}

/// Appends `faces`' triangles to `out`, its points mapped back to the visual surface's and shared across calls.
void append(vtkPolyData* faces, std::unordered_map<std::size_t, std::int32_t>& index, DecimatedSurface& out) {
    auto* source = vtkIdTypeArray::SafeDownCast(faces->GetPointData()->GetArray(kSourceArray));
    const auto drawnPoint = [&](vtkIdType local) {
        const auto original = static_cast<std::size_t>(source->GetValue(local));
        const auto [it, added] = index.try_emplace(original, static_cast<std::int32_t>(out.sourcePoints.size()));
        if (added)
            out.sourcePoints.push_back(original);
        return it->second;
    };
    vtkCellArray* polys = faces->GetPolys();
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
        if (count == 3)
            out.triangles.push_back({drawnPoint(ids[0]), drawnPoint(ids[1]), drawnPoint(ids[2])});
}

} // namespace

DecimatedSurface decimateForView(const SurfaceMesh& mesh, const std::vector<bool>& outer,
                                 const ViewDecimationParams& params) {
    const double reduction = std::clamp(params.targetReduction, 0.0, 0.9);
    DecimatedSurface out;
    std::unordered_map<std::size_t, std::int32_t> index;
    append(decimated(facesOf(mesh, outer, false), reduction), index, out);
    out.innerTriangles = out.triangles.size();
    append(decimated(facesOf(mesh, outer, true), reduction), index, out);
    return out;
}

bool isSoftwareRenderer(std::string_view glRenderer) {
    std::string lower(glRenderer);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const char* name : {"llvmpipe", "softpipe", "swrast", "swiftshader", "basic render driver"})
        if (lower.find(name) != std::string::npos)
            return true;
    return false;
}

} // namespace hs::simrender
