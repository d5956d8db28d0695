// STL, ASCII and binary, through VTK's vtkSTLReader/vtkSTLWriter. The reader is guarded: the file type is decided
// here (binary only when the size is exactly 84 + 50 * count) and must agree with VTK's own guess, VTK's point
// merging is off (its locator misbehaves on non-finite coordinates) and corners are merged here by exact position.

#include "Formats.h"
#include "Parsing.h"
#include "VtkSupport.h"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSTLWriter.h>
#include <vtksys/SystemTools.hxx>

#include <cstring>
#include <filesystem>
#include <unordered_map>

namespace hs::io::detail {
namespace {

struct PointKey {
    std::uint64_t bits[3];
    bool operator==(const PointKey& o) const {
        return bits[0] == o.bits[0] && bits[1] == o.bits[1] && bits[2] == o.bits[2];
    }
};
struct PointKeyHash {
    std::size_t operator()(const PointKey& k) const {
        std::uint64_t h = 1469598103934665603ull;
        for (auto b : k.bits) {
            h ^= b;
            h *= 1099511628211ull;
        }
        return static_cast<std::size_t>(h);
    }
};

PointKey keyOf(const Vec3& p) {
    PointKey key{};
    const double values[3] = {p.x == 0.0 ? 0.0 : p.x, p.y == 0.0 ? 0.0 : p.y, p.z == 0.0 ? 0.0 : p.z}; // -0 == 0
    for (int k = 0; k < 3; ++k)
        std::memcpy(&key.bits[k], &values[k], 8);
    return key;
}

enum class StlKind { Ascii, Binary };

/// Binary when the size matches the triangle count of the header exactly; ASCII when it starts with "solid".
Result<StlKind> detectKind(const std::string& path, std::int64_t fileSize, const ReadLimits& limits) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file)
        return fileError(ErrorCode::IoError, path, "cannot open");
    unsigned char head[84] = {};
    const std::size_t got = std::fread(head, 1, sizeof head, file);
    std::fclose(file);

    if (got == 84) {
        const std::uint64_t count = static_cast<std::uint64_t>(head[80]) | (static_cast<std::uint64_t>(head[81]) << 8) |
                                    (static_cast<std::uint64_t>(head[82]) << 16) |
                                    (static_cast<std::uint64_t>(head[83]) << 24);
        if (static_cast<std::uint64_t>(fileSize) == 84 + 50 * count) {
            if (static_cast<std::int64_t>(count) > cellLimit(limits))
                return fileError(ErrorCode::LimitExceeded, path,
                                 std::to_string(count) + " triangles, limit " + std::to_string(cellLimit(limits)));
            return StlKind::Binary;
        }
    }
    std::size_t start = 0;
    while (start < got && (head[start] == ' ' || head[start] == '\t' || head[start] == '\r' || head[start] == '\n'))
        ++start;
    if (got >= start + 5 && std::memcmp(head + start, "solid", 5) == 0)
        return StlKind::Ascii;
    if (got >= 84) {
        const std::uint64_t count = static_cast<std::uint64_t>(head[80]) | (static_cast<std::uint64_t>(head[81]) << 8) |
                                    (static_cast<std::uint64_t>(head[82]) << 16) |
                                    (static_cast<std::uint64_t>(head[83]) << 24);
        return fileError(ErrorCode::InvalidInput, path,
                         "not an ASCII STL (no 'solid') and not a binary STL: the header declares " +
                             std::to_string(count) + " triangles, which need " + std::to_string(84 + 50 * count) +
                             " bytes, but the file has " + std::to_string(fileSize));
    }
    return fileError(ErrorCode::InvalidInput, path,
                     "too short for an STL file (" + std::to_string(fileSize) + " bytes, no 'solid')");
}

/// Merges the corners of the triangle soup VTK read, by exact position, in first-use order.
Result<SurfaceMesh> fromTriangleSoup(const std::string& path, vtkPolyData* soup, const ReadLimits& limits) {
    vtkPoints* points = soup->GetPoints();
    vtkCellArray* polys = soup->GetPolys();
    if (!points || !polys || polys->GetNumberOfCells() == 0)
        return fileError(ErrorCode::InvalidInput, path, "contains no triangles");
    if (polys->GetNumberOfCells() > cellLimit(limits))
        return fileError(ErrorCode::LimitExceeded, path, "too many triangles");
    SurfaceMesh mesh;
    std::unordered_map<PointKey, std::int32_t, PointKeyHash> index;
    vtkNew<vtkIdList> ids;
    const vtkIdType cellCount = polys->GetNumberOfCells();
    mesh.triangles.reserve(static_cast<std::size_t>(cellCount));
    for (vtkIdType c = 0; c < cellCount; ++c) {
        polys->GetCellAtId(c, ids);
        if (ids->GetNumberOfIds() != 3)
            return fileError(ErrorCode::InvalidInput, path, "facet " + std::to_string(c) + " is not a triangle");
        Triangle t{};
        for (vtkIdType k = 0; k < 3; ++k) {
            const vtkIdType id = ids->GetId(k);
            if (id < 0 || id >= points->GetNumberOfPoints())
                return fileError(ErrorCode::Internal, path, "VTK returned a corner out of range");
            double x[3];
            points->GetPoint(id, x);
            const Vec3 p{x[0], x[1], x[2]};
            if (!isFinite(p))
                return fileError(ErrorCode::InvalidInput, path,
                                 "facet " + std::to_string(c) + " has a non-finite vertex coordinate");
            const auto [it, inserted] = index.try_emplace(keyOf(p), static_cast<std::int32_t>(mesh.points.size()));
            if (inserted)
                mesh.points.push_back(p);
            t[static_cast<std::size_t>(k)] = it->second;
        }
        mesh.triangles.push_back(t);
    }
    if (static_cast<std::int64_t>(mesh.points.size()) > pointLimit(limits))
        return fileError(ErrorCode::LimitExceeded, path,
                         std::to_string(mesh.points.size()) + " points, limit " + std::to_string(pointLimit(limits)));
    HS_TRY(finishSurface(path, mesh));
    return mesh;
}

} // namespace

Result<SurfaceMesh> readStl(const std::string& path, const ReadLimits& limits) {
    // Size and existence first (readFile's checks, without reading the data twice).
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return fileError(ErrorCode::NotFound, path, "no such file");
    if (std::filesystem::is_directory(path, ec))
        return fileError(ErrorCode::InvalidInput, path, "is a directory, not a file");
    if (!std::filesystem::is_regular_file(path, ec))
        return fileError(ErrorCode::InvalidInput, path, "is not a regular file");
    const auto fileSize = static_cast<std::int64_t>(std::filesystem::file_size(path, ec));
    if (ec)
        return fileError(ErrorCode::IoError, path, "cannot get the file size");
    if (fileSize > limits.maxFileBytes)
        return fileError(ErrorCode::LimitExceeded, path,
                         std::to_string(fileSize) + " bytes, limit " + std::to_string(limits.maxFileBytes));

    Result<StlKind> kind = detectKind(path, fileSize, limits);
    if (!kind.ok())
        return kind.failure();
    const auto vtkGuess = vtksys::SystemTools::DetectFileType(path.c_str());
    const bool vtkSaysBinary = vtkGuess != vtksys::SystemTools::FileTypeText;
    if (vtkSaysBinary != (*kind == StlKind::Binary))
        return fileError(ErrorCode::InvalidInput, path,
                         *kind == StlKind::Binary
                             ? "ambiguous STL: the size fits a binary STL but the content looks like text"
                             : "an ASCII STL with binary content (or a binary STL whose size does not match its "
                               "triangle count)");

    VtkMessageCapture capture;
    vtkNew<vtkSTLReader> reader;
    reader->SetFileName(path.c_str());
    reader->MergingOff();
    reader->ScalarTagsOff();
    reader->Update();
    HS_TRY(capture.check(true, path, "reading STL", ErrorCode::InvalidInput));
    return fromTriangleSoup(path, reader->GetOutput(), limits);
}

Status writeStl(const SurfaceMesh& mesh, const std::string& tmpPath, bool binary) {
    VtkMessageCapture capture;
    vtkNew<vtkSTLWriter> writer;
    writer->SetInputData(toPolyData(mesh, false));
    writer->SetFileName(tmpPath.c_str());
    if (binary)
        writer->SetFileTypeToBinary();
    else
        writer->SetFileTypeToASCII();
    writer->SetHeader("hysteroscene");
    const int ok = writer->Write();
    return capture.check(ok == 1, tmpPath, "writing STL");
}

} // namespace hs::io::detail
