// Wavefront OBJ. Read by hand: VTK's vtkOBJReader duplicates vertices wherever texture or normal indices differ
// from vertex indices (which opens closed surfaces at texture seams), and reports errors without line numbers.
// Written with vtkOBJWriter (full double precision, no timestamp).

#include "Formats.h"
#include "Parsing.h"
#include "VtkSupport.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkOBJWriter.h>
#include <vtkPolyData.h>

#include <string_view>
#include <vector>

namespace hs::io::detail {
namespace {

struct ObjParser {
    const std::string& path;
    const ReadLimits& limits;
    SurfaceMesh mesh;
    std::vector<std::int32_t> corners;
    std::size_t line = 0;
    std::string error;
    ErrorCode code = ErrorCode::InvalidInput;

    bool fail(std::string what, ErrorCode errorCode = ErrorCode::InvalidInput) {
        error = std::move(what);
        code = errorCode;
        return false;
    }

    static std::string_view nextToken(std::string_view& rest) {
        std::size_t start = 0;
        while (start < rest.size() && (rest[start] == ' ' || rest[start] == '\t' || rest[start] == '\r'))
            ++start;
        std::size_t end = start;
        while (end < rest.size() && rest[end] != ' ' && rest[end] != '\t' && rest[end] != '\r')
            ++end;
        const std::string_view token = rest.substr(start, end - start);
        rest.remove_prefix(end);
        return token;
    }

    bool parseVertex(std::string_view rest) {
        if (static_cast<std::int64_t>(mesh.points.size()) >= pointLimit(limits))
            return fail("more than " + std::to_string(pointLimit(limits)) + " vertices (limit)",
                        ErrorCode::LimitExceeded);
        Vec3 p;
        for (int k = 0; k < 3; ++k) {
            const std::string_view token = nextToken(rest);
            double value = 0.0;
            if (token.empty())
                return fail("vertex has fewer than 3 coordinates");
            if (!parseDouble(token, value))
                return fail("vertex coordinate '" + std::string(token.substr(0, 40)) + "' is not a number");
            if (!std::isfinite(value))
                return fail("vertex coordinate '" + std::string(token.substr(0, 40)) + "' is not finite");
            p[k] = value;
        }
        mesh.points.push_back(p); // an optional w or colour after x y z is ignored
        return true;
    }

    /// "7", "7/2", "7//3", "7/2/3", or negative (relative to the vertices read so far).
    bool parseCorner(std::string_view token, std::int32_t& out) {
        const std::string_view vertex = token.substr(0, token.find('/'));
        std::int64_t index = 0;
        if (!parseInt(vertex, index))
            return fail("face corner '" + std::string(token.substr(0, 40)) + "' is not a vertex index");
        const auto count = static_cast<std::int64_t>(mesh.points.size());
        const std::int64_t zeroBased = index > 0 ? index - 1 : count + index;
        if (index == 0 || zeroBased < 0 || zeroBased >= count)
            return fail("face references vertex " + std::to_string(index) + " but " + std::to_string(count) +
                        " vertices are defined before this line");
        out = static_cast<std::int32_t>(zeroBased);
        return true;
    }

    bool parseFace(std::string_view rest) {
        corners.clear();
        for (std::string_view token = nextToken(rest); !token.empty(); token = nextToken(rest)) {
            std::int32_t corner = 0;
            if (!parseCorner(token, corner))
                return false;
            if (corners.size() >= mesh.points.size())
                return fail("face has more corners than the file has vertices");
            corners.push_back(corner);
        }
        if (corners.size() < 3)
            return fail("face has " + std::to_string(corners.size()) + " corners, at least 3 needed");
        if (!appendFan(mesh, corners.data(), corners.size(), cellLimit(limits)))
            return fail("more than " + std::to_string(cellLimit(limits)) + " triangles (limit)",
                        ErrorCode::LimitExceeded);
        return true;
    }

    bool parseLine(std::string_view text) {
        for (char c : text) {
            const auto u = static_cast<unsigned char>(c);
            if (u < 0x20 && c != '\t' && c != '\r')
                return fail("binary data (control character " + std::to_string(u) + ") in a text file");
        }
        std::string_view rest = text;
        const std::string_view keyword = nextToken(rest);
        if (keyword.empty() || keyword.front() == '#')
            return true;
        if (keyword == "v")
            return parseVertex(rest);
        if (keyword == "f")
            return parseFace(rest);
        // vt, vn, vp, g, o, s, l, p, usemtl, mtllib and any other statement carry nothing a SurfaceMesh keeps.
        return true;
    }

    Result<SurfaceMesh> run(std::string_view text) {
        std::size_t pos = 0;
        while (pos < text.size()) {
            ++line;
            std::size_t end = text.find('\n', pos);
            if (end == std::string_view::npos)
                end = text.size();
            if (!parseLine(text.substr(pos, end - pos)))
                return hs::fail(code, path + ": line " + std::to_string(line) + ": " + error);
            pos = end + 1;
        }
        HS_TRY(finishSurface(path, mesh));
        return std::move(mesh);
    }
};

} // namespace

Result<SurfaceMesh> readObj(const std::string& path, const ReadLimits& limits) {
    Result<std::string> bytes = readInput(path, limits);
    if (!bytes.ok())
        return bytes.failure();
    ObjParser parser{path, limits, {}, {}, 0, {}, ErrorCode::InvalidInput};
    return parser.run(*bytes);
}

Status writeObj(const SurfaceMesh& mesh, const std::string& tmpPath) {
    VtkMessageCapture capture;
    vtkNew<vtkOBJWriter> writer;
    const vtkSmartPointer<vtkPolyData> polyData = toPolyData(mesh, false);
    writer->SetInputData(polyData);
    writer->SetFileName(tmpPath.c_str());
    const int ok = writer->Write();
    return capture.check(ok == 1, tmpPath, "writing OBJ");
}

} // namespace hs::io::detail
