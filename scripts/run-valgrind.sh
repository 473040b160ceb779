#!/usr/bin/env bash
# Valgrind memcheck on the tests that render (slow under llvmpipe: about 15 minutes a test) and
# on the vtkao program (a small render with each pass: a few minutes each).
# Usage: scripts/run-valgrind.sh [TEST ...]   (default: a contact, a dynamic and a soak test,
#        then `vtkao render` with HAO and with AOV; the item vtkao-hao or vtkao-aov names one)
# Exits non-zero if memcheck reports an error or a definite leak outside the suppressions
# (Testing/Sanitizers/valgrind.supp, each entry explained).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$here/build}"
tests=("$@")
[ "${#tests[@]}" -gt 0 ] ||
  tests=(TestHAOContactOcclusion TestHAODynamicScene TestHAOSoak vtkao-hao vtkao-aov)
mkdir -p "$build/valgrind"
# llvmpipe compiles shaders with LLVM for the host CPU; valgrind 3.19 cannot decode some of the
# AVX code it emits (TestHAOGLState, 2026-12-02: "unrecognised instruction" vmovq xmm0, xmm8 in
# JIT code, SIGILL). Mesa's GALLIUM_OVERRIDE_CPU_CAPS=sse4.1 makes llvmpipe treat the CPU as
# having no AVX, so the JIT emits SSE4.1 code only; the project's code is not affected.
export GALLIUM_OVERRIDE_CPU_CAPS="${GALLIUM_OVERRIDE_CPU_CAPS:-sse4.1}"
# Mesa writes each new shader to its on-disk cache from a thread of its own, compressing blobs
# with uninitialised padding (2026-12-04, TestHAOShadingNormals: 18394 reports from 502
# contexts, all under swrast_dri.so's link and zstd, none in the project): whether they appear
# depends on what the cache already held. Off, the run is the same every time.
export MESA_SHADER_CACHE_DISABLE="${MESA_SHADER_CACHE_DISABLE:-true}"
status=0
for t in "${tests[@]}"; do
  # One log per process (%p): the program first probes for an OpenGL context in a child of
  # its own (vtkaoContext.cxx), which memcheck reports on separately.
  log="$build/valgrind/$t.%p.txt"
  rm -f "$build/valgrind/$t".*.txt
  case "$t" in
    vtkao-*)
      command=("$build/Examples/vtkao" render --method "${t#vtkao-}" --size 160x90 --frames 2
        --output "$build/valgrind/$t.png")
      ;;
    *)
      # The test's own command line, as ctest runs it (each module's tests have a driver of
      # their own: vtkaoCxxTests, vtkaoReferenceCxxTests, vtkaoBakingCxxTests).
      driver=$(cd "$build" && ctest -N -V -R "Cxx-$t\$" | sed -n 's/^[0-9]*: Test command: //p' |
        head -n 1 | awk '{ print $1 }')
      if [ -z "$driver" ]; then
        echo "$t: no such test in $build (ctest -N lists them)"
        status=1
        continue
      fi
      command=("$driver" "$t")
      # The soak's length (its default, 400 frames, would take hours under memcheck).
      [ "$t" != TestHAOSoak ] || command+=(--frames 60)
      ;;
  esac
  ok=true
  xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" valgrind --leak-check=full \
    --show-leak-kinds=definite --errors-for-leak-kinds=definite --error-exitcode=3 \
    --suppressions="$here/Testing/Sanitizers/valgrind.supp" --num-callers=40 \
    --log-file="$log" "${command[@]}" >/dev/null 2>&1 || ok=false
  # Every process's summary counts (the probe's exit status does not reach the program's).
  # No log at all (valgrind did not start) is a failure too.
  logs=("$build/valgrind/$t".*.txt)
  [ -f "${logs[0]}" ] || ok=false
  errors=$(cat "${logs[@]}" 2>/dev/null | grep -o 'ERROR SUMMARY: [0-9]*' |
    awk '{ n += $3 } END { print n + 0 }' || true)
  if $ok && [ "${errors:-0}" -eq 0 ]; then
    echo "$t: clean (${#logs[@]} processes, 0 errors)"
  else
    echo "$t: memcheck reported $errors errors (exit ok: $ok), see $build/valgrind/$t.*.txt"
    status=1
  fi
done
exit $status
