#!/usr/bin/env bash
# Set up, build and run every test configuration (`.ci/run` calls this):
#  1. Debian's VTK 9.1 (build/): the whole ctest suite under Xvfb (VTK 9.1 renders only via X);
#  2. PyPI's VTK 9.5 (build-95/, scripts/setup-vtk95.sh): the whole ctest suite with no X server
#     through EGL, then a smoke set (the main job, one AO test, EXR output) through OSMesa, then
#     the pip wheel built, installed into the venv and used from outside the tree
#     (scripts/test-wheel.sh);
#  3. the ParaView 5.11 plugin's tests (scripts/run-paraview-tests.sh, build-pv/).
# VTKAO_SKIP_PARAVIEW=1 leaves out 3, VTKAO_SKIP_VTK91=1 leaves out 1, VTKAO_SKIP_VTK95=1 2.
# Prints the time of each step at the end.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$here/build}"
build95="${BUILD95_DIR:-$here/build-95}"
status=0
times=()
step() # name command...: runs it, records its time and status, goes on after a failure
{
  local name="$1" start=$SECONDS rc=0
  shift
  echo "=== $name"
  "$@" || rc=$?
  times+=("$(printf '%-34s %5d s  %s' "$name" $((SECONDS - start)) "$([ $rc = 0 ] && echo ok || echo "FAILED ($rc)")")")
  [ $rc = 0 ] || status=1
  return 0
}
ctest_in() { (cd "$1" && shift && "$@"); }

if [ "${VTKAO_SKIP_VTK91:-0}" != 1 ]; then
  step "VTK 9.1: set-up and build" "$here/scripts/setup.sh" "$build"
  step "VTK 9.1: ctest (Xvfb)" ctest_in "$build" \
    xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" ctest --output-on-failure -j2
fi
if [ "${VTKAO_SKIP_VTK95:-0}" != 1 ]; then
  step "VTK 9.5: set-up and build" "$here/scripts/setup-vtk95.sh" "$build95"
  step "VTK 9.5: ctest (EGL, no X)" ctest_in "$build95/build" \
    "$here/scripts/run-headless.sh" egl ctest --output-on-failure -j2
  step "VTK 9.5: smoke (OSMesa, no X)" ctest_in "$build95/build" \
    "$here/scripts/run-headless.sh" osmesa ctest --output-on-failure -j2 -L headless-smoke
  step "VTK 9.5: pip wheel, installed" "$here/scripts/test-wheel.sh" "$build95"
fi
if [ "${VTKAO_SKIP_PARAVIEW:-0}" != 1 ]; then
  step "ParaView 5.11 plugin" "$here/scripts/run-paraview-tests.sh" "${PV_BUILD_DIR:-$here/build-pv}"
fi
echo "=== times"
printf '%s\n' "${times[@]}"
exit "$status"
