// VTK XML PolyData (.vtp) and UnstructuredGrid (.vtu) through VTK's XML readers and writers. Before VTK sees a
// file it passes guardVtkXml (VtkXmlGuard.cpp); after reading, cell offsets, point indices and coordinates are
// checked again before anything is converted.

#include "Formats.h"
#include "Parsing.h"
#include "VtkSupport.h"
#include "VtkXmlGuard.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <exception>
#include <limits>
#include <vector>

namespace hs::io::detail {
namespace {
bool isIntegerArray(vtkDataArray* array) {
    switch (array->GetDataType()) {
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
    case VTK_UNSIGNED_CHAR:
    case VTK_SHORT:
    case VTK_UNSIGNED_SHORT:
    case VTK_INT:
    case VTK_UNSIGNED_INT:
    case VTK_LONG:
    case VTK_UNSIGNED_LONG:
    case VTK_LONG_LONG:
    case VTK_UNSIGNED_LONG_LONG:
    case VTK_ID_TYPE:
        return true;
    default:
        return false;
    }
}

/// Integer single-component arrays, picked at `rows` (one entry per output element), as labels.
Status readLabels(const std::string& path, vtkDataSetAttributes* data, const std::vector<vtkIdType>& rows,
                  const char* what, LabelMap& out) {
    for (int a = 0; a < data->GetNumberOfArrays(); ++a) {
        vtkDataArray* array = data->GetArray(a);
        if (!array || !array->GetName() || array->GetNumberOfComponents() != 1 || !isIntegerArray(array))
            continue;
        const std::string name = array->GetName();
        if (name.empty() || out.count(name) != 0)
            continue;
        std::vector<std::int32_t> values;
        values.reserve(rows.size());
        for (vtkIdType row : rows) {
            if (row >= array->GetNumberOfTuples())
                return fileError(ErrorCode::InvalidInput, path,
                                 std::string(what) + " array '" + name + "' has too few values");
            const double v = array->GetComponent(row, 0);
            if (v < std::numeric_limits<std::int32_t>::min() || v > std::numeric_limits<std::int32_t>::max())
                return fileError(ErrorCode::InvalidInput, path,
                                 std::string(what) + " array '" + name + "' has a value outside the 32-bit range");
            values.push_back(static_cast<std::int32_t>(v));
        }
        out.emplace(name, std::move(values));
    }
    return {};
}

/// Non-integer point arrays with 1..9 components, as PointArrays; a non-finite value is an error.
Status readPointArrays(const std::string& path, vtkDataSetAttributes* data, std::size_t pointCount, PointArrays& out) {
    for (int a = 0; a < data->GetNumberOfArrays(); ++a) {
        vtkDataArray* array = data->GetArray(a);
        if (!array || !array->GetName() || isIntegerArray(array))
            continue;
        const std::string name = array->GetName();
        const int components = array->GetNumberOfComponents();
        if (name.empty() || out.count(name) != 0 || components < 1 || components > 9)
            continue;
        if (array->GetNumberOfTuples() != static_cast<vtkIdType>(pointCount))
            return fileError(ErrorCode::InvalidInput, path,
                             "point array '" + name + "' has " + std::to_string(array->GetNumberOfTuples()) +
                                 " tuples for " + std::to_string(pointCount) + " points");
        PointArray values;
        values.components = components;
        values.values.reserve(pointCount * static_cast<std::size_t>(components));
        for (vtkIdType row = 0; row < static_cast<vtkIdType>(pointCount); ++row)
            for (int c = 0; c < components; ++c) {
                const double v = array->GetComponent(row, c);
                if (!std::isfinite(v))
                    return fileError(ErrorCode::InvalidInput, path,
                                     "point array '" + name + "' has a non-finite value at point " +
                                         std::to_string(row));
                values.values.push_back(v);
            }
        out.emplace(name, std::move(values));
    }
    return {};
}

/// Offsets start at 0, never decrease and end at the connectivity size; every index names an existing point.
Status checkCellArray(const std::string& path, vtkCellArray* cells, vtkIdType pointCount, const char* what) {
    if (!cells)
        return {};
    vtkDataArray* offsets = cells->GetOffsetsArray();
    vtkDataArray* connectivity = cells->GetConnectivityArray();
    if (!offsets || !connectivity)
        return fileError(ErrorCode::InvalidInput, path, std::string(what) + ": missing cell arrays");
    const vtkIdType n = offsets->GetNumberOfTuples();
    const vtkIdType size = connectivity->GetNumberOfTuples();
    if (n == 0)
        return size == 0 ? Status{} : fileError(ErrorCode::InvalidInput, path, std::string(what) + ": no offsets");
    double previous = 0.0;
    for (vtkIdType i = 0; i < n; ++i) {
        const double o = offsets->GetComponent(i, 0);
        if ((i == 0 && o != 0.0) || o < previous || o > static_cast<double>(size))
            return fileError(ErrorCode::InvalidInput, path,
                             std::string(what) + ": cell offsets are not increasing within the connectivity");
        previous = o;
    }
    if (previous != static_cast<double>(size))
        return fileError(ErrorCode::InvalidInput, path, std::string(what) + ": cell offsets do not cover the cells");
    for (vtkIdType i = 0; i < size; ++i) {
        const double id = connectivity->GetComponent(i, 0);
        if (id < 0 || id >= static_cast<double>(pointCount))
            return fileError(ErrorCode::InvalidInput, path,
                             std::string(what) + ": a cell references point " +
                                 std::to_string(static_cast<long long>(id)) + ", allowed 0.." +
                                 std::to_string(pointCount - 1));
    }
    return {};
}

Result<std::vector<Vec3>> readPoints(const std::string& path, vtkPoints* points, const ReadLimits& limits) {
    std::vector<Vec3> out;
    if (!points)
        return out;
    const vtkIdType n = points->GetNumberOfPoints();
    if (n > pointLimit(limits))
        return fileError(ErrorCode::LimitExceeded, path, std::to_string(n) + " points");
    out.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i) {
        double x[3];
        points->GetPoint(i, x);
        out[static_cast<std::size_t>(i)] = {x[0], x[1], x[2]};
        if (!isFinite(out[static_cast<std::size_t>(i)]))
            return fileError(ErrorCode::InvalidInput, path,
                             "point " + std::to_string(i) + " has a non-finite coordinate");
    }
    return out;
}

std::vector<vtkIdType> allRows(std::size_t n) {
    std::vector<vtkIdType> rows(n);
    for (std::size_t i = 0; i < n; ++i)
        rows[i] = static_cast<vtkIdType>(i);
    return rows;
}

/// Appends the triangles of one surface cell (triangle, polygon, quad, pixel, strip); `row` is repeated per triangle.
bool appendSurfaceCell(SurfaceMesh& mesh, std::vector<vtkIdType>& rows, vtkIdType row, int type, vtkIdType npts,
                       const vtkIdType* pts, std::int64_t maxCells) {
    const std::size_t before = mesh.triangles.size();
    std::vector<std::int32_t> corners(pts, pts + npts);
    if (type == VTK_PIXEL && npts == 4)
        std::swap(corners[2], corners[3]);
    if (type == VTK_TRIANGLE_STRIP) {
        for (vtkIdType k = 0; k + 2 < npts; ++k) {
            if (static_cast<std::int64_t>(mesh.triangles.size()) >= maxCells)
                return false;
            const auto a = corners[static_cast<std::size_t>(k)], b = corners[static_cast<std::size_t>(k + 1)],
                       c = corners[static_cast<std::size_t>(k + 2)];
            mesh.triangles.push_back(k % 2 == 0 ? Triangle{a, b, c} : Triangle{b, a, c});
        }
    } else if (!appendFan(mesh, corners.data(), corners.size(), maxCells)) {
        return false;
    }
    rows.insert(rows.end(), mesh.triangles.size() - before, row);
    return true;
}

Result<vtkSmartPointer<vtkDataObject>> readXml(const std::string& path, const ReadLimits& limits, bool polyData) {
    Result<std::string> bytes = readInput(path, limits);
    if (!bytes.ok())
        return bytes.failure();
    HS_TRY(guardVtkXml(path, *bytes, polyData ? "PolyData" : "UnstructuredGrid", limits));
    VtkMessageCapture capture;
    vtkSmartPointer<vtkXMLReader> reader;
    if (polyData)
        reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    else
        reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    reader->ReadFromInputStringOn();
    reader->SetInputString(*bytes);
    try {
        reader->Update();
    } catch (const std::exception& e) {
        // VTK's XML readers size some arrays by values in the data; a forged value can make an allocation fail.
        return fileError(ErrorCode::InvalidInput, path, std::string("VTK could not read the file: ") + e.what());
    }
    HS_TRY(capture.check(true, path, "reading VTK XML", ErrorCode::InvalidInput));
    vtkSmartPointer<vtkDataObject> output = reader->GetOutputDataObject(0);
    if (!output)
        return fileError(ErrorCode::InvalidInput, path, "VTK read no data");
    return output;
}

} // namespace

Result<SurfaceMesh> readVtp(const std::string& path, const ReadLimits& limits, PointArrays* arrays) {
    auto object = readXml(path, limits, true);
    if (!object.ok())
        return object.failure();
    vtkPolyData* data = vtkPolyData::SafeDownCast(*object);
    if (!data)
        return fileError(ErrorCode::InvalidInput, path, "not PolyData");

    SurfaceMesh mesh;
    auto points = readPoints(path, data->GetPoints(), limits);
    if (!points.ok())
        return points.failure();
    mesh.points = std::move(*points);
    const auto pointCount = static_cast<vtkIdType>(mesh.points.size());
    HS_TRY(checkCellArray(path, data->GetVerts(), pointCount, "Verts"));
    HS_TRY(checkCellArray(path, data->GetLines(), pointCount, "Lines"));
    HS_TRY(checkCellArray(path, data->GetPolys(), pointCount, "Polys"));
    HS_TRY(checkCellArray(path, data->GetStrips(), pointCount, "Strips"));

    // Cell data is ordered verts, lines, polys, strips.
    const vtkIdType firstPoly = data->GetNumberOfVerts() + data->GetNumberOfLines();
    const vtkIdType firstStrip = firstPoly + data->GetNumberOfPolys();
    std::vector<vtkIdType> rows;
    vtkIdType npts = 0;
    const vtkIdType* pts = nullptr;
    for (vtkIdType c = 0; c < data->GetNumberOfPolys(); ++c) {
        data->GetPolys()->GetCellAtId(c, npts, pts);
        if (npts < 3)
            return fileError(ErrorCode::InvalidInput, path,
                             "polygon " + std::to_string(c) + " has " + std::to_string(npts) + " corners");
        if (!appendSurfaceCell(mesh, rows, firstPoly + c, VTK_POLYGON, npts, pts, cellLimit(limits)))
            return fileError(ErrorCode::LimitExceeded, path, "too many triangles");
    }
    for (vtkIdType c = 0; c < data->GetNumberOfStrips(); ++c) {
        data->GetStrips()->GetCellAtId(c, npts, pts);
        if (!appendSurfaceCell(mesh, rows, firstStrip + c, VTK_TRIANGLE_STRIP, npts, pts, cellLimit(limits)))
            return fileError(ErrorCode::LimitExceeded, path, "too many triangles");
    }
    HS_TRY(readLabels(path, data->GetCellData(), rows, "cell", mesh.faceLabels));
    HS_TRY(readLabels(path, data->GetPointData(), allRows(mesh.points.size()), "point", mesh.vertexLabels));
    if (arrays)
        HS_TRY(readPointArrays(path, data->GetPointData(), mesh.points.size(), *arrays));
    HS_TRY(finishSurface(path, mesh));
    return mesh;
}

Result<AnyMesh> readVtu(const std::string& path, const ReadLimits& limits) {
    auto object = readXml(path, limits, false);
    if (!object.ok())
        return object.failure();
    vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(*object);
    if (!grid)
        return fileError(ErrorCode::InvalidInput, path, "not an UnstructuredGrid");
    auto points = readPoints(path, grid->GetPoints(), limits);
    if (!points.ok())
        return points.failure();
    const auto pointCount = static_cast<vtkIdType>(points->size());
    const vtkIdType cellCount = grid->GetNumberOfCells();
    if (cellCount > 0) {
        HS_TRY(checkCellArray(path, grid->GetCells(), pointCount, "Cells"));
        vtkUnsignedCharArray* types = grid->GetCellTypesArray();
        if (!types || types->GetNumberOfTuples() != cellCount || grid->GetCells()->GetNumberOfCells() != cellCount)
            return fileError(ErrorCode::InvalidInput, path, "cell types do not match the cells");
    }

    std::vector<vtkIdType> tetRows;
    bool hasSurfaceCells = false;
    for (vtkIdType c = 0; c < cellCount; ++c) {
        const int type = grid->GetCellType(c);
        if (type == VTK_TETRA) {
            tetRows.push_back(c);
        } else if (type == VTK_TRIANGLE || type == VTK_TRIANGLE_STRIP || type == VTK_POLYGON || type == VTK_PIXEL ||
                   type == VTK_QUAD) {
            hasSurfaceCells = true;
        } else if (type > VTK_POLY_LINE) {
            return fileError(ErrorCode::InvalidInput, path,
                             "cell " + std::to_string(c) + " has VTK cell type " + std::to_string(type) +
                                 "; only linear tetrahedra (and surface cells, for a surface) are read");
        }
    }
    vtkIdType npts = 0;
    const vtkIdType* pts = nullptr;
    if (!tetRows.empty() || !hasSurfaceCells) {
        TetMesh mesh;
        mesh.points = std::move(*points);
        mesh.tets.reserve(tetRows.size());
        for (vtkIdType c : tetRows) {
            grid->GetCellPoints(c, npts, pts);
            if (npts != 4)
                return fileError(ErrorCode::InvalidInput, path,
                                 "tetrahedron " + std::to_string(c) + " has " + std::to_string(npts) + " points");
            mesh.tets.push_back({static_cast<std::int32_t>(pts[0]), static_cast<std::int32_t>(pts[1]),
                                 static_cast<std::int32_t>(pts[2]), static_cast<std::int32_t>(pts[3])});
        }
        LabelMap cellLabels;
        HS_TRY(readLabels(path, grid->GetCellData(), tetRows, "cell", cellLabels));
        if (auto region = cellLabels.find("region"); region != cellLabels.end()) {
            mesh.regions = std::move(region->second);
            cellLabels.erase(region);
        }
        mesh.tetLabels = std::move(cellLabels);
        HS_TRY(readLabels(path, grid->GetPointData(), allRows(mesh.points.size()), "point", mesh.pointLabels));
        HS_TRY(finishTetMesh(path, mesh));
        return AnyMesh(std::move(mesh));
    }

    SurfaceMesh mesh;
    mesh.points = std::move(*points);
    std::vector<vtkIdType> rows;
    for (vtkIdType c = 0; c < cellCount; ++c) {
        const int type = grid->GetCellType(c);
        if (type < VTK_TRIANGLE || type == VTK_TETRA)
            continue;
        grid->GetCellPoints(c, npts, pts);
        if (npts < 3)
            return fileError(ErrorCode::InvalidInput, path, "cell " + std::to_string(c) + " has too few points");
        if (!appendSurfaceCell(mesh, rows, c, type, npts, pts, cellLimit(limits)))
            return fileError(ErrorCode::LimitExceeded, path, "too many triangles");
    }
    HS_TRY(readLabels(path, grid->GetCellData(), rows, "cell", mesh.faceLabels));
    HS_TRY(readLabels(path, grid->GetPointData(), allRows(mesh.points.size()), "point", mesh.vertexLabels));
    HS_TRY(finishSurface(path, mesh));
    return AnyMesh(std::move(mesh));
}

namespace {

template <class Writer>
Status writeXml(vtkDataObject* data, const std::string& tmpPath, const WriteOptions& options, const char* action) {
    const bool binary = options.binary;
    VtkMessageCapture capture;
    vtkNew<Writer> writer;
    writer->SetInputData(data);
    writer->SetFileName(tmpPath.c_str());
    if (binary && options.compress) {
        writer->SetCompressorTypeToZLib();
        writer->SetCompressionLevel(5);
    } else {
        writer->SetCompressorTypeToNone();
    }
    writer->SetHeaderTypeToUInt64();
    if (binary) {
        writer->SetDataModeToAppended();
        writer->EncodeAppendedDataOff();
    } else {
        writer->SetDataModeToAscii();
    }
    errno = 0;
    const int ok = writer->Write();
    const int writeErrno = errno;
    Status status = capture.check(ok == 1, tmpPath, action, ErrorCode::IoError);
    if (!status.ok() && (writer->GetErrorCode() != vtkErrorCode::NoError || writeErrno != 0)) {
        // Say why the operating system refused (a full disk, a file size limit): VTK only says that it failed.
        std::string detail = status.error().detail + " (";
        if (writer->GetErrorCode() != vtkErrorCode::NoError)
            detail += std::string(vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode())) +
                      (writeErrno != 0 ? ": " : "");
        if (writeErrno != 0)
            detail += std::strerror(writeErrno);
        return fail(ErrorCode::IoError, detail + ")");
    }
    return status;
}

} // namespace

Status writeVtp(const SurfaceMesh& mesh, const std::string& tmpPath, const WriteOptions& options) {
    const auto* textureCoordinates = options.textureCoordinates;
    const auto* normals = options.normals;
    const auto* pointArrays = options.pointArrays;
    auto poly = toPolyData(mesh, true);
    if (pointArrays)
        for (const auto& [name, array] : *pointArrays) {
            vtkNew<vtkDoubleArray> values;
            values->SetName(name.c_str());
            values->SetNumberOfComponents(array.components);
            values->SetNumberOfTuples(static_cast<vtkIdType>(mesh.points.size()));
            for (std::size_t i = 0; i < array.values.size(); ++i)
                values->SetValue(static_cast<vtkIdType>(i), array.values[i]);
            poly->GetPointData()->AddArray(values);
        }
    if (textureCoordinates && options.textureOriginTopLeft) {
        vtkNew<vtkDoubleArray> uv;
        uv->SetName("uv");
        uv->SetNumberOfComponents(2);
        uv->SetNumberOfTuples(static_cast<vtkIdType>(textureCoordinates->size()));
        for (std::size_t i = 0; i < textureCoordinates->size(); ++i) {
            const auto& t = (*textureCoordinates)[i];
            const double tuple[2] = {static_cast<double>(t[0]), 1.0 - static_cast<double>(t[1])};
            uv->SetTypedTuple(static_cast<vtkIdType>(i), tuple);
        }
        poly->GetPointData()->SetTCoords(uv);
    } else if (textureCoordinates) {
        vtkNew<vtkFloatArray> uv;
        uv->SetName("uv");
        uv->SetNumberOfComponents(2);
        uv->SetNumberOfTuples(static_cast<vtkIdType>(textureCoordinates->size()));
        for (std::size_t i = 0; i < textureCoordinates->size(); ++i)
            uv->SetTypedTuple(static_cast<vtkIdType>(i), (*textureCoordinates)[i].data());
        poly->GetPointData()->SetTCoords(uv);
    }
    if (normals) {
        vtkNew<vtkFloatArray> n;
        n->SetName("normals");
        n->SetNumberOfComponents(3);
        n->SetNumberOfTuples(static_cast<vtkIdType>(normals->size()));
        for (std::size_t i = 0; i < normals->size(); ++i) {
            const Vec3& v = (*normals)[i];
            const float tuple[3] = {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
            n->SetTypedTuple(static_cast<vtkIdType>(i), tuple);
        }
        poly->GetPointData()->SetNormals(n);
    }
    return writeXml<vtkXMLPolyDataWriter>(poly, tmpPath, options, "writing VTP");
}

Status writeVtu(const TetMesh& mesh, const std::string& tmpPath, const WriteOptions& options) {
    return writeXml<vtkXMLUnstructuredGridWriter>(toUnstructuredGrid(mesh), tmpPath, options, "writing VTU");
}

Status writeVtuSurface(const SurfaceMesh& mesh, const std::string& tmpPath, const WriteOptions& options) {
    return writeXml<vtkXMLUnstructuredGridWriter>(toUnstructuredGrid(mesh), tmpPath, options, "writing VTU");
}

} // namespace hs::io::detail
