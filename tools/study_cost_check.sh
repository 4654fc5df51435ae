#!/usr/bin/env bash
# study_cost_check.sh: does the study's cost axis hold on a busy machine? Runs the same study
# twice, into OUT/quiet/ and OUT/loaded/, the second with a busy loop on every core but one
# (started and stopped here), then compares every row's cost (frame_cost_min) and the ratio
# to the copy pass (frame_over_copy), and prints the largest relative differences.
#   tools/study_cost_check.sh [--exact] SHADOWLAB OUT [shadowlab study options...]
# --exact: both runs count instructions under callgrind (tools/cost_exact.sh) instead of CPU time.
# Exit status 1 if a row's cost differs by more than ${SHADOWLAB_COST_TOLERANCE:-10} %.
set -euo pipefail
RUN=()
if [ "${1:-}" = --exact ]; then RUN=("$(dirname "$0")/cost_exact.sh"); shift; fi
BIN="$1"; OUT="$2"; shift 2
export LP_NUM_THREADS="${LP_NUM_THREADS:-2}"
rm -rf "$OUT/quiet" "$OUT/loaded"
"${RUN[@]}" "$BIN" study --out "$OUT/quiet" --no-progress "$@" > "$OUT.quiet.log"
LOADERS=()
for _ in $(seq "$(( $(nproc) > 1 ? $(nproc) - 1 : 1 ))"); do
  ( while :; do :; done ) &
  LOADERS+=("$!")
done
stop() { for p in "${LOADERS[@]}"; do kill "$p" 2>/dev/null || true; done; }
trap stop EXIT
"${RUN[@]}" "$BIN" study --out "$OUT/loaded" --no-progress "$@" > "$OUT.loaded.log"
stop
trap - EXIT
# Rows by key (scene..light_size); columns found by name in the header.
awk -F, -v tol="${SHADOWLAB_COST_TOLERANCE:-10}" '
  function col(name,   i) { for (i = 1; i <= NF; ++i) if ($i == name) return i; return 0 }
  FNR == 1 { cost = col("frame_cost_min"); wall = col("frame_wall_ms_median"); ratio = col("frame_over_copy"); file++; next }
  { key = $1 "|" $4 "|" $5 "|" $6 "|" $8 "|" $9 }
  file == 1 { c[key] = $cost; w[key] = $wall; q[key] = $ratio; next }
  key in c {
    n++
    d = ($cost - c[key]) / c[key]; if (d < 0) d = -d
    dw = ($wall - w[key]) / w[key]; if (dw < 0) dw = -dw
    dq = ($ratio - q[key]) / q[key]; if (dq < 0) dq = -dq
    if (d > worst) { worst = d; worstKey = key }
    if (dw > worstWall) worstWall = dw
    if (dq > worstRatio) worstRatio = dq
    sum += d
  }
  END {
    printf "%d rows compared: cost (frame_cost_min) differs by at most %.3g %% (%s), mean %.3g %%; " \
           "frame/copy ratio at most %.1f %%; wall time (frame_wall_ms_median) at most %.0f %%\n",
           n, 100 * worst, worstKey, 100 * sum / n, 100 * worstRatio, 100 * worstWall
    exit (100 * worst > tol)
  }' "$OUT/quiet/study.csv" "$OUT/loaded/study.csv"
