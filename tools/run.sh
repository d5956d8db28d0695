#!/usr/bin/env bash
# Sets up a Debian 12 machine, builds hysteroscene (Release) and runs the main job on the bundled default:
# the workstation window when a display is available, otherwise the command-line tool on the same default.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
cmake --preset release
cmake --build --preset release
bin=build/release/bin
default_surface=resources/surfaces/default-organ.off
if [ -n "${DISPLAY:-}" ] && [ -z "${HS_HEADLESS:-}" ]; then
    exec "$bin/hysteroscene" "$default_surface"
else
    echo "run: no display; running the command-line tool on the bundled default"
    "$bin/hysteroscene-cli" info "$default_surface"
    "$bin/hysteroscene-cli" validate resources/cases/default.json
fi
