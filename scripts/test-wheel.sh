#!/usr/bin/env bash
# The pip package as a user gets it (issue 15): builds the wheel (scripts/build-wheel.sh: `pip
# wheel .` through scikit-build-core against PyPI's vtk 9.5) and installs it into the venv of
# scripts/setup-vtk95.sh, which holds PyPI's vtk and PyVista; then, from an empty directory,
# with no PYTHONPATH and no X server (EGL):
#  1. `import vtkao` beside vtkmodules loads the installed package (from the venv's
#     site-packages, not the source or build tree);
#  2. Testing/Python/TestPyVistaHAO.py passes against it (a vtkao pass on a vtkmodules
#     renderer in one process; PyVista's contact darkening on and off; the occluder outside
#     the view that enable_ssao() misses);
#  3. the console entry point `vtkao` runs and renders the main job's scene to a PNG.
# Prints the wheel's size.   scripts/test-wheel.sh [BUILD_DIR]   (default: build-95)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="$(mkdir -p "${1:-$here/build-95}" && cd "${1:-$here/build-95}" && pwd)"
"$here/scripts/build-wheel.sh" "$build"
python="$build/venv/bin/python"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
run() { env -u PYTHONPATH "$here/scripts/run-headless.sh" egl "$@"; }
run "$python" -c '
import sys, sysconfig
import vtkmodules.vtkRenderingCore
import vtkao
site = sysconfig.get_paths()["platlib"]
assert vtkao.__file__.startswith(site), "vtkao came from " + vtkao.__file__ + ", not " + site
print("ok: vtkao", vtkao.__file__, "beside vtkmodules", vtkmodules.vtkRenderingCore.__file__)
'
run "$python" "$here/Testing/Python/TestPyVistaHAO.py"
run "$build/venv/bin/vtkao" render --size 320x180 --output "$work/main-job.png"
test -s "$work/main-job.png"
echo "ok: the vtkao entry point rendered $(stat -c %s "$work/main-job.png") bytes"
ls -l "$build"/dist/vtkao-*.whl | awk '{ printf "wheel: %s, %.0f KiB\n", $NF, $5 / 1024 }'
