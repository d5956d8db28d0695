// The mesh quality bars of a scene, checked on its measured quality.
#include "hs/scene/MeshBars.h"

#include <cstdio>

namespace hs::scene {
namespace {

MeshBar bar(const char* name, double value, double limit, bool atLeast, const char* format) {
    MeshBar b;
    b.name = name;
    b.value = value;
    b.limit = limit;
    b.atLeast = atLeast;
    b.met = atLeast ? value >= limit : value <= limit;
    if (!format)
        return b; // the caller words it
    char text[200];
    std::snprintf(text, sizeof text, format, value, b.met ? "meets" : (atLeast ? "below" : "above"), limit);
    b.detail = text;
    return b;
}

} // namespace

std::vector<MeshBar> meshBars(const MeshQuality& q) {
    std::vector<MeshBar> bars;
    bars.push_back(bar("mesh-radius-ratio", q.meanRadiusRatio, kBarMeanRadiusRatio, true,
                       "mean radius ratio %.3f: %s the bar of %.2f"));
    bars.push_back(bar("mesh-min-dihedral", q.minDihedralDeg, kBarMinDihedralDeg, true,
                       "smallest dihedral angle %.2f degrees: %s the bar of %.0f degrees"));
    bars.push_back(bar("mesh-slivers", double(q.sliverCount), 0.0, false,
                       "%.0f slivers (a dihedral angle below 10 degrees): %s the bar of %.0f"));
    bars.push_back(bar("mesh-inverted", double(q.invertedCount + q.degenerateCount), 0.0, false,
                       "%.0f inverted or degenerate tets: %s the bar of %.0f"));
    if (q.hasReference) {
        MeshBar h = bar("mesh-hausdorff", 100.0 * q.hausdorffRelative, 100.0 * kBarHausdorffRelative, false,
                        "Hausdorff distance to the body's surfaces %.2f %% of its bounding-box diagonal: %s the bar of "
                        "%.0f %%");
        h.value = q.hausdorffRelative;
        h.limit = kBarHausdorffRelative;
        char mmText[64];
        std::snprintf(mmText, sizeof mmText, " (%.2f mm)", q.hausdorffDistanceMm);
        h.detail += mmText;
        bars.push_back(h);
    }
    if (q.boundaryNonManifoldEdges && q.boundaryNonManifoldVertices) {
        const std::size_t edges = *q.boundaryNonManifoldEdges, vertices = *q.boundaryNonManifoldVertices;
        MeshBar m = bar("mesh-non-manifold", double(edges + vertices), 0.0, false, nullptr);
        char text[200];
        std::snprintf(text, sizeof text,
                      "the outer boundary has %zu non-manifold edge%s and %zu non-manifold vert%s (parts of the mesh "
                      "touching along an edge or at a point): %s the bar of 0",
                      edges, edges == 1 ? "" : "s", vertices, vertices == 1 ? "ex" : "ices", m.met ? "meets" : "above");
        m.detail = text;
        bars.push_back(m);
    }
    return bars;
}

std::vector<std::string> missedMeshBars(const MeshQuality& quality) {
    std::vector<std::string> out;
    for (const MeshBar& b : meshBars(quality))
        if (!b.met)
            out.push_back(b.name + ": " + b.detail);
    return out;
}

} // namespace hs::scene
