#pragma once
/// Writing files so that readers never see a half-written one.

#include "hs/core/Result.h"

#include <cstdint>
#include <functional>
#include <string>

namespace hs::io {

/// Calls `write(tmpPath)` to write into a temporary file next to `path`, then renames it over `path`.
/// On failure the temporary file is removed and `path` is left as it was.
Status writeAtomically(const std::string& path, const std::function<Status(const std::string& tmpPath)>& write);

/// Writes `bytes` to `path` atomically.
Status writeFileAtomically(const std::string& path, const std::string& bytes);

/// Reads a whole file up to `maxBytes`; LimitExceeded beyond, NotFound/IoError with the path otherwise.
Result<std::string> readFile(const std::string& path, std::int64_t maxBytes);

} // namespace hs::io
