#!/usr/bin/env bash
# cost_exact.sh: runs a `shadowlab study` or `shadowlab bench` with the exact cost clock: every
# pass's instructions, all threads, counted by valgrind's callgrind (framework/render/cost_clock.h),
# which the host's load cannot change. About 50× slower than the CPU clock: for small sweeps.
#   tools/cost_exact.sh [--cycles] SHADOWLAB bench|study [options...]
# --cycles: callgrind also simulates the caches and each pass costs its cycle estimate
# (instructions + 10 per L1 miss + 100 per last-level miss; about twice as slow again). The
# caches' sizes are fixed here, not read from the host, so the figure is the same on any CPU.
# `study` stops under valgrind 3.19 (SIGILL at an rdtscp in libhwy, which OpenImageIO loads
# when the first image is written): the bench, which writes no image, runs.
set -euo pipefail
COST=instructions CACHE=()
if [ "${1:-}" = --cycles ]; then
  shift
  COST=cycles
  CACHE=(--cache-sim=yes --I1=32768,8,64 --D1=32768,8,64 --LL=8388608,16,64)
fi
BIN="$1"; shift
command -v valgrind > /dev/null || { echo "cost_exact.sh: valgrind is not installed (apt-get install valgrind)" >&2; exit 2; }
DUMPS="$(mktemp -d)"
trap 'rm -rf "$DUMPS"' EXIT
# No re-exec for huge pages (valgrind would not follow it); llvmpipe's thread count fixed.
export SHADOWLAB_HUGE_PAGES=0 SHADOWLAB_COST=$COST SHADOWLAB_CALLGRIND_OUT="$DUMPS/cg"
export LP_NUM_THREADS="${LP_NUM_THREADS:-2}"
valgrind --tool=callgrind "${CACHE[@]}" --callgrind-out-file="$DUMPS/cg" --zero-before=shadowlab_cost_zero \
  --dump-after=shadowlab_cost_dump --dump-instr=no --compress-strings=no \
  --log-file="$DUMPS/valgrind.log" "$BIN" "$@"
