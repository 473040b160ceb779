#!/usr/bin/env bash
# Installs every Debian 12 package the project needs (as root, or with sudo) and builds it.
# Usage: scripts/setup.sh [BUILD_DIR]      (default: build)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$here/build}"
packages=(cmake g++ make pkg-config libvtk9-dev python3-vtk9 libglm-dev libopenimageio-dev
  libembree-dev libosmesa6-dev libegl-dev libgl-dev xvfb xauth libgl1-mesa-dri
  gmsh gmsh-doc openscad-testing-data doxygen gnuplot-nox)
# shellcheck source=apt-install-missing.sh
. "$here/scripts/apt-install-missing.sh"
apt_install_missing "${packages[@]}"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build "$build" -j"$(nproc)"
