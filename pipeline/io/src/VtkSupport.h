#pragma once
/// VTK glue that stays inside io/src: capturing VTK's error output, and converting meshes to VTK data sets.

#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/TetMesh.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkDataSetAttributes;
class vtkPoints;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace hs::io::detail {

/// While alive, VTK messages (errors, warnings) raised on this thread are collected here instead of being printed.
/// A process-wide output window is installed once; it routes each message to the capture active on the thread that
/// raised it and forwards messages of threads without a capture to the previous window.
class VtkMessageCapture {
public:
    VtkMessageCapture();
    ~VtkMessageCapture();
    VtkMessageCapture(const VtkMessageCapture&) = delete;
    VtkMessageCapture& operator=(const VtkMessageCapture&) = delete;

    void add(const char* text, bool isError);
    bool hasErrors() const { return m_errors > 0; }
    /// The collected messages on one line, without VTK's source-file prefixes, at most ~1000 characters.
    std::string text() const;
    /// Success when `ok` and no error was captured; otherwise `code` with "path: action failed: messages".
    Status check(bool ok, const std::string& path, const char* action, ErrorCode code = ErrorCode::IoError) const;

private:
    VtkMessageCapture* m_outer;
    std::string m_text;
    int m_errors = 0;
};

vtkSmartPointer<vtkPoints> toVtkPoints(const std::vector<Vec3>& points);
/// Int32 arrays named after the labels (empty arrays are skipped).
void addLabelArrays(vtkDataSetAttributes* attributes, const LabelMap& labels);
vtkSmartPointer<vtkPolyData> toPolyData(const SurfaceMesh& mesh, bool withLabels);
vtkSmartPointer<vtkUnstructuredGrid> toUnstructuredGrid(const TetMesh& mesh);
vtkSmartPointer<vtkUnstructuredGrid> toUnstructuredGrid(const SurfaceMesh& mesh);

} // namespace hs::io::detail
