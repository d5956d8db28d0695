#!/usr/bin/env bash
# Installs every Debian 12 package hysteroscene needs to build, test and run.
# Idempotent: packages already present are skipped; `apt-get update` runs at most once per call.
# Only Debian packages are installed; nothing else is downloaded.
set -euo pipefail

packages=(
    # toolchain
    build-essential cmake ninja-build pkg-config git
    # Qt 6 (Widgets, OpenGLWidgets, Concurrent, Test, LinguistTools, Charts)
    qt6-base-dev qt6-base-dev-tools qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-charts-dev
    libqt6opengl6-dev libgl-dev libglx-dev
    # VTK 9.1 (core modules only; the Qt view is the project's own widget)
    libvtk9-dev
    # geometry, meshing, numerics
    libcgal-dev libgmp-dev libmpfr-dev libtbb-dev libtet1.5-dev libeigen3-dev
    # images and textures
    libopencv-dev libopenimageio-dev
    # files and command line (zlib and minizip: PNG maps and zipped scene packages)
    nlohmann-json3-dev libcli11-dev libtinygltf-dev libhdf5-dev zlib1g-dev libminizip-dev
    # haptic devices
    libhidapi-dev
    # tests: outside tools that read the scene package (meshio; Node.js for the Khronos glTF validator, which
    # tools/test.sh installs from npm) and Gmsh, the speed anchor of the meshing benchmark.
    # Not python3-paraview: on Debian 12 it conflicts with libvtk9-dev.
    libgtest-dev libgmock-dev libbenchmark-dev xvfb xauth libgl1-mesa-dri python3-meshio python3-vtk9 gmsh
    # batch on a real single-node Slurm (the test starts its own munged, slurmctld and slurmd; no systemd)
    slurm-wlm munge
    # batch report: Chart.js inlined into the page, and the browser that checks the page in a test
    libjs-chart.js chromium
)

# Node.js and npm come from Debian only where no other installation provides them (Debian's npm conflicts with
# Node.js builds that bundle their own npm).
if ! command -v npm >/dev/null 2>&1; then
    packages+=(nodejs npm)
fi

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "setup: all ${#packages[@]} packages present"
    exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
    sudo_cmd=(sudo)
fi
echo "setup: installing ${#missing[@]} packages: ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"
