// Stanford PLY, read and written by hand. VTK's reader (the original ply library) allocates lists sized by counts
// read from the body and does not check for the end of the data, so a hostile file could only be guarded by
// parsing it completely first; reading it here costs no more. Integer properties (int/short/char, not uchar, the
// type of colours) of vertices and faces are labels; the writer stores labels as int properties.

#include "Formats.h"
#include "Parsing.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

namespace hs::io::detail {
namespace {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool plyTypeFromName(std::string_view name, PlyType& out) {
    static const struct {
        const char* name;
        PlyType type;
    } kTypes[] = {{"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
                  {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
                  {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
                  {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
                  {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
                  {"float64", PlyType::Float64}};
    for (const auto& t : kTypes) {
        if (name == t.name) {
            out = t.type;
            return true;
        }
    }
    return false;
}

std::int64_t plyTypeSize(PlyType type) {
    switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8:
        return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
        return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
        return 4;
    case PlyType::Float64:
        return 8;
    }
    return 1;
}

/// The range an integer type holds, so that an ASCII value outside it is an error, not a wrapped or undefined cast.
std::pair<std::int64_t, std::int64_t> plyIntegerRange(PlyType type) {
    switch (type) {
    case PlyType::Int8:
        return {INT8_MIN, INT8_MAX};
    case PlyType::UInt8:
        return {0, UINT8_MAX};
    case PlyType::Int16:
        return {INT16_MIN, INT16_MAX};
    case PlyType::UInt16:
        return {0, UINT16_MAX};
    case PlyType::Int32:
        return {INT32_MIN, INT32_MAX};
    case PlyType::UInt32:
    default:
        return {0, UINT32_MAX};
    }
}

bool isFloatType(PlyType type) {
    return type == PlyType::Float32 || type == PlyType::Float64;
}

bool isLabelType(PlyType type) {
    return type == PlyType::Int8 || type == PlyType::Int16 || type == PlyType::Int32;
}

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::Float32;
    bool isList = false;
    PlyType countType = PlyType::UInt8;
};

struct PlyElement {
    std::string name;
    std::int64_t count = 0;
    std::vector<PlyProperty> properties;
    std::size_t line = 0;

    /// Bytes one element takes at least (lists counted as empty).
    std::int64_t minBytes(bool binary) const {
        std::int64_t bytes = 0;
        for (const auto& p : properties)
            bytes += binary ? plyTypeSize(p.isList ? p.countType : p.type) : 2;
        return bytes;
    }
};

enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyHeader {
    PlyEncoding encoding = PlyEncoding::Ascii;
    std::vector<PlyElement> elements;
    std::size_t bodyOffset = 0;
    std::size_t bodyLine = 1;
};

Result<PlyHeader> parseHeader(const std::string& path, std::string_view text, const ReadLimits& limits) {
    PlyHeader header;
    std::size_t pos = 0;
    std::size_t line = 0;
    bool sawFormat = false;
    constexpr std::size_t kMaxHeaderBytes = 1 << 20;
    while (true) {
        ++line;
        const std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos || end > kMaxHeaderBytes)
            return lineError(path, line, "the header does not end with 'end_header' within the file or its first MB");
        std::string_view rest = text.substr(pos, end - pos);
        pos = end + 1;
        if (!rest.empty() && rest.back() == '\r')
            rest.remove_suffix(1);
        TokenReader words(path, rest, 0);
        std::string_view keyword;
        if (!words.word(keyword, "keyword")) {
            if (line == 1)
                return lineError(path, line, "not a PLY file (it must start with 'ply')");
            continue;
        }
        if (line == 1) {
            if (keyword != "ply" || !words.atEnd())
                return lineError(path, line, "not a PLY file (it must start with 'ply')");
            continue;
        }
        if (keyword == "comment" || keyword == "obj_info")
            continue;
        if (keyword == "end_header") {
            if (!sawFormat)
                return lineError(path, line, "the header has no 'format' line");
            header.bodyOffset = pos;
            header.bodyLine = line + 1;
            return header;
        }
        if (keyword == "format") {
            std::string_view encoding, version;
            if (!words.word(encoding, "encoding") || !words.word(version, "version"))
                return lineError(path, line, "format line needs an encoding and a version");
            if (encoding == "ascii")
                header.encoding = PlyEncoding::Ascii;
            else if (encoding == "binary_little_endian")
                header.encoding = PlyEncoding::BinaryLittleEndian;
            else if (encoding == "binary_big_endian")
                header.encoding = PlyEncoding::BinaryBigEndian;
            else
                return lineError(path, line, "unknown PLY encoding '" + std::string(encoding.substr(0, 40)) + "'");
            if (version != "1.0")
                return fail(ErrorCode::Unsupported, path + ": line " + std::to_string(line) + ": PLY version '" +
                                                        std::string(version.substr(0, 20)) + "' (only 1.0)");
            sawFormat = true;
        } else if (keyword == "element") {
            PlyElement element;
            std::string_view name;
            if (!words.word(name, "element name") || !words.integer(element.count, "element count"))
                return words.failure();
            element.name = std::string(name.substr(0, 64));
            element.line = line;
            const std::int64_t limit = element.name == "vertex" ? pointLimit(limits) : cellLimit(limits);
            HS_TRY(checkCount(path, line, element.count, limit, 0, 0, (element.name + " elements").c_str()));
            if (header.elements.size() > 64)
                return lineError(path, line, "more than 64 element types");
            header.elements.push_back(std::move(element));
        } else if (keyword == "property") {
            if (header.elements.empty())
                return lineError(path, line, "property before any element");
            PlyProperty property;
            std::string_view type, name;
            if (!words.word(type, "property type"))
                return words.failure();
            if (type == "list") {
                std::string_view countType;
                property.isList = true;
                if (!words.word(countType, "list count type") || !words.word(type, "list item type"))
                    return words.failure();
                if (!plyTypeFromName(countType, property.countType) || isFloatType(property.countType))
                    return lineError(path, line, "bad list count type '" + std::string(countType.substr(0, 20)) + "'");
            }
            if (!plyTypeFromName(type, property.type))
                return lineError(path, line, "unknown property type '" + std::string(type.substr(0, 20)) + "'");
            if (!words.word(name, "property name"))
                return words.failure();
            property.name = std::string(name.substr(0, 64));
            auto& properties = header.elements.back().properties;
            if (properties.size() > 256)
                return lineError(path, line, "more than 256 properties in one element");
            properties.push_back(std::move(property));
        } else {
            return lineError(path, line, "unknown header keyword '" + std::string(keyword.substr(0, 40)) + "'");
        }
    }
}

/// Reads values of the body, ASCII or binary, with bounds checks; errors name the element and its index.
class PlyBody {
public:
    PlyBody(const std::string& path, std::string_view text, const PlyHeader& header)
        : m_text(text), m_encoding(header.encoding), m_pos(header.bodyOffset),
          m_ascii(path, text.substr(header.bodyOffset), 0) {}

    bool value(PlyType type, double& out, const char* what) {
        if (m_encoding == PlyEncoding::Ascii) {
            if (isFloatType(type))
                return m_ascii.real(out, what);
            std::int64_t i = 0;
            if (!m_ascii.integer(i, what))
                return false;
            const auto [low, high] = plyIntegerRange(type);
            if (i < low || i > high)
                return fail(std::string(what) + " " + std::to_string(i) + " outside the range of its type (" +
                            std::to_string(low) + ".." + std::to_string(high) + ")");
            out = static_cast<double>(i);
            return true;
        }
        const auto size = static_cast<std::size_t>(plyTypeSize(type));
        if (m_pos + size > m_text.size())
            return fail(std::string("unexpected end of file in ") + what);
        unsigned char raw[8];
        std::memcpy(raw, m_text.data() + m_pos, size);
        m_pos += size;
        if (m_encoding == PlyEncoding::BinaryBigEndian)
            for (std::size_t k = 0; k < size / 2; ++k)
                std::swap(raw[k], raw[size - 1 - k]);
        out = decode(type, raw);
        if (!std::isfinite(out))
            return fail(std::string("non-finite ") + what);
        return true;
    }

    std::string where() const {
        if (m_encoding == PlyEncoding::Ascii)
            return "line " + std::to_string(m_ascii.line() + m_lineOffset);
        return "byte " + std::to_string(m_pos);
    }
    std::string error() const { return m_error.empty() ? m_ascii.message() : m_error; }
    bool fail(std::string what) {
        if (m_error.empty())
            m_error = std::move(what);
        return false;
    }
    void setLineOffset(std::size_t offset) { m_lineOffset = offset; }

private:
    static double decode(PlyType type, const unsigned char* raw) {
        switch (type) {
        case PlyType::Int8:
            return static_cast<double>(static_cast<std::int8_t>(raw[0]));
        case PlyType::UInt8:
            return static_cast<double>(raw[0]);
        case PlyType::Int16: {
            std::int16_t v;
            std::memcpy(&v, raw, 2);
            return v;
        }
        case PlyType::UInt16: {
            std::uint16_t v;
            std::memcpy(&v, raw, 2);
            return v;
        }
        case PlyType::Int32: {
            std::int32_t v;
            std::memcpy(&v, raw, 4);
            return v;
        }
        case PlyType::UInt32: {
            std::uint32_t v;
            std::memcpy(&v, raw, 4);
            return v;
        }
        case PlyType::Float32: {
            float v;
            std::memcpy(&v, raw, 4);
            return static_cast<double>(v);
        }
        case PlyType::Float64: {
            double v;
            std::memcpy(&v, raw, 8);
            return v;
        }
        }
        return 0.0;
    }

    std::string_view m_text;
    PlyEncoding m_encoding;
    std::size_t m_pos;
    TokenReader m_ascii;
    std::size_t m_lineOffset = 0;
    std::string m_error;
};

bool isPositionName(const std::string& name) {
    return name == "x" || name == "y" || name == "z";
}

struct PlyReader {
    const std::string& path;
    const ReadLimits& limits;
    const PlyHeader& header;
    PlyBody body;
    SurfaceMesh mesh;
    std::int64_t vertexCount = -1;

    Failure bodyError(const std::string& element, std::int64_t index) const {
        return fail(ErrorCode::InvalidInput,
                    path + ": " + body.where() + ": " + element + " " + std::to_string(index) + ": " + body.error());
    }

    Status readVertices(const PlyElement& element) {
        int axis[3] = {-1, -1, -1};
        for (std::size_t p = 0; p < element.properties.size(); ++p) {
            const auto& prop = element.properties[p];
            if (isPositionName(prop.name) && !prop.isList)
                axis[prop.name[0] - 'x'] = static_cast<int>(p);
            else if (!prop.isList && isLabelType(prop.type))
                mesh.vertexLabels[prop.name].reserve(static_cast<std::size_t>(element.count));
        }
        if (axis[0] < 0 || axis[1] < 0 || axis[2] < 0)
            return lineError(path, element.line, "the vertex element has no x, y and z properties");
        mesh.points.resize(static_cast<std::size_t>(element.count));
        for (std::int64_t v = 0; v < element.count; ++v) {
            for (std::size_t p = 0; p < element.properties.size(); ++p) {
                const auto& prop = element.properties[p];
                if (prop.isList) {
                    if (!skipList(prop))
                        return bodyError("vertex", v);
                    continue;
                }
                double value = 0.0;
                if (!body.value(prop.type, value, "vertex property"))
                    return bodyError("vertex", v);
                if (static_cast<int>(p) == axis[0] || static_cast<int>(p) == axis[1] || static_cast<int>(p) == axis[2])
                    mesh.points[static_cast<std::size_t>(v)][prop.name[0] - 'x'] = value;
                else if (isLabelType(prop.type))
                    mesh.vertexLabels[prop.name].push_back(static_cast<std::int32_t>(value));
            }
        }
        vertexCount = element.count;
        return {};
    }

    bool skipList(const PlyProperty& prop) {
        double count = 0.0;
        if (!body.value(prop.countType, count, "list count"))
            return false;
        if (count < 0)
            return body.fail("negative list count");
        for (double k = 0; k < count; ++k) {
            double ignored = 0.0;
            if (!body.value(prop.type, ignored, "list item"))
                return false;
        }
        return true;
    }

    Status readFaces(const PlyElement& element) {
        if (vertexCount < 0)
            return lineError(path, element.line, "the face element comes before the vertex element");
        int indexProperty = -1;
        for (std::size_t p = 0; p < element.properties.size(); ++p) {
            const auto& prop = element.properties[p];
            if (prop.isList && (prop.name == "vertex_indices" || prop.name == "vertex_index") && indexProperty < 0 &&
                !isFloatType(prop.type))
                indexProperty = static_cast<int>(p);
            else if (!prop.isList && isLabelType(prop.type))
                mesh.faceLabels[prop.name];
        }
        if (indexProperty < 0)
            return lineError(path, element.line, "the face element has no integer list 'vertex_indices'");
        mesh.triangles.reserve(static_cast<std::size_t>(element.count));
        std::vector<std::int32_t> corners;
        std::vector<std::pair<std::vector<std::int32_t>*, std::int32_t>> labelValues;
        for (std::int64_t f = 0; f < element.count; ++f) {
            const std::size_t before = mesh.triangles.size();
            labelValues.clear();
            for (std::size_t p = 0; p < element.properties.size(); ++p) {
                const auto& prop = element.properties[p];
                if (static_cast<int>(p) == indexProperty) {
                    if (!readCorners(prop, corners))
                        return bodyError("face", f);
                    continue;
                }
                if (prop.isList) {
                    if (!skipList(prop))
                        return bodyError("face", f);
                    continue;
                }
                double value = 0.0;
                if (!body.value(prop.type, value, "face property"))
                    return bodyError("face", f);
                if (isLabelType(prop.type))
                    labelValues.emplace_back(&mesh.faceLabels[prop.name], static_cast<std::int32_t>(value));
            }
            if (!appendFan(mesh, corners.data(), corners.size(), cellLimit(limits)))
                return fileError(ErrorCode::LimitExceeded, path,
                                 "more than " + std::to_string(cellLimit(limits)) + " triangles");
            // Every triangle of a split polygon carries the polygon's labels.
            for (const auto& [values, value] : labelValues)
                values->insert(values->end(), mesh.triangles.size() - before, value);
        }
        return {};
    }

    bool readCorners(const PlyProperty& prop, std::vector<std::int32_t>& corners) {
        double count = 0.0;
        if (!body.value(prop.countType, count, "face corner count"))
            return false;
        if (count < 3 || count > static_cast<double>(vertexCount))
            return body.fail("face has " + std::to_string(static_cast<std::int64_t>(count)) + " corners, allowed 3.." +
                             std::to_string(vertexCount));
        corners.clear();
        for (double k = 0; k < count; ++k) {
            double index = 0.0;
            if (!body.value(prop.type, index, "vertex index"))
                return false;
            if (index < 0 || index >= static_cast<double>(vertexCount))
                return body.fail("vertex index " + std::to_string(static_cast<std::int64_t>(index)) +
                                 " out of range 0.." + std::to_string(vertexCount - 1));
            corners.push_back(static_cast<std::int32_t>(index));
        }
        return true;
    }
};

} // namespace

Result<SurfaceMesh> readPly(const std::string& path, const ReadLimits& limits) {
    Result<std::string> bytes = readInput(path, limits);
    if (!bytes.ok())
        return bytes.failure();
    const std::string_view text = *bytes;
    Result<PlyHeader> header = parseHeader(path, text, limits);
    if (!header.ok())
        return header.failure();

    // Before anything is allocated: can the body hold what the header declares?
    const bool binary = header->encoding != PlyEncoding::Ascii;
    std::int64_t bodyBytes = static_cast<std::int64_t>(text.size() - header->bodyOffset);
    for (const auto& element : header->elements) {
        HS_TRY(checkCount(path, element.line, element.count,
                          element.name == "vertex" ? pointLimit(limits) : cellLimit(limits), bodyBytes,
                          std::max<std::int64_t>(element.minBytes(binary), 1), (element.name + " elements").c_str()));
        bodyBytes -= element.count * element.minBytes(binary);
    }

    PlyReader reader{path, limits, *header, PlyBody(path, text, *header), {}, -1};
    reader.body.setLineOffset(header->bodyLine - 1);
    for (const auto& element : header->elements) {
        Status status;
        if (element.name == "vertex")
            status = reader.readVertices(element);
        else if (element.name == "face")
            status = reader.readFaces(element);
        else
            status = [&]() -> Status {
                for (std::int64_t i = 0; i < element.count; ++i)
                    for (const auto& prop : element.properties) {
                        double ignored = 0.0;
                        if (prop.isList ? !reader.skipList(prop) : !reader.body.value(prop.type, ignored, "value"))
                            return reader.bodyError(element.name, i);
                    }
                return {};
            }();
        if (!status.ok())
            return status.failure();
    }
    HS_TRY(finishSurface(path, reader.mesh));
    return std::move(reader.mesh);
}

namespace {

void appendBinary(std::string& out, const void* data, std::size_t size) {
    out.append(static_cast<const char*>(data), size); // little-endian hosts only (checked in writePly)
}

} // namespace

Status writePly(const SurfaceMesh& mesh, const std::string& tmpPath, bool binary) {
    static_assert(sizeof(double) == 8 && sizeof(std::int32_t) == 4, "PLY writer assumes IEEE doubles");
    const std::uint16_t probe = 1;
    unsigned char firstByte = 0;
    std::memcpy(&firstByte, &probe, 1);
    if (binary && firstByte != 1)
        return fail(ErrorCode::Unsupported, tmpPath + ": binary PLY writing needs a little-endian host");

    std::string out = "ply\nformat ";
    out += binary ? "binary_little_endian 1.0\n" : "ascii 1.0\n";
    out += "comment hysteroscene\nelement vertex " + std::to_string(mesh.points.size()) +
           "\nproperty double x\nproperty double y\nproperty double z\n";
    std::vector<const std::vector<std::int32_t>*> vertexLabels, faceLabels;
    for (const auto& [name, values] : mesh.vertexLabels) {
        if (values.empty())
            continue;
        if (isPositionName(name))
            return fail(ErrorCode::InvalidInput, tmpPath + ": vertex label '" + name + "' clashes with a coordinate");
        out += "property int " + name + "\n";
        vertexLabels.push_back(&values);
    }
    out += "element face " + std::to_string(mesh.triangles.size()) + "\nproperty list uchar int vertex_indices\n";
    for (const auto& [name, values] : mesh.faceLabels) {
        if (values.empty())
            continue;
        if (name == "vertex_indices")
            return fail(ErrorCode::InvalidInput, tmpPath + ": face label 'vertex_indices' clashes with the corners");
        out += "property int " + name + "\n";
        faceLabels.push_back(&values);
    }
    out += "end_header\n";

    for (std::size_t v = 0; v < mesh.points.size(); ++v) {
        const Vec3& p = mesh.points[v];
        if (binary) {
            appendBinary(out, &p.x, 8);
            appendBinary(out, &p.y, 8);
            appendBinary(out, &p.z, 8);
            for (const auto* values : vertexLabels)
                appendBinary(out, &(*values)[v], 4);
        } else {
            out += formatDouble(p.x) + " " + formatDouble(p.y) + " " + formatDouble(p.z);
            for (const auto* values : vertexLabels)
                out += " " + std::to_string((*values)[v]);
            out += "\n";
        }
    }
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const Triangle& t = mesh.triangles[f];
        if (binary) {
            const unsigned char three = 3;
            appendBinary(out, &three, 1);
            appendBinary(out, t.data(), 12);
            for (const auto* values : faceLabels)
                appendBinary(out, &(*values)[f], 4);
        } else {
            out += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]);
            for (const auto* values : faceLabels)
                out += " " + std::to_string((*values)[f]);
            out += "\n";
        }
    }
    return writePlainFile(tmpPath, out);
}

} // namespace hs::io::detail
