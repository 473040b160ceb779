#!/usr/bin/env bash
# The whole C++ test suite under AddressSanitizer + UndefinedBehaviorSanitizer (a separate
# build in build-asan). Exits zero only when every test passed and no process left a sanitizer
# report (leaks included). Python tests are excluded (the Debian interpreter is not
# instrumented), and so is vtkao-Consumer (it builds a separate project without sanitizers).
#
# Usage: scripts/run-sanitizers.sh [CTEST ARGS ...]     (e.g. -R vtkao- for some tests)
# Environment: BUILD_DIR (default build-asan), JOBS (build parallelism, default nproc).
#
# What is not the project's, and how it is handled (Documentation/reliability.md):
# - Testing/Sanitizers/keep-loaded.c is preloaded: dlclose() keeps libraries mapped. Mesa
#   unloads its DRI driver when VTK closes the X display, before LeakSanitizer runs at exit;
#   blocks the driver still references from its own (then unmapped) data looked leaked, in
#   frames nobody can name (the "112 bytes inside Mesa").
# - intercept_tls_get_addr=0: GCC 12's sanitizer runtime guesses the layout of dynamic TLS
#   blocks (those of dlopen'ed libraries: Mesa's driver, LLVM) from their address and, when a
#   block happens to sit 16 bytes into a page, scans a range read from the two words before it:
#   LeakSanitizer's tracer then dies at exit ("Tracer caught signal 11 ... LeakSanitizer has
#   encountered a fatal error", seen in vtkao-Importers). The blocks stay reachable (and
#   scanned) through the thread's DTV, so no leak goes unseen.
# - Testing/Sanitizers/lsan.supp: LeakSanitizer suppressions (none needed at present).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$here/build-asan}"
installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "ok installed"; }
if ! installed libvtk9-dev || ! installed libembree-dev || ! installed xvfb; then
  "$here/scripts/setup.sh" # a fresh machine: the project's packages (and the normal build/)
fi
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVTKAO_ENABLE_SANITIZERS=ON \
  -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build "$build" -j"${JOBS:-$(nproc)}"
cc -shared -fPIC -O2 -o "$build/keep-loaded.so" "$here/Testing/Sanitizers/keep-loaded.c"

# Every report goes to a file per process (sanitizer-reports/asan.PID, ubsan.PID) and makes the
# process fail: a report is seen even where a test expects a non-zero exit. No halt_on_error=0
# in ASAN_OPTIONS: with it a LeakSanitizer report leaves the exit status at 0. The preloaded
# shim comes before the ASan runtime, hence verify_asan_link_order=0; detect_odr_violation=0
# because the module libraries are linked both into the tests and into the Python modules.
reports="$build/sanitizer-reports"
rm -rf "$reports"
mkdir -p "$reports"
export LD_PRELOAD="$build/keep-loaded.so${LD_PRELOAD:+:$LD_PRELOAD}"
export ASAN_OPTIONS="detect_leaks=1:detect_odr_violation=0:verify_asan_link_order=0:intercept_tls_get_addr=0:log_path=$reports/asan"
export LSAN_OPTIONS="suppressions=$here/Testing/Sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:log_path=$reports/ubsan"
cd "$build"
status=0
xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" ctest --output-on-failure -j2 -LE python \
  -E "Consumer|Python" "$@" || status=$?
if compgen -G "$reports/*" >/dev/null; then
  echo "sanitizer reports (in $reports):"
  grep -h -E "^SUMMARY: |runtime error: |LeakSanitizer has encountered" "$reports"/* |
    sort | uniq -c
  status=1
else
  echo "no sanitizer report"
fi
exit $status
