// The executables' exit code for an error.
#include "hs/core/ExitCode.h"

namespace hs {

int exitCodeFor(const Error& error) {
    switch (error.code) {
    case ErrorCode::InvalidInput:
    case ErrorCode::NotFound:
    case ErrorCode::Unsupported:
    case ErrorCode::LimitExceeded:
        return kExitInvalidInput;
    case ErrorCode::IoError:
    case ErrorCode::Cancelled:
    case ErrorCode::BackendFailure:
    case ErrorCode::Internal:
        return kExitFailed;
    }
    return kExitFailed;
}

} // namespace hs
