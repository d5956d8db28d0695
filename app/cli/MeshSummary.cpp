#include "MeshSummary.h"

#include <iomanip>
#include <ostream>
#include <sstream>

namespace hs::cli {
namespace {

void addLabels(std::vector<LabelSummary>& out, const std::string& owner, const LabelMap& labels) {
    for (const auto& [name, values] : labels) {
        LabelSummary s{owner, name, {}};
        for (auto v : values)
            ++s.counts[v];
        out.push_back(std::move(s));
    }
}

std::string yesNo(bool b) {
    return b ? "yes" : "no";
}

std::string fixed(double v, int digits = 3) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << v;
    return s.str();
}

void summarizeTopology(MeshSummary& s, const SurfaceMesh& surface) {
    s.topology = analyzeTopology(surface);
    s.surfaceAreaMm2 = surfaceArea(surface);
}

} // namespace

MeshSummary summarize(const io::AnyMesh& mesh) {
    MeshSummary s;
    if (const auto* surface = std::get_if<SurfaceMesh>(&mesh)) {
        s.vertices = surface->points.size();
        s.cells = surface->triangles.size();
        s.box = bounds(*surface);
        summarizeTopology(s, *surface);
        s.volumeMm3 = enclosedVolume(*surface);
        addLabels(s.labels, "vertex", surface->vertexLabels);
        addLabels(s.labels, "face", surface->faceLabels);
    } else {
        const auto& tet = std::get<TetMesh>(mesh);
        s.isTet = true;
        s.vertices = tet.points.size();
        s.cells = tet.tets.size();
        s.box = bounds(tet);
        summarizeTopology(s, extractBoundary(tet));
        s.volumeMm3 = totalVolume(tet);
        s.invertedTets = invertedTetCount(tet);
        s.regionVolumesMm3 = regionVolumes(tet);
        addLabels(s.labels, "tet", tet.tetLabels);
        addLabels(s.labels, "point", tet.pointLabels);
    }
    return s;
}

void printText(std::ostream& out, const MeshSummary& s) {
    out << "kind        " << (s.isTet ? "tetrahedral mesh" : "surface") << '\n';
    out << "vertices    " << s.vertices << '\n';
    out << (s.isTet ? "tetrahedra  " : "triangles   ") << s.cells << '\n';
    if (!s.box.empty()) {
        out << "bounds      [" << fixed(s.box.min.x) << ", " << fixed(s.box.max.x) << "] x [" << fixed(s.box.min.y)
            << ", " << fixed(s.box.max.y) << "] x [" << fixed(s.box.min.z) << ", " << fixed(s.box.max.z) << "] mm\n";
        out << "diagonal    " << fixed(s.box.diagonal()) << " mm\n";
    }
    out << "area        " << fixed(s.surfaceAreaMm2) << " mm^2" << (s.isTet ? " (boundary)" : "") << '\n';
    out << "volume      " << fixed(s.volumeMm3) << " mm^3" << (s.isTet ? " (sum of tetrahedra)" : " (enclosed)")
        << '\n';
    const auto& t = s.topology;
    out << (s.isTet ? "boundary    " : "topology    ") << "closed " << yesNo(t.isClosed()) << ", manifold "
        << yesNo(t.isManifold()) << ", watertight " << yesNo(t.isWatertight()) << ", components " << t.components
        << '\n';
    out << "defects     boundary edges " << t.boundaryEdges << ", non-manifold edges " << t.nonManifoldEdges
        << ", non-manifold vertices " << t.nonManifoldVertices << ", inconsistent edges " << t.inconsistentEdges
        << ", degenerate faces " << t.degenerateFaces << ", unreferenced vertices " << t.unreferencedVertices << '\n';
    if (s.isTet) {
        out << "inverted    " << s.invertedTets << " tetrahedra\n";
        for (const auto& [region, volume] : s.regionVolumesMm3)
            out << "region " << std::setw(4) << region << " " << fixed(volume) << " mm^3\n";
    }
    for (const auto& label : s.labels) {
        out << "label       " << label.owner << " '" << label.name << "': " << label.counts.size() << " values";
        if (label.counts.size() <= 12) {
            out << " (";
            bool first = true;
            for (const auto& [value, count] : label.counts) {
                out << (first ? "" : ", ") << value << " x" << count;
                first = false;
            }
            out << ")";
        }
        out << '\n';
    }
}

void toJson(const MeshSummary& s, nlohmann::ordered_json& j) {
    j["kind"] = s.isTet ? "tetrahedral" : "surface";
    j["vertices"] = s.vertices;
    j[s.isTet ? "tetrahedra" : "triangles"] = s.cells;
    if (!s.box.empty()) {
        j["boundsMm"] = {{"min", {s.box.min.x, s.box.min.y, s.box.min.z}},
                         {"max", {s.box.max.x, s.box.max.y, s.box.max.z}}};
        j["diagonalMm"] = s.box.diagonal();
    }
    j["areaMm2"] = s.surfaceAreaMm2;
    j["volumeMm3"] = s.volumeMm3;
    const auto& t = s.topology;
    j["topology"] = {{"closed", t.isClosed()},
                     {"manifold", t.isManifold()},
                     {"watertight", t.isWatertight()},
                     {"components", t.components},
                     {"boundaryEdges", t.boundaryEdges},
                     {"nonManifoldEdges", t.nonManifoldEdges},
                     {"nonManifoldVertices", t.nonManifoldVertices},
                     {"inconsistentEdges", t.inconsistentEdges},
                     {"degenerateFaces", t.degenerateFaces},
                     {"unreferencedVertices", t.unreferencedVertices}};
    if (s.isTet) {
        j["invertedTetrahedra"] = s.invertedTets;
        auto regions = nlohmann::ordered_json::array();
        for (const auto& [region, volume] : s.regionVolumesMm3)
            regions.push_back({{"region", region}, {"volumeMm3", volume}});
        j["regions"] = regions;
    }
    auto labels = nlohmann::ordered_json::array();
    for (const auto& label : s.labels) {
        auto values = nlohmann::ordered_json::array();
        for (const auto& [value, count] : label.counts)
            values.push_back({{"value", value}, {"count", count}});
        labels.push_back({{"owner", label.owner}, {"name", label.name}, {"values", values}});
    }
    j["labels"] = labels;
}

} // namespace hs::cli
