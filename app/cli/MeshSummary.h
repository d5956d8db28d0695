#pragma once
/// Measured facts about a mesh, for `info` and for the closing lines of `convert`.

#include "hs/io/MeshIO.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace hs::cli {

struct LabelSummary {
    std::string owner; ///< "vertex", "face", "tet", "point"
    std::string name;
    std::map<std::int32_t, std::size_t> counts; ///< value -> elements carrying it
};

struct MeshSummary {
    bool isTet = false;
    std::size_t vertices = 0;
    std::size_t cells = 0; ///< triangles or tetrahedra
    Bounds box;
    double surfaceAreaMm2 = 0.0;
    double volumeMm3 = 0.0;   ///< enclosed (surface) or sum of tets (tet mesh)
    SurfaceTopology topology; ///< of the surface, or of the tet mesh's boundary
    std::size_t invertedTets = 0;
    std::map<std::int32_t, double> regionVolumesMm3; ///< tet meshes
    std::vector<LabelSummary> labels;
};

MeshSummary summarize(const io::AnyMesh& mesh);
void printText(std::ostream& out, const MeshSummary& summary);
void toJson(const MeshSummary& summary, nlohmann::ordered_json& out);

} // namespace hs::cli
