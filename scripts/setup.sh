#!/usr/bin/env bash
# Installs every Debian 12 package the project needs (as root, or with sudo) and builds it.
# Usage: scripts/setup.sh [BUILD_DIR]      (default: build)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$here/build}"
packages=(cmake g++ make pkg-config libvtk9-dev python3-vtk9 libglm-dev libopenimageio-dev
  libembree-dev libosmesa6-dev libegl-dev libgl-dev xvfb xauth libgl1-mesa-dri
  gmsh gmsh-doc openscad-testing-data doxygen gnuplot-nox)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build "$build" -j"$(nproc)"
