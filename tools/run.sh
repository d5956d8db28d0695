#!/usr/bin/env bash
# Sets up a Debian 12 machine, builds hysteroscene (Release) and runs the main job on the bundled default case:
# the whole pipeline writes the default scene package and says where it is; with a display, the workstation then
# opens the scene's tetrahedral mesh (HS_HEADLESS=1 skips the window).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
cmake --preset release
cmake --build --preset release
bin=build/release/bin
scene=build/release/scenes/default
"$bin/hysteroscene-cli" generate resources/cases/default.json -o "$scene"
"$bin/hysteroscene-cli" validate "$scene"
echo "run: the default scene is in $scene"
if [ -n "${DISPLAY:-}" ] && [ -z "${HS_HEADLESS:-}" ]; then
    exec "$bin/hysteroscene" "$scene/tets.vtu"
fi
