#!/usr/bin/env bash
# Builds the pip package (pyproject.toml) against PyPI's vtk 9.5 and installs it into the venv of
# scripts/setup-vtk95.sh:  scripts/build-wheel.sh [BUILD_DIR]   (default: build-95)
# The wheel lands in BUILD_DIR/dist. Its extension module and program link the vtk wheel's
# libraries (found beside them in site-packages at run time) and Debian's OpenImageIO and Embree,
# so it is a wheel for this kind of machine (linux_x86_64), not a manylinux one.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="$(mkdir -p "${1:-$here/build-95}" && cd "${1:-$here/build-95}" && pwd)"
VTKAO_SETUP_ONLY=1 "$here/scripts/setup-vtk95.sh" "$build"
venv="$build/venv"
"$venv/bin/python" -m pip install -q --disable-pip-version-check "scikit-build-core>=0.10"
rm -rf "$build/dist"
# No build isolation: the build uses the venv's vtk and the SDK made for it (VTK_DIR); Debian's
# cmake (a cmake wrapper earlier on PATH, such as a pyenv shim, may not run inside the venv).
PATH="/usr/bin:$PATH" "$venv/bin/python" -m pip wheel -q --disable-pip-version-check --no-build-isolation --no-deps \
  -w "$build/dist" --config-settings="cmake.define.VTK_DIR=$(cat "$build/vtk-dir.txt")" \
  --config-settings="build-dir=$build/wheel-build" "$here"
"$venv/bin/python" -m pip install -q --disable-pip-version-check --force-reinstall --no-deps \
  "$build"/dist/vtkao-*.whl
ls -l "$build"/dist/vtkao-*.whl
