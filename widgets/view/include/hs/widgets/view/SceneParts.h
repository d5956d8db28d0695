#pragma once
/// The parts of a case's results the workstation's 3-D view can show, each in its own actor with a visibility and an
/// opacity (as 3D Slicer's Data module or ParaView's Pipeline Browser list theirs): the organ of the shape model; the
/// displaced organ and each grown pathology; each region of the merged body; the tetrahedral mesh, whose tissues are
/// its regions; the textured visual surface; the simulation mesh. A new result shows the furthest stage's parts and
/// hides the others; what the user shows, hides or makes translucent stays so while the part exists.

#include "hs/clinical/Tissue.h"
#include "hs/core/Vec3.h"
#include "hs/generate/Generate.h"
#include "hs/widgets/view/ResultsDisplay.h"

#include <vtkSmartPointer.h>

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

class vtkActor;
class vtkProp;
class vtkRenderer;

namespace hs::widgets {

class MeshDisplay;

enum class PartKind { Organ, DisplacedOrgan, GrownPathology, MergedRegion, Tissues, TissueRegion, Surface, Simulation };

struct ScenePart {
    ScenePart(std::string key_, std::string parent_, PartKind kind_, ResultLayer layer_, std::string name_ = {},
              int pathology_ = -1, std::int32_t region_ = -1, std::optional<clinical::Tissue> tissue_ = std::nullopt)
        : key(std::move(key_)), parent(std::move(parent_)), kind(kind_), layer(layer_), name(std::move(name_)),
          pathology(pathology_), region(region_), tissue(tissue_) {}

    std::string key;    ///< stable while the part exists: "organ", "growth/organ", "growth/2", "body/1", "tissues", ...
    std::string parent; ///< the key of the part it belongs to (a tissue region's is "tissues"); empty at the top
    PartKind kind = PartKind::Organ;
    ResultLayer layer = ResultLayer::None;  ///< the stage view the part belongs to
    std::string name;                       ///< the region's or pathology's name ("myoma-1", "myometrium"); else empty
    int pathology = -1;                     ///< index of the case's pathology the part is, -1 for none
    std::int32_t region = -1;               ///< a tissue region's scene region id or a merged region's body id
    std::optional<clinical::Tissue> tissue; ///< a tissue region's tissue
};

/// The stage each layer's results come from, for "out of date" marks: Organ, Pathology, Merge, Tissue, Texture; the
/// simulation mesh is the scene's (Stage::Scene).
generate::Stage stageOf(ResultLayer layer);

class SceneParts {
public:
    /// `tissues` shows the tetrahedral mesh (the display the Mesh panel colours and cuts); the other parts get
    /// displays of their own in `renderer`.
    SceneParts(vtkRenderer* renderer, MeshDisplay& tissues);
    ~SceneParts();
    SceneParts(const SceneParts&) = delete;
    SceneParts& operator=(const SceneParts&) = delete;

    /// Rebuilds the parts from `results` and shows those of `layer` (by default the furthest stage there is), the
    /// others hidden; while the layer stays the same, what the user showed or hid stays so; opacities stay by key.
    /// Returns the layer shown; None when `results` has nothing (the parts are then cleared). The same results again (a
    /// layer chosen, placing begun) change only what is shown.
    ResultLayer show(const std::shared_ptr<const generate::Generated>& results,
                     std::optional<ResultLayer> layer = std::nullopt);
    /// Removes every part; the tissue display keeps what it shows (a mesh file, a reviewed package's mesh).
    void clear();

    const std::vector<ScenePart>& parts() const { return m_parts; }
    const ScenePart* find(const std::string& key) const;
    /// A tissue region's visibility is the tissue display's hidden regions; a group's (the growth, the merged body)
    /// is its children's.
    void setShown(const std::string& key, bool shown);
    bool isShown(const std::string& key) const;
    void setOpacity(const std::string& key, double opacity);
    double opacity(const std::string& key) const;
    /// The display of a part with an actor of its own (nullptr for groups, tissue regions and a part not shown yet:
    /// a part is drawn when it is first shown).
    MeshDisplay* display(const std::string& key) const;
    /// Called when a part has been drawn (the tissue mesh: the Mesh panel colours it).
    void setOnBuilt(std::function<void(const std::string& key)> onBuilt) { m_onBuilt = std::move(onBuilt); }

    /// The pathology a pick landed on: `prop` the picked actor, `region` the "region" of its picked cell (-1: none).
    /// -1 when the pick is on no pathology.
    int pathologyAt(const vtkProp* prop, std::int32_t region) const;
    /// Outlines pathology `index` with a box (around its shown parts, or all of them when none is shown); -1 removes
    /// the outline. Returns the box (xmin, xmax,
    /// ymin, ymax, zmin, zmax), zeros when nothing of it is shown.
    std::array<double, 6> highlightPathology(int index);
    int highlightedPathology() const { return m_highlighted; }

    /// Forwarded to every display, so the cut opens the organ, the growth and the mesh alike.
    void setClipEnabled(bool enabled);
    void setClipPlane(const Vec3& origin, const Vec3& normal);
    /// The display the clip plane's handle follows: the first shown part of the layer shown, else the tissues'.
    MeshDisplay& reference() const;

private:
    void build(const generate::Generated& results);
    /// Draws part `key` when it has not been drawn from the current results.
    void ensureBuilt(const std::string& key);
    ResultLayer showLayer(ResultLayer layer);
    void updateHighlight();

    vtkRenderer* m_renderer;
    MeshDisplay& m_tissues;
    std::vector<ScenePart> m_parts;
    std::shared_ptr<const generate::Generated> m_built; ///< the results the parts come from (drawn when shown)
    struct Fill {
        std::function<void(MeshDisplay&)> fill; ///< draws the part; null for groups and tissue regions
        Bounds bounds;                          ///< of its mesh (a tissue region's tets), for the selection's box
    };
    std::map<std::string, Fill> m_fills;
    std::set<std::string> m_builtKeys; ///< parts drawn from m_built
    bool m_tissuesBuilt = false;
    std::map<std::string, bool> m_shownState; ///< each part's visibility, kept while the same layer is shown
    std::function<void(const std::string&)> m_onBuilt;
    Vec3 m_clipOrigin;
    Vec3 m_clipNormal{1.0, 0.0, 0.0};
    bool m_clipPlaneSet = false;
    std::map<std::string, std::unique_ptr<MeshDisplay>> m_displays;
    std::map<std::string, double> m_opacity; ///< what the user set, by key
    ResultLayer m_layer = ResultLayer::None; ///< the layer last shown
    bool m_clipEnabled = false;
    int m_highlighted = -1;
    vtkSmartPointer<vtkActor> m_outline;
};

} // namespace hs::widgets
