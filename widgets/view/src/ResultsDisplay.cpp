#include "hs/widgets/view/ResultsDisplay.h"

#include "hs/widgets/view/MeshDisplay.h"

namespace hs::widgets {

SurfaceMesh combineRegions(const std::vector<std::pair<const SurfaceMesh*, int>>& parts) {
    SurfaceMesh combined;
    std::vector<std::int32_t>& regions = combined.faceLabels["region"];
    for (const auto& [part, region] : parts) {
        const auto offset = static_cast<std::int32_t>(combined.points.size());
        combined.points.insert(combined.points.end(), part->points.begin(), part->points.end());
        for (const Triangle& t : part->triangles) {
            combined.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
            regions.push_back(region);
        }
    }
    return combined;
}

bool hasLayer(const generate::Generated& results, ResultLayer layer) {
    switch (layer) {
    case ResultLayer::Organ:
        return results.organ.has_value();
    case ResultLayer::Pathologies:
        return results.pathologies.has_value();
    case ResultLayer::Body:
        return results.body.has_value();
    case ResultLayer::Tissues:
        return results.tissue.has_value();
    case ResultLayer::Textured:
        return results.appearance.has_value();
    case ResultLayer::None:
        break;
    }
    return false;
}

ResultLayer showResults(MeshDisplay& display, const generate::Generated& results, std::optional<ResultLayer> layer) {
    if (!layer) {
        for (ResultLayer l : {ResultLayer::Textured, ResultLayer::Tissues, ResultLayer::Body, ResultLayer::Pathologies,
                              ResultLayer::Organ})
            if (hasLayer(results, l)) {
                layer = l;
                break;
            }
    }
    if (!layer || !hasLayer(results, *layer))
        return ResultLayer::None;
    switch (*layer) {
    case ResultLayer::Organ:
        display.showSurface(combineRegions({{&results.organ->mesh, 0}}));
        break;
    case ResultLayer::Pathologies: {
        std::vector<std::pair<const SurfaceMesh*, int>> parts{{&results.pathologies->organ, 0}};
        for (std::size_t i = 0; i < results.pathologies->pathologies.size(); ++i)
            parts.emplace_back(&results.pathologies->pathologies[i].surface, static_cast<int>(i + 1));
        display.showSurface(combineRegions(parts));
        break;
    }
    case ResultLayer::Body: {
        std::vector<std::pair<const SurfaceMesh*, int>> parts;
        for (const RegionSurface& s : results.body->body.surfaces)
            parts.emplace_back(&s.surface, s.regionId);
        display.showSurface(combineRegions(parts));
        break;
    }
    case ResultLayer::Tissues:
        display.showTetMesh(results.tissue->tets);
        break;
    case ResultLayer::Textured: {
        const scene::VisualSurface& v = results.appearance->surface;
        display.showTexturedSurface(v.mesh, v.uvs, v.normals, v.albedo);
        break;
    }
    case ResultLayer::None:
        break;
    }
    return *layer;
}

} // namespace hs::widgets
