#pragma once
/// Shared pieces of the command-line tool: exit codes, error printing, JSON output.

#include "hs/core/Error.h"
#include "hs/core/ExitCode.h"

#include <nlohmann/json.hpp>

#include <iosfwd>
#include <string>

namespace hs::cli {

/// Exit codes of hysteroscene-cli (documented in docs/cli.md): hs/core/ExitCode.h.
using hs::ExitCode;
using hs::exitCodeFor;
using hs::kExitFailed;
using hs::kExitInvalidInput;
using hs::kExitOk;
using hs::kExitUsage;

/// Prints "hysteroscene-cli: <command>: <message>" to stderr and returns the exit code for the error.
int reportError(const std::string& command, const Error& error);

/// Options every command shares.
struct CommonOptions {
    bool json = false;    ///< machine-readable output on stdout
    bool verbose = false; ///< per-step timings and details
};

/// Pretty-prints JSON to `out` with a trailing newline.
void printJson(std::ostream& out, const nlohmann::ordered_json& value);

} // namespace hs::cli
