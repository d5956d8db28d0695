// The guard a VTK XML file passes before VTK reads it: every count attribute of its XML part is checked against the
// limits and against what the file size can hold, so a forged header cannot make VTK allocate gigabytes, and the
// markup, appended-data headers, ASCII arrays, cell types and offsets that VTK 9.1 would misread or leak on are
// refused by name first.
#include "VtkXmlGuard.h"

#include "Parsing.h"

#include <cctype>
#include <cstdint>
#include <limits>
#include <string>

namespace hs::io::detail {
namespace {

/// Sum of every `name="N"` attribute in the XML part; InvalidInput when one is not a non-negative integer.
Result<std::int64_t> sumAttribute(const std::string& path, std::string_view xml, const std::string& name) {
    const std::string needle = " " + name + "=\"";
    std::int64_t sum = 0;
    for (std::size_t pos = xml.find(needle); pos != std::string_view::npos; pos = xml.find(needle, pos + 1)) {
        const std::size_t start = pos + needle.size();
        const std::size_t end = xml.find('"', start);
        std::int64_t value = 0;
        if (end == std::string_view::npos || !parseInt(xml.substr(start, end - start), value) || value < 0)
            return fileError(ErrorCode::InvalidInput, path, "attribute " + name + " is not a non-negative integer");
        if (value > std::numeric_limits<std::int64_t>::max() / 4 - sum)
            return fileError(ErrorCode::LimitExceeded, path, "attribute " + name + " is absurdly large");
        sum += value;
    }
    return sum;
}

/// The value of attribute `name` in the tag text `tag`, or empty.
std::string_view attribute(std::string_view tag, std::string_view name) {
    const std::string needle = " " + std::string(name) + "=\"";
    const std::size_t at = tag.find(needle);
    if (at == std::string_view::npos)
        return {};
    const std::size_t start = at + needle.size();
    const std::size_t end = tag.find('"', start);
    return end == std::string_view::npos ? std::string_view{} : tag.substr(start, end - start);
}

/// The coordinates of every piece (the first DataArray inside <Points>) must have 3 components. VTK 9.1 refuses
/// other counts too, but leaks the array it read on that path, so such files never reach it.
Status checkPointsArrays(const std::string& path, std::string_view xml) {
    for (std::size_t pos = xml.find("<Points"); pos != std::string_view::npos; pos = xml.find("<Points", pos + 1)) {
        const std::size_t array = xml.find("<DataArray", pos);
        const std::size_t arrayEnd = array == std::string_view::npos ? array : xml.find('>', array);
        if (arrayEnd == std::string_view::npos)
            return fileError(ErrorCode::InvalidInput, path, "a <Points> element without a DataArray");
        if (attribute(xml.substr(array, arrayEnd - array), "NumberOfComponents") != "3")
            return fileError(ErrorCode::InvalidInput, path,
                             "the Points DataArray must have NumberOfComponents=\"3\" (x, y, z)");
    }
    return {};
}

/// The guard finds attributes as ` name="value"` (as VTK writes them). An XML parser also reads `name = 'value'`,
/// attributes after tabs or line breaks, entities and DOCTYPE declarations; where the guard and VTK would read a tag
/// differently, the guard would check other counts than VTK allocates by. So the markup before the appended data must
/// be in VTK's own form: every start tag's attributes `name="value"` after spaces, no entity or DOCTYPE, comments only.
Status checkMarkup(const std::string& path, std::string_view xml) {
    if (xml.find('&') != std::string_view::npos)
        return fileError(ErrorCode::InvalidInput, path, "the XML part holds an entity reference ('&'), not read");
    const auto nameChar = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':' || c == '.' || c == '-';
    };
    const auto bad = [&](std::size_t at) {
        return fileError(ErrorCode::InvalidInput, path,
                         "the tag at byte " + std::to_string(at) +
                             " is not written as VTK writes tags (attributes name=\"value\", separated by spaces)");
    };
    for (std::size_t i = xml.find('<'); i != std::string_view::npos; i = xml.find('<', i + 1)) {
        if (xml.compare(i, 4, "<!--") == 0) {
            const std::size_t end = xml.find("-->", i + 4);
            if (end == std::string_view::npos)
                return bad(i);
            i = end + 2;
            continue;
        }
        if (i + 1 < xml.size() && xml[i + 1] == '!')
            return fileError(ErrorCode::InvalidInput, path,
                             "the XML part holds a declaration (<!DOCTYPE, <![CDATA[), not read");
        if (i + 1 < xml.size() && (xml[i + 1] == '?' || xml[i + 1] == '/'))
            continue; // the XML declaration, end tags
        std::size_t j = i + 1;
        while (j < xml.size() && nameChar(xml[j]))
            ++j;
        if (j == i + 1)
            return bad(i);
        for (;;) {
            if (j >= xml.size())
                return bad(i);
            if (xml[j] == '>' || xml.compare(j, 2, "/>") == 0)
                break;
            if (xml[j] != ' ')
                return bad(i);
            while (j < xml.size() && xml[j] == ' ')
                ++j;
            if (j < xml.size() && (xml[j] == '>' || xml[j] == '/'))
                continue;
            const std::size_t name = j;
            while (j < xml.size() && nameChar(xml[j]))
                ++j;
            if (j == name || xml.compare(j, 2, "=\"") != 0)
                return bad(i);
            const std::size_t close = xml.find('"', j + 2);
            if (close == std::string_view::npos)
                return bad(i);
            j = close + 1;
        }
        i = j;
    }
    return {};
}

Status precheckXml(const std::string& path, std::string_view text, const char* dataType, const ReadLimits& limits) {
    const std::size_t root = text.find("<VTKFile");
    std::size_t lead = 0;
    while (lead < text.size() && (text[lead] == ' ' || text[lead] == '\n' || text[lead] == '\r' || text[lead] == '\t'))
        ++lead;
    if (root == std::string_view::npos || (text.compare(lead, 5, "<?xml") != 0 && lead != root))
        return fileError(ErrorCode::InvalidInput, path, "not a VTK XML file (no <VTKFile> element at the start)");
    const std::size_t rootEnd = text.find('>', root);
    const std::string_view rootTag = text.substr(root, rootEnd == std::string_view::npos ? 0 : rootEnd - root);
    if (rootTag.find(std::string("type=\"") + dataType + "\"") == std::string_view::npos)
        return fileError(ErrorCode::InvalidInput, path, std::string("not a VTK ") + dataType + " file");

    // Counts live in the XML part; appended binary data follows it.
    const std::size_t appendedTag = text.find("<AppendedData");
    const std::string_view xml = text.substr(0, appendedTag);
    HS_TRY(checkMarkup(path, xml));
    if (appendedTag != std::string_view::npos)
        HS_TRY(checkMarkup(path, text.substr(appendedTag, text.find('>', appendedTag) + 1 - appendedTag)));
    // Compressed data can expand; zlib and lz4 stay below ~1000:1, lzma below ~8000:1.
    const bool compressed = rootTag.find("compressor=") != std::string_view::npos;
    const std::int64_t capacity = static_cast<std::int64_t>(text.size()) * (compressed ? 8000 : 1);

    const auto points = sumAttribute(path, xml, "NumberOfPoints");
    if (!points.ok())
        return points.failure();
    HS_TRY(checkCount(path, 1, *points, pointLimit(limits), capacity, 3, "points (NumberOfPoints)"));
    for (const char* cells : {"NumberOfCells", "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys"}) {
        const auto count = sumAttribute(path, xml, cells);
        if (!count.ok())
            return count.failure();
        HS_TRY(checkCount(path, 1, *count, cellLimit(limits), capacity, 1, cells));
    }
    const auto tuples = sumAttribute(path, xml, "NumberOfTuples");
    if (!tuples.ok())
        return tuples.failure();
    HS_TRY(checkCount(path, 1, *tuples, pointLimit(limits) + cellLimit(limits), capacity, 1, "tuples"));
    // NumberOfComponents is per array: check each, not the sum.
    const std::string needle = " NumberOfComponents=\"";
    for (std::size_t pos = xml.find(needle); pos != std::string_view::npos; pos = xml.find(needle, pos + 1)) {
        const std::size_t start = pos + needle.size();
        const std::size_t end = xml.find('"', start);
        std::int64_t value = 0;
        if (end == std::string_view::npos || !parseInt(xml.substr(start, end - start), value) || value < 0 ||
            value > 64)
            return fileError(ErrorCode::InvalidInput, path, "NumberOfComponents outside 0..64");
    }
    return checkPointsArrays(path, xml);
}

/// Bytes per value of a VTK XML integer type name, 0 for other types.
std::size_t integerTypeSize(std::string_view type) {
    if (type == "Int8" || type == "UInt8")
        return 1;
    if (type == "Int16" || type == "UInt16")
        return 2;
    if (type == "Int32" || type == "UInt32")
        return 4;
    if (type == "Int64" || type == "UInt64")
        return 8;
    return 0;
}

/// Little-endian integer of `size` bytes (signed types: negative values come out huge and fail the bound).
std::uint64_t loadLittleEndian(const char* data, std::size_t size) {
    std::uint64_t value = 0;
    for (std::size_t k = 0; k < size; ++k)
        value |= static_cast<std::uint64_t>(static_cast<unsigned char>(data[k])) << (8 * k);
    return value;
}

/// The size header of an appended array, read before VTK allocates by it: every appended array needs a valid
/// offset (VTK 9.1 leaks the arrays of a piece it fails to read), raw uncompressed data may not be longer than the
/// rest of the file, and compressed data (a header of block count, block size, last block size and one compressed
/// size per block) may not have more blocks than the file holds nor inflate beyond `capacity`.
Status checkAppendedHeader(const std::string& path, std::string_view text, std::string_view tag,
                           std::size_t appendedStart, bool rawAppended, std::size_t headerSize, bool bigEndian,
                           bool compressed, std::int64_t capacity) {
    std::int64_t offset = 0;
    if (appendedStart == std::string_view::npos || !parseInt(attribute(tag, "offset"), offset) || offset < 0)
        return fileError(ErrorCode::InvalidInput, path, "an appended array has no valid offset (or no AppendedData)");
    if (!rawAppended)
        return {}; // base64 appended data: VTK decodes it in bounded blocks
    const std::size_t start = appendedStart + static_cast<std::size_t>(offset);
    if (start > text.size() || text.size() - start < headerSize)
        return fileError(ErrorCode::InvalidInput, path, "an appended array lies beyond the end of the file");
    const std::size_t rest = text.size() - start - headerSize;
    auto load = [&](std::size_t index) {
        std::uint64_t value = 0;
        const char* data = text.data() + start + index * headerSize;
        for (std::size_t k = 0; k < headerSize; ++k) {
            const auto byte = static_cast<std::uint64_t>(static_cast<unsigned char>(data[k]));
            value |= byte << (8 * (bigEndian ? headerSize - 1 - k : k));
        }
        return value;
    };
    const std::uint64_t first = load(0);
    if (!compressed) {
        if (first > rest)
            return fileError(ErrorCode::InvalidInput, path,
                             "an appended array declares " + std::to_string(first) + " bytes, more than the " +
                                 std::to_string(rest) + " left in the file");
        return {};
    }
    // first = number of blocks; the header holds 2 more sizes and one compressed size per block.
    if (first > rest / headerSize || (first + 2) * headerSize > rest)
        return fileError(ErrorCode::InvalidInput, path,
                         "a compressed appended array declares " + std::to_string(first) +
                             " blocks, more than the file holds");
    const std::uint64_t blockSize = load(1);
    const std::uint64_t lastBlock = load(2);
    const auto limit = static_cast<std::uint64_t>(capacity);
    if (blockSize > limit || lastBlock > blockSize || (first > 1 && blockSize > 0 && first - 1 > limit / blockSize))
        return fileError(ErrorCode::InvalidInput, path,
                         "a compressed appended array declares more data than the file can hold when inflated");
    return {};
}

/// The innermost of the sections a data array can stand in that is open at `pos` ("" for none).
std::string_view sectionAt(std::string_view xml, std::size_t pos) {
    std::string_view best;
    std::size_t bestOpen = 0;
    for (const std::string_view name :
         {"PointData", "CellData", "Points", "Cells", "Verts", "Lines", "Strips", "Polys"}) {
        const std::string open = "<" + std::string(name), close = "</" + std::string(name);
        std::size_t at = xml.rfind(open, pos);
        // "<Points" must not match "<PointsX": the name ends the tag's name.
        while (at != std::string_view::npos && at + open.size() < xml.size() &&
               std::isalnum(static_cast<unsigned char>(xml[at + open.size()])))
            at = at == 0 ? std::string_view::npos : xml.rfind(open, at - 1);
        if (at == std::string_view::npos)
            continue;
        const std::size_t closed = xml.rfind(close, pos);
        if ((closed == std::string_view::npos || closed < at) && (best.empty() || at > bestOpen)) {
            best = name;
            bestOpen = at;
        }
    }
    return best;
}

/// An ASCII data array: every value a number (an integer for integer types, a cell type 0-255 for "types"), and at
/// least as many as its piece needs (points or cells times components, one offset or type per cell). VTK 9.1 fails
/// on fewer or unreadable values, and on some of those paths leaks the piece's arrays or reads through a null
/// pointer (vtkXMLDataReader::ReadPieceData on an unreadable cell data value).
Status checkAsciiArray(const std::string& path, std::string_view xml, std::size_t pos, std::string_view tag,
                       std::size_t tagEnd) {
    const std::size_t piece = xml.rfind("<Piece", pos);
    const std::string_view pieceTag =
        piece == std::string_view::npos ? std::string_view() : xml.substr(piece, xml.find('>', piece) - piece);
    const auto count = [&](std::string_view name) {
        std::int64_t n = 0;
        return parseInt(attribute(pieceTag, name), n) && n > 0 ? n : std::int64_t{0};
    };
    const std::int64_t points = count("NumberOfPoints");
    const std::int64_t verts = count("NumberOfVerts"), lines = count("NumberOfLines"), strips = count("NumberOfStrips"),
                       polys = count("NumberOfPolys");
    const std::int64_t cells = count("NumberOfCells") + verts + lines + strips + polys;
    std::int64_t components = 1;
    if (!parseInt(attribute(tag, "NumberOfComponents"), components) || components < 1)
        components = 1;
    const std::string_view section = sectionAt(xml, pos);
    const std::string_view name = attribute(tag, "Name");
    std::int64_t needed = 0;
    if (section == "Points" || section == "PointData")
        needed = points * components;
    else if (section == "CellData")
        needed = cells * components;
    else if (name == "types")
        needed = cells;
    else if (name == "offsets")
        needed = section == "Verts"    ? verts
                 : section == "Lines"  ? lines
                 : section == "Strips" ? strips
                 : section == "Polys"  ? polys
                                       : cells;
    const bool integer = integerTypeSize(attribute(tag, "type")) != 0;
    // The values are the element's text up to its end or its first child (VTK writes InformationKey elements after
    // the values of a points array).
    const std::size_t end = xml.find('<', tagEnd + 1);
    TokenReader values(path, xml.substr(tagEnd + 1, end == std::string_view::npos ? 0 : end - tagEnd - 1), 0);
    const std::string what = "the ASCII array \"" + std::string(name) + "\"";
    std::int64_t read = 0;
    while (!values.atEnd()) {
        std::int64_t n = 0;
        double x = 0.0;
        const bool ok = name == "types" ? values.integerIn(n, 0, 255, "cell type")
                        : integer       ? values.integer(n, "value")
                                        : values.real(x, "value");
        if (!ok)
            return fileError(ErrorCode::InvalidInput, path,
                             what + " holds a value that is not " +
                                 (name == "types" ? "a cell type (0-255)"
                                  : integer       ? "an integer"
                                                  : "a finite number"));
        ++read;
    }
    if (read < needed)
        return fileError(ErrorCode::InvalidInput, path,
                         what + " has " + std::to_string(read) + " values; its piece needs " + std::to_string(needed));
    return {};
}

/// The cell types array of an unstructured grid's piece. VTK 9.1 leaks it when it cannot use it (another type than
/// UInt8, fewer values than cells), so those are refused before VTK reads it: its type, its components, and for raw
/// appended data the byte count its header declares (uncompressed, or the blocks' sizes when compressed).
Status checkCellTypesArray(const std::string& path, std::string_view text, std::string_view xml, std::size_t pos,
                           std::string_view tag, std::size_t appendedStart, bool rawAppended, std::size_t headerSize,
                           bool bigEndian, bool compressed) {
    const std::string_view components = attribute(tag, "NumberOfComponents");
    if (attribute(tag, "type") != "UInt8" || !(components.empty() || components == "1"))
        return fileError(ErrorCode::InvalidInput, path,
                         "the cell types array must be UInt8 with one component (it is " +
                             std::string(attribute(tag, "type")) + ")");
    if (attribute(tag, "format") != "appended" || !rawAppended || appendedStart == std::string_view::npos)
        return {};
    const std::size_t piece = xml.rfind("<Piece", pos);
    std::int64_t cells = 0;
    if (piece == std::string_view::npos ||
        !parseInt(attribute(xml.substr(piece, xml.find('>', piece) - piece), "NumberOfCells"), cells) || cells < 0)
        return {};
    std::int64_t offset = 0;
    if (!parseInt(attribute(tag, "offset"), offset) || offset < 0)
        return {};
    const std::size_t start = appendedStart + static_cast<std::size_t>(offset);
    if (start > text.size() || text.size() - start < 3 * headerSize)
        return {}; // checkAppendedHeader names it
    auto load = [&](std::size_t index) {
        std::uint64_t value = 0;
        for (std::size_t k = 0; k < headerSize; ++k) {
            const auto byte =
                static_cast<std::uint64_t>(static_cast<unsigned char>(text[start + index * headerSize + k]));
            value |= byte << (8 * (bigEndian ? headerSize - 1 - k : k));
        }
        return value;
    };
    std::uint64_t bytes = load(0);
    if (compressed) {
        const std::uint64_t blocks = bytes, blockSize = load(1), lastBlock = load(2);
        bytes = blocks == 0 ? 0 : (blocks - 1) * blockSize + (lastBlock == 0 ? blockSize : lastBlock);
    }
    if (bytes < static_cast<std::uint64_t>(cells))
        return fileError(ErrorCode::InvalidInput, path,
                         "the cell types array holds " + std::to_string(bytes) + " values; its piece has " +
                             std::to_string(cells) + " cells");
    return {};
}

/// VTK sizes each connectivity array by the last value of its "offsets" array, which is data, not a header
/// attribute. Checks every offset of uncompressed ASCII and raw appended offsets arrays against what the file can
/// hold (one byte per connectivity entry at least); compressed or base64 data is left to VTK and the limits.
Status checkOffsetsArrays(const std::string& path, std::string_view text, std::string_view xml, std::int64_t capacity,
                          bool compressed) {
    const std::size_t rootStart = text.find("<VTKFile");
    const std::string_view root = text.substr(rootStart, text.find('>', rootStart) - rootStart);
    const std::size_t headerSize = attribute(root, "header_type") == "UInt64" ? 8 : 4;
    const bool bigEndian = attribute(root, "byte_order") == "BigEndian";
    const std::size_t appendedTag = text.find("<AppendedData");
    std::size_t appendedStart = std::string_view::npos;
    bool rawAppended = false;
    if (appendedTag != std::string_view::npos) {
        const std::size_t tagEnd = text.find('>', appendedTag);
        rawAppended = attribute(text.substr(appendedTag, tagEnd - appendedTag), "encoding") == "raw";
        // Where VTK starts the appended data (vtkXMLDataParser::FindAppendedDataPosition): after the tag's '>' and
        // any white space (isspace), past a '_'. Anything else there would make VTK read every array from another
        // place than this guard checks.
        std::size_t at = tagEnd == std::string_view::npos ? text.size() : tagEnd + 1;
        while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at])))
            ++at;
        if (at >= text.size() || text[at] != '_')
            return fileError(ErrorCode::InvalidInput, path,
                             "the appended data does not begin with '_' after the <AppendedData> tag");
        appendedStart = at + 1;
    }
    auto tooLarge = [&](std::uint64_t value) { return value > static_cast<std::uint64_t>(capacity); };
    const Failure bad = fileError(ErrorCode::InvalidInput, path,
                                  "an \"offsets\" array declares more cell corners than the file can hold");

    for (std::size_t pos = xml.find("<DataArray"); pos != std::string_view::npos;
         pos = xml.find("<DataArray", pos + 1)) {
        const std::size_t tagEnd = xml.find('>', pos);
        if (tagEnd == std::string_view::npos)
            break;
        const std::string_view tag = xml.substr(pos, tagEnd - pos);
        // VTK reads an array from the appended data when it has an offset attribute, whatever its format says, and
        // inline as ASCII unless the format is "binary": the two must agree for the checks below to be VTK's reading.
        const std::string_view arrayFormat = attribute(tag, "format");
        const bool hasOffset = tag.find(" offset=\"") != std::string_view::npos;
        if (hasOffset != (arrayFormat == "appended") ||
            (arrayFormat != "appended" && arrayFormat != "ascii" && arrayFormat != "binary"))
            return fileError(ErrorCode::InvalidInput, path,
                             "a DataArray's format is \"" + std::string(arrayFormat) +
                                 "\"; allowed: ascii, binary, or appended with an offset");
        if (attribute(tag, "format") == "appended")
            HS_TRY(checkAppendedHeader(path, text, tag, appendedStart, rawAppended, headerSize, bigEndian, compressed,
                                       capacity));
        if (attribute(tag, "format") == "ascii")
            HS_TRY(checkAsciiArray(path, xml, pos, tag, tagEnd));
        if (attribute(tag, "Name") == "types" && sectionAt(xml, pos) == "Cells")
            HS_TRY(checkCellTypesArray(path, text, xml, pos, tag, appendedStart, rawAppended, headerSize, bigEndian,
                                       compressed));
        if (attribute(tag, "Name") != "offsets")
            continue;
        const std::size_t valueSize = integerTypeSize(attribute(tag, "type"));
        if (valueSize == 0)
            return fileError(ErrorCode::InvalidInput, path, "an \"offsets\" array is not of an integer type");
        const std::string_view format = attribute(tag, "format");
        if (format == "ascii") {
            const std::size_t end = xml.find("</DataArray>", tagEnd);
            TokenReader values(path, xml.substr(tagEnd + 1, end == std::string_view::npos ? 0 : end - tagEnd - 1), 0);
            std::int64_t value = 0;
            while (!values.atEnd()) {
                if (!values.integer(value, "offset") || value < 0 || tooLarge(static_cast<std::uint64_t>(value)))
                    return bad;
            }
        } else if (format == "appended" && rawAppended && !compressed && !bigEndian &&
                   appendedStart != std::string_view::npos) {
            std::int64_t offset = 0;
            if (!parseInt(attribute(tag, "offset"), offset) || offset < 0)
                return fileError(ErrorCode::InvalidInput, path, "an appended array has no valid offset");
            const std::size_t start = appendedStart + static_cast<std::size_t>(offset);
            if (start > text.size() || text.size() - start < headerSize)
                return fileError(ErrorCode::InvalidInput, path, "an appended array lies beyond the end of the file");
            const std::uint64_t bytes = loadLittleEndian(text.data() + start, headerSize);
            if (bytes > text.size() - start - headerSize)
                return fileError(ErrorCode::InvalidInput, path,
                                 "an appended array is longer than the rest of the file (truncated?)");
            for (std::size_t k = 0; k + valueSize <= bytes; k += valueSize)
                if (tooLarge(loadLittleEndian(text.data() + start + headerSize + k, valueSize)))
                    return bad;
        }
    }
    return {};
}

} // namespace

Status guardVtkXml(const std::string& path, std::string_view text, const char* dataType, const ReadLimits& limits) {
    HS_TRY(precheckXml(path, text, dataType, limits));
    const std::size_t root = text.find("<VTKFile");
    const bool compressed =
        text.substr(root, text.find('>', root) - root).find("compressor=") != std::string_view::npos;
    return checkOffsetsArrays(path, text, text.substr(0, text.find("<AppendedData")),
                              static_cast<std::int64_t>(text.size()) * (compressed ? 8000 : 1), compressed);
}

} // namespace hs::io::detail
