#include "hs/widgets/view/SceneParts.h"

#include "hs/widgets/view/MeshDisplay.h"

#include <vtkActor.h>
#include <vtkOutlineSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <limits>
#include <set>

namespace hs::widgets {

namespace {

const std::string kTissues = "tissues";
const std::string kGrowth = "growth";
const std::string kBody = "body";

/// A box around `a` and `b` (either may be empty: xmin > xmax).
std::array<double, 6> unite(std::array<double, 6> a, const std::array<double, 6>& b) {
    for (int axis = 0; axis < 3; ++axis) {
        a[2 * axis] = std::min(a[2 * axis], b[2 * axis]);
        a[2 * axis + 1] = std::max(a[2 * axis + 1], b[2 * axis + 1]);
    }
    return a;
}

constexpr std::array<double, 6> kEmptyBox{std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
                                          std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
                                          std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest()};

} // namespace

generate::Stage stageOf(ResultLayer layer) {
    switch (layer) {
    case ResultLayer::Organ:
        return generate::Stage::Organ;
    case ResultLayer::Pathologies:
        return generate::Stage::Pathology;
    case ResultLayer::Body:
        return generate::Stage::Merge;
    case ResultLayer::Tissues:
        return generate::Stage::Tissue;
    case ResultLayer::Textured:
        return generate::Stage::Texture;
    case ResultLayer::None:
        break;
    }
    return generate::Stage::Scene;
}

SceneParts::SceneParts(vtkRenderer* renderer, MeshDisplay& tissues)
    : m_renderer(renderer), m_tissues(tissues), m_outline(vtkSmartPointer<vtkActor>::New()) {
    m_outline->VisibilityOff();
    m_outline->PickableOff();
    m_outline->GetProperty()->SetColor(1.0, 0.85, 0.1);
    m_outline->GetProperty()->SetLineWidth(2.0);
    m_outline->GetProperty()->LightingOff();
    m_renderer->AddActor(m_outline);
}

SceneParts::~SceneParts() {
    m_renderer->RemoveActor(m_outline);
}

MeshDisplay& SceneParts::addDisplay(const std::string& key) {
    auto& slot = m_displays[key];
    if (!slot)
        slot = std::make_unique<MeshDisplay>(m_renderer);
    slot->setClipEnabled(m_clipEnabled);
    return *slot;
}

void SceneParts::clear() {
    m_built.reset();
    m_layer = ResultLayer::None;
    m_userShown.clear();
    m_parts.clear();
    m_displays.clear();
    m_highlighted = -1;
    m_outline->VisibilityOff();
}

ResultLayer SceneParts::show(const std::shared_ptr<const generate::Generated>& shared,
                             std::optional<ResultLayer> layer) {
    if (!shared) {
        clear();
        m_tissues.clear();
        return ResultLayer::None;
    }
    const generate::Generated& results = *shared;
    if (!layer) {
        for (ResultLayer l : {ResultLayer::Textured, ResultLayer::Tissues, ResultLayer::Body, ResultLayer::Pathologies,
                              ResultLayer::Organ})
            if (hasLayer(results, l)) {
                layer = l;
                break;
            }
    }
    if (!layer || !hasLayer(results, *layer)) {
        clear();
        m_tissues.clear();
        return ResultLayer::None;
    }
    if (m_built.lock() != shared) {
        build(results);
        m_built = shared;
    }
    return showLayer(*layer);
}

void SceneParts::build(const generate::Generated& results) {
    std::vector<ScenePart> parts;
    std::map<std::string, std::unique_ptr<MeshDisplay>> old;
    old.swap(m_displays);
    // A display is reused by key, so a part keeps its actor (and the renderer its order) across results.
    const auto surface = [&](ScenePart part, const SurfaceMesh& mesh, int colourRegion) {
        if (auto it = old.find(part.key); it != old.end())
            m_displays[part.key] = std::move(it->second);
        MeshDisplay& d = addDisplay(part.key);
        d.showSurface(combineRegions({{&mesh, colourRegion}}));
        parts.push_back(std::move(part));
    };
    if (results.organ)
        surface({"organ", {}, PartKind::Organ, ResultLayer::Organ}, results.organ->mesh, 0);
    if (results.pathologies) {
        parts.push_back({kGrowth, {}, PartKind::DisplacedOrgan, ResultLayer::Pathologies});
        surface({kGrowth + "/organ", kGrowth, PartKind::DisplacedOrgan, ResultLayer::Pathologies},
                results.pathologies->organ, 0);
        for (std::size_t i = 0; i < results.pathologies->pathologies.size(); ++i) {
            const int index = static_cast<int>(i);
            const std::string name = i < results.spec.pathologies.size() ? results.spec.pathologies[i].id : "";
            surface({kGrowth + "/" + std::to_string(i + 1), kGrowth, PartKind::GrownPathology, ResultLayer::Pathologies,
                     name, index},
                    results.pathologies->pathologies[i].surface, index + 1);
        }
    }
    if (results.body) {
        parts.push_back({kBody, {}, PartKind::MergedRegion, ResultLayer::Body});
        for (const RegionSurface& s : results.body->body.surfaces) {
            // Body region 0 is the wall, region i + 1 pathology i.
            const int pathology = s.regionId > 0 ? s.regionId - 1 : -1;
            surface({kBody + "/" + std::to_string(s.regionId), kBody, PartKind::MergedRegion, ResultLayer::Body, s.name,
                     pathology, s.regionId},
                    s.surface, s.regionId);
        }
    }
    if (results.tissue) {
        m_tissues.showTetMesh(results.tissue->tets);
        parts.push_back({kTissues, {}, PartKind::Tissues, ResultLayer::Tissues});
        for (const scene::SceneRegion& r : results.tissue->regions) {
            int pathology = -1;
            for (std::size_t i = 0; i < results.spec.pathologies.size(); ++i)
                if (!r.pathologyId.empty() && results.spec.pathologies[i].id == r.pathologyId)
                    pathology = static_cast<int>(i);
            parts.push_back({kTissues + "/" + std::to_string(r.id), kTissues, PartKind::TissueRegion,
                             ResultLayer::Tissues, r.name, pathology, r.id, r.tissue});
        }
    } else {
        m_tissues.clear();
    }
    if (results.appearance) {
        const scene::VisualSurface& v = results.appearance->surface;
        ScenePart part{"surface", {}, PartKind::Surface, ResultLayer::Textured};
        if (auto it = old.find(part.key); it != old.end())
            m_displays[part.key] = std::move(it->second);
        addDisplay(part.key).showTexturedSurface(v.mesh, v.uvs, v.normals, v.albedo);
        parts.push_back(std::move(part));
    }
    if (results.scene && results.scene->simulation) {
        ScenePart part{"simulation", {}, PartKind::Simulation, ResultLayer::None};
        if (auto it = old.find(part.key); it != old.end())
            m_displays[part.key] = std::move(it->second);
        MeshDisplay& d = addDisplay(part.key);
        d.showTetMesh(results.scene->simulation->tets);
        d.setWireframe(true);
        parts.push_back(std::move(part));
    }
    m_parts = std::move(parts);
    old.clear(); // parts the new results lack leave the renderer
}

ResultLayer SceneParts::showLayer(ResultLayer shown) {
    const std::optional<ResultLayer> layer = shown;

    // A new layer shows its parts and hides every other; the same layer again keeps what the user showed or hid
    // (a part new to it shows when it is the layer's). The tissue regions stay as the Mesh panel leaves them.
    const bool sameLayer = *layer == m_layer;
    for (const auto& [key, display] : m_displays) {
        const ScenePart* part = find(key);
        const bool byDefault = part && part->layer == *layer;
        const auto wasShown = m_userShown.find(key);
        display->setShown(sameLayer && wasShown != m_userShown.end() ? wasShown->second : byDefault);
        const auto opacity = m_opacity.find(key);
        display->setOpacity(opacity == m_opacity.end() ? 1.0 : opacity->second);
    }
    const auto tissuesShown = m_userShown.find(kTissues);
    m_tissues.setShown(sameLayer && tissuesShown != m_userShown.end() ? tissuesShown->second
                                                                      : *layer == ResultLayer::Tissues);
    m_layer = *layer;
    m_userShown.clear();
    for (const ScenePart& part : m_parts)
        if (const MeshDisplay* d = display(part.key))
            m_userShown[part.key] = d->isShown();
    const auto opacity = m_opacity.find(kTissues);
    m_tissues.setOpacity(opacity == m_opacity.end() ? 1.0 : opacity->second);
    // One cut for every part: the reference's plane (its mesh's centre).
    const MeshDisplay& ref = reference();
    setClipPlane(ref.clipOrigin(), ref.clipNormal());
    if (m_highlighted >= 0)
        updateHighlight();
    return *layer;
}

const ScenePart* SceneParts::find(const std::string& key) const {
    for (const ScenePart& p : m_parts)
        if (p.key == key)
            return &p;
    return nullptr;
}

MeshDisplay* SceneParts::display(const std::string& key) const {
    if (key == kTissues)
        return find(key) ? &m_tissues : nullptr;
    const auto it = m_displays.find(key);
    return it == m_displays.end() ? nullptr : it->second.get();
}

void SceneParts::setShown(const std::string& key, bool shown) {
    const ScenePart* part = find(key);
    if (!part)
        return;
    if (part->kind == PartKind::TissueRegion) {
        std::set<std::int32_t> hidden = m_tissues.hiddenRegions();
        if (shown)
            hidden.erase(part->region);
        else
            hidden.insert(part->region);
        m_tissues.setHiddenRegions(hidden);
    } else if (MeshDisplay* d = display(key)) {
        d->setShown(shown);
        m_userShown[key] = shown;
        if (shown && part->kind == PartKind::Tissues) // the mesh shown again: every tissue in it
            m_tissues.setHiddenRegions({});
    } else {
        for (const ScenePart& child : m_parts)
            if (child.parent == key)
                setShown(child.key, shown);
    }
    updateHighlight();
}

bool SceneParts::isShown(const std::string& key) const {
    const ScenePart* part = find(key);
    if (!part)
        return false;
    if (part->kind == PartKind::TissueRegion)
        return m_tissues.isShown() && m_tissues.hiddenRegions().count(part->region) == 0;
    if (const MeshDisplay* d = display(key))
        return d->isShown();
    // A group is shown when any of its parts is.
    return std::any_of(m_parts.begin(), m_parts.end(),
                       [&](const ScenePart& child) { return child.parent == key && isShown(child.key); });
}

void SceneParts::setOpacity(const std::string& key, double opacity) {
    const ScenePart* part = find(key);
    if (!part)
        return;
    opacity = std::clamp(opacity, 0.0, 1.0);
    if (MeshDisplay* d = display(key)) {
        m_opacity[key] = opacity;
        d->setOpacity(opacity);
        return;
    }
    // A group's opacity is its parts'; a tissue region's is the mesh's.
    for (const ScenePart& child : m_parts)
        if (child.parent == key)
            setOpacity(child.key, opacity);
    if (part->kind == PartKind::TissueRegion)
        setOpacity(kTissues, opacity);
}

double SceneParts::opacity(const std::string& key) const {
    const ScenePart* part = find(key);
    if (!part)
        return 1.0;
    if (part->kind == PartKind::TissueRegion)
        return m_tissues.opacity();
    if (const MeshDisplay* d = display(key))
        return d->opacity();
    for (const ScenePart& child : m_parts)
        if (child.parent == key)
            return opacity(child.key);
    return 1.0;
}

int SceneParts::pathologyAt(const vtkProp* prop, std::int32_t region) const {
    if (!prop)
        return -1;
    for (const ScenePart& part : m_parts) {
        if (part.kind == PartKind::Tissues && m_tissues.actor() == prop) {
            for (const ScenePart& r : m_parts)
                if (r.kind == PartKind::TissueRegion && r.region == region)
                    return r.pathology;
            return -1;
        }
        const MeshDisplay* d = display(part.key);
        if (d && d->actor() == prop && part.kind != PartKind::Tissues)
            return part.pathology;
    }
    return -1;
}

std::array<double, 6> SceneParts::highlightPathology(int index) {
    m_highlighted = index;
    updateHighlight();
    std::array<double, 6> box{};
    if (m_outline->GetVisibility())
        std::copy_n(m_outline->GetBounds(), 6, box.begin());
    return box;
}

void SceneParts::updateHighlight() {
    // The box of the pathology's shown parts; when none is shown (the textured surface covers it), of all its parts.
    std::array<double, 6> box = kEmptyBox;
    bool any = false;
    for (const bool shownOnly : {true, false}) {
        for (const ScenePart& part : m_parts) {
            if (m_highlighted < 0 || part.pathology != m_highlighted || (shownOnly && !isShown(part.key)))
                continue;
            if (const MeshDisplay* d = display(part.key); d && part.kind != PartKind::Tissues) {
                box = unite(box, d->meshBounds());
                any = true;
            } else if (part.kind == PartKind::TissueRegion) {
                box = unite(box, m_tissues.regionBounds(part.region));
                any = true;
            }
        }
        if (any)
            break;
    }
    if (!any || box[0] > box[1]) {
        m_outline->VisibilityOff();
        return;
    }
    auto outline = vtkSmartPointer<vtkOutlineSource>::New();
    outline->SetBounds(box.data());
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(outline->GetOutputPort());
    m_outline->SetMapper(mapper);
    m_outline->VisibilityOn();
}

void SceneParts::setClipEnabled(bool enabled) {
    m_clipEnabled = enabled;
    m_tissues.setClipEnabled(enabled);
    for (const auto& [key, display] : m_displays)
        display->setClipEnabled(enabled);
}

void SceneParts::setClipPlane(const Vec3& origin, const Vec3& normal) {
    m_tissues.setClipPlane(origin, normal);
    for (const auto& [key, display] : m_displays)
        display->setClipPlane(origin, normal);
}

MeshDisplay& SceneParts::reference() const {
    for (const ScenePart& part : m_parts)
        if (MeshDisplay* d = display(part.key); d && d->isShown() && !d->isEmpty())
            return *d;
    return m_tissues;
}

} // namespace hs::widgets
