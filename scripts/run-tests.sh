#!/usr/bin/env bash
# Set up, build and run the whole test suite: ctest under Xvfb, then the ParaView plugin's
# tests (scripts/run-paraview-tests.sh: ParaView 5.11 unpacked into build-pv; pvpython and
# pvbatch under mpiexec -np 1, 2, 4). VTKAO_SKIP_PARAVIEW=1 runs only ctest.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$here/build}"
"$here/scripts/setup.sh" "$build"
status=0
(cd "$build" && xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" ctest --output-on-failure -j2) ||
  status=1
if [ "${VTKAO_SKIP_PARAVIEW:-0}" != 1 ]; then
  "$here/scripts/run-paraview-tests.sh" "${PV_BUILD_DIR:-$here/build-pv}" || status=1
fi
exit "$status"
