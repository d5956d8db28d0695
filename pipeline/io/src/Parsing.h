#pragma once
/// Shared helpers of the hand-written readers and writers: a tokenizer that tracks line numbers, strict number
/// parsing, count checks against ReadLimits and the file size, and locale-independent number formatting.

#include "hs/core/Result.h"
#include "hs/core/SurfaceMesh.h"
#include "hs/core/TetMesh.h"
#include "hs/io/MeshIO.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace hs::io::detail {

/// "path: what"
Failure fileError(ErrorCode code, const std::string& path, const std::string& what);
/// "path: line N: what" (InvalidInput)
Failure lineError(const std::string& path, std::size_t line, const std::string& what);

/// Reads a whole file within limits.maxFileBytes; the error names the path.
Result<std::string> readInput(const std::string& path, const ReadLimits& limits);

/// Strict parsers: the whole token must be a number. Accept a leading '+'.
bool parseDouble(std::string_view token, double& out);
bool parseInt(std::string_view token, std::int64_t& out);

/// Shortest text that reads back to the same double ("0.1", "1e-300"), independent of the locale.
std::string formatDouble(double value);

/// Checks a count read from a header before anything is allocated for it: not negative, at most `limit`
/// (LimitExceeded), and not more elements than `bytesLeft` can hold at `minBytesEach` bytes each (InvalidInput).
Status checkCount(const std::string& path, std::size_t line, std::int64_t count, std::int64_t limit,
                  std::int64_t bytesLeft, std::int64_t minBytesEach, const char* what);

/// The largest point count a mesh may have: the limit, and what an int32 index can address.
std::int64_t pointLimit(const ReadLimits& limits);
std::int64_t cellLimit(const ReadLimits& limits);

/// Whitespace-separated tokens with line numbers. A comment character (0 for none) skips to the end of the line.
/// Errors are kept in the reader: a false return means `failure()` describes the problem with the line number.
class TokenReader {
public:
    TokenReader(std::string path, std::string_view text, char comment);

    /// The next token; false (with an "unexpected end of file" error naming `what`) at the end.
    bool word(std::string_view& out, const char* what);
    /// A finite number.
    bool real(double& out, const char* what);
    /// An integer.
    bool integer(std::int64_t& out, const char* what);
    /// An integer in [lo, hi].
    bool integerIn(std::int64_t& out, std::int64_t lo, std::int64_t hi, const char* what);
    /// Three finite numbers.
    bool point(Vec3& out, const char* what);

    /// Skips what is left of the current line (for optional trailing values such as colours).
    void skipLine();
    /// True when only whitespace and comments remain.
    bool atEnd();
    /// Line of the last token read (1-based).
    std::size_t line() const { return m_tokenLine; }
    std::int64_t bytesLeft() const { return static_cast<std::int64_t>(m_text.size() - m_pos); }
    std::size_t offset() const { return m_pos; }
    const std::string& path() const { return m_path; }

    /// Records an error at the current line; always returns false, for `return in.error("...")`.
    bool error(const std::string& what);
    Failure failure() const;
    /// The recorded problem without path and line.
    const std::string& message() const { return m_error; }

private:
    void skipSpace();

    std::string m_path;
    std::string_view m_text;
    char m_comment;
    std::size_t m_pos = 0;
    std::size_t m_line = 1;
    std::size_t m_tokenLine = 1;
    std::string m_error;
};

/// Final checks of a parsed surface: at least one triangle, and hs::validate; errors are prefixed with the path.
Status finishSurface(const std::string& path, const SurfaceMesh& mesh);
Status finishTetMesh(const std::string& path, const TetMesh& mesh);

/// Checks a mesh before it is written: valid, not empty, label names that every format can store.
Status checkWritable(const SurfaceMesh& mesh, const std::string& path);
Status checkWritable(const TetMesh& mesh, const std::string& path);

/// Appends triangles of a polygon (fan from its first corner) to `mesh`; InvalidInput beyond the cell limit.
/// 1 to 64 characters from A-Z a-z 0-9 _ - . (label and array names that every format can hold).
bool isPortableName(const std::string& name);

bool appendFan(SurfaceMesh& mesh, const std::int32_t* corners, std::size_t count, std::int64_t maxCells);

} // namespace hs::io::detail

namespace hs::io::detail {
/// Writes `bytes` to `path` (a temporary file of writeAtomically).
Status writePlainFile(const std::string& path, const std::string& bytes);
} // namespace hs::io::detail
