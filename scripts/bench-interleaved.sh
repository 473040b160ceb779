#!/usr/bin/env bash
# Interleaved frame times of two vtkao binaries (say, before and after a change) against the
# plain frame and vtkSSAOPass in one session, so that the machine's load moves all four alike.
#
#   scripts/bench-interleaved.sh BEFORE_VTKAO AFTER_VTKAO [ROUNDS] [-- extra render options]
#
# Each round renders, in turn: plain and vtkSSAOPass (kernel 32) with AFTER, HAO with BEFORE,
# HAO with AFTER, each `render --size 1280x720 --frames 8 --orbit 2` (the built-in scene unless
# the extra options name inputs). Prints the medians of frames 1-7 over the rounds (total,
# trace, filter) and each HAO's AO overhead relative to vtkSSAOPass's. VTK 9.1 builds need an
# X server: run the script under xvfb-run.
set -euo pipefail
if [ $# -lt 2 ]; then
  sed -n '2,10p' "$0" >&2
  exit 2
fi
before=$1 after=$2
shift 2
rounds=3
if [ $# -gt 0 ] && [ "$1" != "--" ]; then
  rounds=$1
  shift
fi
[ "${1:-}" = "--" ] && shift
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for ((i = 1; i <= rounds; ++i)); do
  for run in "none:$after:--method none" "ssao:$after:--method ssao" "before:$before:" "after:$after:"; do
    IFS=: read -r tag bin method <<<"$run"
    # shellcheck disable=SC2086
    "$bin" render $method --size 1280x720 --frames 8 --orbit 2 --timings "$out/$tag$i.json" \
      --output "$out/frame.png" "$@" >/dev/null
  done
done
python3 - "$out" "$rounds" <<'PY'
import json, statistics, sys
out, rounds = sys.argv[1], int(sys.argv[2])
median = {}
for tag in ("none", "ssao", "before", "after"):
    rows = []
    for i in range(1, rounds + 1):
        rows += json.load(open(f"{out}/{tag}{i}.json"))["frames"][1:]
    median[tag] = statistics.median(r["total_ms"] for r in rows)
    stages = " ".join(f"{k[:-3]} {statistics.median(r[k] for r in rows):.1f}"
                      for k in ("trace_ms", "filter_ms") if k in rows[0])
    print(f"{tag:7s} frame {median[tag]:.1f} ms  {stages}")
overhead = lambda t: median[t] - median["none"]
print(f"AO overhead / vtkSSAOPass's: before {overhead('before') / overhead('ssao'):.2f}, "
      f"after {overhead('after') / overhead('ssao'):.2f}")
PY
