#!/usr/bin/env bash
# Valgrind memcheck on the tests that render (slow under llvmpipe: about 15 minutes a test).
# Usage: scripts/run-valgrind.sh [TEST ...]   (default: a contact, a dynamic and a soak test)
# Exits non-zero if memcheck reports an error or a definite leak outside the suppressions
# (Testing/Sanitizers/valgrind.supp, each entry explained).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$here/build}"
tests=("$@")
[ "${#tests[@]}" -gt 0 ] || tests=(TestHAOContactOcclusion TestHAODynamicScene TestHAOSoak)
mkdir -p "$build/valgrind"
status=0
for t in "${tests[@]}"; do
  log="$build/valgrind/$t.txt"
  if xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" valgrind --leak-check=full \
      --show-leak-kinds=definite --errors-for-leak-kinds=definite --error-exitcode=3 \
      --suppressions="$here/Testing/Sanitizers/valgrind.supp" --num-callers=40 \
      --log-file="$log" "$build/bin/vtkaoCxxTests" "$t" --frames 60 >/dev/null 2>&1; then
    echo "$t: clean ($(grep -o 'ERROR SUMMARY: [0-9]* errors' "$log"))"
  else
    echo "$t: memcheck reported errors, see $log"
    status=1
  fi
done
exit $status
