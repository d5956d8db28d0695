#pragma once
/// The exit codes of the project's executables (hysteroscene-cli, hysteroscene-sim; docs/cli.md, docs/simulator.md).

#include "hs/core/Error.h"

namespace hs {

enum ExitCode : int {
    kExitOk = 0,           ///< the command did what was asked
    kExitUsage = 2,        ///< bad command line (unknown option, missing argument)
    kExitInvalidInput = 3, ///< an input file or parameter is invalid (the message names it)
    kExitFailed = 4,       ///< the command failed for another reason (I/O, backend, cancelled, internal)
};

/// The exit code for an error: input problems give 3, everything else 4.
int exitCodeFor(const Error& error);

} // namespace hs
