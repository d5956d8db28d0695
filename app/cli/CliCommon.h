#pragma once
/// Shared pieces of the command-line tool: exit codes, error printing, JSON output.

#include "hs/core/Error.h"

#include <nlohmann/json.hpp>

#include <iosfwd>
#include <string>

namespace hs::cli {

/// Exit codes of hysteroscene-cli (documented in docs/cli.md).
enum ExitCode : int {
    kExitOk = 0,           ///< the command did what was asked
    kExitUsage = 2,        ///< bad command line (unknown option, missing argument)
    kExitInvalidInput = 3, ///< an input file or parameter is invalid (the message names it)
    kExitFailed = 4,       ///< the command failed for another reason (I/O, backend, cancelled, internal)
};

/// The exit code for an error: input problems give 3, everything else 4.
int exitCodeFor(const Error& error);

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
