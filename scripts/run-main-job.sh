#!/usr/bin/env bash
# The main job: the built-in scene with HAO, off screen, to a PNG, printing per-stage timings.
# Sets up VTK 9.5 from PyPI and builds the program (scripts/setup-vtk95.sh), then renders with no
# X server through EGL (VTKAO_GL=osmesa: through OSMesa).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$here/build-95}"
VTKAO_BUILD_TARGET=vtkao "$here/scripts/setup-vtk95.sh" "$build"
mkdir -p "$here/out"
"$here/scripts/run-headless.sh" "${VTKAO_GL:-egl}" "$build/build/Examples/vtkao" render \
  --method hao --frames 5 --orbit 2 --timings "$here/out/hao-timings.json" \
  --output "$here/out/hao.png"
