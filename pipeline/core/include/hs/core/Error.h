#pragma once
/// Error codes and the Error value every stage returns on an expected failure.

#include <string>
#include <string_view>

namespace hs {

/// What went wrong, in a form the GUI can translate (it never shows `Error::detail` raw).
enum class ErrorCode {
    InvalidInput,   ///< the input (file, parameter, mesh) breaks a documented rule
    NotFound,       ///< a file or resource does not exist
    IoError,        ///< reading or writing failed at the operating-system level
    Unsupported,    ///< a format, version or option this build does not handle
    LimitExceeded,  ///< a size or count above the documented limits (guards against huge allocations)
    Cancelled,      ///< the caller asked to stop through Progress
    BackendFailure, ///< a third-party library failed
    Internal,       ///< a broken invariant: a bug
};

/// Stable lower-case key of an error code ("invalid-input", ...), for logs and JSON output.
std::string_view errorCodeKey(ErrorCode code);

struct Error {
    ErrorCode code = ErrorCode::Internal;
    std::string detail; ///< English, for logs and the CLI: names the file, field and allowed range

    /// "invalid-input: detail"
    std::string message() const;
};

} // namespace hs
