#!/usr/bin/env bash
# VTK 9.5 from PyPI beside Debian's VTK 9.1, and the project built against it, headless.
# Usage: scripts/setup-vtk95.sh [BUILD_DIR]      (default: build-95)
#   BUILD_DIR/venv   Python venv (Debian's python3) with vtk==$VTKAO_VTK95_VERSION from PyPI
#   BUILD_DIR/sdk    that wheel's C++ SDK (scripts/vtk95-sdk.py: why it is made here)
#   BUILD_DIR/build  the project (modules, vtkao, tests) built against it
# Rendering needs no X server: VTK 9.5 picks EGL (Mesa's software device here) or OSMesa at
# run time (VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow or vtkOSOpenGLRenderWindow forces one).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="$(mkdir -p "${1:-$here/build-95}" && cd "${1:-$here/build-95}" && pwd)"
version="${VTKAO_VTK95_VERSION:-9.5.0}"
packages=(cmake g++ make pkg-config python3-venv python3-dev libglm-dev libopenimageio-dev libembree-dev
  libegl1 libegl-mesa0 libgl1-mesa-dri libosmesa6 libgl-dev libegl-dev libx11-6 libxrender1)
# shellcheck source=apt-install-missing.sh
. "$here/scripts/apt-install-missing.sh"
apt_install_missing "${packages[@]}"

venv="$build/venv"
[ -x "$venv/bin/python" ] || /usr/bin/python3 -m venv "$venv"
site="$("$venv/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')"
if ! "$venv/bin/python" -c "import importlib.metadata as m, sys; sys.exit(m.version('vtk') != '$version')" 2>/dev/null; then
  "$venv/bin/python" -m pip install -q --disable-pip-version-check "vtk==$version"
fi
# PyVista for the tests of the Python package (vtkao.pyvista); it must keep the pinned vtk.
if ! "$venv/bin/python" -c "import pyvista" 2>/dev/null; then
  "$venv/bin/python" -m pip install -q --disable-pip-version-check pyvista "vtk==$version"
fi

sdk="$build/sdk"
marker="$sdk/.made-$version-$(sha1sum "$here/scripts/vtk95-sdk.py" | cut -c1-12)"
if [ ! -f "$marker" ]; then
  # The only vtk-sdk wheels on PyPI are macOS ones; their headers serve (scripts/vtk95-sdk.py).
  if ! ls "$build"/download/vtk_sdk-"$version"-*.whl >/dev/null 2>&1; then
    "$venv/bin/python" -m pip download -q --disable-pip-version-check --no-deps \
      --only-binary=:all: --platform macosx_11_0_arm64 --python-version 3.10 \
      -d "$build/download" "vtk-sdk==$version"
  fi
  "$venv/bin/python" "$here/scripts/vtk95-sdk.py" "$build"/download/vtk_sdk-"$version"-*.whl \
    "$site" "$sdk" > "$build/vtk-dir.txt"
  rm -f "$sdk"/.made-*
  touch "$marker"
fi
vtk_dir="$(cat "$build/vtk-dir.txt")"
[ "${VTKAO_SETUP_ONLY:-0}" != 1 ] || exit 0
# The SDK's Python wrapping tools are macOS programs: no wrapped package; the pip package's
# hand-written extension instead (VTKAO_PYTHON_WHEEL, tested in the suite with PyVista).
cmake -S "$here" -B "$build/build" -DCMAKE_BUILD_TYPE=Release -DVTK_DIR="$vtk_dir" \
  -DVTKAO_WRAP_PYTHON=OFF -DVTKAO_PYTHON_WHEEL=ON -DPython3_EXECUTABLE="$venv/bin/python" \
  >/dev/null
cmake --build "$build/build" -j"$(nproc)" ${VTKAO_BUILD_TARGET:+--target "$VTKAO_BUILD_TARGET"}
