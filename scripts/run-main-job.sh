#!/usr/bin/env bash
# The main job: the built-in scene with HAO, off screen, to a PNG, printing per-stage timings.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$here/build}"
"$here/scripts/setup.sh" "$build"
mkdir -p "$here/out"
xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" "$build/Examples/vtkao" render --method hao \
  --frames 5 --orbit 2 --timings "$here/out/hao-timings.json" --output "$here/out/hao.png"
