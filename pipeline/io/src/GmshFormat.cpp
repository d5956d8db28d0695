// Gmsh MSH 4.1 ASCII, read and written by hand (VTK has no MSH 4 reader). A tetrahedron's region id is the first
// physical tag of its volume entity (the entity tag when the entity has no physical tag). The writer puts one
// volume entity per region, with the region id as its physical tag, and numbers elements by tet index + 1 so the
// reader can restore the original tet order.

#include "Formats.h"
#include "Parsing.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <limits>
#include <map>
#include <vector>

namespace hs::io::detail {
namespace {

/// Nodes per element of the MSH element types (0: unknown), and each type's dimension.
int nodesPerElement(std::int64_t type) {
    static const int kNodes[] = {0, 2,  3,  4,  4, 8,  6,  5,  3,  6,  9, 10, 27, 18, 14, 1,
                                 8, 20, 15, 13, 9, 10, 12, 15, 15, 21, 4, 5,  6,  20, 35, 56};
    return type >= 0 && type < static_cast<std::int64_t>(std::size(kNodes)) ? kNodes[type] : 0;
}
int elementDimension(std::int64_t type) {
    switch (type) {
    case 15:
        return 0;
    case 1:
    case 8:
    case 26:
    case 27:
    case 28:
        return 1;
    case 2:
    case 3:
    case 9:
    case 10:
    case 16:
    case 20:
    case 21:
    case 22:
    case 23:
    case 24:
    case 25:
        return 2;
    default:
        return 3;
    }
}

struct GmshReader {
    const std::string& path;
    const ReadLimits& limits;
    TokenReader in;
    std::map<std::int64_t, std::int32_t> volumeRegion; ///< volume entity tag -> region id
    std::vector<std::pair<std::int64_t, Vec3>> nodes;  ///< (tag, position)
    struct TetRecord {
        std::int64_t tag;
        std::array<std::int64_t, 4> nodeTags;
        std::int32_t region;
    };
    std::vector<TetRecord> tets;
    bool sawFormat = false, sawNodes = false, sawElements = false;

    bool expectEnd(std::string_view section) {
        std::string_view word;
        if (!in.word(word, "section end"))
            return false;
        if (word != "$End" + std::string(section))
            return in.error("expected $End" + std::string(section) + ", found '" + std::string(word.substr(0, 40)) +
                            "'");
        return true;
    }

    Status readFormat() {
        std::string_view version;
        std::int64_t fileType = 0, dataSize = 0;
        if (!in.word(version, "MSH version") || !in.integer(fileType, "file type") ||
            !in.integer(dataSize, "data size"))
            return in.failure();
        if (version != "4.1")
            return fail(ErrorCode::Unsupported, path + ": line " + std::to_string(in.line()) + ": MSH version '" +
                                                    std::string(version.substr(0, 20)) + "' (only 4.1 is read)");
        if (fileType != 0)
            return fail(ErrorCode::Unsupported, path + ": binary MSH is not read (only ASCII)");
        if (!expectEnd("MeshFormat"))
            return in.failure();
        sawFormat = true;
        return {};
    }

    bool readPhysicals(std::int64_t& first) {
        std::int64_t count = 0;
        if (!in.integerIn(count, 0, 1 << 20, "physical tag count"))
            return false;
        for (std::int64_t k = 0; k < count; ++k) {
            std::int64_t tag = 0;
            if (!in.integerIn(tag, std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max(),
                              "physical tag"))
                return false;
            if (k == 0)
                first = tag;
        }
        return true;
    }

    Status readEntities() {
        std::int64_t counts[4] = {};
        for (auto& c : counts)
            if (!in.integer(c, "entity count"))
                return in.failure();
        for (int dim = 0; dim < 4; ++dim) {
            // An entity line takes at least 8 bytes.
            HS_TRY(checkCount(path, in.line(), counts[dim], cellLimit(limits), in.bytesLeft(), 8, "entities"));
            for (std::int64_t e = 0; e < counts[dim]; ++e) {
                std::int64_t tag = 0, physical = 0;
                double ignored = 0.0;
                if (!in.integer(tag, "entity tag"))
                    return in.failure();
                for (int k = 0; k < (dim == 0 ? 3 : 6); ++k)
                    if (!in.real(ignored, "entity bounding box"))
                        return in.failure();
                physical = tag;
                if (!readPhysicals(physical))
                    return in.failure();
                if (dim > 0) {
                    std::int64_t bounding = 0, ignoredTag = 0;
                    if (!in.integerIn(bounding, 0, in.bytesLeft(), "bounding entity count"))
                        return in.failure();
                    for (std::int64_t b = 0; b < bounding; ++b)
                        if (!in.integer(ignoredTag, "bounding entity tag"))
                            return in.failure();
                }
                if (dim == 3) {
                    if (physical < std::numeric_limits<std::int32_t>::min() ||
                        physical > std::numeric_limits<std::int32_t>::max())
                        return lineError(path, in.line(), "volume entity tag out of the 32-bit range");
                    volumeRegion[tag] = static_cast<std::int32_t>(physical);
                }
            }
        }
        if (!expectEnd("Entities"))
            return in.failure();
        return {};
    }

    Status readNodes() {
        if (sawNodes)
            return lineError(path, in.line(), "a second $Nodes section");
        sawNodes = true;
        std::int64_t blocks = 0, total = 0, minTag = 0, maxTag = 0;
        if (!in.integer(blocks, "node block count") || !in.integer(total, "node count") ||
            !in.integer(minTag, "minimum node tag") || !in.integer(maxTag, "maximum node tag"))
            return in.failure();
        // A node takes at least "1\n0 0 0\n" (8 bytes), a block header "3 1 0 0\n" (8 bytes).
        HS_TRY(checkCount(path, in.line(), total, pointLimit(limits), in.bytesLeft(), 8, "nodes"));
        HS_TRY(checkCount(path, in.line(), blocks, cellLimit(limits), in.bytesLeft(), 8, "node blocks"));
        nodes.reserve(static_cast<std::size_t>(total));
        std::vector<std::int64_t> tags;
        for (std::int64_t b = 0; b < blocks; ++b) {
            std::int64_t dim = 0, entity = 0, parametric = 0, count = 0;
            if (!in.integerIn(dim, 0, 3, "entity dimension") || !in.integer(entity, "entity tag") ||
                !in.integerIn(parametric, 0, 1, "parametric flag") ||
                !in.integerIn(count, 0, total - static_cast<std::int64_t>(nodes.size()), "nodes in block"))
                return in.failure();
            if (parametric != 0)
                return fail(ErrorCode::Unsupported, path + ": line " + std::to_string(in.line()) +
                                                        ": parametric node coordinates are not read");
            tags.resize(static_cast<std::size_t>(count));
            for (auto& tag : tags)
                if (!in.integerIn(tag, 1, std::numeric_limits<std::int64_t>::max(), "node tag"))
                    return in.failure();
            for (auto tag : tags) {
                Vec3 p;
                if (!in.point(p, "node coordinate"))
                    return in.failure();
                nodes.emplace_back(tag, p);
            }
        }
        if (static_cast<std::int64_t>(nodes.size()) != total)
            return lineError(path, in.line(),
                             "the blocks hold " + std::to_string(nodes.size()) + " nodes, the header says " +
                                 std::to_string(total));
        if (!expectEnd("Nodes"))
            return in.failure();
        return {};
    }

    Status readElements() {
        if (sawElements)
            return lineError(path, in.line(), "a second $Elements section");
        sawElements = true;
        std::int64_t blocks = 0, total = 0, minTag = 0, maxTag = 0;
        if (!in.integer(blocks, "element block count") || !in.integer(total, "element count") ||
            !in.integer(minTag, "minimum element tag") || !in.integer(maxTag, "maximum element tag"))
            return in.failure();
        // An element takes at least "1 1\n" (4 bytes).
        HS_TRY(checkCount(path, in.line(), total, cellLimit(limits), in.bytesLeft(), 4, "elements"));
        HS_TRY(checkCount(path, in.line(), blocks, cellLimit(limits), in.bytesLeft(), 8, "element blocks"));
        std::int64_t seen = 0;
        for (std::int64_t b = 0; b < blocks; ++b) {
            std::int64_t dim = 0, entity = 0, type = 0, count = 0;
            if (!in.integerIn(dim, 0, 3, "entity dimension") || !in.integer(entity, "entity tag") ||
                !in.integer(type, "element type") || !in.integerIn(count, 0, total - seen, "elements in block"))
                return in.failure();
            const int corners = nodesPerElement(type);
            if (corners == 0)
                return fail(ErrorCode::Unsupported,
                            path + ": line " + std::to_string(in.line()) + ": element type " + std::to_string(type));
            if (elementDimension(type) != dim)
                return lineError(path, in.line(),
                                 "element type " + std::to_string(type) + " in an entity of dimension " +
                                     std::to_string(dim));
            if (dim == 3 && type != 4)
                return lineError(path, in.line(),
                                 "volume element type " + std::to_string(type) + " (only 4-node tetrahedra are read)");
            std::int32_t region = 0;
            if (dim == 3) {
                const auto it = volumeRegion.find(entity);
                if (it != volumeRegion.end())
                    region = it->second;
                else if (entity >= std::numeric_limits<std::int32_t>::min() &&
                         entity <= std::numeric_limits<std::int32_t>::max())
                    region = static_cast<std::int32_t>(entity);
                else
                    return lineError(path, in.line(), "volume entity tag out of the 32-bit range");
            }
            for (std::int64_t e = 0; e < count; ++e) {
                std::int64_t tag = 0, node = 0;
                if (!in.integer(tag, "element tag"))
                    return in.failure();
                TetRecord record{tag, {}, region};
                for (int k = 0; k < corners; ++k) {
                    if (!in.integer(node, "element node tag"))
                        return in.failure();
                    if (dim == 3)
                        record.nodeTags[static_cast<std::size_t>(k)] = node;
                }
                if (dim == 3)
                    tets.push_back(record);
            }
            seen += count;
        }
        if (seen != total)
            return lineError(path, in.line(),
                             "the blocks hold " + std::to_string(seen) + " elements, the header says " +
                                 std::to_string(total));
        if (!expectEnd("Elements"))
            return in.failure();
        return {};
    }

    /// Skips an unknown section ($PhysicalNames, $NodeData, ...) up to its $End line.
    Status skipSection(std::string_view name) {
        const std::string end = "$End" + std::string(name);
        std::string_view word;
        while (in.word(word, end.c_str()))
            if (word == end)
                return {};
        return in.failure();
    }

    Result<TetMesh> assemble() {
        if (!sawNodes || !sawElements)
            return fileError(ErrorCode::InvalidInput, path, "no $Nodes or no $Elements section");
        std::sort(nodes.begin(), nodes.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (std::size_t i = 1; i < nodes.size(); ++i)
            if (nodes[i].first == nodes[i - 1].first)
                return fileError(ErrorCode::InvalidInput, path,
                                 "node tag " + std::to_string(nodes[i].first) + " is defined twice");
        std::stable_sort(tets.begin(), tets.end(), [](const auto& a, const auto& b) { return a.tag < b.tag; });
        for (std::size_t i = 1; i < tets.size(); ++i)
            if (tets[i].tag == tets[i - 1].tag)
                return fileError(ErrorCode::InvalidInput, path,
                                 "element tag " + std::to_string(tets[i].tag) + " is used twice");
        TetMesh mesh;
        mesh.points.reserve(nodes.size());
        for (const auto& node : nodes)
            mesh.points.push_back(node.second);
        mesh.tets.reserve(tets.size());
        mesh.regions.reserve(tets.size());
        for (const auto& record : tets) {
            Tet tet{};
            for (std::size_t k = 0; k < 4; ++k) {
                const std::int64_t tag = record.nodeTags[k];
                const auto it = std::lower_bound(nodes.begin(), nodes.end(), tag,
                                                 [](const auto& node, std::int64_t t) { return node.first < t; });
                if (it == nodes.end() || it->first != tag)
                    return fileError(ErrorCode::InvalidInput, path,
                                     "element " + std::to_string(record.tag) + " references undefined node " +
                                         std::to_string(tag));
                tet[k] = static_cast<std::int32_t>(it - nodes.begin());
            }
            mesh.tets.push_back(tet);
            mesh.regions.push_back(record.region);
        }
        HS_TRY(finishTetMesh(path, mesh));
        return mesh;
    }

    Result<TetMesh> run() {
        std::string_view word;
        while (!in.atEnd()) {
            if (!in.word(word, "section"))
                return in.failure();
            if (word.empty() || word.front() != '$')
                return lineError(path, in.line(),
                                 "expected a $Section, found '" + std::string(word.substr(0, 40)) + "'");
            const std::string_view name = word.substr(1);
            if (!sawFormat && name != "MeshFormat")
                return lineError(path, in.line(), "not an MSH file (it must start with $MeshFormat)");
            Status status;
            if (name == "MeshFormat")
                status = readFormat();
            else if (name == "Entities")
                status = readEntities();
            else if (name == "Nodes")
                status = readNodes();
            else if (name == "Elements")
                status = readElements();
            else if (name == "PartitionedEntities")
                status = fail(ErrorCode::Unsupported, path + ": partitioned meshes are not read");
            else
                status = skipSection(name);
            if (!status.ok())
                return status.failure();
        }
        return assemble();
    }
};

} // namespace

Result<TetMesh> readGmsh(const std::string& path, const ReadLimits& limits) {
    Result<std::string> bytes = readInput(path, limits);
    if (!bytes.ok())
        return bytes.failure();
    GmshReader reader{path, limits, TokenReader(path, *bytes, 0), {}, {}, {}};
    return reader.run();
}

Status writeGmsh(const TetMesh& mesh, const std::string& tmpPath) {
    // One volume entity per region id, in increasing order; entity tags 1..R.
    std::map<std::int32_t, std::vector<std::size_t>> byRegion;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
        byRegion[mesh.regionOf(t)].push_back(t);

    std::string out =
        "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 0 " + std::to_string(byRegion.size()) + "\n";
    int entity = 0;
    for (const auto& [region, tets] : byRegion) {
        Bounds box;
        for (std::size_t t : tets)
            for (auto v : mesh.tets[t])
                box.add(mesh.points[static_cast<std::size_t>(v)]);
        out += std::to_string(++entity) + " " + formatDouble(box.min.x) + " " + formatDouble(box.min.y) + " " +
               formatDouble(box.min.z) + " " + formatDouble(box.max.x) + " " + formatDouble(box.max.y) + " " +
               formatDouble(box.max.z) + " 1 " + std::to_string(region) + " 0\n";
    }
    const std::string nodeCount = std::to_string(mesh.points.size());
    // Every node goes in one block on the first volume entity: MSH needs each node in some entity, and readers
    // (Gmsh included) accept nodes shared by the elements of other entities.
    out += "$EndEntities\n$Nodes\n1 " + nodeCount + " 1 " + nodeCount + "\n3 1 0 " + nodeCount + "\n";
    for (std::size_t i = 0; i < mesh.points.size(); ++i)
        out += std::to_string(i + 1) + "\n";
    for (const auto& p : mesh.points)
        out += formatDouble(p.x) + " " + formatDouble(p.y) + " " + formatDouble(p.z) + "\n";
    const std::string tetCount = std::to_string(mesh.tets.size());
    out += "$EndNodes\n$Elements\n" + std::to_string(byRegion.size()) + " " + tetCount + " 1 " + tetCount + "\n";
    entity = 0;
    for (const auto& [region, tets] : byRegion) {
        out += "3 " + std::to_string(++entity) + " 4 " + std::to_string(tets.size()) + "\n";
        for (std::size_t t : tets) {
            const Tet& tet = mesh.tets[t];
            out += std::to_string(t + 1) + " " + std::to_string(tet[0] + 1) + " " + std::to_string(tet[1] + 1) + " " +
                   std::to_string(tet[2] + 1) + " " + std::to_string(tet[3] + 1) + "\n";
        }
    }
    out += "$EndElements\n";
    return writePlainFile(tmpPath, out);
}

} // namespace hs::io::detail
