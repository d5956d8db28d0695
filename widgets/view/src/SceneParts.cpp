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

/// The bounds of region `region`'s tets of `mesh`; empty when it has none.
Bounds regionBounds(const TetMesh& mesh, std::int32_t region) {
    Bounds box;
    for (std::size_t t = 0; t < mesh.tets.size() && t < mesh.regions.size(); ++t)
        if (mesh.regions[t] == region)
            for (const auto i : mesh.tets[t])
                box.add(mesh.points[static_cast<std::size_t>(i)]);
    return box;
}

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

void SceneParts::clear() {
    m_built.reset();
    m_layer = ResultLayer::None;
    m_shownState.clear();
    m_fills.clear();
    m_builtKeys.clear();
    m_tissuesBuilt = false;
    m_clipPlaneSet = false;
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
    if (m_built != shared) {
        build(results);
        m_built = shared; // kept: the parts not drawn yet are drawn from it when shown
    }
    return showLayer(*layer);
}

void SceneParts::build(const generate::Generated& results) {
    // Only the parts shown are drawn (turned into VTK data) now, the others when first shown: a result on the GUI
    // thread costs what the view shows, not every stage's meshes.
    std::vector<ScenePart> parts;
    std::map<std::string, std::unique_ptr<MeshDisplay>> old;
    old.swap(m_displays);
    m_fills.clear();
    m_builtKeys.clear();
    m_clipPlaneSet = false; // the new result's cut is set when it is shown
    const auto keep = [&](const std::string& key) {
        // A display is reused by key, so a part keeps its actor (and the renderer its order) across results.
        if (auto it = old.find(key); it != old.end()) {
            m_displays[key] = std::move(it->second);
            m_displays[key]->setShown(false);
        }
    };
    const auto surface = [&](ScenePart part, const SurfaceMesh* mesh, int colourRegion) {
        keep(part.key);
        m_fills[part.key] = {[mesh, colourRegion](MeshDisplay& d) {
                                 d.showSurface(combineRegions({{mesh, colourRegion}}));
                             },
                             bounds(*mesh)};
        parts.push_back(std::move(part));
    };
    if (results.organ)
        surface({"organ", {}, PartKind::Organ, ResultLayer::Organ}, &results.organ->mesh, 0);
    if (results.pathologies) {
        parts.push_back({kGrowth, {}, PartKind::DisplacedOrgan, ResultLayer::Pathologies});
        surface({kGrowth + "/organ", kGrowth, PartKind::DisplacedOrgan, ResultLayer::Pathologies},
                &results.pathologies->organ, 0);
        for (std::size_t i = 0; i < results.pathologies->pathologies.size(); ++i) {
            const int index = static_cast<int>(i);
            const std::string name = i < results.spec.pathologies.size() ? results.spec.pathologies[i].id : "";
            surface({kGrowth + "/" + std::to_string(i + 1), kGrowth, PartKind::GrownPathology, ResultLayer::Pathologies,
                     name, index},
                    &results.pathologies->pathologies[i].surface, index + 1);
        }
    }
    if (results.body) {
        parts.push_back({kBody, {}, PartKind::MergedRegion, ResultLayer::Body});
        for (const RegionSurface& s : results.body->body.surfaces) {
            // Body region 0 is the wall, region i + 1 pathology i.
            const int pathology = s.regionId > 0 ? s.regionId - 1 : -1;
            surface({kBody + "/" + std::to_string(s.regionId), kBody, PartKind::MergedRegion, ResultLayer::Body, s.name,
                     pathology, s.regionId},
                    &s.surface, s.regionId);
        }
    }
    m_tissues.clear(); // until it is shown
    m_tissuesBuilt = false;
    if (results.tissue) {
        const TetMesh* tets = &results.tissue->tets;
        m_fills[kTissues] = {[tets](MeshDisplay& d) { d.showTetMesh(*tets); }, bounds(*tets)};
        parts.push_back({kTissues, {}, PartKind::Tissues, ResultLayer::Tissues});
        for (const scene::SceneRegion& r : results.tissue->regions) {
            int pathology = -1;
            for (std::size_t i = 0; i < results.spec.pathologies.size(); ++i)
                if (!r.pathologyId.empty() && results.spec.pathologies[i].id == r.pathologyId)
                    pathology = static_cast<int>(i);
            parts.push_back({kTissues + "/" + std::to_string(r.id), kTissues, PartKind::TissueRegion,
                             ResultLayer::Tissues, r.name, pathology, r.id, r.tissue});
            m_fills[parts.back().key] = {nullptr, regionBounds(*tets, r.id)};
        }
    }
    if (results.appearance) {
        const scene::VisualSurface* v = &results.appearance->surface;
        keep("surface");
        m_fills["surface"] = {[v](MeshDisplay& d) { d.showTexturedSurface(v->mesh, v->uvs, v->normals, v->albedo); },
                              bounds(v->mesh)};
        parts.push_back({"surface", {}, PartKind::Surface, ResultLayer::Textured});
    }
    if (results.scene && results.scene->simulation) {
        const TetMesh* tets = &results.scene->simulation->tets;
        keep("simulation");
        m_fills["simulation"] = {[tets](MeshDisplay& d) {
                                     d.showTetMesh(*tets);
                                     d.setWireframe(true);
                                 },
                                 bounds(*tets)};
        parts.push_back({"simulation", {}, PartKind::Simulation, ResultLayer::None});
    }
    m_parts = std::move(parts);
    old.clear(); // parts the new results lack leave the renderer
}

void SceneParts::ensureBuilt(const std::string& key) {
    const auto fill = m_fills.find(key);
    if (fill == m_fills.end() || !fill->second.fill)
        return;
    if (key == kTissues) {
        if (m_tissuesBuilt)
            return;
        fill->second.fill(m_tissues);
        m_tissuesBuilt = true;
    } else {
        auto& slot = m_displays[key];
        if (slot && m_builtKeys.count(key))
            return;
        if (!slot)
            slot = std::make_unique<MeshDisplay>(m_renderer);
        slot->setShown(false);
        fill->second.fill(*slot);
        m_builtKeys.insert(key);
    }
    MeshDisplay& d = key == kTissues ? m_tissues : *m_displays[key];
    d.setClipEnabled(m_clipEnabled);
    d.setClipPlane(m_clipOrigin, m_clipNormal);
    const auto opacity = m_opacity.find(key);
    d.setOpacity(opacity == m_opacity.end() ? 1.0 : opacity->second);
    if (m_onBuilt)
        m_onBuilt(key);
}

ResultLayer SceneParts::showLayer(ResultLayer layer) {
    // A new layer shows its parts and hides every other; the same layer again keeps what the user showed or hid
    // (a part new to it shows when it is the layer's). The tissue regions stay as the Mesh panel leaves them.
    const bool sameLayer = layer == m_layer;
    std::map<std::string, bool> state;
    for (const ScenePart& part : m_parts) {
        const auto fill = m_fills.find(part.key);
        if (fill == m_fills.end() || !fill->second.fill)
            continue; // a group or a tissue region: its parts' state is its state
        const auto was = m_shownState.find(part.key);
        const bool shown = sameLayer && was != m_shownState.end() ? was->second : part.layer == layer;
        state[part.key] = shown;
        if (shown)
            ensureBuilt(part.key);
        if (MeshDisplay* d = display(part.key))
            d->setShown(shown && (part.key != kTissues || m_tissuesBuilt));
    }
    m_shownState = std::move(state);
    m_layer = layer;
    // A new result's cut goes through the centre of what is shown, as the reference display puts it.
    if (!m_clipPlaneSet) {
        const MeshDisplay& ref = reference();
        setClipPlane(ref.clipOrigin(), ref.clipNormal());
    }
    updateHighlight();
    return layer;
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
        if (shown && !isShown(kTissues))
            setShown(kTissues, true);
        std::set<std::int32_t> hidden = m_tissues.hiddenRegions();
        if (shown)
            hidden.erase(part->region);
        else
            hidden.insert(part->region);
        m_tissues.setHiddenRegions(hidden);
    } else if (m_fills.count(key)) {
        m_shownState[key] = shown;
        if (shown)
            ensureBuilt(key);
        if (MeshDisplay* d = display(key))
            d->setShown(shown && (key != kTissues || m_tissuesBuilt));
        if (shown && key == kTissues) // the mesh shown again: every tissue in it
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
        return isShown(kTissues) && m_tissues.hiddenRegions().count(part->region) == 0;
    if (m_fills.count(key)) {
        const auto state = m_shownState.find(key);
        return state != m_shownState.end() && state->second;
    }
    // A group is shown when any of its parts is.
    return std::any_of(m_parts.begin(), m_parts.end(),
                       [&](const ScenePart& child) { return child.parent == key && isShown(child.key); });
}

void SceneParts::setOpacity(const std::string& key, double opacity) {
    const ScenePart* part = find(key);
    if (!part)
        return;
    opacity = std::clamp(opacity, 0.0, 1.0);
    if (part->kind == PartKind::TissueRegion) {
        setOpacity(kTissues, opacity); // a tissue region's opacity is the mesh's
        return;
    }
    if (m_fills.count(key)) {
        m_opacity[key] = opacity;
        if (MeshDisplay* d = display(key))
            d->setOpacity(opacity);
        return;
    }
    for (const ScenePart& child : m_parts) // a group's opacity is its parts'
        if (child.parent == key)
            setOpacity(child.key, opacity);
}

double SceneParts::opacity(const std::string& key) const {
    const ScenePart* part = find(key);
    if (!part)
        return 1.0;
    if (part->kind == PartKind::TissueRegion)
        return opacity(kTissues);
    if (m_fills.count(key)) {
        const auto value = m_opacity.find(key);
        return value == m_opacity.end() ? 1.0 : value->second;
    }
    for (const ScenePart& child : m_parts)
        if (child.parent == key)
            return opacity(child.key);
    return 1.0;
}

int SceneParts::pathologyAt(const vtkProp* prop, std::int32_t region) const {
    if (!prop)
        return -1;
    if (m_tissuesBuilt && m_tissues.actor() == prop) {
        for (const ScenePart& r : m_parts)
            if (r.kind == PartKind::TissueRegion && r.region == region)
                return r.pathology;
        return -1;
    }
    for (const ScenePart& part : m_parts)
        if (const MeshDisplay* d = display(part.key); d && part.kind != PartKind::Tissues && d->actor() == prop)
            return part.pathology;
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
    Bounds box;
    for (const bool shownOnly : {true, false}) {
        for (const ScenePart& part : m_parts) {
            if (m_highlighted < 0 || part.pathology != m_highlighted || (shownOnly && !isShown(part.key)))
                continue;
            if (const auto fill = m_fills.find(part.key); fill != m_fills.end() && !fill->second.bounds.empty()) {
                box.add(fill->second.bounds.min);
                box.add(fill->second.bounds.max);
            }
        }
        if (!box.empty())
            break;
    }
    if (box.empty()) {
        m_outline->VisibilityOff();
        return;
    }
    auto outline = vtkSmartPointer<vtkOutlineSource>::New();
    outline->SetBounds(box.min.x, box.max.x, box.min.y, box.max.y, box.min.z, box.max.z);
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
    m_clipOrigin = origin;
    m_clipNormal = normal;
    m_clipPlaneSet = true;
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
