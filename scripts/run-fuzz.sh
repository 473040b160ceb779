#!/usr/bin/env bash
# Fuzz the vtkao program with libFuzzer for a time budget, on one core (Documentation/reliability.md).
#
# Usage: scripts/run-fuzz.sh [BUDGET] [TARGET ...]
#   BUDGET  total fuzzing time: seconds, or with a suffix s/m/h (default 30m). It is split over
#           the targets by weight: 1 for each option parser, 3 for each file format.
#   TARGET  option parsers: render compare bake view bench quality
#           readers (vtkao::AddFile): vtp vtu vtk stl ply obj objmtl glb gltf
#           (default: all of them)
#
# Builds the libFuzzer targets of Testing/Fuzz in build-fuzz (clang, AddressSanitizer +
# UndefinedBehaviorSanitizer) with Debian's VTK 9.1 reader sources compiled in with coverage
# (`apt-get source vtk9`, fetched once into build-fuzz/vtk-src), then runs each target in
# libFuzzer's fork mode (one worker: a crash, timeout or out-of-memory is saved and fuzzing
# goes on). Per target: the corpus grows in build-fuzz/fuzz-corpus/T (seeded from
# Testing/Fuzz/seeds/T), findings go to build-fuzz/fuzz-findings/T, the log to
# build-fuzz/fuzz-logs/T.log; build-fuzz/fuzz-summary.md gets executions, coverage and findings,
# and each finding is run once more to name it (sanitizer summary and first frame).
#
# Environment: BUILD_DIR (default build-fuzz), JOBS (build parallelism, default 2),
# FUZZ_SEED_ONLY=1 (build, then run each target over its seeds only: a smoke test).
# Exit status: 0 when no target saved a finding in this run, 3 when some did, other = failure.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$here/build-fuzz}"
budget="${1:-30m}"
shift || true
options_targets=(render compare bake view bench quality)
reader_targets=(vtp vtu vtk stl ply obj objmtl glb gltf)
targets=("$@")
[ "${#targets[@]}" -gt 0 ] || targets=("${options_targets[@]}" "${reader_targets[@]}")

case "$budget" in
  *h) seconds=$((${budget%h} * 3600)) ;;
  *m) seconds=$((${budget%m} * 60)) ;;
  *s) seconds=${budget%s} ;;
  *) seconds=$budget ;;
esac
[[ "$seconds" =~ ^[0-9]+$ ]] && [ "$seconds" -gt 0 ] || { echo "bad budget '$budget'" >&2; exit 2; }

# --- tools and the VTK sources -------------------------------------------------------------
# A fresh machine: the project's packages (scripts/setup.sh, which also builds build/), then
# clang (libFuzzer) and dpkg-dev (apt-get source).
installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "ok installed"; }
if ! installed libvtk9-dev || ! installed libembree-dev || ! installed libopenimageio-dev; then
  "$here/scripts/setup.sh"
fi
SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo" # as scripts/setup.sh
for p in clang dpkg-dev; do
  if ! installed "$p"; then
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "$p" >/dev/null
  fi
done
vtk_version="$(dpkg-query -W -f='${Version}' libvtk9-dev)"
vtk_src="$(ls -d "$build"/vtk-src/vtk9-*/ 2>/dev/null | head -n1 || true)"
if [ -z "$vtk_src" ]; then
  mkdir -p "$build/vtk-src"
  if ! apt-cache showsrc vtk9 2>/dev/null | grep -q "^Version: $vtk_version\$"; then
    # apt-get source needs the deb-src index of the Debian mirror the binaries came from.
    echo "run-fuzz: adding deb-src entries for bookworm (/etc/apt/sources.list.d/vtkao-deb-src.sources)"
    $SUDO tee /etc/apt/sources.list.d/vtkao-deb-src.sources >/dev/null <<'EOF'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm bookworm-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg

Types: deb-src
URIs: http://deb.debian.org/debian-security
Suites: bookworm-security
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
EOF
    $SUDO apt-get update -qq >/dev/null 2>&1 || true
  fi
  if (cd "$build/vtk-src" && apt-get source "vtk9=$vtk_version" >apt-source.log 2>&1); then
    vtk_src="$(ls -d "$build"/vtk-src/vtk9-*/ | head -n1)"
  else
    echo "run-fuzz: apt-get source vtk9=$vtk_version failed (see $build/vtk-src/apt-source.log):" \
      "the VTK readers run without coverage instrumentation" >&2
  fi
fi
vtk_src="${vtk_src%/}"

# --- build -------------------------------------------------------------------------------------
CC=clang CXX=clang++ cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DVTKAO_ENABLE_SANITIZERS=ON -DVTKAO_ENABLE_FUZZING=ON -DBUILD_TESTING=OFF \
  -DVTKAO_WRAP_PYTHON=OFF -DVTKAO_FUZZ_VTK_SOURCE_DIR="$vtk_src" >/dev/null
fuzz_binaries=()
for t in "${targets[@]}"; do
  case " ${reader_targets[*]} " in
    *" $t "*) fuzz_binaries+=(vtkaoFuzzReader) ;;
    *) fuzz_binaries+=("vtkaoFuzz${t^}") ;;
  esac
done
mapfile -t fuzz_binaries < <(printf '%s\n' "${fuzz_binaries[@]}" | sort -u)
nice cmake --build "$build" -j"${JOBS:-2}" --target "${fuzz_binaries[@]}" >/dev/null

# --- run -----------------------------------------------------------------------------------
# Leaks are the sanitizer suite's business (scripts/run-sanitizers.sh); the fuzz targets mix
# instrumented and uninstrumented VTK code, which makes container-overflow checks unreliable.
export ASAN_OPTIONS="detect_leaks=0:detect_odr_violation=0:detect_container_overflow=0:abort_on_error=1:symbolize=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$here/Testing/Fuzz/ubsan.supp"
weight() { case " ${reader_targets[*]} " in *" $1 "*) echo 3 ;; *) echo 1 ;; esac; }
total_weight=0
for t in "${targets[@]}"; do total_weight=$((total_weight + $(weight "$t"))); done
mkdir -p "$build/fuzz-logs" "$build/fuzz-corpus" "$build/fuzz-findings"
summary="$build/fuzz-summary.md"
{
  echo "vtkao fuzzing, $(date -u +%Y-%m-%dT%H:%MZ), budget ${seconds} s on one core; $(clang --version | head -n1)"
  echo "VTK reader sources instrumented: ${vtk_src:-no}"
  echo
  echo "| target | seconds | executions | exec/s | coverage (edges) | features | corpus | new findings (crash/oom/timeout) |"
  echo "|---|---|---|---|---|---|---|---|"
} >"$summary"
status=0
for t in "${targets[@]}"; do
  case " ${reader_targets[*]} " in
    *" $t "*) binary="$build/fuzz/vtkaoFuzzReader"; dict="" ; max_len=20000
      case "$t" in
        vtp | vtu) dict=xml ;; vtk) dict=legacy ;; stl) dict=stl ;; ply) dict=ply ;;
        obj | objmtl) dict=obj ;; glb | gltf) dict=gltf ;;
      esac ;;
    *) binary="$build/fuzz/vtkaoFuzz${t^}"; dict=options; max_len=1024 ;;
  esac
  time_t=$((seconds * $(weight "$t") / total_weight))
  [ "$time_t" -ge 10 ] || time_t=10
  corpus="$build/fuzz-corpus/$t"
  findings="$build/fuzz-findings/$t"
  mkdir -p "$corpus" "$findings"
  ls "$findings" | sort >"$build/fuzz-logs/$t.before"
  log="$build/fuzz-logs/$t.log"
  echo "run-fuzz: $t for ${time_t} s ..."
  args=(-timeout=10 -rss_limit_mb=2560 -malloc_limit_mb=1024 -max_len="$max_len"
        -dict="$here/Testing/Fuzz/dict/$dict.dict" -artifact_prefix="$findings/"
        -print_final_stats=1)
  if [ "${FUZZ_SEED_ONLY:-0}" = 1 ]; then
    args+=(-runs=0)
  else
    args+=(-fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1 -max_total_time="$time_t")
  fi
  start=$(date +%s)
  set +e
  VTKAO_FUZZ_FORMAT="$t" nice -n 10 timeout $((time_t + 300)) "$binary" "${args[@]}" \
    "$corpus" "$here/Testing/Fuzz/seeds/$t" >"$log" 2>&1
  rc=$?
  set -e
  elapsed=$(($(date +%s) - start))
  # Fork mode prints "#N: cov: C ft: F corp: K exec/s: E oom/timeout/crash: a/b/c time: T";
  # a single process prints "#N ... cov: C ft: F corp: K/..b exec/s: E".
  last="$(grep -E '^#[0-9]+' "$log" | tail -n1 || true)"
  execs="$(sed -nE 's/^#([0-9]+).*/\1/p' <<<"$last")"
  cov="$(sed -nE 's/.*cov: ([0-9]+).*/\1/p' <<<"$last")"
  ft="$(sed -nE 's/.*ft: ([0-9]+).*/\1/p' <<<"$last")"
  corp="$(ls "$corpus" | wc -l)"
  eps=$((${execs:-0} / (elapsed > 0 ? elapsed : 1)))
  new_crash=0 new_oom=0 new_timeout=0
  ls "$findings" | sort | comm -13 "$build/fuzz-logs/$t.before" - >"$build/fuzz-logs/$t.new"
  for f in $(cat "$build/fuzz-logs/$t.new"); do
    case "$f" in
      oom-*) new_oom=$((new_oom + 1)) ;;
      timeout-*) new_timeout=$((new_timeout + 1)) ;;
      *) new_crash=$((new_crash + 1)) ;;
    esac
  done
  echo "| $t | $elapsed | ${execs:-?} | $eps | ${cov:-?} | ${ft:-?} | $corp | $new_crash/$new_oom/$new_timeout |" >>"$summary"
  if [ $((new_crash + new_oom + new_timeout)) -gt 0 ]; then
    status=3
  fi
  if [ "${FUZZ_SEED_ONLY:-0}" = 1 ] && [ "$rc" -ne 0 ]; then
    echo "run-fuzz: $t failed on its seeds (rc $rc), see $log" >&2
    status=1
  fi
done

# --- name the findings ------------------------------------------------------------------------
{
  echo
  echo "New findings of this run (each re-run once: sanitizer summary, first frame in vtkao or VTK code):"
  echo
} >>"$summary"
for t in "${targets[@]}"; do
  case " ${reader_targets[*]} " in
    *" $t "*) binary="$build/fuzz/vtkaoFuzzReader" ;; *) binary="$build/fuzz/vtkaoFuzz${t^}" ;;
  esac
  for name in $(cat "$build/fuzz-logs/$t.new"); do
    f="$build/fuzz-findings/$t/$name"
    out="$(VTKAO_FUZZ_FORMAT="$t" timeout 120 "$binary" -runs=1 -timeout=10 -rss_limit_mb=2560 \
      -malloc_limit_mb=1024 "$f" 2>&1 || true)"
    what="$(grep -m1 -E 'SUMMARY: |ERROR: libFuzzer: |vtkao fuzz finding: ' <<<"$out" || echo "no longer reproduces")"
    frame="$(grep -m1 -E '^ +#[0-9]+ .* in .*(/Examples/|/Testing/Fuzz/|/vtk-src/)' <<<"$out" \
      | sed -E 's/^ +#[0-9]+ 0x[0-9a-f]+ in //; s#/work/[^ ]*/(Examples|Testing|IO|Filters|Common)/#\1/#' || true)"
    echo "- $t/$(basename "$f"): ${what#*SUMMARY: }${frame:+ — $frame}" >>"$summary"
  done
done
cat "$summary"
exit $status
