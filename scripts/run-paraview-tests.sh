#!/usr/bin/env bash
# Tests of the ParaView plugin (Plugins/ParaView) with ParaView 5.11 unpacked by
# scripts/setup-paraview.sh (run first, every time: it also rebuilds the plugin).
#
#   scripts/run-paraview-tests.sh [BUILD_DIR] [--pictures] [--benchmark]
#
# (a) pvpython: the view, every property, AO asserted on the AO-only image; the same script
#     with AO off must fail (the assertions detect missing occlusion).
# (b) pvbatch --symmetric under mpiexec -np 1, 2, 4, the plane on rank 0 and the objects on
#     the other ranks: the composited AO-only image of 2 and 4 ranks matches 1 rank
#     (RMSE <= 0.01; 128 cells, and the view's automatic grid on 2 ranks); with the grid
#     reduction off it must not; ParaView's built-in SSAO
#     (UseAmbientOcclusion) differs between 1 and 2 ranks (measured, RMSE >= 0.02).
# --pictures   also write Documentation/images/paraview/*.png (1 rank, 4 ranks, SSAO 4 ranks)
# --benchmark  also measure the grid reduction per re-voxelization (2 and 4 ranks; grids
#              128, 256, 512) into BUILD_DIR/test-output/benchmark.{jsonl,md}
# Exit status: the number of failed tests (0: all passed).
set -uo pipefail

SOURCE_DIR="$(cd "$(dirname "$0")/.." && pwd)"
BUILD_DIR="${SOURCE_DIR}/build-pv"
PICTURES=0
BENCHMARK=0
for arg in "$@"; do
  case "${arg}" in
    --pictures) PICTURES=1 ;;
    --benchmark) BENCHMARK=1 ;;
    -*) echo "unknown option ${arg}" >&2; exit 2 ;;
    *) BUILD_DIR="${arg}" ;;
  esac
done
# Always: the set-up is incremental (a few seconds when nothing changed) and rebuilds the plugin
# after a source change, which a stale build would otherwise hide.
"${SOURCE_DIR}/scripts/setup-paraview.sh" "${BUILD_DIR}" || exit 1
# shellcheck disable=SC1091
source "${BUILD_DIR}/paraview-env.sh"
T="${SOURCE_DIR}/Plugins/ParaView/Testing"
OUT="${BUILD_DIR}/test-output"
rm -rf "${OUT}"
mkdir -p "${OUT}"
XVFB=(xvfb-run -a -s "-screen 0 1920x1080x24 -noreset")
PVPYTHON="${PARAVIEW_PREFIX}/bin/pvpython"
PVBATCH="${PARAVIEW_PREFIX}/bin/pvbatch"
failed=0
passed=0
start_all=$(date +%s)

# run NAME EXPECTED_RC COMMAND...: run under a 10-minute limit, log to OUT/NAME.log.
run() {
  local name="$1" expected="$2"
  shift 2
  local t0 rc
  t0=$(date +%s)
  timeout 600 "$@" > "${OUT}/${name}.log" 2>&1
  rc=$?
  if [ "${rc}" -eq "${expected}" ]; then
    passed=$((passed + 1))
    printf 'PASS %-34s (%3ss, exit %s as expected)\n' "${name}" "$(($(date +%s) - t0))" "${rc}"
  else
    failed=$((failed + 1))
    printf 'FAIL %-34s (%3ss, exit %s, expected %s): see %s\n' "${name}" \
      "$(($(date +%s) - t0))" "${rc}" "${expected}" "${OUT}/${name}.log"
    tail -n 15 "${OUT}/${name}.log" | sed 's/^/    /'
  fi
  grep -h "^COMPARE\|^AOSTATS" "${OUT}/${name}.log" | sed 's/^/    /' || true
}
# run_ranks NAME EXPECTED_RC N ARGS...: render_ranks.py with pvbatch --symmetric on N ranks.
run_ranks() {
  local name="$1" expected="$2" n="$3"
  shift 3
  # shellcheck disable=SC2086
  run "${name}" "${expected}" "${XVFB[@]}" ${MPIEXEC} -np "${n}" "${PVBATCH}" --symmetric \
    "${T}/render_ranks.py" "$@"
}
# run_compare NAME EXPECTED_RC ARGS...: compare_images.py with pvpython.
run_compare() {
  local name="$1" expected="$2"
  shift 2
  run "${name}" "${expected}" "${PVPYTHON}" "${T}/compare_images.py" "$@"
}

# (a) pvpython
run pvpython-view 0 "${XVFB[@]}" "${PVPYTHON}" "${T}/TestAmbientOcclusionView.py" \
  --output-dir "${OUT}/view"
run pvpython-view-ao-off-must-fail 1 "${XVFB[@]}" "${PVPYTHON}" \
  "${T}/TestAmbientOcclusionView.py" --method None --output-dir "${OUT}/view-off"

# (b) pvbatch on 1, 2 and 4 ranks
for n in 1 2 4; do
  run_ranks "pvbatch-hao-np${n}" 0 "${n}" --method hao --ao-only --output "${OUT}/hao-np${n}.png"
done
run_ranks pvbatch-hao-np2-no-reduction 0 2 --method hao --ao-only --no-reduction \
  --output "${OUT}/hao-np2-no-reduction.png"
# Progressive stills on 2 ranks: every rank renders the 8 frames (IceT composites each), and
# the converged still stays the single-rank image's within the same bound.
run_ranks pvbatch-hao-np2-accumulate 0 2 --method hao --ao-only --accumulate 8 \
  --output "${OUT}/hao-np2-accumulate.png"
# The view's default grid (automatic: cells of R/64, 523 x 396 x 512 here, cut into chunks
# for the sparse reduction) on 1 and 2 ranks.
for n in 1 2; do
  run_ranks "pvbatch-hao-auto-np${n}" 0 "${n}" --method hao --ao-only --voxel-resolution 0 \
    --output "${OUT}/hao-auto-np${n}.png"
done
run_ranks pvbatch-ssao-np1 0 1 --method ssao --output "${OUT}/ssao-np1.png"
run_ranks pvbatch-ssao-np2 0 2 --method ssao --output "${OUT}/ssao-np2.png"
run_compare compare-hao-np2-vs-np1 0 "${OUT}/hao-np1.png" "${OUT}/hao-np2.png" --max-rmse 0.01 \
  --label "HAO AO-only, 2 ranks vs 1"
run_compare compare-hao-np4-vs-np1 0 "${OUT}/hao-np1.png" "${OUT}/hao-np4.png" --max-rmse 0.01 \
  --label "HAO AO-only, 4 ranks vs 1"
run_compare compare-hao-accumulate-np2-vs-np1 0 "${OUT}/hao-np1.png" \
  "${OUT}/hao-np2-accumulate.png" --max-rmse 0.01 --label "HAO AO-only, 8 frames on 2 ranks vs 1 frame"
run_compare compare-hao-auto-np2-vs-np1 0 "${OUT}/hao-auto-np1.png" "${OUT}/hao-auto-np2.png" \
  --max-rmse 0.01 --label "HAO AO-only, automatic grid, 2 ranks vs 1"
run_compare compare-hao-no-reduction-must-fail 1 "${OUT}/hao-np1.png" \
  "${OUT}/hao-np2-no-reduction.png" --max-rmse 0.01 \
  --label "HAO AO-only without grid reduction, 2 ranks vs 1"
run_compare compare-ssao-np2-differs 0 "${OUT}/ssao-np1.png" "${OUT}/ssao-np2.png" \
  --min-rmse 0.02 --label "built-in SSAO, 2 ranks vs 1"

if [ "${PICTURES}" -eq 1 ]; then
  IMG="${SOURCE_DIR}/Documentation/images/paraview"
  mkdir -p "${IMG}"
  BG=0.32,0.34,0.43 # ParaView's default background
  run_ranks picture-hao-np1 0 1 --method hao --background "${BG}" --output "${IMG}/hao-1rank.png"
  run_ranks picture-hao-np4 0 4 --method hao --background "${BG}" --output "${IMG}/hao-4ranks.png"
  run_ranks picture-ssao-np4 0 4 --method ssao --background "${BG}" --output "${IMG}/ssao-4ranks.png"
  run_ranks picture-ssao-np1 0 1 --method ssao --background "${BG}" --output "${IMG}/ssao-1rank.png"
  cp "${OUT}/hao-np1.png" "${IMG}/hao-ao-only-1rank.png"
  cp "${OUT}/hao-np4.png" "${IMG}/hao-ao-only-4ranks.png"
  cp "${OUT}/hao-np2-no-reduction.png" "${IMG}/hao-ao-only-2ranks-no-reduction.png"
  # measured for Documentation/paraview.md (shaded images, no threshold on HAO)
  run_compare measure-hao-shaded-np4-vs-np1 0 "${IMG}/hao-1rank.png" "${IMG}/hao-4ranks.png" \
    --label "HAO shaded, 4 ranks vs 1"
  run_compare compare-ssao-np4-differs 0 "${IMG}/ssao-1rank.png" "${IMG}/ssao-4ranks.png" \
    --min-rmse 0.02 --label "built-in SSAO shaded, 4 ranks vs 1"
fi

if [ "${BENCHMARK}" -eq 1 ]; then
  : > "${OUT}/benchmark.jsonl"
  for n in 2 4; do
    for r in 128 256 512; do
      run_ranks "benchmark-np${n}-r${r}" 0 "${n}" --method hao --ao-only --voxel-resolution "${r}" \
        --benchmark 7
      grep -h "^AOBENCH" "${OUT}/benchmark-np${n}-r${r}.log" | sed 's/^AOBENCH //' \
        >> "${OUT}/benchmark.jsonl"
    done
  done
  /usr/bin/python3 "${T}/summarize_benchmark.py" "${OUT}/benchmark.jsonl" | tee "${OUT}/benchmark.md"
fi

echo "paraview tests: ${passed} passed, ${failed} failed, $(($(date +%s) - start_all)) s; output in ${OUT}"
exit "${failed}"
