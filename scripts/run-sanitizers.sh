#!/usr/bin/env bash
# The whole C++ test suite under AddressSanitizer + UndefinedBehaviorSanitizer (a separate
# build in build-asan). Zero reports from the project's code is the goal; suppressions for
# Mesa/X/VTK internals are in Testing/Sanitizers/lsan.supp, each explained.
# Python tests are excluded (the Debian interpreter is not instrumented).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$here/build-asan}"
"$here/scripts/setup.sh" "$build" >/dev/null 2>&1 || true # packages only; configure below
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVTKAO_ENABLE_SANITIZERS=ON \
  -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build "$build" -j"$(nproc)"
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=0:abort_on_error=0:detect_odr_violation=0"
export LSAN_OPTIONS="suppressions=$here/Testing/Sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd "$build"
xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" ctest --output-on-failure -j2 -LE python \
  -E "Consumer|Python" "$@"
