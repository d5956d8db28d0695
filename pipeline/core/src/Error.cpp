#include "hs/core/Error.h"

namespace hs {

std::string_view errorCodeKey(ErrorCode code) {
    switch (code) {
    case ErrorCode::InvalidInput:
        return "invalid-input";
    case ErrorCode::NotFound:
        return "not-found";
    case ErrorCode::IoError:
        return "io-error";
    case ErrorCode::Unsupported:
        return "unsupported";
    case ErrorCode::LimitExceeded:
        return "limit-exceeded";
    case ErrorCode::Cancelled:
        return "cancelled";
    case ErrorCode::BackendFailure:
        return "backend-failure";
    case ErrorCode::Internal:
        return "internal";
    }
    return "internal";
}

std::string Error::message() const {
    std::string text(errorCodeKey(code));
    if (!detail.empty()) {
        text += ": ";
        text += detail;
    }
    return text;
}

} // namespace hs
