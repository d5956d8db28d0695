// Object File Format (OFF), read and written by hand: VTK has no OFF reader.

#include "Formats.h"
#include "Parsing.h"

#include <vector>

namespace hs::io::detail {

Result<SurfaceMesh> readOff(const std::string& path, const ReadLimits& limits) {
    Result<std::string> bytes = readInput(path, limits);
    if (!bytes.ok())
        return bytes.failure();
    TokenReader in(path, *bytes, '#');

    std::string_view keyword;
    if (!in.word(keyword, "the OFF keyword"))
        return in.failure();
    if (keyword != "OFF")
        return lineError(path, in.line(), "not an OFF file (it must start with 'OFF'; COFF/NOFF/4OFF are not read)");

    std::int64_t vertexCount = 0, faceCount = 0, edgeCount = 0;
    if (!in.integer(vertexCount, "vertex count") || !in.integer(faceCount, "face count") ||
        !in.integer(edgeCount, "edge count"))
        return in.failure();
    const std::size_t headerLine = in.line();
    // Every vertex takes at least "0 0 0\n" (6 bytes), every face at least "3 0 0 0\n" (8 bytes).
    HS_TRY(checkCount(path, headerLine, vertexCount, pointLimit(limits), in.bytesLeft(), 6, "vertices"));
    HS_TRY(checkCount(path, headerLine, faceCount, cellLimit(limits), in.bytesLeft() - 6 * vertexCount, 8, "faces"));

    SurfaceMesh mesh;
    mesh.points.resize(static_cast<std::size_t>(vertexCount));
    for (auto& p : mesh.points) {
        if (!in.point(p, "vertex coordinate"))
            return in.failure();
        in.skipLine(); // optional colour
    }
    mesh.triangles.reserve(static_cast<std::size_t>(faceCount));
    std::vector<std::int32_t> corners;
    for (std::int64_t f = 0; f < faceCount; ++f) {
        std::int64_t n = 0;
        if (!in.integerIn(n, 3, vertexCount, "face corner count"))
            return in.failure();
        corners.clear();
        for (std::int64_t k = 0; k < n; ++k) {
            std::int64_t v = 0;
            if (!in.integerIn(v, 0, vertexCount - 1, "vertex index"))
                return in.failure();
            corners.push_back(static_cast<std::int32_t>(v));
        }
        in.skipLine(); // optional colour
        if (!appendFan(mesh, corners.data(), corners.size(), cellLimit(limits)))
            return fileError(ErrorCode::LimitExceeded, path,
                             "more than " + std::to_string(cellLimit(limits)) + " triangles after splitting polygons");
    }
    HS_TRY(finishSurface(path, mesh));
    return mesh;
}

Status writeOff(const SurfaceMesh& mesh, const std::string& tmpPath) {
    std::string out =
        "OFF\n" + std::to_string(mesh.points.size()) + " " + std::to_string(mesh.triangles.size()) + " 0\n";
    for (const auto& p : mesh.points)
        out += formatDouble(p.x) + " " + formatDouble(p.y) + " " + formatDouble(p.z) + "\n";
    for (const auto& t : mesh.triangles)
        out += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
    return writePlainFile(tmpPath, out);
}

} // namespace hs::io::detail
