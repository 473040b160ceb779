#!/usr/bin/env bash
# Set up, build and run the whole test suite (ctest under Xvfb).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$here/build}"
"$here/scripts/setup.sh" "$build"
cd "$build"
xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" ctest --output-on-failure -j2
