#pragma once
/// Shows a surface or a tetrahedral mesh in one renderer: colours by the "region" label when there is one, and for
/// a tet mesh a clipping plane that keeps whole tetrahedra (a crinkle cut), so the inside of the mesh can be read.

#include "hs/core/SurfaceMesh.h"
#include "hs/core/TetMesh.h"
#include "hs/core/Vec3.h"

#include <vtkSmartPointer.h>

#include <cstddef>

class vtkActor;
class vtkAlgorithm;
class vtkDataSetSurfaceFilter;
class vtkExtractGeometry;
class vtkPlane;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkRenderer;
class vtkUnstructuredGrid;

namespace hs::widgets {

/// What a loaded mesh holds, for the status bar.
struct MeshCounts {
    std::size_t vertices = 0;
    std::size_t triangles = 0; ///< surface triangles; 0 for a tet mesh
    std::size_t tets = 0;      ///< 0 for a surface
    std::size_t regions = 0;   ///< distinct region ids; 1 for a non-empty mesh without region labels
};

/// A VTK surface of `mesh` with a "region" cell (or point) array and RGB colours when the mesh has region labels.
vtkSmartPointer<vtkPolyData> toPolyData(const SurfaceMesh& mesh);
/// A VTK grid of tetrahedra with "region" and RGB colour cell arrays.
vtkSmartPointer<vtkUnstructuredGrid> toUnstructuredGrid(const TetMesh& mesh);
/// Counts of a surface; regions from the face label "region", else the vertex label "region".
MeshCounts countsOf(const SurfaceMesh& mesh);
MeshCounts countsOf(const TetMesh& mesh);

/// Owns one actor in `renderer` (VTK actors cannot be shared between views: make one MeshDisplay per view).
class MeshDisplay {
public:
    explicit MeshDisplay(vtkRenderer* renderer);
    ~MeshDisplay();
    MeshDisplay(const MeshDisplay&) = delete;
    MeshDisplay& operator=(const MeshDisplay&) = delete;

    void showSurface(const SurfaceMesh& mesh);
    /// Shows the outer surface of `mesh`; with the clip on, the tetrahedra on one side of the clipping plane.
    void showTetMesh(const TetMesh& mesh);
    void clear();

    bool isEmpty() const { return m_kind == Kind::None; }
    bool isTetMesh() const { return m_kind == Kind::Tets; }
    const MeshCounts& counts() const { return m_counts; }

    /// Only affects tet meshes; the setting is kept when another mesh is shown.
    void setClipEnabled(bool enabled);
    bool clipEnabled() const { return m_clipEnabled; }
    /// Keeps the tetrahedra with at least one point on the side opposite `normal`. showTetMesh resets the plane to
    /// the mesh's bounding-box centre with normal +x.
    void setClipPlane(const Vec3& origin, const Vec3& normal);
    /// Tetrahedra drawn (all of them with the clip off) for a tet mesh; triangles for a surface.
    std::size_t visibleCellCount() const;

    vtkActor* actor() const;

private:
    enum class Kind { None, Surface, Tets };

    void connectTetPipeline();

    vtkRenderer* m_renderer;
    vtkSmartPointer<vtkActor> m_actor;
    vtkSmartPointer<vtkPolyDataMapper> m_mapper;
    vtkSmartPointer<vtkUnstructuredGrid> m_grid;
    vtkSmartPointer<vtkPlane> m_plane;
    vtkSmartPointer<vtkExtractGeometry> m_clip;
    vtkSmartPointer<vtkDataSetSurfaceFilter> m_gridSurface;
    vtkSmartPointer<vtkAlgorithm> m_surfaceNormals;
    Kind m_kind = Kind::None;
    bool m_clipEnabled = false;
    MeshCounts m_counts;
};

} // namespace hs::widgets
