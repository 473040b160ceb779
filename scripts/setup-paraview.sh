#!/usr/bin/env bash
# Build environment for the ParaView plugin (Plugins/ParaView), on Debian 12, as root.
#
#   scripts/setup-paraview.sh [BUILD_DIR]        (default: build-pv)
#
# Debian's paraview-dev cannot be installed beside libvtk9-dev (python3-paraview conflicts with
# python3-vtk9), so ParaView 5.11 is not installed: its runtime dependencies come from apt-get,
# and the packages paraview, paraview-dev and python3-paraview are downloaded and unpacked
# (dpkg -x) into BUILD_DIR/prefix. The plugin is then configured against that ParaView (its own
# VTK 9.2, libraries suffixed -pv5.11) and built into BUILD_DIR/plugin.
#
# Writes BUILD_DIR/paraview-env.sh: source it to run the prefix's pvpython / pvbatch
# (LD_LIBRARY_PATH, PYTHONPATH, VTKAO_PARAVIEW_PLUGIN, PV_PLUGIN_PATH, MPIEXEC).
set -euo pipefail

SOURCE_DIR="$(cd "$(dirname "$0")/.." && pwd)"
BUILD_DIR="${1:-${SOURCE_DIR}/build-pv}"
mkdir -p "${BUILD_DIR}"
BUILD_DIR="$(cd "${BUILD_DIR}" && pwd)"
PV_VERSION="5.11.0+dfsg-1+b1"
PREFIX="${BUILD_DIR}/prefix"
export DEBIAN_FRONTEND=noninteractive

log() { echo "setup-paraview: $*"; }

# 1. Tools, ParaView's runtime dependencies (the Depends of paraview and python3-paraview,
#    without paraview itself), the -dev packages its CMake package looks for, OpenMPI, Xvfb.
packages=(
  build-essential cmake xvfb xauth
  openmpi-bin libopenmpi-dev
  # runtime libraries of paraview / python3-paraview 5.11.0
  libavcodec59 libavformat59 libavutil57 libswscale6 libdouble-conversion3 libexpat1
  libfreetype6 libgdal32 libgl2ps1.4 libglew2.2 libglx0 libopengl0 libhdf5-openmpi-103-1
  libjpeg62-turbo liblz4-1 liblzma5 libnetcdf19 libogg0 libopenmpi3 libpng16-16 libpython3.11
  libqt5core5a libqt5gui5 libqt5help5 libqt5network5 libqt5opengl5 libqt5widgets5 libtheora0
  libtiff6 libx11-6 libxcursor1 libxml2 zlib1g tcl
  python3 python3-numpy python3-matplotlib python3-mpi4py python3-six
  # what ParaView's CMake package (its VTK's find-packages) asks for with our components
  libeigen3-dev libglew-dev libgl-dev libx11-dev libxt-dev zlib1g-dev libpng-dev libjpeg-dev
  libtiff-dev libfreetype-dev libexpat1-dev liblzma-dev liblz4-dev libdouble-conversion-dev
  libutfcpp-dev python3-dev
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  log "apt-get install ${missing[*]}"
  apt-get update -qq
  apt-get install -y --no-install-recommends "${missing[@]}"
fi

# 2. ParaView itself, unpacked into the prefix (not installed).
DEBS="${BUILD_DIR}/debs"
mkdir -p "${DEBS}"
for p in paraview paraview-dev python3-paraview; do
  if ! ls "${DEBS}/${p}_"*.deb > /dev/null 2>&1; then
    log "apt-get download ${p}=${PV_VERSION}"
    (cd "${DEBS}" && apt-get download "${p}=${PV_VERSION}")
  fi
done
if [ ! -x "${PREFIX}/usr/bin/pvbatch" ]; then
  for deb in "${DEBS}"/*.deb; do
    log "dpkg -x $(basename "${deb}")"
    dpkg -x "${deb}" "${PREFIX}"
  done
fi
PV_LIBDIR="${PREFIX}/usr/lib/x86_64-linux-gnu"
ParaView_DIR="${PV_LIBDIR}/cmake/paraview-5.11"
[ -f "${ParaView_DIR}/paraview-config.cmake" ] || { log "no ParaView CMake package in ${ParaView_DIR}"; exit 1; }

# No path needs patching: every targets/config file of the package computes its prefix from
# its own location (CMAKE_CURRENT_LIST_FILE); the absolute "/usr/..." strings left in them
# only serve REALPATH guards that are false outside /usr (rewriting them breaks VTKmConfig).
# Check that the unpacked package is intact (an earlier run of this script patched it):
if grep -q "_realOrig \"${PREFIX}" "${ParaView_DIR}/vtk/vtkm/VTKmConfig.cmake" 2>/dev/null; then
  log "re-extracting the packages (patched config files found)"
  for deb in "${DEBS}"/*.deb; do dpkg -x "${deb}" "${PREFIX}"; done
fi

# 3. Configure and build the plugin against the prefix's ParaView.
log "configure Plugins/ParaView (ParaView_DIR=${ParaView_DIR})"
cmake -S "${SOURCE_DIR}/Plugins/ParaView" -B "${BUILD_DIR}/plugin" \
  -DCMAKE_BUILD_TYPE=Release \
  -DParaView_DIR="${ParaView_DIR}" \
  -DPython3_EXECUTABLE=/usr/bin/python3
cmake --build "${BUILD_DIR}/plugin" -j "$(nproc)"
PLUGIN="${BUILD_DIR}/plugin/lib/paraview-plugins/AmbientOcclusionView/AmbientOcclusionView.so"
[ -f "${PLUGIN}" ] || { log "plugin not built: ${PLUGIN}"; exit 1; }

# 4. The environment to run the prefix's ParaView with the plugin.
cat > "${BUILD_DIR}/paraview-env.sh" <<ENV
# Source this file to run ParaView 5.11 from ${PREFIX} with the plugin.
export PARAVIEW_PREFIX="${PREFIX}/usr"
export PATH="${PREFIX}/usr/bin:\${PATH}"
export LD_LIBRARY_PATH="${PV_LIBDIR}\${LD_LIBRARY_PATH:+:\${LD_LIBRARY_PATH}}"
export PYTHONPATH="${PREFIX}/usr/lib/python3/dist-packages\${PYTHONPATH:+:\${PYTHONPATH}}"
export VTKAO_PARAVIEW_PLUGIN="${PLUGIN}"
export PV_PLUGIN_PATH="$(dirname "${PLUGIN}")"
# as root, OpenMPI needs --allow-run-as-root; two cores: --oversubscribe for 4 ranks
export MPIEXEC="mpiexec --allow-run-as-root --oversubscribe"
ENV
log "plugin: ${PLUGIN}"
log "environment: source ${BUILD_DIR}/paraview-env.sh"
