#include "Parsing.h"

#include "hs/io/AtomicFile.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace hs::io::detail {

Failure fileError(ErrorCode code, const std::string& path, const std::string& what) {
    return fail(code, path + ": " + what);
}

Failure lineError(const std::string& path, std::size_t line, const std::string& what) {
    return fail(ErrorCode::InvalidInput, path + ": line " + std::to_string(line) + ": " + what);
}

Result<std::string> readInput(const std::string& path, const ReadLimits& limits) {
    return readFile(path, limits.maxFileBytes);
}

bool parseDouble(std::string_view token, double& out) {
    if (!token.empty() && token.front() == '+')
        token.remove_prefix(1);
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, out);
    if (ec == std::errc::result_out_of_range && ptr == end) {
        // Underflow reads as zero, overflow as infinity (refused later as non-finite), as strtod would.
        const std::size_t e = token.find_first_of("eE");
        const bool tiny = e != std::string_view::npos && e + 1 < token.size() && token[e + 1] == '-';
        const double sign = token.front() == '-' ? -1.0 : 1.0;
        out = tiny ? sign * 0.0 : sign * std::numeric_limits<double>::infinity();
        return true;
    }
    return ec == std::errc() && ptr == end && !token.empty();
}

bool parseInt(std::string_view token, std::int64_t& out) {
    if (!token.empty() && token.front() == '+')
        token.remove_prefix(1);
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, out);
    return ec == std::errc() && ptr == end && !token.empty();
}

std::string formatDouble(double value) {
    char buffer[32];
    const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return ec == std::errc() ? std::string(buffer, ptr) : std::string("nan");
}

Status checkCount(const std::string& path, std::size_t line, std::int64_t count, std::int64_t limit,
                  std::int64_t bytesLeft, std::int64_t minBytesEach, const char* what) {
    if (count < 0)
        return lineError(path, line, "negative " + std::string(what) + " count " + std::to_string(count));
    if (count > limit)
        return fail(ErrorCode::LimitExceeded, path + ": line " + std::to_string(line) + ": " + std::to_string(count) +
                                                  " " + what + ", limit " + std::to_string(limit));
    if (minBytesEach > 0 && count > std::max<std::int64_t>(bytesLeft, 0) / minBytesEach)
        return lineError(path, line,
                         "the header declares " + std::to_string(count) + " " + what + " but the " +
                             std::to_string(std::max<std::int64_t>(bytesLeft, 0)) +
                             " bytes left in the file can hold at most " +
                             std::to_string(std::max<std::int64_t>(bytesLeft, 0) / minBytesEach));
    return {};
}

std::int64_t pointLimit(const ReadLimits& limits) {
    return std::min<std::int64_t>(limits.maxPoints, std::numeric_limits<std::int32_t>::max());
}

std::int64_t cellLimit(const ReadLimits& limits) {
    return std::min<std::int64_t>(limits.maxCells, std::numeric_limits<std::int32_t>::max());
}

TokenReader::TokenReader(std::string path, std::string_view text, char comment)
    : m_path(std::move(path)), m_text(text), m_comment(comment) {}

void TokenReader::skipSpace() {
    while (m_pos < m_text.size()) {
        const char c = m_text[m_pos];
        if (c == '\n') {
            ++m_line;
            ++m_pos;
        } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            ++m_pos;
        } else if (m_comment != 0 && c == m_comment) {
            while (m_pos < m_text.size() && m_text[m_pos] != '\n')
                ++m_pos;
        } else {
            break;
        }
    }
}

bool TokenReader::atEnd() {
    skipSpace();
    return m_pos >= m_text.size();
}

void TokenReader::skipLine() {
    while (m_pos < m_text.size() && m_text[m_pos] != '\n')
        ++m_pos;
}

bool TokenReader::word(std::string_view& out, const char* what) {
    skipSpace();
    m_tokenLine = m_line;
    if (m_pos >= m_text.size())
        return error("unexpected end of file, expected " + std::string(what));
    const std::size_t start = m_pos;
    while (m_pos < m_text.size()) {
        const char c = m_text[m_pos];
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v' ||
            (m_comment != 0 && c == m_comment))
            break;
        ++m_pos;
    }
    out = m_text.substr(start, m_pos - start);
    return true;
}

namespace {
std::string quoted(std::string_view token) {
    constexpr std::size_t kMax = 40;
    std::string text;
    for (char c : token.substr(0, kMax))
        text += (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) ? '?' : c;
    if (token.size() > kMax)
        text += "...";
    return "'" + text + "'";
}
} // namespace

bool TokenReader::real(double& out, const char* what) {
    std::string_view token;
    if (!word(token, what))
        return false;
    if (!parseDouble(token, out))
        return error("expected " + std::string(what) + ", found " + quoted(token));
    if (!std::isfinite(out))
        return error("non-finite " + std::string(what) + " " + quoted(token));
    return true;
}

bool TokenReader::integer(std::int64_t& out, const char* what) {
    std::string_view token;
    if (!word(token, what))
        return false;
    if (!parseInt(token, out))
        return error("expected " + std::string(what) + " (an integer), found " + quoted(token));
    return true;
}

bool TokenReader::integerIn(std::int64_t& out, std::int64_t lo, std::int64_t hi, const char* what) {
    if (!integer(out, what))
        return false;
    if (out < lo || out > hi)
        return error(std::string(what) + " " + std::to_string(out) + " out of range " + std::to_string(lo) + ".." +
                     std::to_string(hi));
    return true;
}

bool TokenReader::point(Vec3& out, const char* what) {
    return real(out.x, what) && real(out.y, what) && real(out.z, what);
}

bool TokenReader::error(const std::string& what) {
    if (m_error.empty())
        m_error = what;
    return false;
}

Failure TokenReader::failure() const {
    return lineError(m_path, m_tokenLine, m_error.empty() ? std::string("parse error") : m_error);
}

Status finishSurface(const std::string& path, const SurfaceMesh& mesh) {
    if (mesh.triangles.empty())
        return fileError(ErrorCode::InvalidInput, path, "contains no triangles");
    const Status valid = validate(mesh);
    if (!valid.ok())
        return fileError(valid.error().code, path, valid.error().detail);
    return {};
}

Status finishTetMesh(const std::string& path, const TetMesh& mesh) {
    if (mesh.tets.empty())
        return fileError(ErrorCode::InvalidInput, path, "contains no tetrahedra");
    const Status valid = validate(mesh);
    if (!valid.ok())
        return fileError(valid.error().code, path, valid.error().detail);
    return {};
}

namespace {

Status checkLabelNames(const LabelMap& labels, const std::string& path, const char* what) {
    for (const auto& [name, values] : labels) {
        if (!isPortableName(name))
            return fileError(ErrorCode::InvalidInput, path,
                             std::string(what) + " label name " + quoted(name) +
                                 " cannot be written: use 1 to 64 characters from A-Z a-z 0-9 _ - .");
    }
    return {};
}

} // namespace

bool isPortableName(const std::string& name) {
    if (name.empty() || name.size() > 64)
        return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
               c == '.';
    });
}

Status checkWritable(const SurfaceMesh& mesh, const std::string& path) {
    const Status valid = validate(mesh);
    if (!valid.ok())
        return fileError(ErrorCode::InvalidInput, path,
                         "refusing to write an invalid surface: " + valid.error().detail);
    if (mesh.triangles.empty())
        return fileError(ErrorCode::InvalidInput, path, "refusing to write a surface without triangles");
    HS_TRY(checkLabelNames(mesh.vertexLabels, path, "vertex"));
    HS_TRY(checkLabelNames(mesh.faceLabels, path, "face"));
    return {};
}

Status checkWritable(const TetMesh& mesh, const std::string& path) {
    const Status valid = validate(mesh);
    if (!valid.ok())
        return fileError(ErrorCode::InvalidInput, path,
                         "refusing to write an invalid tetrahedral mesh: " + valid.error().detail);
    if (mesh.tets.empty())
        return fileError(ErrorCode::InvalidInput, path, "refusing to write a mesh without tetrahedra");
    HS_TRY(checkLabelNames(mesh.pointLabels, path, "point"));
    HS_TRY(checkLabelNames(mesh.tetLabels, path, "tetrahedron"));
    if (!mesh.regions.empty() && mesh.tetLabels.count("region") != 0)
        return fileError(ErrorCode::InvalidInput, path,
                         "tetrahedron label 'region' clashes with the region ids, which are written under that name");
    return {};
}

bool appendFan(SurfaceMesh& mesh, const std::int32_t* corners, std::size_t count, std::int64_t maxCells) {
    for (std::size_t k = 1; k + 1 < count; ++k) {
        if (static_cast<std::int64_t>(mesh.triangles.size()) >= maxCells)
            return false;
        mesh.triangles.push_back({corners[0], corners[k], corners[k + 1]});
    }
    return true;
}

} // namespace hs::io::detail

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace hs::io::detail {

Status writePlainFile(const std::string& path, const std::string& bytes) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file)
        return fileError(ErrorCode::IoError, path, std::string("cannot create: ") + std::strerror(errno));
    const std::size_t written = bytes.empty() ? 0 : std::fwrite(bytes.data(), 1, bytes.size(), file);
    const bool closed = std::fclose(file) == 0;
    if (written != bytes.size() || !closed)
        return fileError(ErrorCode::IoError, path, "write failed (disk full?)");
    return {};
}

} // namespace hs::io::detail
