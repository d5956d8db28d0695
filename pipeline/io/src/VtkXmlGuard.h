#pragma once
/// The guard every VTK XML file passes before VTK's readers see it (VTK sizes allocations by counts in the file).

#include "hs/core/Result.h"
#include "hs/io/MeshIO.h"

#include <string>
#include <string_view>

namespace hs::io::detail {

/// Checks `text`, the whole file `path` of VTK XML type `dataType` ("PolyData" or "UnstructuredGrid"): the root
/// element and type, VTK's own markup form, every count against `limits` and the file size (8000:1 when
/// compressed), the appended arrays' headers, ASCII arrays, cell types and connectivity offsets. InvalidInput or
/// LimitExceeded naming the file and the field.
Status guardVtkXml(const std::string& path, std::string_view text, const char* dataType, const ReadLimits& limits);

} // namespace hs::io::detail
