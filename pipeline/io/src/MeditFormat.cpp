// MEDIT .mesh (ASCII, MeshVersionFormatted 1 to 4: the version only changes the binary word sizes), read and written by
// hand: VTK has no MEDIT reader. A tetrahedron's reference is its region id; vertex references and surface sections are
// not kept.

#include "Formats.h"
#include "Parsing.h"

#include <cctype>
#include <limits>
#include <set>
#include <vector>

namespace hs::io::detail {
namespace {

std::string lower(std::string_view word) {
    std::string out(word.substr(0, 64));
    for (char& c : out)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

/// Sections this reader skips, with the numbers per entry.
int skippedEntrySize(const std::string& keyword) {
    static const struct {
        const char* name;
        int values;
    } kSections[] = {{"edges", 3},
                     {"triangles", 4},
                     {"quadrilaterals", 5},
                     {"corners", 1},
                     {"ridges", 1},
                     {"requiredvertices", 1},
                     {"requirededges", 1},
                     {"requiredtriangles", 1},
                     {"normals", 3},
                     {"normalatvertices", 2},
                     {"tangents", 3},
                     {"tangentatvertices", 2},
                     {"normalattrianglevertices", 3},
                     {"tangentatedges", 3}};
    for (const auto& s : kSections)
        if (keyword == s.name)
            return s.values;
    return 0;
}

} // namespace

Result<TetMesh> readMedit(const std::string& path, const ReadLimits& limits) {
    Result<std::string> bytes = readInput(path, limits);
    if (!bytes.ok())
        return bytes.failure();
    TokenReader in(path, *bytes, '#');
    TetMesh mesh;
    std::set<std::string> seen;
    bool sawVersion = false, sawVertices = false, sawTets = false;

    std::string_view word;
    while (!in.atEnd()) {
        if (!in.word(word, "keyword"))
            return in.failure();
        const std::string keyword = lower(word);
        if (!sawVersion && keyword != "meshversionformatted")
            return lineError(path, in.line(), "not a MEDIT file (it must start with MeshVersionFormatted)");
        if (keyword == "end")
            break;
        if (!seen.insert(keyword).second)
            return lineError(path, in.line(), "section '" + keyword + "' appears twice");
        std::int64_t value = 0;
        if (keyword == "meshversionformatted") {
            if (!in.integerIn(value, 1, 4, "MeshVersionFormatted"))
                return in.failure();
            sawVersion = true;
        } else if (keyword == "dimension") {
            if (!in.integerIn(value, 3, 3, "dimension"))
                return in.failure();
        } else if (keyword == "vertices") {
            if (!in.integer(value, "vertex count"))
                return in.failure();
            // A vertex takes at least "0 0 0 0\n" (8 bytes).
            HS_TRY(checkCount(path, in.line(), value, pointLimit(limits), in.bytesLeft(), 8, "vertices"));
            mesh.points.resize(static_cast<std::size_t>(value));
            for (auto& p : mesh.points) {
                std::int64_t ref = 0;
                if (!in.point(p, "vertex coordinate") || !in.integer(ref, "vertex reference"))
                    return in.failure();
            }
            sawVertices = true;
        } else if (keyword == "tetrahedra") {
            if (!sawVertices)
                return lineError(path, in.line(), "Tetrahedra before Vertices");
            if (!in.integer(value, "tetrahedron count"))
                return in.failure();
            // A tetrahedron takes at least "1 1 1 1 0\n" (10 bytes).
            HS_TRY(checkCount(path, in.line(), value, cellLimit(limits), in.bytesLeft(), 10, "tetrahedra"));
            const auto n = static_cast<std::int64_t>(mesh.points.size());
            mesh.tets.resize(static_cast<std::size_t>(value));
            mesh.regions.resize(static_cast<std::size_t>(value));
            for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
                for (auto& v : mesh.tets[t]) {
                    std::int64_t index = 0;
                    if (!in.integerIn(index, 1, n, "vertex index"))
                        return in.failure();
                    v = static_cast<std::int32_t>(index - 1);
                }
                std::int64_t ref = 0;
                if (!in.integerIn(ref, std::numeric_limits<std::int32_t>::min(),
                                  std::numeric_limits<std::int32_t>::max(), "tetrahedron reference"))
                    return in.failure();
                mesh.regions[t] = static_cast<std::int32_t>(ref);
            }
            sawTets = true;
        } else if (keyword == "hexahedra" || keyword == "prisms" || keyword == "pyramids") {
            return lineError(path, in.line(), "volume cells other than tetrahedra ('" + keyword + "') are not read");
        } else if (const int values = skippedEntrySize(keyword); values > 0) {
            if (!in.integer(value, "entry count"))
                return in.failure();
            HS_TRY(checkCount(path, in.line(), value, cellLimit(limits), in.bytesLeft(), 2 * values, keyword.c_str()));
            std::string_view ignored;
            for (std::int64_t k = 0; k < value * values; ++k)
                if (!in.word(ignored, keyword.c_str()))
                    return in.failure();
        } else {
            return fail(ErrorCode::Unsupported,
                        path + ": line " + std::to_string(in.line()) + ": unknown section '" + keyword + "'");
        }
    }
    if (!sawTets)
        return fileError(ErrorCode::InvalidInput, path, "no Tetrahedra section");
    HS_TRY(finishTetMesh(path, mesh));
    return mesh;
}

Status writeMedit(const TetMesh& mesh, const std::string& tmpPath) {
    std::string out = "MeshVersionFormatted 2\nDimension 3\nVertices\n" + std::to_string(mesh.points.size()) + "\n";
    for (const auto& p : mesh.points)
        out += formatDouble(p.x) + " " + formatDouble(p.y) + " " + formatDouble(p.z) + " 0\n";
    out += "Tetrahedra\n" + std::to_string(mesh.tets.size()) + "\n";
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
        const Tet& tet = mesh.tets[t];
        out += std::to_string(tet[0] + 1) + " " + std::to_string(tet[1] + 1) + " " + std::to_string(tet[2] + 1) + " " +
               std::to_string(tet[3] + 1) + " " + std::to_string(mesh.regionOf(t)) + "\n";
    }
    out += "End\n";
    return writePlainFile(tmpPath, out);
}

} // namespace hs::io::detail
