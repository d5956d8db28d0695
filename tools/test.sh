#!/usr/bin/env bash
# Sets up a Debian 12 machine, builds hysteroscene (Release, warnings as errors) and runs the whole test suite.
# GUI tests need a display: the suite runs under xvfb-run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
cmake --preset ci
cmake --build --preset ci
xvfb-run -a -s "-screen 0 1280x1024x24" ctest --preset ci -j 2
