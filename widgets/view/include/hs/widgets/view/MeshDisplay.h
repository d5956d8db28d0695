#pragma once
/// Shows a surface or a tetrahedral mesh in one renderer: colours by the "region" label when there is one, and for
/// a tet mesh a clipping plane that keeps whole tetrahedra (a crinkle cut), so the inside of the mesh can be read.

#include "hs/core/Image.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/TetMesh.h"
#include "hs/core/Vec3.h"

#include <vtkSmartPointer.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

class vtkActor;
class vtkAlgorithm;
class vtkClipPolyData;
class vtkExtractCells;
class vtkDataSetSurfaceFilter;
class vtkExtractGeometry;
class vtkLegendBoxActor;
class vtkObject;
class vtkScalarBarActor;
class vtkPlane;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkRenderer;
class vtkTexture;
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
    /// Shows `mesh` with `albedo` mapped by `uvs` (one per point, origin at the image's top left) and smooth
    /// `normals` (one per point; empty: computed), lit as tissue under a lamp.
    void showTexturedSurface(const SurfaceMesh& mesh, const std::vector<std::array<float, 2>>& uvs,
                             const std::vector<Vec3>& normals, const ImageU8& albedo);
    bool isTextured() const { return m_textured; }
    /// Shows the outer surface of `mesh`; with the clip on, the tetrahedra on one side of the clipping plane.
    void showTetMesh(const TetMesh& mesh);
    void clear();

    bool isEmpty() const { return m_kind == Kind::None; }
    bool isTetMesh() const { return m_kind == Kind::Tets; }
    const MeshCounts& counts() const { return m_counts; }

    /// Tet meshes keep whole tetrahedra on one side; surfaces are cut open (to see and click the cavity's wall).
    /// The setting is kept when another mesh is shown.
    void setClipEnabled(bool enabled);
    bool clipEnabled() const { return m_clipEnabled; }
    /// Keeps the tetrahedra with at least one point on the side opposite `normal`. showTetMesh resets the plane to
    /// the mesh's bounding-box centre with normal +x.
    void setClipPlane(const Vec3& origin, const Vec3& normal);
    Vec3 clipOrigin() const;
    Vec3 clipNormal() const;
    /// The whole mesh's bounds (xmin, xmax, ymin, ymax, zmin, zmax), whatever the clip shows; zeros when empty.
    std::array<double, 6> meshBounds() const;
    /// Tet meshes: the bounds of region `region`'s tets; xmin > xmax when it has none.
    std::array<double, 6> regionBounds(std::int32_t region) const;
    /// Tetrahedra drawn (all of them with the clip off) for a tet mesh; triangles for a surface.
    std::size_t visibleCellCount() const;

    /// Tet meshes: colours each tet by `values` (one per tet) on a blue (low) to red (high) scale over [low, high],
    /// with a colour bar titled `title` in the view's corner; an empty `values` goes back to the region colours and
    /// their legend.
    void colourTets(const std::vector<double>& values, double low, double high, const std::string& title = {});
    /// The names of a tet mesh's regions for its legend (a swatch of each region's colour and its name, in the view's
    /// corner while the tets are coloured by region); regions without a name are left out, none: no legend.
    void setRegionNames(const std::map<std::int32_t, std::string>& names);
    /// What the legend shows now: the regions' names, or the colour bar's title; empty when none is shown.
    std::vector<std::string> legendEntries() const;
    std::string colourBarTitle() const;
    /// Tet meshes: hides the tets of the given regions (the others stay, cut by the clip when it is on).
    void setHiddenRegions(const std::set<std::int32_t>& regions);
    const std::set<std::int32_t>& hiddenRegions() const { return m_hiddenRegions; }
    /// Outlines one tet (of the mesh shown) in a second actor; a negative index removes the outline. Returns the
    /// tet's bounds (xmin, xmax, ymin, ymax, zmin, zmax) for framing the camera.
    std::array<double, 6> highlightTet(std::int64_t tet);

    /// Whether the mesh is drawn (the scene tree's check box); a hidden display keeps its mesh. Shown by default.
    void setShown(bool shown);
    bool isShown() const { return m_shown; }
    /// 0 (invisible) to 1 (opaque); the highlight and the legends stay opaque.
    void setOpacity(double opacity);
    double opacity() const;
    /// Draws the mesh's edges only (the simulation mesh beside the surface it carries).
    void setWireframe(bool wireframe);

    vtkActor* actor() const;

private:
    enum class Kind { None, Surface, Tets };

    void connectTetPipeline();
    void updateLegend();
    void placeLegends(vtkObject*, unsigned long, void*);
    void connectSurfacePipeline();

    vtkRenderer* m_renderer;
    vtkSmartPointer<vtkActor> m_actor;
    vtkSmartPointer<vtkPolyDataMapper> m_mapper;
    vtkSmartPointer<vtkUnstructuredGrid> m_grid;
    vtkSmartPointer<vtkPlane> m_plane;
    vtkSmartPointer<vtkExtractGeometry> m_clip;
    vtkSmartPointer<vtkDataSetSurfaceFilter> m_gridSurface;
    vtkSmartPointer<vtkAlgorithm> m_surfaceNormals;
    vtkSmartPointer<vtkPolyData> m_surface;
    vtkSmartPointer<vtkClipPolyData> m_surfaceClip;
    vtkSmartPointer<vtkExtractCells> m_regionFilter;
    vtkSmartPointer<vtkActor> m_highlight;
    vtkSmartPointer<vtkLegendBoxActor> m_legend;
    vtkSmartPointer<vtkScalarBarActor> m_colourBar;
    std::map<std::int32_t, std::string> m_regionNames;
    bool m_colouredByValue = false;
    unsigned long m_legendObserver = 0; ///< placeLegends on the renderer's StartEvent
    vtkSmartPointer<vtkTexture> m_texture;
    bool m_textured = false;
    std::set<std::int32_t> m_hiddenRegions;
    Kind m_kind = Kind::None;
    bool m_clipEnabled = false;
    bool m_shown = true;
    MeshCounts m_counts;
};

} // namespace hs::widgets
