#!/usr/bin/env bash
# Frame-time ratios HAO/plain and SSAO/plain (vtkao bench, main series, built-in scene) on each
# OpenGL path of this machine, one after the other: VTK 9.1 through GLX under Xvfb, VTK 9.5
# through EGL, VTK 9.5 through OSMesa. Ratios within one run, not absolute times, are the result.
#   scripts/bench-backends.sh [FRAMES] [WxH]     (defaults: 10, 1280x720); needs build/ and build-95/
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
frames="${1:-10}"
size="${2:-1280x720}"
out="$here/out/bench-backends"
mkdir -p "$out"
args=(bench --quick --series main --frames "$frames" --size "$size")
xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" "$here/build/Examples/vtkao" "${args[@]}" \
  --output-json "$out/vtk91-glx.json" > "$out/vtk91-glx.log"
"$here/scripts/run-headless.sh" egl "$here/build-95/build/Examples/vtkao" "${args[@]}" \
  --output-json "$out/vtk95-egl.json" > "$out/vtk95-egl.log"
"$here/scripts/run-headless.sh" osmesa "$here/build-95/build/Examples/vtkao" "${args[@]}" \
  --output-json "$out/vtk95-osmesa.json" > "$out/vtk95-osmesa.log"
python3 - "$out" <<'PY'
import json, sys, pathlib
out = pathlib.Path(sys.argv[1])
print(f"{'path':14} {'mode':7} {'HAO/plain':>10} {'SSAO32/plain':>13} {'SSAO128/plain':>14}  GL")
for name in ("vtk91-glx", "vtk95-egl", "vtk95-osmesa"):
    d = json.loads((out / f"{name}.json").read_text())
    for mode in ("orbit", "moving"):
        m = {c["method"]: c["median_ms"] for c in d["cases"]
             if c["series"] == "main" and c["scene"] == "builtin" and c["mode"] == mode}
        print(f"{name:14} {mode:7} {m['hao'] / m['none']:10.2f} {m['ssao32'] / m['none']:13.2f} "
              f"{m['ssao128'] / m['none']:14.2f}  {d.get('gl_renderer', '?')}")
PY
