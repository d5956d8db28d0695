#include "CliCommon.h"

#include <iostream>

namespace hs::cli {

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

int reportError(const std::string& command, const Error& error) {
    std::cerr << "hysteroscene-cli: " << command << ": " << error.message() << '\n';
    return exitCodeFor(error);
}

void printJson(std::ostream& out, const nlohmann::ordered_json& value) {
    out << value.dump(2) << '\n';
}

} // namespace hs::cli
